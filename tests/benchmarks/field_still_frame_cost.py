#!/usr/bin/python3
"""What a converged still frame costs through a medium from data, against the homogeneous
medium: the scene and the composite, and the sampling's choice (the error model's features; a
still view keeps what it measured of the field).

    tools/measure.sh field-still-cost

The test scene of tests/python/test_medium_field.py: the floor lit by a spot and a point light
("pair"), a 48^3 plume, at --size (96x72: the frame is mostly processor work), Final,
ProgressiveRefinement on. Rendered until converged, then --frames frames timed (each
finished); then --moving frames with the camera turned by 0.5 degree each.
"""

import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import progress  # noqa: E402
from test_medium_field import plume_image, scene  # noqa: E402


def timed(window):
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, nargs=2, default=(96, 72))
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--moving", type=int, default=10)
    args = parser.parse_args()
    for field in progress.steps((False, True), "media"):
        renderer, window, info, shafts = scene("pair", *args.size)
        shafts.SetQualityToFinal()
        shafts.ProgressiveRefinementOn()
        if field:
            shafts.GetMedium().SetDensityField(plume_image())
        for _ in range(64):
            window.Render()
            if shafts.GetLastFrame().GetRefinementConverged():
                break
        still = [timed(window) for _ in range(args.frames)]
        camera = renderer.GetActiveCamera()
        moving = []
        for _ in range(args.moving):
            camera.Azimuth(0.5)
            moving.append(timed(window))
        print(f"{'a 48^3 plume' if field else 'homogeneous':12s}: converged still frame median "
              f"{1000 * statistics.median(still):.2f} ms, moving frame median "
              f"{1000 * statistics.median(moving):.0f} ms")


if __name__ == "__main__":
    main()
