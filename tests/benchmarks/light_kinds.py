#!/usr/bin/python3
"""Cost and accuracy per light: each light kind alone, and several lights, against the float64
reference.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/light_kinds.py --output-dir docs

Scene: the sphere over the floor (scenes.sphere_and_floor) with its light as a spot, a point
light (at (0.4, 3.4, 0.3), attenuation 1 / (1 + 0.05 r^2)) or a directional light (from the plane
through (0.5, 6, 0) towards the origin), and with two lights (the spot and the point light) and
four lights (two spots, two point lights). For every setting: the median frame time over
--frames frames after a warm-up frame, each finished with glFinish, divided by the median frame
time of the same scene without the pass measured in the same run; the GPU time of each light's
in-scatter (GetLastFrame().GetLightTime: shadow map, slabs or march, own passes; median over the frames);
and the relative RMS error of the in-scatter against vtkLightShaftReference (exact surfaces and
shadows, float64; pixels above 1% of the reference's peak). "surfaces" rows add ShadowSurfaces
(one more scene render, and one full-screen pass per light) to the defaults.

Writes light-kinds.csv and light-kinds.md into --output-dir. --smoke runs a tiny version.
"""

import argparse
import csv
import os
import platform
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from benchmark import reference_image  # noqa: E402  (tests/benchmarks/benchmark.py)
from lightshafts import parameter_owner, scenes, vtkLightShaftPass  # noqa: E402

SIGMA_S, SIGMA_A = (0.05, 0.04, 0.03), (0.01, 0.01, 0.01)


def spot(renderer, info):
    return [info.light]


def point(renderer, info):
    light = info.light
    light.SetConeAngle(180.0)
    light.SetPosition(0.4, 3.4, 0.3)
    light.SetAttenuationValues(1.0, 0.0, 0.05)
    return [light]


def directional(renderer, info):
    info.light.SetPositional(False)
    return [info.light]


def two(renderer, info):
    other = scenes.add_point_light(renderer, (-1.6, 3.0, 0.5), color=(0.4, 0.6, 1.0),
                                   attenuation=(1.0, 0.0, 0.05))
    return [info.light, other]


def four(renderer, info):
    lights = two(renderer, info)
    lights.append(scenes.add_spotlight(renderer, (-3.0, 5.5, -1.0), (0.5, 0.0, 0.0),
                                       cone_angle=20.0, color=(1.0, 0.5, 0.3)))
    lights.append(scenes.add_point_light(renderer, (1.8, 2.6, -0.8), color=(0.5, 1.0, 0.5),
                                         attenuation=(1.0, 0.0, 0.2)))
    return lights


SCENES = {"spot": spot, "point": point, "directional": directional, "spot + point": two,
          "2 spots + 2 points": four}

# The defaults (64 slices, jitter, blur 2) and 512 plain slabs with 2048^2 maps: the presets
# of earlier releases, named by their settings (the presets are now the error model's choices).
DEFAULTS = dict()
SLABS_512 = dict(NumberOfSlices=512, ShadowMapSize=2048, Jitter=False, BlurRadius=0)
SETTINGS = [
    ("64 slices, jitter, blur 2 (defaults)", DEFAULTS),
    ("512 slices, 2048^2 maps", SLABS_512),
    ("ray march (default)", dict(Method=vtkLightShaftPass.RAY_MARCH)),
    ("radial blur (default)", dict(Method=vtkLightShaftPass.RADIAL_BLUR)),
    ("defaults + surfaces", dict(ShadowSurfaces=True)),
]


def configure(shafts, lights, params):
    shafts.GetMedium().SetScatteringCoefficient(*SIGMA_S)
    shafts.GetMedium().SetAbsorptionCoefficient(*SIGMA_A)
    shafts.SetExposure(20.0)
    for light in lights:
        shafts.AddLight(light)
    for name, value in params.items():
        if name == "Quality":
            getattr(shafts, "SetQualityTo" + value)()
        else:
            getattr(parameter_owner(shafts, name), "Set" + name)(value)


def measure(window, shafts, frames):
    """(median frame time, [median GPU ms per light])."""
    times, gpu = [], []
    window.Render()
    window.WaitForCompletion()
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
        gpu.append([shafts.GetLastFrame().GetLightTime(i)
                    for i in range(shafts.GetLastFrame().GetNumberOfUsedLights())])
    per_light = [float(np.median([g[i] for g in gpu])) for i in range(len(gpu[0]))]
    return float(np.median(times)), per_light


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default="docs")
    parser.add_argument("--size", type=int, nargs=2, default=(480, 360))
    parser.add_argument("--frames", type=int, default=15)
    parser.add_argument("--smoke", action="store_true")
    args = parser.parse_args()
    scene_names, settings = list(SCENES), SETTINGS
    if args.smoke:
        args.size, args.frames = (96, 72), 2
        settings = SETTINGS[:1] + SETTINGS[-1:]

    rows = []
    for name in progress.steps(scene_names, "lights"):
        renderer, window = rh.make_window(*args.size)
        info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
        lights = SCENES[name](renderer, info)
        plain = rh.median_frame_time(window, args.frames)
        reference = None
        for label, params in settings:
            shafts = vtkLightShaftPass()
            configure(shafts, lights, params)
            renderer.SetPass(shafts)
            frame, per_light = measure(window, shafts, args.frames)
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
            assert shafts.GetLastFrame().GetNumberOfUsedLights() == len(lights)
            if reference is None:
                reference = reference_image(renderer, shafts)
            error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
            row = dict(lights=name, setting=label, time_ratio=frame / plain,
                       plain_ms=1000 * plain,
                       gpu_ms_per_light=" / ".join(f"{t:.1f}" for t in per_light),
                       relative_rmse=error)
            rows.append(row)
            print(f"{name:20s} {label:24s} {row['time_ratio']:7.2f} "
                  f"{row['gpu_ms_per_light']:>24s} {100 * error:6.2f}%", flush=True)
            renderer.SetPass(None)

    os.makedirs(args.output_dir, exist_ok=True)
    with open(os.path.join(args.output_dir, "light-kinds.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    command = ("PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s \"-noreset\" "
               "/usr/bin/python3 tests/benchmarks/light_kinds.py --output-dir docs")
    lines = ["# Cost and accuracy per light", "",
             __doc__.split("\n\n")[2].replace("\n", " "), "",
             f"{args.size[0]}x{args.size[1]}, median of {args.frames} frames.", "",
             "| lights | setting | time ratio | GPU ms per light | relative RMSE |",
             "|---|---|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['lights']} | {r['setting']} | {r['time_ratio']:.2f} | "
                     f"{r['gpu_ms_per_light']} | {100 * r['relative_rmse']:.2f}% |")
    lines += ["", f"Machine: {platform.machine()}, {os.cpu_count()} cores, Mesa llvmpipe "
              "(software OpenGL) under Xvfb; only the ratios carry over to other machines.", "",
              f"Command: `{command}`", ""]
    with open(os.path.join(args.output_dir, "light-kinds.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
