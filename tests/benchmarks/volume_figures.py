#!/usr/bin/python3
"""The figures of docs/translucent-and-volumes.md's camera leg and volumes, measured against the
float64 reference on the scenes of tests/python/test_camera_leg.py and test_volumes.py.

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/volume_figures.py

Prints, per case, the in-scatter's ratio to the scene's without the pane or volume (the pass's
and the reference's, over the pixels the case names) and the pass's relative RMS error against
the reference over the image.
"""

import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import test_camera_leg as leg  # noqa: E402
import test_volumes as vol  # noqa: E402


def ratios(case, with_, without, mask):
    (image, expected, _), (clear, clear_ref) = with_, without
    error, _ = ref.relative_rms_error(image, expected)
    measured = image[mask].sum(axis=0) / clear[mask].sum(axis=0)
    reference = expected[mask].sum(axis=0) / clear_ref[mask].sum(axis=0)
    print(f"| {case} | {np.round(measured, 4)} | {np.round(reference, 4)} | {error:.3%} |",
          flush=True)


def main():
    print("| case | pass: ratio | reference: ratio | pass vs reference (RMS) |")
    print("|---|---|---|---|")
    covered = np.zeros((leg.HEIGHT, leg.WIDTH), dtype=bool)
    covered[:, : leg.WIDTH // 2 - 8] = True
    for kind in progress.steps(leg.KINDS, "camera-leg cases"):
        (a, ea, _), (b, eb, _) = leg.measured(kind, [(9.0, leg.BLACK, 0.5)])
        ratios(f"black pane 0.5, {kind}", (a, ea, None), (b, eb),
               covered & vol.lit(eb))
    for kind in progress.steps(["vertical"] + vol.KINDS, "volume cases"):
        if kind in ("spot", "point"):
            def build(renderer):
                vol.add_slab(renderer, low=(-6.0, 4.0, -6.0), high=(6.0, 4.4, 6.0))
        else:
            build = vol.add_slab
        with_, without = vol.measured(kind, build)
        mask = vol.lit(without[1])
        if kind == "vertical":
            mask &= np.all(np.abs(with_[1] / np.maximum(without[1], 1e-300) - vol.SLAB) < 1e-6,
                           axis=-1)
        ratios(f"slab 0.5^0.4, {kind}" + (" (below it)" if kind == "vertical" else ""),
               with_, without, mask)


if __name__ == "__main__":
    main()
