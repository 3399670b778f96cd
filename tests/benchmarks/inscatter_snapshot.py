#!/usr/bin/python3
"""Record, or compare with a record, the pass's in-scattered radiance for every benchmark
setting (every method and preset) on the three benchmark scenes: a guard for changes that must
not change the output (refactorings).

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s -noreset /usr/bin/python3 \
        tests/benchmarks/inscatter_snapshot.py --save before.npz
    ... change the code, rebuild ...
    PYTHONPATH=... tests/benchmarks/inscatter_snapshot.py --compare before.npz

--compare prints, per scene and setting, the largest relative difference over the pixels above
1% of the recorded image's peak, and exits with status 1 when one exceeds --tolerance (1e-5).
"""

import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import benchmark  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402


def images(size):
    """{"scene / setting": in-scatter} for every benchmark scene and setting."""
    result = {}
    for name, (build, sigma_s, sigma_a) in benchmark.SCENES.items():
        renderer, window = rh.make_window(*size)
        build(renderer)
        for _, label, params in progress.steps(benchmark.SETTINGS, f"settings ({name})"):
            shafts = vtkLightShaftPass()
            benchmark.configure(shafts, sigma_s, sigma_a, params)
            renderer.SetPass(shafts)
            window.Render()
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
            result[f"{name} / {label}"] = rh.in_scatter(shafts).astype(np.float32)
            renderer.SetPass(None)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--save", help="write the images to this .npz")
    group.add_argument("--compare", help="compare the images with this .npz")
    parser.add_argument("--size", type=int, nargs=2, default=(240, 180))
    parser.add_argument("--tolerance", type=float, default=1e-5)
    args = parser.parse_args()
    current = images(args.size)
    if args.save:
        np.savez_compressed(args.save, **current)
        print(f"{len(current)} images written to {args.save}")
        return 0
    recorded = np.load(args.compare)
    worst = 0.0
    failures = 0
    for key in recorded.files:
        before, after = recorded[key].astype(np.float64), current[key].astype(np.float64)
        peak = before.max()
        lit = before > 0.01 * peak
        difference = (np.abs(after - before)[lit] / before[lit]).max() if lit.any() else 0.0
        worst = max(worst, difference)
        flag = "FAIL" if difference > args.tolerance else "ok"
        failures += flag == "FAIL"
        print(f"{flag:4s} {difference:9.2e}  {key}")
    print(f"{len(recorded.files)} images, largest relative difference {worst:.2e} "
          f"(tolerance {args.tolerance:g}), {failures} over")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
