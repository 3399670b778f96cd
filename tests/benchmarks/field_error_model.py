#!/usr/bin/python3
"""The error model through a medium from data: random scenes with random density fields, the
ladder's settings that render a field, their error against the float64 reference and what
the model predicted (the homogeneous fit times vtkLightShaftErrorModel::FieldFactor, or
FieldFactorEpipolar, plus FieldMargin times the field's own quadrature error,
GetLastFrame().GetFieldError()).

    tools/measure.sh field-error-model

runs, against the build in build/ (about 15 minutes each):

    field_error_model.py --seed 11 --scenes 16      # calibration: the factors
    field_error_model.py --seed 12 --scenes 16      # validation: held-out scenes

and prints, per setting and per method family, how often the measured error is within the
prediction, and the factor on the homogeneous prediction that would hold nine scenes in ten
(the 90th percentile of (error - margin * field error) / homogeneous prediction). --csv writes
every row; --summarise CSV... prints the table of rows written before.
"""

import argparse
import csv
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, HERE)

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import random_scenes as rs  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402

# The ladder's settings that render a field (LIGHT_VOLUME gives way to RAY_MARCH).
SETTINGS = [(name, params) for name, params in rs.LADDER
            if name in rs.fitted_ladder() and params["Method"] != vtkLightShaftPass.LIGHT_VOLUME]


def random_field(rng, bounds):
    """A density field of mean about 1 over `bounds` (expanded by a fifth): a plume (a few
    Gaussian blobs), a layer (density 1 on one side of a tilted plane, 0 on the other, its
    edge one cell thick, a cell 0.02-0.2 of the box), or noise (random values on a coarse
    grid, trilinear). Returns (kind, image)."""
    low = np.array(bounds[0::2], float)
    high = np.array(bounds[1::2], float)
    pad = 0.2 * (high - low) + 0.1
    low, high = low - pad, high + pad
    kind = str(rng.choice(["plume", "layer", "noise"]))
    if kind == "layer":
        cells = int(rng.integers(5, 50))
    elif kind == "noise":
        cells = int(rng.integers(3, 12))
    else:
        cells = int(rng.integers(16, 48))
    n = cells + 1
    axes = [np.linspace(low[k], high[k], n) for k in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")  # x fastest when raveled
    points = np.stack([x, y, z], axis=-1)
    if kind == "plume":
        values = np.zeros(x.shape)
        for _ in range(int(rng.integers(1, 4))):
            centre = rng.uniform(low, high)
            width = rng.uniform(0.1, 0.4) * float(np.min(high - low))
            values += np.exp(-np.sum((points - centre) ** 2, axis=-1) / (2 * width ** 2))
    elif kind == "layer":
        normal = rs._unit([rng.uniform(-0.5, 0.5), 1.0, rng.uniform(-0.5, 0.5)])
        height = rng.uniform(0.3, 0.8) * (high[1] - low[1]) + low[1]
        values = ((points - [0.0, height, 0.0]) @ normal < 0.0).astype(float)
    else:
        values = rng.uniform(0.0, 2.0, x.shape)
    values *= 1.0 / max(values.mean(), 1e-6)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(*low)
    image.SetSpacing(*((high - low) / cells))
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True))
    return kind, image


