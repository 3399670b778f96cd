#!/usr/bin/python3
"""How long the float64 reference (vtkLightShaftReference) takes, against the pass's frame of
the same scene measured in the same run.

    tools/measure.sh reference-speed [--runs 3] [--width 640 --height 480]

Scene: the sphere over the floor (scenes.sphere_and_floor, a 256-segment sphere), σ_s (0.05,
0.04, 0.03), σ_a (0.02, 0.01, 0.03), the pass at 512 slices with a 2048² shadow map. Prints the
median wall time of --runs references (vtkSMPTools over the machine's cores;
VTK_SMP_MAX_THREADS limits them), the median frame time of the pass (each frame finished with
glFinish, after a warm-up frame), their ratio, and the pass's relative RMS error against the
reference. A timed unit test would fail on a busy machine: this is the figure instead.
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
from lightshafts import scenes, vtkLightShaftPass, vtkLightShaftReference  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkVersion  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    args = parser.parse_args()

    renderer, window = rh.make_window(args.width, args.height)
    scenes.sphere_and_floor(renderer, sphere_resolution=256)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.SetNumberOfSlices(512)
    shafts.SetShadowMapSize(2048)
    renderer.SetPass(shafts)
    frame = rh.median_frame_time(window, args.frames)

    seconds = []
    for _ in progress.steps(range(args.runs), "reference runs"):
        reference = vtkLightShaftReference()
        reference.SetRenderer(renderer)
        reference.SetLightShaftPass(shafts)
        start = time.perf_counter()
        reference.Update()
        seconds.append(time.perf_counter() - start)
    image = reference.GetOutput()
    w, h, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetArray("InScatteredRadiance")).reshape(h, w, 3)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), values)
    median = statistics.median(seconds)
    print(f"VTK {vtkVersion.GetVTKVersion()}, {platform.node()}, {os.cpu_count()} cores, "
          f"{args.width}x{args.height}")
    print(f"reference: median {median:.1f} s over {args.runs} runs "
          f"({', '.join(f'{s:.1f}' for s in seconds)})")
    print(f"pass frame (512 slices, 2048^2 map): median {frame * 1e3:.0f} ms over {args.frames} "
          f"frames; reference / pass frame = {median / frame:.0f}")
    print(f"pass against the reference: {100 * error:.3f}% relative RMS")


if __name__ == "__main__":
    main()
