#!/usr/bin/python3
"""The frame budget along a camera path, then the still view's refinement, measured.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/budget.py --output-dir docs

Scene: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure 40) at
--size, with the pass's still setting (--still: a preset, or RAY_MARCH 16 steps with a 2048²
map) and ProgressiveRefinement on. The path: the window's DesiredUpdateRate set to --rate (what
VTK's interactors do while the user drags: the renderer's AllocatedRenderTime becomes the
budget), the camera turned by 0.5 degree per frame for --frames frames, each finished
(WaitForCompletion) and timed; the error of the in-scatter against vtkLightShaftReference
(exact surfaces and shadows, float64; pixels above 1% of its peak) on every --every-th frame.
Then the rate set back to rest (0.0001) and the still view refined until converged: the error
and the seconds since the camera stopped after each power of two of estimates.

Writes budget.md into --output-dir (and prints it).
"""

import argparse
import os
import platform
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, vtkLightShaftPass  # noqa: E402
from refinement import timed_render  # noqa: E402  (tests/benchmarks/refinement.py)

STILL = {
    "RAY_MARCH 16 steps, 2048² map": dict(Method=vtkLightShaftPass.RAY_MARCH, NumberOfSteps=16,
                                          InterleaveSize=1, ShadowMapSize=2048, BlurRadius=0),
    "Interactive": None, "Final": None, "Draft": None,
}


def error_now(renderer, shafts):
    image = rh.in_scatter(shafts)
    error, _ = ref.relative_rms_error(image, rh.scene_reference(renderer, shafts))
    return error


def run(args):
    renderer, window, plain, shafts = rh.window_scene(*args.size)
    still = STILL[args.still]
    if still is None:
        getattr(shafts, "SetQualityTo" + args.still)()
    else:
        for key, value in still.items():
            getattr(parameter_owner(shafts, key), "Set" + key)(value)
    shafts.SetRefinementFrames(args.estimates)
    shafts.ProgressiveRefinementOn()
    renderer.SetPass(shafts)
    for _ in range(3):  # the shaders compiled at rest
        timed_render(window)
    camera = renderer.GetActiveCamera()
    moving = []
    window.SetDesiredUpdateRate(args.rate)
    try:
        for frame in progress.steps(range(args.frames), "frames (moving)"):
            camera.Azimuth(0.5)
            seconds = timed_render(window)
            name = vtkLightShaftPass.GetErrorModelSettingName(shafts.GetLastFrame().GetErrorModelSetting())
            error = error_now(renderer, shafts) if frame % args.every == args.every - 1 else None
            moving.append((frame, seconds, shafts.GetLastFrame().GetPredictedFrameTime(), name,
                           shafts.GetLastFrame().GetDownsampleFactor(), error))
    finally:
        window.SetDesiredUpdateRate(0.0001)
    refining = []
    elapsed = 0.0
    for k in progress.steps(range(1, args.estimates + 1), "estimates (still)"):
        elapsed += timed_render(window)
        if k & (k - 1) == 0 or shafts.GetLastFrame().GetRefinementConverged():
            refining.append((shafts.GetLastFrame().GetRefinementEstimates(), elapsed,
                             error_now(renderer, shafts)))
        if shafts.GetLastFrame().GetRefinementConverged():
            break
    renderer.SetPass(None)
    return plain, moving, refining


def table(args, plain, moving, refining):
    times = [seconds for _, seconds, *_ in moving[2:]]
    errors = [e for *_, e in moving if e is not None]
    lines = [f"# The frame budget along a camera path ({args.size[0]}x{args.size[1]}, window "
             "scene)", "",
             f"{platform.node()}, {platform.processor() or platform.machine()}; command: "
             f"`tools/measure.sh budget{' ' + ' '.join(sys.argv[1:]) if sys.argv[1:] else ''}`.",
             "",
             f"Plain frame (no pass, settled): {plain * 1000:.1f} ms. Budget: 1/{args.rate:g} s "
             f"= {1000 / args.rate:.0f} ms (DesiredUpdateRate {args.rate:g}). Still setting: "
             f"{args.still}.", "",
             f"While moving (frames 3 to {len(moving)}): median frame {statistics.median(times) * 1000:.0f} ms "
             f"({1 / statistics.median(times):.1f} fps), p90 "
             f"{sorted(times)[int(0.9 * (len(times) - 1))] * 1000:.0f} ms, max "
             f"{max(times) * 1000:.0f} ms; error against the reference on every "
             f"{args.every}th frame: median {100 * statistics.median(errors):.2f}%, max "
             f"{100 * max(errors):.2f}%.", "",
             "| frame | time | predicted | setting | resolution | error |",
             "|---:|---:|---:|---|---:|---:|"]
    for frame, seconds, predicted, name, factor, error in moving:
        lines.append(f"| {frame + 1} | {seconds * 1000:.0f} ms | {predicted * 1000:.0f} ms | "
                     f"{name} | 1/{factor} | "
                     f"{'' if error is None else f'{100 * error:.2f}%'} |")
    lines += ["", "After the path stops (rate back to rest, refinement):", "",
              "| estimates | seconds since the camera stopped | error |", "|---:|---:|---:|"]
    for estimates, elapsed, error in refining:
        lines.append(f"| {estimates} | {elapsed:.2f} s | {100 * error:.2f}% |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--rate", type=float, default=15.0)
    parser.add_argument("--frames", type=int, default=40)
    parser.add_argument("--every", type=int, default=8)
    parser.add_argument("--estimates", type=int, default=32)
    parser.add_argument("--still", default="RAY_MARCH 16 steps, 2048² map", choices=list(STILL))
    args = parser.parse_args()
    text = table(args, *run(args))
    print(text)
    if args.output_dir:
        with open(os.path.join(args.output_dir, "budget.md"), "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
