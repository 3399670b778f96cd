#!/usr/bin/python3
"""What translucent props in view and a volume cost: the frame with k panes between the camera
and the beam (the camera leg's layers), and with a volume in the beam, each against the same
scene where they are transparent (opacity 0: the pass peels and computes nothing for them), in
one run.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/camera_leg_cost.py [--size 640x480] [--frames 7] [--layers 4]

Scene: scenes.sphere_and_floor (the spot at (0.5, 6, 0), 30 degrees; sphere of 64 x 64 facets),
SetQualityToFinal() (RAY_MARCH, 256 steps, a 2048^2 map). Panes: k = 0 .. --layers vertical
panes at z = 6 + 0.5 j over the left half of the view, opacity 0.5. Volume: a 32^3 puff of smoke
(examples/smoke_in_beam.py's) in the beam, opacity up to 0.8 per 0.3 units. The camera turns a
little each frame (the layers are peeled again, the volume's light-leg table kept); for the
volume also with its opacity function changed each frame (the table built again). The two
scenes are measured in alternating blocks (on, off, off, on), so that a drift of the machine's
speed weighs on both alike. Prints markdown tables: the median frames and the extra.
"""

import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import scenes, vtkLightShaftPass  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

import smoke_in_beam  # noqa: E402


def add_pane(renderer, z):
    pane = vtkPlaneSource()
    pane.SetOrigin(-6.0, -1.0, z)
    pane.SetPoint1(0.0, -1.0, z)
    pane.SetPoint2(-6.0, 8.0, z)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(pane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.4, 0.5, 0.6)
    renderer.AddActor(actor)
    return actor


def timed(width, height, frames, build, rebuild=None):
    """Median frame times (seconds) of the scene with the props as built by `build(renderer,
    on)` (on: as given; off: transparent), and what the last frame with them on reported.
    `rebuild(frame)` changes them each frame (None: the camera turns instead). The test
    helpers' one window holds one renderer at a time: the two scenes are measured in blocks,
    on, off, off, on, each after a warm-up frame, so that a drift of the machine's speed
    weighs on both alike."""
    times = {True: [], False: []}
    report = None
    for on in (True, False, False, True):
        renderer, window = rh.make_window(width, height)
        scenes.sphere_and_floor(renderer, sphere_resolution=64)
        build(renderer, on)
        shafts = vtkLightShaftPass()
        shafts.GetMedium().SetScatteringCoefficient(0.05)
        shafts.SetQualityToFinal()
        renderer.SetPass(shafts)
        for frame in range(frames // 2 + 1):
            if rebuild:
                rebuild(frame)
            else:
                renderer.GetActiveCamera().Azimuth(0.2)
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            if frame:
                times[on].append(time.perf_counter() - start)
            last = shafts.GetLastFrame()
            assert last.GetGLErrorCount() == 0
            if on:
                report = (last.GetCameraTranslucentLayers(), last.GetCameraTranslucentBytes(),
                          last.GetLightVolumeShadowBuildTime(0))
    return statistics.median(times[True]), statistics.median(times[False]), report


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--layers", type=int, default=4)
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    print(f"At {width}x{height}, Final quality (RAY_MARCH 256 steps, 2048^2 map), median of "
          f"{args.frames} frames; the extra is against the same props at opacity 0.\n")
    print("| panes in view | camera layers | memory (MiB) | frame (ms) | extra (ms) |")
    print("|---|---|---|---|---|")
    for panes in progress.steps(range(args.layers + 1), "panes"):
        def build(renderer, on, panes=panes):
            for j in range(panes):
                add_pane(renderer, 6.0 + 0.5 * j).GetProperty().SetOpacity(0.5 if on else 0.0)

        on, off, (layers, memory, _) = timed(width, height, args.frames, build)
        print(f"| {panes} | {layers} | {memory / 2**20:.1f} | {1e3 * on:.0f} | "
              f"{1e3 * (on - off):+.0f} |", flush=True)

    print("\n| volume | frame (ms) | extra (ms) | light-leg table build (ms) |")
    print("|---|---|---|---|")
    volumes = {}

    def build_volume(renderer, on):
        volume = smoke_in_beam.add_smoke(renderer)
        volumes["last"] = volume if on else None  # (the transparent one is not changed)
        if not on:
            volume.GetProperty().GetScalarOpacity().RemoveAllPoints()
            volume.GetProperty().GetScalarOpacity().AddPoint(0.0, 0.0)

    def rebuild(frame):
        if volumes.get("last") is not None:
            opacity = volumes["last"].GetProperty().GetScalarOpacity()
            opacity.RemoveAllPoints()
            opacity.AddPoint(0.15, 0.0)
            opacity.AddPoint(1.0, 0.8 + 0.001 * (frame % 2))

    for name, change in progress.steps((("kept (the camera turns)", None),
                                        ("rebuilt (its opacity changes)", rebuild)), "volumes"):
        volumes.clear()
        on, off, (_, _, build_ms) = timed(width, height, args.frames, build_volume, change)
        print(f"| {name} | {1e3 * on:.0f} | {1e3 * (on - off):+.0f} | {build_ms:.0f} |",
              flush=True)


if __name__ == "__main__":
    main()
