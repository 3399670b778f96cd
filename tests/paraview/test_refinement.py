"""pvbatch test: progressive refinement and the frame budget in a LightShaftsRenderView, as a
script sees them through the view's information properties.

  1. With ProgressiveRefinement and RefinementFrames 4, each still render adds one estimate
     (RefinementEstimates 1, 2, 3, 4) and the fourth is converged (RefinementConverged 1);
     later renders keep it. No budget applies to a still render (LastTimeBudget 0).
  2. An interactive render (what ParaView's interaction renders) follows the interaction's
     budget: LastTimeBudget is the time ParaView allocates it (1/15 s in 5.11, 1/20 s in 5.13
     and 6.1), under a second.
  3. The still render after it refines again from one estimate and converges.
  4. ExactFinish: a still view's float64 reference finishes in the background (ExactFinishState
     1, ExactFinishFraction growing); the renders until RefinementConverged end it complete
     (ExactFinishState 2, fraction 1, LastPredictedError 0), and a change of the camera starts
     it again.
Usage: pvbatch test_refinement.py OUTPUT_DIR
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402


def read_out(view):
    view.UpdatePropertyInformation()
    return (view.GetPropertyValue("RefinementEstimates"),
            view.GetPropertyValue("RefinementConverged"),
            view.GetPropertyValue("LastTimeBudget"))


def refine(view, failures, label):
    """Still renders until converged; the estimates seen after each."""
    from paraview import simple
    seen = []
    for _ in range(6):
        simple.Render(view)
        estimates, converged, budget = read_out(view)
        seen.append(estimates)
        if budget != 0.0:
            failures.append(f"{label}: a still render followed a budget of {budget} s")
        if converged:
            break
    print(f"{label}: estimates {seen}")
    if seen != [1, 2, 3, 4]:
        failures.append(f"{label}: estimates {seen}, not [1, 2, 3, 4] then converged")


def main():
    from paraview import simple
    scene.load_plugin()
    view, _, _ = scene.make_scene(ShaftMethod="Ray March")
    view.ProgressiveRefinement = 1
    view.RefinementFrames = 4
    failures = []
    refine(view, failures, "still")
    simple.Render(view)
    estimates, converged, _ = read_out(view)
    if (estimates, converged) != (4, 1):
        failures.append(f"a converged view rendered again: estimates {estimates}, "
                        f"converged {converged}")

    view.SMProxy.InteractiveRender()
    _, _, budget = read_out(view)
    print(f"interactive render: budget {budget:.4f} s")
    if not 0.0 < budget < 1.0:
        failures.append(f"the interactive render followed a budget of {budget} s, not the "
                        "interaction's")

    refine(view, failures, "still after the interaction")
    exact_finish(view, failures)
    return scene.report(failures)


def finish_state(view):
    view.UpdatePropertyInformation()
    return (view.GetPropertyValue("ExactFinishState"),
            view.GetPropertyValue("ExactFinishFraction"),
            view.GetPropertyValue("RefinementConverged"),
            view.GetPropertyValue("LastPredictedError"))


def exact_finish(view, failures):
    import time
    from paraview import simple
    view.ExactFinish = 1
    for attempt in ("first", "after a camera change"):
        if attempt != "first":
            view.CameraPosition = [0.5, 3.0, 14.0]
        seen = []
        start = time.monotonic()
        while time.monotonic() - start < 120.0:
            simple.Render(view)
            state = finish_state(view)
            seen.append(state[0])
            if state[2]:
                break
            time.sleep(0.05)
        state, fraction, converged, predicted = finish_state(view)
        print(f"exact finish {attempt}: {len(seen)} renders, states {sorted(set(seen))}, "
              f"fraction {fraction}, predicted error {predicted}")
        if 1 not in seen or (state, fraction, converged, predicted) != (2, 1.0, 1, 0.0):
            failures.append(f"exact finish {attempt}: states {sorted(set(seen))}, last "
                            f"{(state, fraction, converged, predicted)}, not complete "
                            f"(2, 1, 1, 0): {view.GetPropertyValue('ExactFinishProblem')}")
    view.ExactFinish = 0


if __name__ == "__main__":
    scene.finish(main())
