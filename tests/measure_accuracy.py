#!/usr/bin/python3
"""Measure the pass's in-scatter error against the float64 reference and write a markdown table.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \
        tests/measure_accuracy.py --output docs/accuracy.md

Scene: lightshafts.scenes.sphere_and_floor at 640x480, sigma_s = (0.05, 0.04, 0.03),
sigma_a = (0.02, 0.01, 0.03) per unit; isotropic and Henyey-Greenstein (g = 0.6) phase, and an
inverse-square light seen in the picture (Rayleigh phase).
"""

import argparse
import os
import platform
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "python"))

import lightshaft_reference as ref  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import scenes, vtkLightShaftPass  # noqa: E402


def gl_renderer(window):
    try:
        return window.ReportCapabilities().split("OpenGL renderer string:")[1].splitlines()[0].strip()
    except (IndexError, AttributeError):
        return "unknown"


def measure(case, slices_list, shadow_sizes, width, height):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.JitterOff()  # the slab integration alone
    shafts.SetBlurRadius(0)
    if case == "hg":
        shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
        shafts.GetMedium().SetAnisotropy(0.6)
    elif case == "light-in-view":
        info.light.SetAttenuationValues(0.0, 0.0, 1.0)
        shafts.GetMedium().SetPhaseFunctionToRayleigh()
        camera = renderer.GetActiveCamera()
        camera.SetPosition(0.0, 8.0, 12.0)
        camera.SetFocalPoint(0.0, 4.0, 0.0)
        renderer.ResetCameraClippingRange()
    renderer.SetPass(shafts)
    window.Render()
    start = time.time()
    reference = rh.reference_for(renderer, window, info, shafts)
    reference_seconds = time.time() - start
    rows = []
    for size in shadow_sizes:
        shafts.SetShadowMapSize(size)
        for slices in slices_list:
            shafts.SetNumberOfSlices(slices)
            window.Render()
            image = rh.in_scatter(shafts)
            rel, pixels = ref.relative_rms_error(image, reference)
            rel_low, pixels_low = ref.relative_rms_error(image, reference, threshold=1e-4)
            rows.append((slices, size, rel, ref.energy_error(image, reference), pixels,
                         rel_low, pixels_low))
    return rows, reference_seconds, gl_renderer(window)


def frame_times(slices_list, width, height, frames=15):
    """Median frame time with the pass (per slice count) over the same scene without it."""
    renderer, window = rh.make_window(width, height)
    scenes.sphere_and_floor(renderer)

    plain = rh.median_frame_time(window, frames)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.SetShadowMapSize(2048)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    renderer.SetPass(shafts)
    rows = []
    for slices in slices_list:
        shafts.SetNumberOfSlices(slices)
        rows.append((slices, rh.median_frame_time(window, frames) / plain))
    return plain, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output", default=None)
    parser.add_argument("--size", type=int, nargs=2, default=(640, 480))
    args = parser.parse_args()
    slices_list = [8, 16, 32, 64, 128, 256, 512, 1024]
    shadow_sizes = [512, 2048]
    lines = ["# Accuracy of the slice integration against the float64 reference", "",
             "Measured by `tests/measure_accuracy.py` (command below); regenerate after changes "
             "to the integration.", ""]
    command = ("PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 "
               "tests/measure_accuracy.py --output docs/accuracy.md")
    gl = None
    for case, title in [("isotropic", "Isotropic phase"), ("hg", "Henyey-Greenstein, g = 0.6"),
                        ("light-in-view", "Rayleigh phase, A = 1/r^2, light in the picture")]:
        rows, seconds, gl = measure(case, slices_list, shadow_sizes, *args.size)
        lines += [f"## {title}", "",
                  f"Reference: {seconds:.1f} s (numpy, {args.size[0]}x{args.size[1]}).", "",
                  "| slices | shadow map | relative RMS error (> 1% of peak) | energy error "
                  "| pixels compared | relative RMS error (> 0.01% of peak) | pixels |",
                  "|---:|---:|---:|---:|---:|---:|---:|"]
        for slices, size, rel, energy, pixels, rel_low, pixels_low in rows:
            lines.append(f"| {slices} | {size} | {100 * rel:.3f}% | {100 * energy:.4f}% | "
                         f"{pixels} | {100 * rel_low:.3f}% | {pixels_low} |")
        lines.append("")
    plain, timing = frame_times([16, 64, 128, 256, 512, 1024], *args.size)
    lines += ["## Frame time", "",
              f"Median of 15 frames (with glFinish) of the isotropic scene at "
              f"{args.size[0]}x{args.size[1]}, 2048^2 shadow map, relative to the same scene "
              f"rendered without the pass in the same run ({1000 * plain:.1f} ms on this "
              f"machine; software rendering, so only the ratios mean anything).", "",
              "| slices | frame time / without the pass |", "|---:|---:|"]
    lines += [f"| {slices} | {ratio:.2f} |" for slices, ratio in timing]
    lines.append("")
    lines += ["Relative RMS error: ||L - L_ref|| / ||L_ref|| over the pixels whose reference "
              "exceeds 1% of its peak; energy error: |sum L - sum L_ref| / sum L_ref over the "
              "image. Scene: `lightshafts.scenes.sphere_and_floor` (spotlight, sphere occluder, "
              "floor), sigma_s = (0.05, 0.04, 0.03), sigma_a = (0.02, 0.01, 0.03) per unit.", "",
              f"Machine: {platform.machine()}, {os.cpu_count()} cores, GL: {gl}.", "",
              f"Command: `{command}`", ""]
    text = "\n".join(lines)
    print(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
