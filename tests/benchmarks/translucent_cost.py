#!/usr/bin/python3
"""What translucent casters cost (vtkLightShaftPass::TranslucentShadows): per layer of
translucent surfaces the light meets, the frame with the layers against the same scene with
TranslucentShadows off, in one run.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/translucent_cost.py [--size 640x480] [--frames 7] [--layers 4]

Scene: scenes.sphere_and_floor (the spot at (0.5, 6, 0), 30 degrees; sphere of 64 x 64 facets),
SetQualityToFinal() (RAY_MARCH, 256 steps, a 2048^2 map), with k = 0 .. --layers coloured panes
at opacity 0.5 stacked across the spot's beam between the light and the sphere (each a 64 x 64
quad grid). For each k, the median frame (of --frames, after one) in two cases:
  - kept: the camera turns a little each frame; the map and its layers are kept (only the
    lookups cost);
  - rebuilt: a pane's colour changes each frame; the map and its layers are rendered again.
Each against the same scene and case with TranslucentShadows off (the panes cast nothing),
measured frame by frame alternately (one pass each, so each keeps its own maps), so that a busy
machine slows both alike. Prints a markdown
table: the frame times, the extra per frame, and the layers' memory.
"""

import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import scenes, vtkLightShaftPass  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

COLOURS = [(1.0, 0.3, 0.3), (0.3, 1.0, 0.3), (0.3, 0.3, 1.0), (1.0, 1.0, 0.3),
           (0.3, 1.0, 1.0), (1.0, 0.3, 1.0), (0.8, 0.8, 0.8), (0.5, 0.9, 0.6)]


def add_pane(renderer, height, colour):
    pane = vtkPlaneSource()
    pane.SetOrigin(-2.0, height, -2.0)
    pane.SetPoint1(2.0, height, -2.0)
    pane.SetPoint2(-2.0, height, 2.0)
    pane.SetResolution(64, 64)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(pane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    actor.GetProperty().SetOpacity(0.5)
    renderer.AddActor(actor)
    return actor


def measure(width, height, panes, frames, rebuilt):
    """Median frame times (seconds) with the panes' layers and without, and the layers."""
    renderer, window = rh.make_window(width, height)
    scenes.sphere_and_floor(renderer, sphere_resolution=64)
    actors = [add_pane(renderer, 5.5 - 0.3 * k, COLOURS[k % len(COLOURS)])
              for k in range(panes)]
    # One pass each way, taking turns: each keeps its own maps (kept case).
    passes = {}
    for translucent in (True, False):
        shafts = vtkLightShaftPass()
        shafts.GetMedium().SetScatteringCoefficient(0.05)
        shafts.SetQualityToFinal()
        shafts.SetTranslucentShadowLayers(max(panes, 1))
        shafts.SetTranslucentShadows(translucent)
        passes[translucent] = shafts
    camera = renderer.GetActiveCamera()
    times = {True: [], False: []}
    layers = bytes_ = 0
    for frame in range(frames + 1):
        if rebuilt and actors:
            actors[0].GetProperty().SetColor(1.0, 0.3 + 0.01 * (frame % 2), 0.3)
        else:
            camera.Azimuth(0.2)
        for translucent in (True, False):
            shafts = passes[translucent]
            renderer.SetPass(shafts)
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            if frame:
                times[translucent].append(time.perf_counter() - start)
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
            if translucent:
                layers = shafts.GetLastFrame().GetLightTranslucentLayers(0)
                bytes_ = shafts.GetLastFrame().GetLightTranslucentBytes(0)
    return statistics.median(times[True]), statistics.median(times[False]), layers, bytes_


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--frames", type=int, default=7)
    parser.add_argument("--layers", type=int, default=4)
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    print(f"Translucent casters at {width}x{height}, Final quality (RAY_MARCH 256 steps, 2048^2 "
          f"map), median of {args.frames} frames; the extra is against TranslucentShadows off "
          "in the same scene.\n")
    print("| panes | layers | memory (MiB) | kept: frame (ms) | kept: extra (ms) | "
          "rebuilt: frame (ms) | rebuilt: extra (ms) |")
    print("|---|---|---|---|---|---|---|")
    for panes in progress.steps(range(args.layers + 1), "panes"):
        kept_on, kept_off, layers, memory = measure(width, height, panes, args.frames, False)
        built_on, built_off, _, _ = measure(width, height, panes, args.frames, True)
        print(f"| {panes} | {layers} | {memory / 2**20:.0f} | {1e3 * kept_on:.0f} | "
              f"{1e3 * (kept_on - kept_off):+.0f} | {1e3 * built_on:.0f} | "
              f"{1e3 * (built_on - built_off):+.0f} |", flush=True)


if __name__ == "__main__":
    main()
