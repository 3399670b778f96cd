#!/usr/bin/python3
"""How the shafts' time of the budget's ladder settings follows the in-scatter's resolution:
the resolution exponents of vtkLightShaftCostModel.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/resolution_cost.py

Scene: the README picture's window scene (σ_s 0.05, exposure 40) at --size, the camera turned ±0.5
degree every frame (as while moving: the shadow map is kept, the epipolar lines are not).
For each setting at DownsampleFactor 1, 2 and 4: the median frame (of --frames, after two)
less the plain frame, and the exponent e of time ∝ (pixels / factor²)^e between full and
quarter resolution (and between full and half).
"""

import argparse
import math
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import parameter_owner, vtkLightShaftPass as P  # noqa: E402

SETTINGS = {  # the ladder's E16, E32, V256 and M128 (plugin/core/vtkLightShaftErrorModelTable.h)
    "E16 l128 s256 k8 m512": dict(Method=P.EPIPOLAR, NumberOfSteps=16, ShadowMapSize=512,
                                  EpipolarLines=128, EpipolarSamples=256, EpipolarStep=8),
    "E32 l256 s256 k8 m1024": dict(Method=P.EPIPOLAR, NumberOfSteps=32, ShadowMapSize=1024,
                                   EpipolarLines=256, EpipolarSamples=256, EpipolarStep=8),
    "V256 m1024": dict(Method=P.LIGHT_VOLUME, LightVolumeResolution=256, ShadowMapSize=1024),
    "M128 i1 m2048": dict(Method=P.RAY_MARCH, NumberOfSteps=128, InterleaveSize=1,
                          ShadowMapSize=2048),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--frames", type=int, default=5)
    args = parser.parse_args()
    renderer, window, plain, shafts = rh.window_scene(*args.size)
    shafts.SetBlurRadius(0)
    renderer.SetPass(shafts)
    camera = renderer.GetActiveCamera()
    print(f"plain frame {1000 * plain:.1f} ms ({args.size[0]}x{args.size[1]})")
    print("| setting | 1/1 | 1/2 | 1/4 | exponent 1..4 | exponent 1..2 |")
    print("|---|---:|---:|---:|---:|---:|")
    for name, params in progress.steps(SETTINGS.items(), "settings", total=len(SETTINGS)):
        shafts_time = {}
        for factor in (1, 2, 4):
            shafts.SetDownsampleFactor(factor)
            for key, value in params.items():
                getattr(parameter_owner(shafts, key), "Set" + key)(value)
            times = []
            for i in range(args.frames + 2):
                camera.Azimuth(0.5 if i % 2 else -0.5)
                start = time.perf_counter()
                window.Render()
                window.WaitForCompletion()
                times.append(time.perf_counter() - start)
            shafts_time[factor] = max(statistics.median(times[2:]) - plain, 1e-6)
        quarter = math.log(shafts_time[1] / shafts_time[4]) / math.log(16)
        half = math.log(shafts_time[1] / shafts_time[2]) / math.log(4)
        print(f"| {name} | " + " | ".join(f"{1000 * shafts_time[f]:.0f} ms" for f in (1, 2, 4))
              + f" | {quarter:.2f} | {half:.2f} |", flush=True)


if __name__ == "__main__":
    main()
