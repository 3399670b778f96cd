#!/usr/bin/python3
"""Speed versus accuracy of vtkLightShaftPass's methods on three scenes, against the float64
reference.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \
        tests/benchmarks/benchmark.py --output-dir docs

For every scene (sphere and floor; a window with bars; an isosurface of a VTK dataset) and
every setting: the median frame time over --frames frames after a warm-up frame, each finished
with glFinish, divided by the median frame time of the same scene without the pass measured in
the same run; and the in-scatter image's error against vtkLightShaftReference (exact surfaces and
shadows, float64): RMSE, relative RMSE (pixels above 1% of the reference's peak), PSNR with the
reference's peak as the one fixed peak, and SSIM (scikit-image, Wang 2004 settings: Gaussian
sigma 1.5, K1 0.01, K2 0.03, population covariance) after one fixed tone map
x -> 1 - exp(-x / m), m the reference's 99th percentile. Settings whose medium the reference
does not model (cookie, noise) get no error columns.

The fetch floor (vtkLightShaftFetchFloor): for the slice-count settings and the presets, a
trivial full-screen shader doing as many texture fetches per pixel as the slabs do (two per slab
and covered in-scatter pixel: scene depth and shadow map, averaged over the screen); the column
"slab cost / fetch floor" is (pass time - time without the pass) / fetch-floor time, so 1 would
mean the slabs cost no more than their fetches.

Writes benchmark.csv, benchmark.md and images/pareto.png into --output-dir. --smoke runs a
tiny version (one scene, three settings, 2 frames) for the test suite.
"""

import argparse
import csv
import math
import os
import platform
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, scenes, vtkLightShaftFetchFloor, vtkLightShaftPass  # noqa: E402

SCENES = {
    "sphere-and-floor": (scenes.sphere_and_floor, (0.05, 0.04, 0.03), (0.02, 0.01, 0.03)),
    "window": (scenes.window_room, (0.05, 0.047, 0.043), (0.005, 0.005, 0.005)),
    "isosurface": (scenes.isosurface, (0.04, 0.04, 0.04), (0.004, 0.004, 0.004)),
}

# (family, label, parameters); the family is a curve on the Pareto plot.
SETTINGS = [
    ("slices", "16 slices", dict(NumberOfSlices=16)),
    ("slices", "32 slices", dict(NumberOfSlices=32)),
    ("slices", "64 slices", dict(NumberOfSlices=64)),
    ("slices", "128 slices", dict(NumberOfSlices=128)),
    ("slices", "256 slices", dict(NumberOfSlices=256)),
    ("slices", "512 slices", dict(NumberOfSlices=512)),
    ("slices", "1024 slices", dict(NumberOfSlices=1024)),
    ("shadow map", "shadow map 256", dict(ShadowMapSize=256)),
    ("shadow map", "shadow map 1024", dict(ShadowMapSize=1024)),
    ("shadow map", "shadow map 4096", dict(ShadowMapSize=4096)),
    ("jitter + blur", "32 slices + jitter", dict(NumberOfSlices=32, Jitter=True)),
    ("jitter + blur", "32 slices + jitter + blur 2",
     dict(NumberOfSlices=32, Jitter=True, BlurRadius=2)),
    ("jitter + blur", "64 slices + jitter + blur 2",
     dict(NumberOfSlices=64, Jitter=True, BlurRadius=2)),
    ("downsample", "downsample 2", dict(DownsampleFactor=2)),
    ("downsample", "downsample 4", dict(DownsampleFactor=4)),
    ("precision", "16-bit float", dict(AccumulationPrecision=1)),
    ("precision", "8-bit (Exposure 40)", dict(AccumulationPrecision=2, Exposure=40.0)),
    ("features", "cookie on", dict(Cookie=True)),
    ("features", "noise on", dict(NoiseAmplitude=1.0)),
    ("ray march", "ray march 8 steps", dict(Method=1, NumberOfSteps=8, InterleaveSize=1)),
    ("ray march", "ray march 32 steps", dict(Method=1, NumberOfSteps=32, InterleaveSize=1)),
    ("ray march", "ray march 128 steps", dict(Method=1, NumberOfSteps=128, InterleaveSize=1)),
    ("ray march, interleaved", "8 steps, 2x2", dict(Method=1, NumberOfSteps=8, InterleaveSize=2)),
    ("ray march, interleaved", "16 steps, 2x2 (default)",
     dict(Method=1, NumberOfSteps=16, InterleaveSize=2)),
    ("ray march, interleaved", "16 steps, 4x4",
     dict(Method=1, NumberOfSteps=16, InterleaveSize=4)),
    ("ray march, interleaved", "32 steps, 3x3",
     dict(Method=1, NumberOfSteps=32, InterleaveSize=3)),
    ("radial blur", "radial blur 16 samples", dict(Method=2, RadialSamples=16)),
    ("radial blur", "radial blur 64 samples (default)", dict(Method=2, RadialSamples=64)),
    ("radial blur", "radial blur 64, half resolution", dict(Method=2, DownsampleFactor=2)),
    ("radial blur", "radial blur 64, guard band 2", dict(Method=2, RadialGuardBand=2.0)),
    ("analytic (no shadows)", "analytic", dict(Method=3)),
    ("lattice", "32 slices, lattice 8", dict(NumberOfSlices=32, LatticeResolution=8)),
    ("lattice", "64 slices, lattice 8", dict(NumberOfSlices=64, LatticeResolution=8)),
    ("lattice", "64 slices, lattice 16", dict(NumberOfSlices=64, LatticeResolution=16)),
    ("lattice", "128 slices, lattice 16", dict(NumberOfSlices=128, LatticeResolution=16)),
    ("lattice", "128 slices, lattice 32", dict(NumberOfSlices=128, LatticeResolution=32)),
    # The presets of earlier releases, by their settings (what docs/benchmark.md measured).
    ("former presets", "32 slices, jitter, blur 2, half resolution, 512 map",
     dict(NumberOfSlices=32, Jitter=True, BlurRadius=2, DownsampleFactor=2, ShadowMapSize=512)),
    ("former presets", "64 slices, jitter, blur 2 (defaults)",
     dict(NumberOfSlices=64, Jitter=True, BlurRadius=2)),
    ("former presets", "512 slices, 2048 map", dict(NumberOfSlices=512, ShadowMapSize=2048)),
    ("presets", "Draft", dict(Quality="Draft")),
    ("presets", "Interactive", dict(Quality="Interactive")),
    ("presets", "Final", dict(Quality="Final")),
]


