#!/usr/bin/python3
"""What a medium from data (vtkLightShaftPass::SetMediumDensity) costs: RAY_MARCH's frame with
a density field against the homogeneous medium at the same setting, in one run.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/medium_field_cost.py [--size 640x480] [--frames 5]

Scene: the README picture's window scene (σ_s 0.05, exposure 40), RAY_MARCH at --steps. Fields: VTK's
wavelet (vtkRTAnalyticSource) at 64³, 128³ and 256³ samples over the scene's bounds, rescaled to
mean 1. For each: the median frame (of --frames, after one; each frame's Time differs, so the
shafts are computed every frame), the first frame after the field was set less that (the
upload), and the texture's memory (float32 samples). The shafts' time is the frame less the
plain frame.
"""

import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import numpy as np  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass as P  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402


def wavelet_field(samples, bounds):
    """VTK's wavelet at samples³ over `bounds`, rescaled to mean 1 (non-negative)."""
    source = vtkRTAnalyticSource()
    half = samples // 2
    source.SetWholeExtent(-half, samples - half - 1, -half, samples - half - 1,
                          -half, samples - half - 1)
    source.Update()
    image = source.GetOutput()
    values = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)
    values = np.maximum(values - values.min(), 0.0)
    values /= values.mean()
    array = numpy_to_vtk(values, deep=True)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    image.SetOrigin(0.0, 0.0, 0.0)
    image.SetExtent(0, samples - 1, 0, samples - 1, 0, samples - 1)
    lengths = [bounds[2 * k + 1] - bounds[2 * k] for k in range(3)]
    image.SetSpacing(*[length / (samples - 1) for length in lengths])
    image.SetOrigin(bounds[0], bounds[2], bounds[4])
    return image


def median_shaft_frame(window, shafts, frames):
    times = []
    for frame in range(frames + 1):
        shafts.GetMedium().SetTime(0.1 * frame + 0.01 * len(times))
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        if frame:
            times.append(time.perf_counter() - start)
    return float(np.median(times))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--steps", type=int, default=64)
    parser.add_argument("--samples", type=int, nargs="+", default=[64, 128, 256],
                        help="the fields' samples per axis")
    parser.add_argument("--resolutions", type=int, nargs="+", default=[0, 64, 128],
                        help="MediumShadowResolution values (0: the light leg marched)")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    renderer, window, plain, shafts = rh.window_scene(width, height)
    shafts.SetMethod(P.RAY_MARCH)
    shafts.SetNumberOfSteps(args.steps)
    renderer.SetPass(shafts)
    bounds = renderer.ComputeVisiblePropBounds()
    homogeneous = median_shaft_frame(window, shafts, args.frames)
    print(f"window scene {width}x{height}, RAY_MARCH {args.steps} steps; plain frame "
          f"{1e3 * plain:.1f} ms")
    print("| medium | light leg | frame | shafts | shafts / homogeneous | first frame extra "
          "| light-leg build | light-leg table | field texture |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    print(f"| homogeneous | | {1e3 * homogeneous:.0f} ms | {1e3 * (homogeneous - plain):.0f} ms "
          f"| 1.00 | | | | |")
    for samples in progress.steps(args.samples, "fields"):
        field = wavelet_field(samples, bounds)
        shafts.GetMedium().SetDensityField(field)
        for resolution in args.resolutions:
            shafts.GetMedium().SetFieldShadowResolution(resolution)
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            first = time.perf_counter() - start
            build = sum(shafts.GetLastFrame().GetLightFieldShadowBuildTime(i)
                        for i in range(shafts.GetLastFrame().GetNumberOfUsedLights()))
            table = sum(shafts.GetLastFrame().GetLightFieldShadowBytes(i)
                        for i in range(shafts.GetLastFrame().GetNumberOfUsedLights()))
            frame = median_shaft_frame(window, shafts, args.frames)
            ratio = (frame - plain) / (homogeneous - plain)
            memory = samples ** 3 * 4 / 2 ** 20
            leg = f"table {resolution}" if resolution else "marched"
            build_text = f"{build:.0f} ms" if resolution else ""
            table_text = f"{table / 2 ** 20:.1f} MiB" if resolution else ""
            print(f"| wavelet {samples}³ | {leg} | {1e3 * frame:.0f} ms "
                  f"| {1e3 * (frame - plain):.0f} ms | {ratio:.2f} | {1e3 * (first - frame):.0f} ms "
                  f"| {build_text} | {table_text} | {memory:.0f} MiB |", flush=True)
        shafts.GetMedium().SetDensityField(None)


if __name__ == "__main__":
    main()
