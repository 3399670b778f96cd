#!/usr/bin/python3
"""What a still view's refined picture cannot get below, and what it is made of, measured.

    tools/measure.sh refinement-floor      # docs/refinement-floor.md (about 5 min)

Scene: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure 40)
at --size, RAY_MARCH with no interleaving and no blur. For each (shadow-map size, steps):
- one estimate (ProgressiveRefinement off): its relative RMS error against
  vtkLightShaftReference with exact visibility, and against the reference that looks visibility
  up in the pass's own shadow map (VisibilityMode SHADOW_MAP: the same map, so the difference is
  everything but the map); and the map's own share, the two references apart;
- the picture refined with --estimates estimates (the map's texel grid, the steps and the
  lookups shifted each estimate): its error against the exact reference.
Then where the floor lies in the picture: for the finest setting, the share of the squared
error held by the worst pixels, and the median ratio of pass to reference (a bias shows there).

Writes refinement-floor.md into --output-dir (and prints it).
"""

import argparse
import os
import platform
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass, vtkLightShaftReference  # noqa: E402

SETTINGS = [(1024, 64), (2048, 64), (4096, 64), (8192, 64), (4096, 16), (4096, 256),
            (4096, 1024)]


def map_reference(renderer, shafts, size):
    reference = vtkLightShaftReference()
    reference.SetRenderer(renderer)
    reference.SetLightShaftPass(shafts)
    reference.SetVisibilityModeToShadowMap()
    reference.Update()
    image = reference.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(
        size[1], size[0], 3).astype(np.float64)


def percent(a, b):
    return 100 * ref.relative_rms_error(a, b)[0]


def run(args):
    renderer, window, _, shafts = rh.window_scene(*args.size)
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetInterleaveSize(1)
    shafts.SetBlurRadius(0)
    shafts.SetRefinementFrames(args.estimates)
    renderer.SetPass(shafts)
    window.Render()
    exact = rh.scene_reference(renderer, shafts)
    rows = []
    for size, steps in progress.steps(SETTINGS, "settings"):
        shafts.SetShadowMapSize(size)
        shafts.SetNumberOfSteps(steps)
        shafts.ProgressiveRefinementOff()
        window.Render()
        one = rh.in_scatter(shafts)
        with_map = map_reference(renderer, shafts, args.size)
        shafts.ProgressiveRefinementOn()
        for _ in range(args.estimates):
            window.Render()
            if shafts.GetLastFrame().GetRefinementConverged():
                break
        refined = rh.in_scatter(shafts)
        rows.append((size, steps, percent(one, exact), percent(one, with_map),
                     percent(with_map, exact), shafts.GetLastFrame().GetRefinementEstimates(),
                     percent(refined, exact)))
    # Where the finest single estimate's error lies.
    shafts.ProgressiveRefinementOff()
    window.Render()
    finest = rh.in_scatter(shafts)
    lit = exact.max(axis=-1) > 0.01 * exact.max()
    squared = np.where(lit, ((finest - exact) ** 2).sum(axis=-1), 0.0)
    worst = np.sort(squared.ravel())[::-1]
    shares = [(q, worst[:int(q * lit.sum())].sum() / worst.sum()) for q in (0.001, 0.01, 0.05)]
    ratio = finest.sum(axis=-1)[lit] / exact.sum(axis=-1)[lit]
    return rows, shares, (np.median(ratio), np.percentile(ratio, 10), np.percentile(ratio, 90))


def table(args, rows, shares, ratio):
    command = "tools/measure.sh refinement-floor" + (
        " " + " ".join(sys.argv[1:]) if sys.argv[1:] else "")
    lines = [f"# What the refined picture's floor is made of ({args.size[0]}x{args.size[1]}, "
             "window scene)", "",
             f"{platform.node()}, {platform.processor() or platform.machine()}; command: "
             f"`{command}`.", "",
             "RAY_MARCH, no interleaving, no blur. Errors: relative RMS over the pixels above 1% "
             "of the reference's peak.", "",
             "| map | steps | one estimate vs exact | vs the reference in the pass's map | "
             "the map's own (references apart) | estimates | refined vs exact |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for size, steps, one, one_map, map_only, estimates, refined in rows:
        lines.append(f"| {size}² | {steps} | {one:.3f}% | {one_map:.3f}% | {map_only:.3f}% | "
                     f"{estimates} | {refined:.3f}% |")
    lines += ["", "Where the finest setting's error lies (one estimate, "
              f"{SETTINGS[-1][0]}² map, {SETTINGS[-1][1]} steps): " + ", ".join(
                  f"the worst {100 * q:g}% of the lit pixels hold {100 * s:.0f}% of the squared "
                  "error" for q, s in shares) +
              f"; pass over reference per pixel: median {ratio[0]:.5f}, 10th percentile "
              f"{ratio[1]:.4f}, 90th {ratio[2]:.4f}."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--size", type=int, nargs=2, default=(640, 360))
    parser.add_argument("--estimates", type=int, default=32)
    args = parser.parse_args()
    text = table(args, *run(args))
    print(text)
    if args.output_dir:
        with open(os.path.join(args.output_dir, "refinement-floor.md"), "w") as out:
            out.write(text + "\n")


if __name__ == "__main__":
    main()
