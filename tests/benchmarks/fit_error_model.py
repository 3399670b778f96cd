#!/usr/bin/python3
"""Fit the error model of TargetError (vtkLightShaftErrorModel) on random-scene training runs.

    tools/measure.sh error-model

runs, against the build in build/:

    # 1. the training runs: the ladder's settings on seeds 8 and 9 (errors; single frames)
    random_scenes.py --ladder --seed 8 --scenes 30 --max-height 720 --frames 0 --output-dir A
    random_scenes.py --ladder --seed 9 --scenes 25 --max-height 720 --frames 0 --output-dir B
    # 2. the fit: features of each scene as the pass computes them, one model per setting
    fit_error_model.py A/random-scenes.csv B/random-scenes.csv

For every setting of the ladder (random_scenes.LADDER, cheapest first) it fits
log(relative RMS error) as a linear function of the variables vtkLightShaftErrorModel.cxx
computes from a frame's geometry (1, log depth range in beam widths, log beam width in pixels,
log(1 + optical depth), light in view with falling attenuation, light in view, point light,
directional light, light in view times each log, log shadow-map texel in pixels), by ridge
regression, and adds the 90th percentile of the leave-one-out
residuals as a margin: the prediction is an upper estimate that held-out scenes should meet
nine times in ten. It writes plugin/core/vtkLightShaftErrorModelTable.h (the ladder and the
coefficients), docs/error-model.md (the fit, the presets the training percentiles choose) and
docs/error-model-training.csv (the training rows with their features).

The features are read from the pass (GetLastFrame().GetDepthRangeInBeamWidths(), ...) by rendering each
training scene once, so that the fit and the pass use exactly the same numbers.
"""

import argparse
import csv
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, HERE)

import progress  # noqa: E402
import random_scenes as rs  # noqa: E402

FEATURES = ("depth_range_in_beam_widths", "beam_width_in_pixels", "model_optical_depth",
            "shadow_texel_in_pixels",
            "model_light_in_view", "falling_attenuation", "kind")
RIDGE = 0.05       # on the slopes only (not the intercept)
QUANTILE = 90      # of the leave-one-out residuals: the margin
# Errors below are taken as this: a tenth of the smallest target validated (0.5%), so that the
# fit spends nothing on telling 0.001% from 0.0001%.
ERROR_FLOOR = 5e-4
# The presets' aims: 90th-percentile error of each (docs/quality-and-cost.md).
AIMS = (("Draft", 0.05), ("Interactive", 0.02), ("Final", 0.005))


def variables(row):
    """The model's variables, exactly as vtkLightShaftErrorModel.cxx's Variables()."""
    def log_clamped(x):
        return math.log(min(max(float(x), 1e-3), 1e6))
    in_view = int(row["model_light_in_view"])
    depth_range = log_clamped(row["depth_range_in_beam_widths"])
    beam_pixels = log_clamped(row["beam_width_in_pixels"])
    return [1.0,
            depth_range,
            beam_pixels,
            math.log1p(min(max(float(row["model_optical_depth"]), 0.0), 1e3)),
            float(in_view and int(row["falling_attenuation"])),
            float(in_view),
            float(row["kind"] == "point"),
            float(row["kind"] == "directional"),
            in_view * depth_range,
            in_view * beam_pixels,
            log_clamped(row["shadow_texel_in_pixels"]) if float(row["shadow_texel_in_pixels"]) > 0
            else 0.0]


def scene_features(scene_json):
    """The pass's error-model features of a scene (one render of its cheapest setting)."""
    import render_helpers as rh
    from lightshafts import vtkLightShaftPass
    scene = rs.Scene(**json.loads(scene_json))
    renderer, window = rh.make_window(scene.width, scene.height)
    light = rs.build(renderer, scene)
    shafts = vtkLightShaftPass()
    rs.configure(shafts, scene, light, rs.LADDER[0][1])
    renderer.SetPass(shafts)
    window.Render()
    features = rs.error_model_columns(shafts, scene)
    renderer.SetPass(None)
    window.Finalize()
    return features


def fit(x, y):
    """Ridge least squares (intercept free) and the leave-one-out residuals."""
    penalty = RIDGE * np.eye(x.shape[1])
    penalty[0, 0] = 0.0
    gram = x.T @ x + penalty
    beta = np.linalg.solve(gram, x.T @ y)
    hat = np.einsum("ij,jk,ik->i", x, np.linalg.inv(gram), x)
    residuals = (y - x @ beta) / np.maximum(1.0 - hat, 1e-6)
    return beta, residuals


