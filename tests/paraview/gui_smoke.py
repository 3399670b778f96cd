"""Run inside the ParaView GUI (paraview --script=...): load the LightShafts plugin, build the
test scene in a "Render View (Light Shafts)" shown in the layout, and check that the GUI keeps a
still view refining (the plugin's pqLightShaftsRefinement) and pauses while the user interacts.
The steps run from the interactor's timers, inside the GUI's event loop (the test's events
only keep that loop running: gui_smoke_events.xml):

  0. Progressive Refinement on, Refinement Frames 8, one render: the GUI renders again by itself
     until the shafts converge (RefinementEstimates 8, RefinementConverged 1).
  1. The user starts interacting and the camera moves (one still render: 1 estimate). While the
     interaction lasts, nothing renders again: still 1 estimate, not converged.
  2. The interaction ends (ParaView's still render): the GUI refines again to 8 estimates.

What happened goes to $LIGHTSHAFTS_SMOKE_OUT, with "ok" as its last line when every step held,
for run_gui_smoke.sh to check."""

import os
import sys
import time

# (The GUI runs the script without __file__: run_gui_smoke.sh says where it is.)
sys.path.insert(0, os.environ["LIGHTSHAFTS_PARAVIEW_TESTS"])
import lightshafts_pvscene as scene  # noqa: E402

from paraview import simple  # noqa: E402

STEP_SECONDS = (6.0, 3.0, 6.0)   # refine; interact; refine again (llvmpipe needs < 2 s each)

simple.LoadPlugin(os.environ["LIGHTSHAFTS_PARAVIEW_PLUGIN"], remote=False, ns=globals())
view = simple.CreateView("LightShaftsRenderView")
scene.make_scene(view, ShaftMethod="Ray March")
view.ProgressiveRefinement = 1
view.RefinementFrames = 8
simple.AssignViewToLayout(view)
simple.Render(view)
interactor = view.SMProxy.GetInteractor()
lines = [f"{view.GetXMLName()} {interactor.GetClassName()}"]
failures = []


def refinement():
    view.UpdatePropertyInformation()
    return (view.GetPropertyValue("RefinementEstimates"),
            view.GetPropertyValue("RefinementConverged"))


def expect(label, wanted):
    seen = refinement()
    lines.append(f"{label}: estimates, converged = {seen}")
    if seen != wanted:
        failures.append(f"{label}: {seen}, expected {wanted}")


def finish():
    lines.extend(f"FAIL: {failure}" for failure in failures)
    if not failures:
        lines.append("ok")
    with open(os.environ["LIGHTSHAFTS_SMOKE_OUT"], "w") as f:
        f.write("\n".join(lines) + "\n")


def still_refined():
    expect("refined by the GUI", (8, 1))
    interactor.InvokeEvent("StartInteractionEvent")
    camera = view.GetActiveCamera()
    camera.Azimuth(5.0)
    simple.Render(view)
    expect("camera moved, interacting", (1, 0))


def paused():
    expect("still interacting", (1, 0))
    interactor.InvokeEvent("EndInteractionEvent")
    simple.Render(view)


def refined_again():
    expect("refined after the interaction", (8, 1))
    finish()


steps = [still_refined, paused, refined_again]
due = [time.monotonic() + STEP_SECONDS[0]]


def on_timer(caller, event):
    # (ParaView's own timers fire here too: act only on ours, when it is due; Qt's timers can
    # fire a little early.)
    if not steps or time.monotonic() < due[0] - 0.5:
        return
    steps.pop(0)()
    if steps:
        due[0] = time.monotonic() + STEP_SECONDS[3 - len(steps)]
        interactor.CreateOneShotTimer(int(STEP_SECONDS[3 - len(steps)] * 1000))


interactor.AddObserver("TimerEvent", on_timer)
interactor.CreateOneShotTimer(int(STEP_SECONDS[0] * 1000))
