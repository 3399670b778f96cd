#!/usr/bin/python3
"""A still view's refinement through a medium from data: the light leg's table refined (or the
leg marched) where the error model finds its term too large, measured on
field_error_model.py's random scenes.

    tools/measure.sh field-still          # seed 11, scenes 17 12 3 5 (docs/medium-field.md)

For each scene (random_scenes.py's scene and field_error_model.py's random field, at --size):
ProgressiveRefinement on, the setting --setting (a name of the ladder's, M256 i1 m2048 by
default), one frame from another camera position, then --frames frames of the still view; each
frame's in-scatter against the float64 reference, the light leg's table's bytes (0: marched)
and the frame's time.
"""

import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, HERE)

import numpy as np  # noqa: E402

import field_error_model as fem  # noqa: E402
import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import random_scenes as rs  # noqa: E402
import render_helpers as rh  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402


def measure(seed, index, setting, size, frames):
    scene = rs.draw_scene(seed, index, 0, size[1], size=size)
    rng = np.random.default_rng([seed, index, 99])
    renderer, window = rh.make_window(*size)
    light = rs.build(renderer, scene)
    window.Render()
    kind, image = fem.random_field(rng, renderer.ComputeVisiblePropBounds())
    params = dict(fem.SETTINGS)[setting]
    shafts = vtkLightShaftPass()
    rs.configure(shafts, scene, light, params)
    shafts.GetMedium().SetDensityField(image)
    reference = rs.reference_image(renderer, shafts)
    shafts.ProgressiveRefinementOn()
    renderer.SetPass(shafts)
    camera = renderer.GetActiveCamera()
    camera.Azimuth(1.0)
    window.Render()
    camera.Azimuth(-1.0)  # the moving frame arrives where the reference saw the scene
    print(f"scene {index} ({kind}, {scene.light_kind} light), {setting}:")
    for k in range(frames + 1):
        start = time.perf_counter()
        window.Render()
        seconds = time.perf_counter() - start
        error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
        frame = shafts.GetLastFrame()
        print(f"  {'moving' if k == 0 else f'still {k}':8s} {1000 * seconds:6.0f} ms  error "
              f"{100 * error:6.3f}%  predicted {100 * frame.GetPredictedError():6.2f}%  table "
              f"{frame.GetLightFieldShadowBytes(0) / 2 ** 20:5.1f} MiB  estimates "
              f"{frame.GetRefinementEstimates()}", flush=True)
    renderer.SetPass(None)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--scenes", type=int, nargs="+", default=[17, 12, 3, 5])
    parser.add_argument("--setting", default="M256 i1 m2048")
    parser.add_argument("--size", type=int, nargs=2, default=(240, 180))
    parser.add_argument("--frames", type=int, default=4)
    args = parser.parse_args()
    for index in progress.steps(args.scenes, "scenes"):
        measure(args.seed, index, args.setting, args.size, args.frames)


if __name__ == "__main__":
    main()