def write_table(path, ladder, fits, presets):
    lines = ["/**",
             " * @file   vtkLightShaftErrorModelTable.h",
             " * @brief  The error model's ladder and coefficients (private, not installed). "
             "Written by",
             " *         tests/benchmarks/fit_error_model.py: do not edit by hand.",
             " */",
             "#ifndef vtkLightShaftErrorModelTable_h",
             "#define vtkLightShaftErrorModelTable_h",
             "",
             "#include \"vtkLightShaftErrorModel.h\" // For vtkLightShaftErrorModel::Setting",
             "#include \"vtkLightShaftEnums.h\"      // For the methods",
             "",
             "namespace vtkLightShaftErrorModelTable",
             "{",
             "/// 1, log depth range in beam widths, log beam width in pixels, log(1 + optical "
             "depth),",
             "/// light in view with falling attenuation, light in view, point light, "
             "directional light,",
             "/// light in view times the two logs, log shadow-map texel in pixels (0: no map).",
             "constexpr int NumberOfVariables = 11;",
             "",
             "struct Row",
             "{",
             "  vtkLightShaftErrorModel::Setting Ladder;",
             "  double Coefficients[NumberOfVariables]; ///< of the log of the relative RMS "
             "error",
             "  double Margin; ///< the 90th percentile of the fit's leave-one-out residuals "
             "(log)",
             "};",
             "",
             "// clang-format off",
             "constexpr Row Rows[] = {"]
    for (label, p), (beta, margin) in zip(ladder, fits):
        method = rs.vtkLightShaftPass.GetMethodName(p["Method"]).upper().replace("-", "_")
        samples = {"SLICES": p.get("NumberOfSlices"), "RAY_MARCH": p.get("NumberOfSteps"),
                   "EPIPOLAR": p.get("NumberOfSteps"),
                   "LIGHT_VOLUME": p.get("LightVolumeResolution")}[method]
        jitter = str(p.get("Jitter", False)).lower()
        epipolar = (f'{p["EpipolarLines"]}, {p["EpipolarSamples"]}, {p["EpipolarStep"]}'
                    if method == "EPIPOLAR" else "0, 0, 0")
        setting = (f'"{label}", vtkLightShaftEnums::{method}, {samples}, {jitter}, '
                   f'{p["BlurRadius"]}, {p["DownsampleFactor"]}, {p["ShadowMapSize"]}, '
                   f'{p.get("InterleaveSize", 1)}, {epipolar}')
        coefficients = ", ".join(f"{b:.6g}" for b in beta)
        lines.append(f"  {{ {{ {setting} }}, {{ {coefficients} }}, {margin:.6g} }},")
    lines += ["};", "",
              "/// The presets (Rows' indices): the cheapest setting whose training p90 meets "
              "each aim."]
    names = [label for label, _ in ladder]
    for name, aim, setting in presets:
        # No setting meets the aim: the most accurate one.
        index = names.index(setting) if setting else len(names) - 1
        lines.append(f"constexpr int {name}Setting = {index}; // {names[index]}, aim p90 <= "
                     f"{100 * aim:g}%")
    lines += ["// clang-format on", "}", "", "#endif", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("training", nargs="+",
                        help="random-scenes.csv of --ladder runs (their rows are merged)")
    parser.add_argument("--table", default=os.path.join(ROOT, "plugin", "core",
                                                        "vtkLightShaftErrorModelTable.h"))
    parser.add_argument("--docs", default=os.path.join(ROOT, "docs"))
    parser.add_argument("--previous", help="an earlier training CSV whose rows of the "
                        "settings not in `training` are kept")
    args = parser.parse_args()
    rows = []
    for path in args.training:
        with open(path) as f:
            rows += list(csv.DictReader(f))
    if args.previous:
        # An earlier fit's rows (its docs/error-model-training.csv) for the settings the new
        # runs did not measure: settings added to the ladder are trained without re-running
        # the others.
        measured = {r["setting"] for r in rows}
        with open(args.previous) as f:
            rows += [r for r in csv.DictReader(f) if r["setting"] not in measured]
    # Rows of earlier fits (docs/error-model-training.csv) carry their features; new runs'
    # rows get them here.
    cache = {}
    for row in progress.steps(rows, "training rows"):
        if all(row.get(k) not in (None, "") for k in FEATURES):
            continue
        key = row["scene_json"]  # the scene, whatever run it came from
        if key not in cache:
            cache[key] = scene_features(row["scene_json"])
            print(f"scene {row['scene']}: {cache[key]}", flush=True)
        row.update(cache[key])
    ladder = [(label, p) for label, p in rs.LADDER
              if any(r["setting"] == label for r in rows)]
    # Cost: each setting's time ratio over the dearest setting's on the same scene (single
    # frames of the training run: indicative), median over the scenes.
    dearest = ladder[-1][0]
    dear = {r["scene_json"]: float(r["time_ratio"]) for r in rows if r["setting"] == dearest}
    fits, report = [], []
    for label, _ in ladder:
        sub = [r for r in rows if r["setting"] == label]
        x = np.array([variables(r) for r in sub])
        y = np.log(np.maximum([float(r["relative_rmse"]) for r in sub], ERROR_FLOOR))
        beta, residuals = fit(x, y)
        margin = float(np.percentile(residuals, QUANTILE))
        fits.append((beta, margin))
        errors = np.exp(y)
        report.append(dict(setting=label, n=len(sub), median=float(np.median(errors)),
                           p90=float(np.percentile(errors, 90)),
                           spread=float(np.std(y)), residual=float(np.std(residuals)),
                           margin=margin,
                           ratio=float(np.median([float(r["time_ratio"]) for r in sub])),
                           cost=float(np.median([float(r["time_ratio"]) / dear[r["scene_json"]]
                                                 for r in sub if r["scene_json"] in dear]
                                                or [math.nan]))))
        print(f"{label:20s} n {len(sub)} p50 {100 * report[-1]['median']:.2f}% p90 "
              f"{100 * report[-1]['p90']:.2f}%  log-sd {report[-1]['spread']:.2f} -> LOO "
              f"{report[-1]['residual']:.2f}, margin {margin:.2f}")
    # A setting whose training p90 is no better than a cheaper one's is never worth its cost:
    # the ladder keeps the others, so that each step up buys accuracy.
    kept, best = [], math.inf
    for index, r in enumerate(report):
        r["kept"] = r["p90"] < best
        if r["kept"]:
            kept.append(index)
            best = r["p90"]
    presets = []
    for name, aim in AIMS:
        meeting = [r for r in report if r["kept"] and r["p90"] <= aim]
        presets.append((name, aim, meeting[0]["setting"] if meeting else None))
    write_table(args.table, [ladder[i] for i in kept], [fits[i] for i in kept], presets)
    with open(os.path.join(args.docs, "error-model-training.csv"), "w", newline="") as f:
        fieldnames = list(dict.fromkeys(k for row in rows for k in row))
        writer = csv.DictWriter(f, fieldnames=fieldnames, restval="")
        writer.writeheader()
        writer.writerows(rows)
    write_markdown(os.path.join(args.docs, "error-model.md"), report, presets, rows)


def write_markdown(path, report, presets, rows):
    n = len({r["scene_json"] for r in rows})
    lines = ["# The error model of TargetError", "",
             f"Fitted by `tests/benchmarks/fit_error_model.py` on {n} random scenes "
             "(`tools/measure.sh error-model`: seeds 8 and 9, 240p-720p; validated on the "
             "held-out seed 0, docs/quality-and-cost.md and docs/random-scenes.md). Per "
             "setting of the ladder (cheapest first): the training errors "
             "(relative RMS against the float64 reference), the spread of log(error) around "
             "its geometric mean and around the fit (leave-one-out), and the margin added to "
             "the fit (90th percentile of the leave-one-out residuals, log).", "",
             "| setting | n | median error | p90 error | time / dearest's | sd log(error) | "
             "sd LOO residual | margin | in the ladder |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in report:
        kept = "yes" if r["kept"] else "no: a cheaper setting's p90 is lower"
        lines.append(f"| {r['setting']} | {r['n']} | {100 * r['median']:.2f}% | "
                     f"{100 * r['p90']:.2f}% | {r['cost']:.3f} | {r['spread']:.2f} | "
                     f"{r['residual']:.2f} | {r['margin']:.2f} | {kept} |")
    lines += ["", "Settings: S = slices, j = jitter, b = blur radius (pixels), d = "
              "downsampling, m = shadow-map size; M = ray-march steps, i = interleave; E = "
              "EPIPOLAR steps per sample, l = lines, s = samples per line, k = every k-th "
              "marched; V = LIGHT_VOLUME cells. The time is that of one frame per scene "
              "(indicative), over the dearest setting's on the same scene; settings trained "
              "in a later run (`tools/measure.sh error-model-add`) are timed against the "
              "earlier run's dearest.", "",
              "The cheapest setting whose training p90 meets each preset's aim:", ""]
    for name, aim, setting in presets:
        lines.append(f"- {name} (p90 <= {100 * aim:g}%): {setting or 'none'}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
