"""Frame time and peak memory of the pass at the worst corners of its parameter ranges.

Each corner renders the sphere-and-floor scene in its own process (so that its peak resident
memory is its own; on llvmpipe the GL's textures and buffers are process memory too): one
frame, then the median of --frames more. Writes a Markdown table (and prints it).

Usage (from the repository root, after tools/quickstart.sh):
  PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 \
      tests/benchmarks/worst_corners.py --output docs/robustness.md
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import time

import progress

CORNERS = [
    ("defaults (64 slices, jitter, blur 2)", {}),
    ("NumberOfSlices 4096", {"NumberOfSlices": 4096}),
    ("AutomaticSliceCount, MaximumNumberOfSlices 4096",
     {"AutomaticSliceCount": 1, "MaximumNumberOfSlices": 4096}),
    ("NumberOfSlices 512, LatticeResolution 256", {"NumberOfSlices": 512,
                                                   "LatticeResolution": 256}),
    ("NumberOfSlices 4096, LatticeResolution 256", {"NumberOfSlices": 4096,
                                                    "LatticeResolution": 256}),
    ("AUTOMATIC, NumberOfSlices 4096, LatticeResolution 32",
     {"Method": 4, "NumberOfSlices": 4096, "LatticeResolution": 32}),
    ("RAY_MARCH, NumberOfSteps 4096, InterleaveSize 8",
     {"Method": 1, "NumberOfSteps": 4096, "InterleaveSize": 8}),
    ("RAY_MARCH, NumberOfSteps 4096, InterleaveSize 1",
     {"Method": 1, "NumberOfSteps": 4096, "InterleaveSize": 1}),
    ("EPIPOLAR, NumberOfSteps 4096, EpipolarStep 1",
     {"Method": 5, "NumberOfSteps": 4096, "EpipolarStep": 1}),
    ("RADIAL_BLUR, RadialSamples 1024, RadialGuardBand 4",
     {"Method": 2, "RadialSamples": 1024, "RadialGuardBand": 4.0}),
    ("ShadowMapSize 16384", {"ShadowMapSize": 16384}),
    ("ShadowMapSize 16384, ShadowSurfaces", {"ShadowMapSize": 16384, "ShadowSurfaces": 1}),
    ("4096 slices, 8-bit, DownsampleFactor 4, BlurRadius 32",
     {"NumberOfSlices": 4096, "AccumulationPrecision": 2, "DownsampleFactor": 4,
      "BlurRadius": 32}),
    ("512 plain slices, 2048^2 map, cookie, noise, window MultiSamples 8",
     {"NumberOfSlices": 512, "ShadowMapSize": 2048, "Jitter": 0, "BlurRadius": 0,
      "NoiseAmplitude": 1.0, "cookie": True, "multisamples": 8}),
    ("point light, ShadowMapSize 16384 (faces 5461)", {"kind": "point", "ShadowMapSize": 16384}),
    ("point light, ShadowMapSize 16384, ShadowSurfaces",
     {"kind": "point", "ShadowMapSize": 16384, "ShadowSurfaces": 1}),
    ("directional light, ShadowMapSize 16384", {"kind": "directional", "ShadowMapSize": 16384}),
    ("8 lights (4 spots, 4 points), 512 plain slices, 2048^2 maps, ShadowSurfaces",
     {"kind": "eight", "NumberOfSlices": 512, "ShadowMapSize": 2048, "Jitter": 0,
      "BlurRadius": 0, "ShadowSurfaces": 1}),
    # Every sampling maximum again with several lights: they share the frame's segments.
    ("8 lights, NumberOfSlices 4096, LatticeResolution 256",
     {"kind": "eight", "NumberOfSlices": 4096, "LatticeResolution": 256}),
    ("8 lights, AUTOMATIC, NumberOfSlices 4096, LatticeResolution 32",
     {"kind": "eight", "Method": 4, "NumberOfSlices": 4096, "LatticeResolution": 32}),
    ("8 lights, RAY_MARCH, NumberOfSteps 4096, InterleaveSize 1",
     {"kind": "eight", "Method": 1, "NumberOfSteps": 4096, "InterleaveSize": 1}),
    ("8 lights, EPIPOLAR, NumberOfSteps 4096, EpipolarStep 1",
     {"kind": "eight", "Method": 5, "NumberOfSteps": 4096, "EpipolarStep": 1}),
    ("8 lights, RADIAL_BLUR, RadialSamples 1024, RadialGuardBand 4",
     {"kind": "eight", "Method": 2, "RadialSamples": 1024, "RadialGuardBand": 4.0}),
]


def make_lights(renderer, light, kind):
    """The corner's lights: sphere_and_floor's spot turned into a point or a directional light,
    or joined by four spots and four point lights around the sphere (the spot switched off).
    Returns the lights to give the pass (a directional light scatters only when given)."""
    from lightshafts import scenes
    if kind == "point":
        light.SetConeAngle(180.0)
        light.SetPosition(0.4, 3.4, 0.3)
        light.SetAttenuationValues(1.0, 0.0, 0.05)
    elif kind == "directional":
        light.SetPositional(False)
        return [light]
    elif kind == "eight":
        import math
        for k in range(4):
            x, z = 4.0 * math.cos(k * math.pi / 2), 4.0 * math.sin(k * math.pi / 2)
            scenes.add_spotlight(renderer, (x, 5.0, z), (0.0, 0.5, 0.0), cone_angle=15.0)
            scenes.add_point_light(renderer, (0.5 * x, 3.2, 0.5 * z), intensity=0.1,
                                   attenuation=(1.0, 0.0, 0.2))
        light.SwitchOff()
    return []


def run_corner(params, width, height, frames):
    """In the child process: render the corner and print its figures as JSON."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    from lightshafts import parameter_owner, scenes, vtkLightShaftPass
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(params.pop("multisamples", 0))
    window.SetSize(width, height)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    given = make_lights(renderer, info.light, params.pop("kind", "spot"))
    window.Render()
    baseline = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    shafts = vtkLightShaftPass()
    for light in given:
        shafts.AddLight(light)
    if params.pop("cookie", False):
        sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "python"))
        import render_helpers as rh
        shafts.SetCookie(rh.uniform_cookie(256, 200))
    for name, value in params.items():
        if value is None:
            getattr(parameter_owner(shafts, name), "Set" + name)()
        else:
            getattr(parameter_owner(shafts, name), "Set" + name)(value)
    renderer.SetPass(shafts)
    times = []
    for _ in range(frames + 1):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    print(json.dumps({
        "first_s": times[0], "median_s": statistics.median(times[1:]),
        "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
        "baseline_mib": baseline, "lattice": shafts.GetLastFrame().GetLatticeResolution(),
        "slabs": shafts.GetLastFrame().GetNumberOfSlicesDrawn(), "batches": shafts.GetLastFrame().GetNumberOfSlabBatches(),
        "steps": shafts.GetLastFrame().GetNumberOfSteps(),
        "gl_errors": shafts.GetLastFrame().GetGLErrorCount()}))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--output", help="Markdown file to write")
    parser.add_argument("--only", help="run only the corners whose label contains this")
    parser.add_argument("--corner", help=argparse.SUPPRESS)  # child process
    args = parser.parse_args()
    if args.corner:
        run_corner(json.loads(args.corner), args.width, args.height, args.frames)
        return
    rows = []
    for label, params in progress.steps(CORNERS, "corners"):
        if args.only and args.only not in label:
            continue
        child = subprocess.run(
            [sys.executable, __file__, "--corner", json.dumps(params), "--width",
             str(args.width), "--height", str(args.height), "--frames", str(args.frames)],
            capture_output=True, text=True)
        result = None
        for line in child.stdout.splitlines():
            if line.startswith("{"):
                result = json.loads(line)
        if result is None:
            rows.append(f"| {label} | failed (exit {child.returncode}) | | | |")
            print(child.stdout[-2000:], child.stderr[-2000:])
        else:
            lattice = f", lattice used {result['lattice']}" if result["lattice"] else ""
            if result.get("steps"):
                lattice += f", {result['steps']} steps"
            rows.append(f"| {label} | {result['first_s']:.2f} | {result['median_s']:.2f} | "
                        f"{result['peak_mib']:.0f} | {result['peak_mib'] - result['baseline_mib']:.0f}"
                        f" | {result['slabs']} slabs in {result['batches']} draw(s){lattice}; "
                        f"{result['gl_errors']} GL errors |")
        print(rows[-1], flush=True)
    table = "\n".join([
        f"Worst corners of the parameter ranges: {args.width}x{args.height}, sphere-and-floor "
        f"scene, first frame and median of {args.frames} more; peak resident memory of the "
        "process (llvmpipe keeps GL objects in process memory) and its growth over the same "
        "scene rendered without the pass.",
        "",
        "| setting | first frame (s) | median frame (s) | peak memory (MiB) | over no pass (MiB) "
        "| what was drawn |",
        "|---|---:|---:|---:|---:|---|",
        *rows])
    if args.output:
        with open(args.output, "w") as f:
            f.write("# Robustness: cost at the worst corners\n\n" + table + "\n\n"
                    "Reproduce (from the repository root):\n\n```\n"
                    "PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a /usr/bin/python3 "
                    "tests/benchmarks/worst_corners.py --output docs/robustness.md\n```\n")


if __name__ == "__main__":
    main()
