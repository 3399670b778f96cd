#!/usr/bin/python3
"""A still view's picture after the camera stops, with and without the exact finish, measured.

    tools/measure.sh exact-finish                  # the window scene (docs/exact-finish.md)
    tools/measure.sh exact-finish --scene sphere   # the sphere over a floor

Scenes, at --size (1280x720):
- window: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure
  40), the Interactive preset as the still setting;
- sphere: a sphere over a floor (lightshafts.scenes.sphere_and_floor, σ_s 0.05, exposure 40),
  SLICES 64 with a 2048² map as the still setting (a user's own, which the budget beats while
  moving).

For each run (ExactFinish off, then on, --repeats times each, alternating, so that the frame
times compared are pooled over the same stretch of the machine's time; ProgressiveRefinement on
in both): the camera turned by
0.5 degree per frame for --frames frames under a frame budget (the window's DesiredUpdateRate
--rate, as VTK's interactors set it while the user drags), each frame finished and timed. Then
the rate set back to rest and the still view rendered every --period seconds, as an
application's idle loop (or ParaView's view) renders it, for --seconds or until the picture is
converged: each frame timed, the in-scatter read back every --every seconds; then --reused
frames of the converged picture, every --period seconds too (the scene and the composite: a
still frame's work while the finish runs, without it running). The errors against
vtkLightShaftReference (exact surfaces and shadows, float64; pixels above 1% of its peak) are
computed after the run, so that computing them takes no processor time from the finish.

Reported: the error of the last moving frame and of the still picture over time; the still
frames' times with the finish running against those without it (the same view and setting).
Writes exact-finish[-sphere].md into --output-dir (and prints it).
"""

import argparse
import os
import platform
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import numpy as np  # noqa: E402

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import scenes, vtkLightShaftFrameReport, vtkLightShaftPass  # noqa: E402
from refinement import timed_render  # noqa: E402  (tests/benchmarks/refinement.py)

STATES = {vtkLightShaftFrameReport.EXACT_FINISH_OFF: "off",
          vtkLightShaftFrameReport.EXACT_FINISH_RUNNING: "running",
          vtkLightShaftFrameReport.EXACT_FINISH_COMPLETE: "complete",
          vtkLightShaftFrameReport.EXACT_FINISH_UNSUPPORTED: "unsupported",
          vtkLightShaftFrameReport.EXACT_FINISH_FAILED: "failed"}


def make_scene(name, size):
    if name == "window":
        renderer, window, plain, shafts = rh.window_scene(*size)
        shafts.SetQualityToInteractive()
        return renderer, window, shafts, "the Interactive preset"
    renderer, window = rh.make_window(*size)
    scenes.sphere_and_floor(renderer)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(40.0)
    shafts.SetMethod(vtkLightShaftPass.SLICES)
    shafts.SetNumberOfSlices(64)
    shafts.SetShadowMapSize(2048)
    return renderer, window, shafts, "SLICES 64, 2048² map"


def run(args, finish):
    renderer, window, shafts, still = make_scene(args.scene, args.size)
    shafts.ProgressiveRefinementOn()
    shafts.SetExactFinish(finish)
    renderer.SetPass(shafts)
    for _ in range(3):  # the shaders compiled at rest
        timed_render(window)
    camera = renderer.GetActiveCamera()
    window.SetDesiredUpdateRate(args.rate)
    moving = []
    try:
        for _ in range(args.frames):
            camera.Azimuth(0.5)
            moving.append(timed_render(window))
    finally:
        window.SetDesiredUpdateRate(0.0001)
    last_moving = rh.in_scatter(shafts).astype(np.float32)
    moving_setting = vtkLightShaftPass.GetErrorModelSettingName(
        shafts.GetLastFrame().GetErrorModelSetting())
    factor = shafts.GetLastFrame().GetDownsampleFactor()
    stopped = time.perf_counter()
    frames, pictures = [], []
    next_picture = 0.0
    while True:
        seconds = timed_render(window)
        now = time.perf_counter() - stopped
        report = shafts.GetLastFrame()
        frames.append((now, seconds, STATES[report.GetExactFinishState()],
                       report.GetInScatterReused()))
        converged = report.GetRefinementConverged()
        if now >= next_picture or converged:
            pictures.append((now, report.GetExactFinishFraction(),
                             rh.in_scatter(shafts).astype(np.float32)))
            next_picture += args.every
        if converged or now > args.seconds:
            break
        time.sleep(max(0.0, args.period - (time.perf_counter() - stopped - now)))
    # The converged picture reused: the scene and the composite, what a frame costs while the
    # finish runs, without it running. Paced as the still frames are: frames back to back run
    # faster (caches warm, the processors awake), and were once mistaken for the finish's cost.
    reused = []
    for _ in range(args.reused):
        reused.append(timed_render(window))
        time.sleep(max(0.0, args.period - reused[-1]))
    exact = rh.scene_reference(renderer, shafts)
    renderer.SetPass(None)

    def error(image):
        return ref.relative_rms_error(image.astype(np.float64), exact)[0]

    return dict(still=still, moving=moving, moving_setting=moving_setting, factor=factor,
                moving_error=error(last_moving), frames=frames, reused=reused,
                timeline=[(t, fraction, error(image)) for t, fraction, image in pictures])