def run(seed, scenes, size, log):
    rows = []
    # (The bar counts the scenes drawn; one without light in view is drawn again.)
    for index in progress.steps(range(4 * scenes), "scenes drawn", total=scenes):
        if len({r["scene"] for r in rows}) >= scenes:
            break
        scene = rs.draw_scene(seed, index, 0, size[1], size=size)
        rng = np.random.default_rng([seed, index, 99])
        renderer, window = rh.make_window(*size)
        light = rs.build(renderer, scene)
        window.Render()
        kind, image = random_field(rng, renderer.ComputeVisiblePropBounds())
        reference = None
        for name, params in SETTINGS:
            shafts = vtkLightShaftPass()
            rs.configure(shafts, scene, light, params)
            shafts.GetMedium().SetDensityField(image)
            if reference is None:
                reference = rs.reference_image(renderer, shafts)
                luminance = reference.mean(-1)
                if luminance.max() <= 0 or np.mean(luminance > 0.01 * luminance.max()) < 0.02:
                    break
            renderer.SetPass(shafts)
            window.Render()
            error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
            frame = shafts.GetLastFrame()
            _, unexpected = log.take()
            if unexpected:
                print("\n".join(unexpected), file=sys.stderr)
            rows.append(dict(scene=scene.index, field=kind, light=scene.light_kind, setting=name,
                             error=error, predicted=frame.GetPredictedError(),
                             field_error=frame.GetFieldError(),
                             optical_depth=frame.GetOpticalDepth()))
            r = rows[-1]
            print(f"scene {scene.index:3d} {kind:6s} {scene.light_kind:11s} {name:24s} "
                  f"error {100 * error:6.2f}%  predicted {100 * r['predicted']:6.2f}%  "
                  f"field {100 * r['field_error']:6.2f}%", flush=True)
            renderer.SetPass(None)
    return rows


def summarise(rows, constants):
    """Per setting: how often the error is within the prediction, and the factor on the
    homogeneous prediction that would hold nine scenes in ten (the 90th percentile of
    (error - margin * field error) / homogeneous prediction); the same per method family."""
    margin = constants["FieldMargin"]

    def factor(name):
        return constants["FieldFactorEpipolar" if name.startswith("E") else "FieldFactor"]

    for r in rows:
        # What the homogeneous fit alone predicted, and the factor this scene needed.
        r["homogeneous"] = (r["predicted"] - margin * r["field_error"]) / factor(r["setting"])
        r["needed"] = (r["error"] - margin * r["field_error"]) / max(r["homogeneous"], 1e-12)
    print(f"\nFieldFactor {constants['FieldFactor']:g}, FieldFactorEpipolar "
          f"{constants['FieldFactorEpipolar']:g}, FieldMargin {margin:g}:")
    print("| setting | scenes | within the prediction | median error | median predicted |"
          " median field error | factor for 9 in 10 |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    groups = [(name, [r for r in rows if r["setting"] == name]) for name, _ in SETTINGS]
    groups += [("all EPIPOLAR", [r for r in rows if r["setting"].startswith("E")]),
               ("all others", [r for r in rows if not r["setting"].startswith("E")])]
    for name, mine in groups:
        if not mine:
            continue
        within = sum(r["error"] <= r["predicted"] for r in mine)
        print(f"| {name} | {len(mine)} | {within} ({100 * within / len(mine):.0f}%) | "
              f"{100 * np.median([r['error'] for r in mine]):.2f}% | "
              f"{100 * np.median([r['predicted'] for r in mine]):.2f}% | "
              f"{100 * np.median([r['field_error'] for r in mine]):.3f}% | "
              f"{np.percentile([r['needed'] for r in mine], 90):.2f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--scenes", type=int, default=24)
    parser.add_argument("--size", type=int, nargs=2, default=(240, 180))
    parser.add_argument("--csv")
    parser.add_argument("--summarise", metavar="CSV", nargs="+",
                        help="only summarise rows written by --csv")
    args = parser.parse_args()
    if args.summarise:
        rows = []
        for path in args.summarise:
            with open(path) as f:
                rows += [{k: (v if k in ("field", "light", "setting") else float(v))
                          for k, v in r.items()} for r in csv.DictReader(f)]
        summarise(rows, field_constants())
        return
    log = rs.WarningLog()
    rows = run(args.seed, args.scenes, tuple(args.size), log)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    summarise(rows, field_constants())


def field_constants():
    """vtkLightShaftErrorModel's FieldFactor, FieldFactorEpipolar and FieldMargin, as the
    header has them."""
    import re
    with open(os.path.join(HERE, "..", "..", "plugin", "vtkLightShaftErrorModel.h")) as f:
        text = f.read()
    return {name: float(re.search(name + r" = ([0-9.]+);", text).group(1))
            for name in ("FieldFactor", "FieldFactorEpipolar", "FieldMargin")}


if __name__ == "__main__":
    main()