def configure(shafts, sigma_s, sigma_a, params):
    shafts.GetMedium().SetScatteringCoefficient(*sigma_s)
    shafts.GetMedium().SetAbsorptionCoefficient(*sigma_a)
    # Plain slabs unless the setting says otherwise (the presets set everything themselves).
    shafts.SetNumberOfSlices(128)
    shafts.SetShadowMapSize(1024)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    for key, value in params.items():
        if key == "Cookie":
            shafts.SetCookie(rh.uniform_cookie())
        elif key == "Quality":
            getattr(shafts, f"SetQualityTo{value}")()
        else:
            getattr(parameter_owner(shafts, key), "Set" + key)(value)


def reference_image(renderer, shafts):
    return rh.scene_reference(renderer, shafts)


def metrics(image, reference):
    from skimage.metrics import structural_similarity
    peak = reference.max()
    rmse = float(np.sqrt(np.mean((image - reference) ** 2)))
    relative, _ = ref.relative_rms_error(image, reference)
    psnr = float(20.0 * math.log10(peak / rmse)) if rmse > 0 else float("inf")
    scale = max(np.percentile(reference, 99), 1e-30)
    tone = lambda x: 1.0 - np.exp(-x / scale)  # noqa: E731
    ssim = float(structural_similarity(
        tone(image.mean(-1)), tone(reference.mean(-1)), gaussian_weights=True, sigma=1.5,
        use_sample_covariance=False, data_range=1.0, K1=0.01, K2=0.03))
    return rmse, relative, psnr, ssim


