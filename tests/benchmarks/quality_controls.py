#!/usr/bin/python3
"""Measure what each quality control of vtkLightShaftPass costs and what it does to the error.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \
        tests/benchmarks/quality_controls.py --output docs/quality-controls.md

One run, one scene (lightshafts.scenes.sphere_and_floor, 480x360): for every setting, the median
frame time over 15 frames (glFinish after each) divided by the median frame time of the same
scene without the pass, measured in the same run; the relative RMS and energy error of the
in-scatter image against the float64 reference (tests/python/lightshaft_reference.py). The
absolute times are this machine's (software rendering here); the ratios are the result.
"""

import argparse
import os
import platform
import sys


HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, scenes, vtkLightShaftPass  # noqa: E402


BASE = dict(NumberOfSlices=128, ShadowMapSize=1024, Jitter=False, BlurRadius=0)
SETTINGS = [
    ("32 slices", dict(NumberOfSlices=32)),
    ("128 slices (baseline)", {}),
    ("512 slices", dict(NumberOfSlices=512)),
    ("automatic slice count (max 512)", dict(AutomaticSliceCount=True)),
    ("automatic slice count (max 128)", dict(AutomaticSliceCount=True, MaximumNumberOfSlices=128)),
    ("32 slices + jitter", dict(NumberOfSlices=32, Jitter=True)),
    ("32 slices + jitter + blur 2", dict(NumberOfSlices=32, Jitter=True, BlurRadius=2)),
    ("blur radius 2", dict(BlurRadius=2)),
    ("blur radius 4", dict(BlurRadius=4)),
    ("downsample 2", dict(DownsampleFactor=2)),
    ("downsample 4", dict(DownsampleFactor=4)),
    ("16-bit float accumulation", dict(AccumulationPrecision=1)),
    ("8-bit accumulation (Exposure 40)", dict(AccumulationPrecision=2, Exposure=40.0)),
    ("8-bit accumulation, 512 slices", dict(AccumulationPrecision=2, Exposure=40.0,
                                            NumberOfSlices=512)),
    ("shadow map 512", dict(ShadowMapSize=512)),
    ("shadow map 2048", dict(ShadowMapSize=2048)),
    ("cookie (uniform white)", dict(Cookie="white")),
    ("noise amplitude 1", dict(NoiseAmplitude=1.0)),
]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output")
    parser.add_argument("--size", type=int, nargs=2, default=(480, 360))
    parser.add_argument("--frames", type=int, default=15)
    args = parser.parse_args()

    renderer, window = rh.make_window(*args.size)
    info = scenes.sphere_and_floor(renderer)
    plain = rh.median_frame_time(window, args.frames)
    rows = []
    reference = None
    for name, params in progress.steps(SETTINGS, "settings"):
        shafts = vtkLightShaftPass()
        shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
        shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
        for key, value in {**BASE, **params}.items():
            if key == "Cookie":
                shafts.SetCookie(rh.uniform_cookie())
            else:
                getattr(parameter_owner(shafts, key), "Set" + key)(value)
        renderer.SetPass(shafts)
        ratio = rh.median_frame_time(window, args.frames) / plain
        if reference is None:
            reference = rh.reference_for(renderer, window, info, shafts)
        image = rh.in_scatter(shafts)
        error, _ = ref.relative_rms_error(image, reference)
        energy = ref.energy_error(image, reference)
        rows.append((name, ratio, error, energy, shafts.GetLastFrame().GetNumberOfSlicesDrawn(),
                     shafts.GetLastFrame().GetShaderVariant()))
        print(f"{name:40s} {ratio:7.2f} {100 * error:8.3f}% {100 * energy:8.4f}%", flush=True)
        renderer.SetPass(None)

    command = ("PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 "
               "tests/benchmarks/quality_controls.py --output docs/quality-controls.md")
    lines = [
        "# Quality controls: cost and error, measured", "",
        f"Scene `lightshafts.scenes.sphere_and_floor` at {args.size[0]}x{args.size[1]}, "
        "sigma_s = (0.05, 0.04, 0.03), sigma_a = (0.02, 0.01, 0.03) per unit, isotropic phase; "
        "baseline 128 slices, 1024^2 shadow map, no jitter or blur, 32-bit float accumulation. Time: median of "
        f"{args.frames} frames (glFinish after each) over the same scene without the pass "
        f"({1000 * plain:.1f} ms here), in one run. Error: relative RMS over pixels above 1% of "
        "the reference's peak, and energy error, against the float64 reference. With noise the "
        "medium differs from the reference's homogeneous one: its error column measures how much "
        "texture the noise adds (and its energy column that the mean is kept).", "",
        "| setting | frame time / without the pass | relative RMS error | energy error | slabs "
        "drawn | compiled features |",
        "|---|---:|---:|---:|---:|---|"]
    for name, ratio, error, energy, slabs, variant in rows:
        lines.append(f"| {name} | {ratio:.2f} | {100 * error:.2f}% | {100 * energy:.3f}% | "
                     f"{slabs} | `{variant}` |")
    lines += ["", f"Machine: {platform.machine()}, {os.cpu_count()} cores, Mesa llvmpipe "
              "(software OpenGL) under Xvfb.", "", f"Command: `{command}`", ""]
    text = "\n".join(lines)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    print(text)


if __name__ == "__main__":
    main()
