"""No setting stalls a frame: the README's sphere scene with four spotlights at each method's
sampling maxima (SLICES: 4096 slices, lattice 256; RAY_MARCH: 4096 steps; EPIPOLAR: 2048 lines
x 2048 samples, 4096 steps; RADIAL_BLUR 1024 samples; and LIGHT_VOLUME 1024, not split), 4096²
shadow maps, no budget, ProgressiveRefinement on with one group of estimates
(RefinementFrames 1; the scene and pass of tests/python/test_responsive.py):

- the whole setting in one frame (SplitLongFrames off): its time and its in-scatter;
- the same setting split among frames (SplitLongFrames on, the default): every frame's time
  (the first, after the change, and the rest), the number of shares, and the in-scatter once
  refinement has added them up, against the whole frame's (relative RMS, pixels above 1% of
  the peak), with the default filters and without them (BlurRadius 0, InterleaveSize 1).

    tools/measure.sh frame-bound [--size 640 480] [--lights 4] [--methods slices ray-march ...]
                                 [--reference]
"""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
import test_responsive as slow  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402

MAXIMA = dict(slow.MAXIMA, **{
    "radial-blur": dict(Method=vtkLightShaftPass.RADIAL_BLUR, RadialSamples=1024),
    # Not split: beyond its allowance a refining view's frame draws a coarser mesh (four
    # spotlights' 1024^2 fit at 640x480).
    "light-volume": dict(Method=vtkLightShaftPass.LIGHT_VOLUME, LightVolumeResolution=1024),
})


def configured(renderer, params, split, filters=True):
    return slow.refining_pass(renderer, params, split, shadow_map=4096, filters=filters)


def change(shafts):
    """A change, as a slider's: the medium set again (a new modification time, the same values),
    so that the next frame computes the setting again."""
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.0301)
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)


def timed_render(window):
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return time.perf_counter() - start


def measure(renderer, window, params, filters=True, reference=None):
    """(the whole frame's time, the split frames' times, shares, relative RMS, and against
    `reference` (when given) the whole frame's and the refined picture's relative RMS)."""
    shafts = configured(renderer, params, split=False, filters=filters)
    timed_render(window)  # (the first frame readies shaders and maps)
    change(shafts)
    whole_time = timed_render(window)
    whole = rh.in_scatter(shafts)
    shafts = configured(renderer, params, split=True, filters=filters)
    timed_render(window)  # (shaders readied)
    change(shafts)
    times = []
    for _ in range(256):
        times.append(timed_render(window))
        if shafts.GetLastFrame().GetRefinementConverged():
            break
    split = shafts.GetLastFrame().GetRefinementSplit()
    print("  frames (s):", " ".join(f"{t:.2f}" for t in times), file=sys.stderr)
    refined = rh.in_scatter(shafts)
    error, _ = ref.relative_rms_error(refined, whole)
    against = None
    if reference is not None:
        against = (ref.relative_rms_error(whole, reference)[0],
                   ref.relative_rms_error(refined, reference)[0])
    renderer.SetPass(None)
    return whole_time, times, split, error, against


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, nargs=2, default=(640, 480))
    parser.add_argument("--methods", nargs="+", default=list(MAXIMA), choices=list(MAXIMA))
    parser.add_argument("--lights", type=int, default=4)
    parser.add_argument("--reference", action="store_true",
                        help="also the whole frame's and the refined picture's error against "
                             "the float64 reference (minutes)")
    args = parser.parse_args()
    renderer, window = slow.spotlights_scene(*args.size, lights=args.lights,
                                             sphere_resolution=256)
    reference = None
    if args.reference:
        shafts = configured(renderer, {}, split=False)
        window.Render()
        reference = rh.scene_reference(renderer, shafts)
        renderer.SetPass(None)
    width, height = args.size
    print(f"sphere scene, {args.lights} spotlights, {width}x{height}, 4096² shadow map")
    print("| setting | whole frame (s) | split into | slowest split frame (s) | "
          "refined vs whole | the same without filters |")
    print("|---|---:|---:|---:|---:|---:|")
    for name in progress.steps(args.methods, "methods"):
        params = MAXIMA[name]
        whole_time, times, split, error, against = measure(renderer, window, params,
                                                           reference=reference)
        plain = measure(renderer, window, params, filters=False) if split > 1 else None
        setting = ", ".join(f"{k} {v}" for k, v in params.items() if k != "Method")
        unfiltered = f"{100 * plain[3]:.3f}%" if plain else "(not split)"
        print(f"| {name}: {setting} | {whole_time:.2f} | {split} | {max(times):.2f} | "
              f"{100 * error:.3f}% | {unfiltered} |", flush=True)
        if against:
            print(f"  against the reference: the whole frame {100 * against[0]:.3f}%, "
                  f"refined {100 * against[1]:.3f}%", flush=True)


if __name__ == "__main__":
    main()