def pareto_plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = list(dict.fromkeys(r["scene"] for r in rows))
    figure, axes = plt.subplots(1, len(names), figsize=(5 * len(names), 4.2), squeeze=False)
    families = list(dict.fromkeys(r["family"] for r in rows))
    colours = plt.cm.tab20.colors
    markers = "osD^v<>phX*"
    for axis, name in zip(axes[0], names):
        for index, family in enumerate(families):
            points = [(r["time_ratio"], r["relative_rmse"]) for r in rows
                      if r["scene"] == name and r["family"] == family and r["relative_rmse"] != ""]
            if not points:
                continue
            points.sort()
            xs, ys = zip(*points)
            axis.plot(xs, [100 * y for y in ys], "-", marker=markers[index % len(markers)],
                      color=colours[(2 * index) % 20 + (index // 10) % 2], label=family,
                      markersize=4)
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("frame time / without the pass")
        axis.set_ylabel("relative RMS error (%)")
        axis.set_title(name)
        axis.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default="docs")
    parser.add_argument("--size", type=int, nargs=2, default=(480, 360))
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--smoke", action="store_true")
    parser.add_argument("--families", nargs="+", help="only these families (e.g. slices lattice)")
    parser.add_argument("--replot", action="store_true",
                        help="only redraw images/pareto.png from the CSV in --output-dir")
    args = parser.parse_args()
    if args.replot:
        with open(os.path.join(args.output_dir, "benchmark.csv")) as f:
            rows = [{k: (float(v) if k in ("time_ratio", "relative_rmse") and v else v)
                     for k, v in r.items()} for r in csv.DictReader(f)]
        pareto_plot(rows, os.path.join(args.output_dir, "images", "pareto.png"))
        return
    scene_names = list(SCENES)
    settings = SETTINGS
    if args.families:
        settings = [s for s in SETTINGS if s[0] in args.families]
    if args.smoke:
        args.size, args.frames = (96, 72), 2
        scene_names = scene_names[:1]
        settings = [SETTINGS[i] for i in (1, 11, 17, 23, 26, 29, 30, 31)]
    os.makedirs(os.path.join(args.output_dir, "images"), exist_ok=True)

    rows = []
    for name in scene_names:
        build, sigma_s, sigma_a = SCENES[name]
        renderer, window = rh.make_window(*args.size)
        build(renderer)
        # After the scene's first frames have settled (docs/known-issues.md).
        plain = rh.median_frame_time(window, args.frames, warm_up=30, warm_up_seconds=2.0)
        reference = None
        for family, label, params in progress.steps(settings, f"settings ({name})"):
            shafts = vtkLightShaftPass()
            configure(shafts, sigma_s, sigma_a, params)
            renderer.SetPass(shafts)
            ratio = rh.median_frame_time(window, args.frames) / plain
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
            row = dict(scene=name, family=family, setting=label, time_ratio=ratio,
                       plain_ms=1000 * plain, slabs=shafts.GetLastFrame().GetNumberOfSlicesDrawn(),
                       rmse="", relative_rmse="", psnr_db="", ssim="", fetches_per_pixel="",
                       over_fetch_floor="")
            if family in ("slices", "presets"):
                lit = float(np.mean(rh.in_scatter(shafts).max(axis=-1) > 0.0))
                factor = shafts.GetDownsampleFactor()
                fetches = int(round(2 * row["slabs"] * lit / (factor * factor)))
                floor = vtkLightShaftFetchFloor().Measure(window, *args.size, fetches,
                                                          args.frames)
                row["fetches_per_pixel"] = fetches
                row["over_fetch_floor"] = (ratio - 1.0) * plain / floor if floor > 0 else ""
            if "Cookie" not in params and "NoiseAmplitude" not in params:
                if reference is None:
                    reference = reference_image(renderer, shafts)
                image = rh.in_scatter(shafts)
                row["rmse"], row["relative_rmse"], row["psnr_db"], row["ssim"] = \
                    metrics(image, reference)
            rows.append(row)
            print(f"{name:18s} {label:30s} {ratio:7.2f} "
                  f"{row['relative_rmse'] if row['relative_rmse'] == '' else 100 * row['relative_rmse']:>8}",
                  flush=True)
            renderer.SetPass(None)

    fields = list(rows[0].keys())
    with open(os.path.join(args.output_dir, "benchmark.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    pareto_plot(rows, os.path.join(args.output_dir, "images", "pareto.png"))

    command = ("PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 "
               "tests/benchmarks/benchmark.py --output-dir docs")
    lines = ["# Benchmark: frame time and error against the float64 reference", "",
             __doc__.split("\n\n")[2].replace("\n", " "), "",
             "![Pareto plot](images/pareto.png)", ""]
    for name in scene_names:
        scene_rows = [r for r in rows if r["scene"] == name]
        lines += [f"## {name} ({args.size[0]}x{args.size[1]}, without the pass "
                  f"{scene_rows[0]['plain_ms']:.1f} ms)", "",
                  "| setting | time ratio | relative RMSE | RMSE | PSNR (dB) | SSIM | slabs | "
                  "fetches per pixel | slab cost / fetch floor |",
                  "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for r in scene_rows:
            if r["relative_rmse"] == "":
                errors = "— | — | — | —"
            else:
                errors = (f"{100 * r['relative_rmse']:.2f}% | {r['rmse']:.2e} | "
                          f"{r['psnr_db']:.1f} | {r['ssim']:.4f}")
            floor = (f"{r['fetches_per_pixel']} | {r['over_fetch_floor']:.1f}"
                     if r["over_fetch_floor"] != "" else "— | —")
            lines.append(f"| {r['setting']} | {r['time_ratio']:.2f} | {errors} | {r['slabs']} | "
                         f"{floor} |")
        lines.append("")
    lines += [f"Machine: {platform.machine()}, {os.cpu_count()} cores, Mesa llvmpipe (software "
              "OpenGL) under Xvfb; only the ratios carry over to other machines.", "",
              f"Command: `{command}`", ""]
    with open(os.path.join(args.output_dir, "benchmark.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
