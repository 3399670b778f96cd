#!/usr/bin/python3
"""Progressive refinement of a still view, measured: how the error against the float64
reference falls with the estimates, and the seconds that takes.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/refinement.py --output-dir docs

Scene: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure 40) at
--size. For each setting: the plain frame (no pass; median of --frames after the scene has
settled, as tools/measure.sh random-scenes measures it); then, with ProgressiveRefinement on,
the camera nudged (a new picture) and --estimates frames rendered one after another, each
finished (WaitForCompletion) and timed; after 1, 2, 4, 8, ... estimates the in-scatter's
relative RMS error against vtkLightShaftReference (exact surfaces and shadows, float64; pixels
above 1% of its peak). Also the frames after convergence (the converged picture reused).

Writes refinement.md into --output-dir (and prints it).
"""

import argparse
import os
import platform
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, scenes, vtkLightShaftPass  # noqa: E402

SETTINGS = {
    "RAY_MARCH 4 steps, 1024² map": dict(Method=vtkLightShaftPass.RAY_MARCH, NumberOfSteps=4,
                                         InterleaveSize=1, ShadowMapSize=1024),
    "RAY_MARCH 16 steps, 2048² map": dict(Method=vtkLightShaftPass.RAY_MARCH, NumberOfSteps=16,
                                          InterleaveSize=1, ShadowMapSize=2048),
    "EPIPOLAR 16 steps (Draft's lines), 1024² map": dict(
        Method=vtkLightShaftPass.EPIPOLAR, NumberOfSteps=16, EpipolarLines=128,
        EpipolarSamples=256, EpipolarStep=8, ShadowMapSize=1024),
}


def make_scene(width, height):
    renderer, window = rh.make_window(width, height)
    scenes.window_room(renderer)
    return renderer, window


def timed_render(window):
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return time.perf_counter() - start


def measure(name, params, width, height, estimates, frames):
    renderer, window = make_scene(width, height)
    plain = rh.median_frame_time(window, frames, warm_up=30, warm_up_seconds=2.0)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(40.0)
    shafts.SetBlurRadius(0)
    for key, value in params.items():
        getattr(parameter_owner(shafts, key), "Set" + key)(value)
    shafts.SetRefinementFrames(estimates)
    shafts.ProgressiveRefinementOn()
    renderer.SetPass(shafts)
    for _ in range(3):  # the shaders compiled, the scene settled
        timed_render(window)
    renderer.GetActiveCamera().Azimuth(0.01)  # a new picture
    rows = []
    elapsed = 0.0
    reference = None
    for k in range(1, estimates + 1):
        seconds = timed_render(window)
        elapsed += seconds
        assert shafts.GetLastFrame().GetRefinementEstimates() == k
        if k & (k - 1) == 0 or k == estimates:
            image = rh.in_scatter(shafts)
            if reference is None:
                reference = rh.scene_reference(renderer, shafts)
            error, _ = ref.relative_rms_error(image, reference)
            rows.append((k, seconds, elapsed, error))
    assert shafts.GetLastFrame().GetRefinementConverged()
    reused = statistics.median(timed_render(window) for _ in range(frames))
    assert shafts.GetLastFrame().GetInScatterReused()
    renderer.SetPass(None)
    return dict(name=name, plain=plain, rows=rows, reused=reused)


def table(results, width, height):
    lines = [f"# Progressive refinement, measured ({width}x{height}, window scene)", "",
             f"{platform.node()}, {platform.processor() or platform.machine()}; "
             "command: `tools/measure.sh refinement`.", ""]
    for result in results:
        plain = result["plain"]
        lines += [f"## {result['name']}", "",
                  f"Plain frame (no pass): {plain * 1000:.1f} ms. Frames after convergence "
                  f"(the converged picture reused): {result['reused'] * 1000:.1f} ms.", "",
                  "| estimates | this frame | seconds since the view stopped | error against "
                  "the reference |", "|---:|---:|---:|---:|"]
        for k, seconds, elapsed, error in result["rows"]:
            lines.append(f"| {k} | {seconds * 1000:.0f} ms | {elapsed:.2f} s | "
                         f"{100 * error:.2f}% |")
        lines.append("")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--estimates", type=int, default=32)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--settings", nargs="+", default=list(SETTINGS))
    args = parser.parse_args()
    results = [measure(name, SETTINGS[name], *args.size, args.estimates, args.frames)
               for name in progress.steps(args.settings, "settings")]
    text = table(results, *args.size)
    print(text)
    if args.output_dir:
        with open(os.path.join(args.output_dir, "refinement.md"), "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
