"""What lighting the surfaces as the shafts are lit (ShadowSurfaces) costs, on the README
picture's window scene (render_helpers.window_scene): the median frame time without
ShadowSurfaces, with it and AttenuateSurfaceLight off (the shadows alone), and with both (the
default), each as a ratio to the first, in one run. Run it on two builds to compare them (the
figures of docs/lights-and-cookies.md compare this version with the one before).

    tools/measure.sh surface-light [--size 1280 720] [--frames 15]
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--frames", type=int, default=15)
    args = parser.parse_args()
    renderer, window, plain, shafts = rh.window_scene(*args.size)
    renderer.SetPass(shafts)
    settings = [("without ShadowSurfaces", {"ShadowSurfaces": False}),
                ("ShadowSurfaces, AttenuateSurfaceLight off", {"ShadowSurfaces": True,
                                                               "AttenuateSurfaceLight": False}),
                ("ShadowSurfaces (AttenuateSurfaceLight on)", {"ShadowSurfaces": True,
                                                              "AttenuateSurfaceLight": True})]
    times = []
    for name, values in progress.steps(settings, "settings"):
        for key, value in values.items():
            if hasattr(shafts, "Set" + key):  # (an earlier build has no AttenuateSurfaceLight)
                getattr(shafts, "Set" + key)(value)
        times.append((name, rh.median_frame_time(window, args.frames, warm_up=5)))
    width, height = args.size
    print(f"window scene {width}x{height}, {args.frames} frames each; VTK alone "
          f"{1e3 * plain:.1f} ms")
    print("| setting | median frame (ms) | vs without ShadowSurfaces |")
    print("|---|---:|---:|")
    for name, seconds in times:
        print(f"| {name} | {1e3 * seconds:.1f} | {seconds / times[0][1]:.2f} |")


if __name__ == "__main__":
    main()
