#!/usr/bin/python3
"""The Final preset in a still view, its frames whole or split among estimates, measured.

    tools/measure.sh still-final       # docs/still-final.md

Scene: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure
40) at --size (1280x720), the Final preset (RAY_MARCH 256 steps, 2048² map), ProgressiveRefinement
on with --refinement-frames. Two runs on the same views, in both
the camera turned by 0.5 degree per frame for --frames frames under a frame budget (the
window's DesiredUpdateRate --rate, as VTK's interactors set it while the user drags), then
stopped:
- whole: ProgressiveRefinement switched on as the camera stops (a new view for the pass), and
  SplitLongFrames off: each still frame computes one Final estimate, as still views did before
  settings were split;
- split: ProgressiveRefinement on throughout: where a Final frame would overrun the budget's
  frame, each still estimate marches a share of its steps (GetRefinementSplit()), and the
  picture shown is the moving one until the shares add up to one Final frame, then that of the
  last complete group.
The still view is rendered back to back, each frame finished and timed, until the picture is
converged or --seconds have passed; the in-scatter is read back after each frame (outside the
timing) and compared with vtkLightShaftReference (exact surfaces and shadows, float64; pixels
above 1% of its peak) after the run.

Reported: each run's still frames (the first, the median, the longest), the seconds after which
the picture first reaches a Final frame's error, and the error over time.
Writes still-final.md into --output-dir (and prints it).
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
from lightshafts import vtkLightShaftPass  # noqa: E402
from refinement import timed_render  # noqa: E402  (tests/benchmarks/refinement.py)


def run(args, split):
    """One run: the moving path, then the still view. Returns (moving frame times, still
    frames as (seconds since the camera stopped, frame seconds, estimates, held, split,
    in-scatter), the reference)."""
    renderer, window, plain, shafts = rh.window_scene(*args.size)
    shafts.SetQualityToFinal()
    shafts.SetProgressiveRefinement(split)
    # (Whole: each still frame one whole Final estimate, also where it integrates more than a
    # long frame's 2^26 segments, as at 1280x720.)
    shafts.SetSplitLongFrames(split)
    shafts.SetRefinementFrames(args.refinement_frames)
    renderer.SetPass(shafts)
    timed_render(window)  # the shaders compiled at rest
    camera = renderer.GetActiveCamera()
    moving = []
    window.SetDesiredUpdateRate(args.rate)
    try:
        for _ in range(args.frames):
            camera.Azimuth(0.5)
            moving.append(timed_render(window))
    finally:
        window.SetDesiredUpdateRate(0.0001)
    moving_picture = rh.in_scatter(shafts)
    # (Whole: refinement switched on as the camera stops, a change of parameter: the still view
    # starts anew, as before still settings were split.)
    shafts.ProgressiveRefinementOn()
    still = []
    elapsed = 0.0
    while elapsed < args.seconds:
        seconds = timed_render(window)
        elapsed += seconds
        frame = shafts.GetLastFrame()
        still.append((elapsed, seconds, frame.GetRefinementEstimates(), frame.GetRefinementHeld(),
                      frame.GetRefinementSplit(), rh.in_scatter(shafts)))
        if frame.GetRefinementConverged():
            break
    exact = rh.scene_reference(renderer, shafts)
    renderer.SetPass(None)
    return moving, ref.relative_rms_error(moving_picture, exact)[0], still, exact


def summary(name, moving, moving_error, still, exact, aim):
    times = [seconds for _, seconds, *_ in still]
    errors = [ref.relative_rms_error(picture, exact)[0] for *_, picture in still]
    # (Within float rounding: a complete group of shares is one Final frame, piece for piece.)
    reached = next((t for (t, *_), e in zip(still, errors) if e <= aim * (1 + 1e-4)), None)
    lines = [f"- {name}: moving frames median {1000 * statistics.median(moving):.0f} ms, the last "
             f"one's picture {100 * moving_error:.2f}% from the reference; still frames: the "
             f"first {1000 * times[0]:.0f} ms, median {1000 * statistics.median(times):.0f} ms, "
             f"longest {1000 * max(times):.0f} ms ({len(times)} frames, split "
             f"{still[0][4]}); within one Final frame's error ({100 * aim:.2f}%) "
             + (f"after {reached:.1f} s." if reached is not None else "not within the run.")]
    return lines, errors


def table(args, whole, split):
    # A Final frame's error: the whole run's first still frame (one Final frame).
    aim = ref.relative_rms_error(whole[2][0][-1], whole[3])[0]
    whole_lines, whole_errors = summary("Whole", *whole, aim)
    split_lines, split_errors = summary("Split", *split, aim)
    lines = [f"# The Final preset in a still view, whole or split ({args.size[0]}x{args.size[1]}, "
             "window scene)", "",
             f"{platform.node()}, {platform.processor() or platform.machine()}; command: "
             f"`tools/measure.sh still-final{' ' + ' '.join(sys.argv[1:]) if sys.argv[1:] else ''}`.",
             "",
             f"Final preset, RefinementFrames {args.refinement_frames}. The camera turned "
             f"{args.frames} frames by 0.5 degree under a budget of 1/{args.rate:g} s "
             f"(DesiredUpdateRate {args.rate:g}), then still, rendered back to back for "
             f"{args.seconds:g} s at most. Whole: ProgressiveRefinement switched on as the camera "
             "stops (the still view starts anew: whole Final estimates). Split: on throughout "
             "(the still estimates split where a Final frame would overrun the budget).", ""]
    lines += whole_lines + split_lines
    lines += ["", "| whole: seconds since the camera stopped | this frame | estimates | error "
              "| split: seconds | this frame | estimates | held | error |",
              "|---:|---:|---:|---:|---:|---:|---:|---|---:|"]

    def rows(still, errors):
        # Every frame while few, then the frames at powers of two of estimates and the last.
        out = []
        for i, ((t, seconds, estimates, held, _, _), error) in enumerate(zip(still, errors)):
            if i < 4 or estimates & (estimates - 1) == 0 or i == len(still) - 1:
                out.append((f"{t:.2f} s", f"{1000 * seconds:.0f} ms", str(estimates),
                            "yes" if held else "", f"{100 * error:.3f}%"))
        return out

    left = rows(whole[2], whole_errors)
    right = rows(split[2], split_errors)
    for i in range(max(len(left), len(right))):
        a = left[i] if i < len(left) else ("",) * 5
        b = right[i] if i < len(right) else ("",) * 5
        lines.append(f"| {a[0]} | {a[1]} | {a[2]} | {a[4]} | {b[0]} | {b[1]} | {b[2]} | {b[3]} "
                     f"| {b[4]} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--rate", type=float, default=15.0)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--refinement-frames", type=int, default=4)
    parser.add_argument("--seconds", type=float, default=30.0)
    args = parser.parse_args()
    whole, split = [run(args, split=s) for s in progress.steps((False, True), "runs")]
    text = table(args, whole, split)
    print(text)
    if args.output_dir:
        with open(os.path.join(args.output_dir, "still-final.md"), "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
