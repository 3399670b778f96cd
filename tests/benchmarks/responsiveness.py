"""How soon the pass gives the view back: the exact finish's stop after a change, and the
float64 reference's abort, on the slow scene of tests/python/test_responsive.py (four
spotlights in a 65³ random density field, σ_s 10: about 0.2 s of a core per pixel).

- `--changes` random changes (the camera, the medium, a light, a prop, the window's size) of a
  still, finishing view, each after a random wait of up to 30 ms so that the workers are
  anywhere inside a pixel: the frame report's ExactFinishStopTime of the frame after each
  (median, 99th percentile, maximum);
- the reference of a 1080p frame of the sphere scene, aborted from a ProgressEvent observer
  after `--abort-after` seconds: the progress events' spacing and the time from the abort to
  Update()'s return.

    tools/measure.sh responsiveness [--changes 1000] [--abort-after 3]
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
import test_responsive as slow  # noqa: E402
from lightshafts import scenes, vtkLightShaftFrameReport, vtkLightShaftPass  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402

RUNNING = vtkLightShaftFrameReport.EXACT_FINISH_RUNNING


def stop_times(changes, seed):
    return np.array(slow.stop_waits(changes, seed, lambda it: progress.steps(it, "changes")))


def abort_latency(after):
    renderer, window = rh.make_window(1920, 1080)
    scenes.sphere_and_floor(renderer, sphere_resolution=64)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    renderer.SetPass(shafts)
    window.Render()
    reference = slow.reference(renderer, shafts)
    seen = []
    aborted = []
    share = []  # the progress when aborted (VTK 9.3 and later report 1.0 once it returns)

    def on_progress(caller, _event):
        seen.append(time.monotonic())
        if not aborted and seen[-1] - seen[0] > after:
            caller.SetAbortExecute(1)
            aborted.append(time.monotonic())
            share.append(caller.GetProgress())

    reference.AddObserver(vtkCommand.ProgressEvent, on_progress)
    reference.Update()
    end = time.monotonic()
    return np.diff([t for t in seen if t <= aborted[0]]), end - aborted[0], share[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--changes", type=int, default=1000)
    parser.add_argument("--abort-after", type=float, default=3.0)
    parser.add_argument("--seed", type=int, default=51)
    args = parser.parse_args()
    waits = 1e3 * stop_times(args.changes, args.seed)
    print(f"exact finish, stop after a change ({args.changes} changes, 64x48, slow scene): "
          f"median {np.median(waits):.2f} ms, 99th percentile {np.percentile(waits, 99):.2f} ms,"
          f" max {waits.max():.2f} ms")
    spacing, latency, share = abort_latency(args.abort_after)
    print(f"reference, 1080p sphere scene: progress events every {np.median(spacing):.3f} s "
          f"(max {spacing.max():.3f} s); aborted after {args.abort_after:.0f} s at "
          f"{100 * share:.1f}% of the frame, returned {1e3 * latency:.0f} ms after the abort")


if __name__ == "__main__":
    main()
