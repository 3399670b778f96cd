"""The figures of docs/any-scene.md's clipping range and medium-from-the-scene entries, on the
README's sphere scene (tests/python/test_any_scene.readme_scene): the one-liner with no
coefficients at scales 0.01, 1 and 100 (the coefficient and exposure chosen, the in-scatter's
relative RMS difference from scale 1, the shafts' peak over the picture without them), and the
picture with the far plane moved (max and mean difference, in 8-bit levels).

    tools/measure.sh any-scene
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))

import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
import test_any_scene as scenes  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scales", type=float, nargs="+", default=[0.01, 1.0, 100.0],
                        help="scene scales (the first 1 is the one compared against)")
    args = parser.parse_args()
    plain = scenes.readme_scene_plain()
    results = {}
    for scale in progress.steps(args.scales, "scales"):
        renderer, window, shafts = scenes.readme_scene(scale)
        window.Render()
        results[scale] = (rh.in_scatter(shafts), shafts.GetMedium().GetScatteringCoefficient()[0],
                          shafts.GetExposure(), rh.screenshot(window).astype(int))
    unit = results.get(1.0, next(iter(results.values())))
    print("| scale | sigma_s chosen | exposure chosen | in-scatter vs scale 1 (rel. RMS) |")
    print("|---:|---:|---:|---:|")
    for scale, (in_scatter, sigma, exposure, _) in results.items():
        error, _ = rh.ref.relative_rms_error(in_scatter, unit[0])
        print(f"| {scale:g} | {sigma:.6g} | {exposure:.4g} | {error:.4%} |")
    print(f"shafts' peak over the picture without them: {np.clip(unit[3] - plain, 0, None).max()}"
          f" levels")

    renderer, window, shafts = scenes.readme_scene(ScatteringCoefficient=0.05, Exposure=40)
    camera = renderer.GetActiveCamera()
    near, far = camera.GetClippingRange()
    window.Render()
    reference = rh.screenshot(window).astype(int)
    print(f"backdrop {shafts.GetLastFrame().GetBackdropDepth():.2f}; VTK's far plane {far:.2f}")
    for far_plane in (10.0 * far, 1000.0):
        camera.SetClippingRange(near, far_plane)
        window.Render()
        difference = np.abs(rh.screenshot(window).astype(int) - reference)
        print(f"far plane {far_plane:.1f}: max {difference.max()}, mean {difference.mean():.4f}"
              f" levels")


if __name__ == "__main__":
    main()
