#!/usr/bin/python3
"""What a frame of the pass costs besides its integral, on held-out random scenes.

    tools/measure.sh fixed-cost [--scenes 3] [--frames 9]

For each scene of tests/benchmarks/random_scenes.py (seed --seed, scenes 0 to --scenes - 1 at up
to --max-height; each scene's first draw, as no reference decides here whether it is kept),
measured in one run: the plain frame (no pass), ANALYTIC at full resolution,
ANALYTIC at DownsampleFactor 8 (the integral over 1/64 of the pixels: the frame is then nearly
all fixed cost: the scene into the pass's targets, the depth-aware upsampling, the composite),
the same without AttenuateScene (the composite's aerial perspective), and the in-scatter's own
GPU time (GetLastFrame().GetLightTime, timer queries). Each is a median of --frames frames after a warm-up
frame (glFinish), and a ratio to the plain frame. Prints one line per scene and setting.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import progress  # noqa: E402
import random_scenes as rs  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402

SETTINGS = [
    ("ANALYTIC", dict(Method=vtkLightShaftPass.ANALYTIC, DownsampleFactor=1, BlurRadius=0)),
    ("ANALYTIC d8", dict(Method=vtkLightShaftPass.ANALYTIC, DownsampleFactor=8, BlurRadius=0)),
    ("ANALYTIC d8, no AttenuateScene",
     dict(Method=vtkLightShaftPass.ANALYTIC, DownsampleFactor=8, BlurRadius=0,
          AttenuateScene=False)),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--scenes", type=int, default=3)
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--max-height", type=int, default=720)
    parser.add_argument("--size", type=int, nargs=2, help="force every scene to this size")
    args = parser.parse_args()

    log = rs.WarningLog()
    for index in progress.steps(range(args.scenes), "scenes"):
        scene = rs.draw_scene(args.seed, index, 0, args.max_height,
                              tuple(args.size) if args.size else None)
        renderer, window = rh.make_window(scene.width, scene.height)
        light = rs.build(renderer, scene)
        plain = rh.median_frame_time(window, args.frames)
        print(f"scene {index} ({scene.summary()}): plain frame "
              f"{1000 * plain:.2f} ms", flush=True)
        for label, params in SETTINGS:
            shafts = vtkLightShaftPass()
            rs.configure(shafts, scene, light, params)
            renderer.SetPass(shafts)
            frame = rh.median_frame_time(window, args.frames)
            in_scatter = shafts.GetLastFrame().GetLightTime(0) if shafts.GetLastFrame().GetNumberOfUsedLights() else -1.0
            print(f"  {label:32s} frame {1000 * frame:8.2f} ms  ratio {frame / plain:7.2f}  "
                  f"in-scatter (GPU) {in_scatter:7.2f} ms", flush=True)
            renderer.SetPass(None)
            del shafts
        _, unexpected = log.take()
        if unexpected:
            print("\n".join(unexpected), file=sys.stderr)
            sys.exit(1)


if __name__ == "__main__":
    main()