def first_within(timeline, bound):
    return next((t for t, _, e in timeline if e <= bound), None)


def pooled(runs):
    """The runs' frame times together (their first run's timeline and errors)."""
    first = dict(runs[0])
    first["frames"] = [f for r in runs for f in r["frames"]]
    first["reused"] = [t for r in runs for t in r["reused"]]
    first["repeats"] = len(runs)
    return first


def table(args, off, on):
    size = f"{args.size[0]}x{args.size[1]}"
    command = "tools/measure.sh exact-finish" + (" " + " ".join(sys.argv[1:]) if sys.argv[1:] else "")
    lines = [f"# The exact finish: the {args.scene} scene at {size}", "",
             f"{platform.node()}, {platform.processor() or platform.machine()}, "
             f"{os.cpu_count()} cores; command: `{command}`.", "",
             f"Still setting: {on['still']}, ProgressiveRefinement on. Moving: {args.frames} frames "
             f"under a budget of 1/{args.rate:g} s; the last moving frame's setting: "
             f"{on['moving_setting'] or 'none of the ladder'} at 1/{on['factor']} resolution, "
             f"{100 * on['moving_error']:.2f}% from the reference (without the finish: "
             f"{100 * off['moving_error']:.2f}%). The still view rendered every "
             f"{args.period:g} s. Moving frames: median "
             f"{1000 * statistics.median(on['moving'][2:]):.0f} ms. Frame times pooled over "
             f"{on['repeats']} runs of each (alternating without and with the finish); the "
             f"errors over time are the first runs'.", ""]
    def stats(times):
        if not times:
            return "none"
        times = sorted(times)
        return (f"{len(times)}, median {1000 * statistics.median(times):.0f} ms, p90 "
                f"{1000 * times[int(0.9 * (len(times) - 1))]:.0f} ms, max {1000 * times[-1]:.0f} ms")

    # Frames that compute an estimate, and frames that show a picture again (the history, with
    # the finished tiles uploaded into it while the finish runs).
    for name, result, frames in (
            ("without the finish", off, off["frames"]),
            ("with the finish, while it ran", on,
             [f for f in on["frames"] if f[2] == "running"])):
        estimates = [seconds for _, seconds, _, reused in frames if not reused]
        shown = [seconds for _, seconds, _, reused in frames if reused] + (
            off["reused"] if result is off else [])
        lines.append(f"- Still frames {name}: computing an estimate {stats(estimates)}; "
                     f"showing the picture again {stats(shown)}.")
    lines.append(f"- With the finish, after it completed (the same view, no worker running): "
                 f"showing the picture again {stats(on['reused'])}.")
    running = sorted(s for _, s, state, reused in on["frames"] if reused and state == "running")
    without = sorted([s for _, s, _, reused in off["frames"] if reused] + off["reused"])
    if running and without:
        def p90(times):
            return times[int(0.9 * (len(times) - 1))]
        lines.append(f"- Frames that show the picture again, with the finish running over "
                     f"without it: median {statistics.median(running) / statistics.median(without):.2f}, "
                     f"p90 {p90(running) / p90(without):.2f}.")
    lines.append("")
    for bound in (0.005, 0.001):
        lines.append(f"Within {100 * bound:g}% of the reference: without the finish "
                     f"{_seconds(first_within(off['timeline'], bound))}, with it "
                     f"{_seconds(first_within(on['timeline'], bound))}.")
    lines += ["", "| without the finish: seconds since the camera stopped | error | with it: "
              "seconds | error | tiles finished |", "|---:|---:|---:|---:|---:|"]
    for k in range(max(len(off["timeline"]), len(on["timeline"]))):
        cells = []
        for result in (off, on):
            row = result["timeline"][k] if k < len(result["timeline"]) else None
            cells.append(" | " if row is None else f"{row[0]:.1f} s | {100 * row[2]:.3f}%")
        fraction = on["timeline"][k][1] if k < len(on["timeline"]) else None
        lines.append(f"| {cells[0]} | {cells[1]} | "
                     f"{'' if fraction is None else f'{100 * fraction:.0f}%'} |")
    return "\n".join(lines)


def _seconds(value):
    return "not within the run" if value is None else f"after {value:.1f} s"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--scene", default="window", choices=("window", "sphere"))
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--rate", type=float, default=15.0)
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--period", type=float, default=0.1)
    parser.add_argument("--every", type=float, default=0.5)
    parser.add_argument("--reused", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=5,
                        help="runs of each, alternating, their frame times pooled")
    args = parser.parse_args()
    off, on = [], []
    for _ in progress.steps(range(args.repeats), "repeats"):
        off.append(run(args, False))
        on.append(run(args, True))
    text = table(args, pooled(off), pooled(on))
    print(text)
    if args.output_dir:
        name = "exact-finish" + ("" if args.scene == "window" else "-" + args.scene) + ".md"
        with open(os.path.join(args.output_dir, name), "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
