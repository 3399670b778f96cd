#!/usr/bin/python3
"""Speed against error through a medium from data: each method that renders a density field
(RAY_MARCH, SLICES, EPIPOLAR) at several settings, and RAY_MARCH with the light leg marched
instead of tabulated, against the float64 reference, in one run.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/medium_field_pareto.py [--size 240 180] [--frames 8]

Scene: the sphere-and-floor scene's spot light (shadowed by the sphere) and a blue point light,
through a smooth plume (a Gaussian of peak 4, 48³ samples over [-3, 3] x [-1, 3] x [-3, 3]; the
spot sees its box from outside: one face; the point light is inside it: a cube). σ_s (0.05,
0.04, 0.03), σ_a (0.02, 0.01, 0.03). Blur off, full resolution. Frame time: the median of
--frames (after warm-up), over the plain scene's (no pass) measured in the same run. Error:
relative RMS against vtkLightShaftReference (exact visibility, both legs integrated exactly
through the trilinear field). Writes docs/medium-field-pareto.csv and
docs/images/medium_field_pareto.png, and prints the table.
"""

import argparse
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, HERE)

import benchmark  # noqa: E402
import lightshaft_reference as ref  # noqa: E402
import numpy as np  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, scenes, vtkLightShaftPass as P  # noqa: E402
from test_medium_field import plume_image  # noqa: E402

SETTINGS = (
    [("RAY_MARCH", f"{n} steps", dict(Method=P.RAY_MARCH, NumberOfSteps=n, InterleaveSize=1))
     for n in (16, 32, 64, 128, 256)] +
    [("RAY_MARCH, light leg marched", f"{n} steps",
      dict(Method=P.RAY_MARCH, NumberOfSteps=n, InterleaveSize=1, FieldShadowResolution=0))
     for n in (32, 64, 128)] +
    [("SLICES", f"{n} slices", dict(Method=P.SLICES, NumberOfSlices=n))
     for n in (32, 64, 128, 256)] +
    [("EPIPOLAR", f"{n} steps, every {k}th", dict(Method=P.EPIPOLAR, NumberOfSteps=n,
                                                  EpipolarStep=k))
     for n, k in ((16, 8), (32, 8), (64, 4), (128, 2))])


def configure(shafts, params):
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.SetBlurRadius(0)
    shafts.SetAutomaticSliceCount(False)
    shafts.JitterOff()
    shafts.SetShadowMapSize(2048)
    for key, value in params.items():
        getattr(parameter_owner(shafts, key), "Set" + key)(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, nargs=2, default=(240, 180))
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--output-dir", default=os.path.join(HERE, "..", "..", "docs"))
    args = parser.parse_args()
    renderer, window = rh.make_window(*args.size)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    point = scenes.add_point_light(renderer, (-1.5, 3.2, 1.0), intensity=0.8,
                                   color=(0.3, 0.6, 1.0), attenuation=(1.0, 0.0, 0.1))
    plain = rh.median_frame_time(window, args.frames, warm_up=30, warm_up_seconds=2.0)
    field = plume_image()
    reference = None
    rows = []
    print(f"plume 48³, spot + point light, {args.size[0]}x{args.size[1]}; plain frame "
          f"{1e3 * plain:.1f} ms")
    print("| method | setting | frame / plain | relative RMS error |")
    print("|---|---|---:|---:|")
    for family, label, params in progress.steps(SETTINGS, "settings"):
        shafts = P()
        shafts.AddLight(info.light)
        shafts.AddLight(point)
        configure(shafts, params)
        shafts.GetMedium().SetDensityField(field)
        renderer.SetPass(shafts)
        ratio = rh.median_frame_time(window, args.frames) / plain
        assert shafts.GetLastFrame().GetGLErrorCount() == 0
        if reference is None:
            reference = rh.scene_reference(renderer, shafts)
        error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
        rows.append(dict(scene="plume 48³, spot + point light", family=family, setting=label,
                         time_ratio=ratio, relative_rmse=error))
        print(f"| {family} | {label} | {ratio:.1f} | {100 * error:.3f}% |", flush=True)
        renderer.SetPass(None)
    os.makedirs(os.path.join(args.output_dir, "images"), exist_ok=True)
    with open(os.path.join(args.output_dir, "medium-field-pareto.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    benchmark.pareto_plot(rows, os.path.join(args.output_dir, "images",
                                             "medium_field_pareto.png"))


if __name__ == "__main__":
    main()
