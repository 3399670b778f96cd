#!/usr/bin/python3
"""How far an exact in-scatter picture carried from one camera to the next is from the next
camera's own: the bound on reusing earlier frames by reprojecting the picture (issue 21, item 3).

    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" /usr/bin/python3 \
        tests/benchmarks/reprojection_bound.py --output docs/reprojection.md

Scene: the README picture's window scene (lightshafts.scenes.window_room, σ_s 0.05, exposure 40) at
--size. For each camera move (one frame of an interactor's path), the float64 reference
(vtkLightShaftReference: exact surfaces and shadows) at camera A is carried to camera B three
ways and compared with B's reference (relative RMS over the pixels above 1% of its peak):
- "through the surface": each pixel of B looks up A's picture (bilinear) where the surface
  point it sees was in A: what temporal reprojection of a screen-space picture does;
- "along the ray direction": where the pixel's direction was in A (the point at infinity):
  exact for a camera turning in place;
- "not moved": A's picture as it is.
There is no noise in these pictures: what remains is what reprojection itself adds per frame,
before any averaging. A history worth keeping must be closer than one fresh estimate (the
moving frames' error, docs/budget.md).
"""

import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402

MOVES = {
    "orbit: azimuth 0.5°": lambda camera, sign: camera.Azimuth(0.5 * sign),
    "orbit: elevation 0.5°": lambda camera, sign: camera.Elevation(0.5 * sign),
    "dolly 1%": lambda camera, sign: camera.Dolly(1.01 ** sign),
    "turn in place: yaw 0.5°": lambda camera, sign: camera.Yaw(0.5 * sign),
}


class View:
    """The window scene with the pass; the reference picture, depth and camera of a view."""

    def __init__(self, width, height):
        self.size = (width, height)
        self.renderer, self.window, _, self.shafts = rh.window_scene(width, height)
        self.renderer.SetPass(self.shafts)
        self.window.Render()

    def capture(self):
        """(reference picture, window depth, world-to-clip matrix) of the current camera."""
        w, h = self.size
        self.renderer.ResetCameraClippingRange()
        self.renderer.SetPass(None)
        self.window.Render()
        z = vtkFloatArray()
        self.window.GetZbufferData(0, 0, w - 1, h - 1, z)
        depth = vtk_to_numpy(z).reshape(h, w).astype(np.float64)
        self.renderer.SetPass(self.shafts)
        self.window.Render()
        m = self.renderer.GetActiveCamera().GetCompositeProjectionTransformMatrix(w / h, -1, 1)
        clip = np.array([[m.GetElement(i, j) for j in range(4)] for i in range(4)])
        return rh.scene_reference(self.renderer, self.shafts), depth, clip


def carry(picture, clip_from, depth_to, clip_to, through_surface):
    """`picture` (seen with clip_from) looked up for each pixel of the view (clip_to, depth_to):
    through the pixel's surface point, or along its direction."""
    h, w = depth_to.shape
    ys, xs = np.mgrid[0:h, 0:w]
    depth = depth_to if through_surface else np.full_like(depth_to, 1.0 - 1e-7)
    ndc = np.stack([(xs + 0.5) / w * 2 - 1, (ys + 0.5) / h * 2 - 1, depth * 2 - 1,
                    np.ones_like(depth)], -1).reshape(-1, 4)
    world = ndc @ np.linalg.inv(clip_to).T
    world /= world[:, 3:4]
    before = world @ clip_from.T
    position = (before[:, :2] / before[:, 3:4] * 0.5 + 0.5) * [w, h] - 0.5
    base = np.floor(position).astype(int)
    f = position - base
    out = np.zeros((w * h, 3))
    for dj in (0, 1):
        for di in (0, 1):
            x = np.clip(base[:, 0] + di, 0, w - 1)
            y = np.clip(base[:, 1] + dj, 0, h - 1)
            weight = (f[:, 0] if di else 1 - f[:, 0]) * (f[:, 1] if dj else 1 - f[:, 1])
            out += weight[:, None] * picture[y, x]
    return out.reshape(h, w, 3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, nargs=2, default=(1280, 720))
    parser.add_argument("--output", help="Markdown file to write")
    args = parser.parse_args()
    view = View(*args.size)
    camera = view.renderer.GetActiveCamera()
    rows = []
    for name, move in progress.steps(MOVES.items(), "moves", total=len(MOVES)):
        picture, _, clip_a = view.capture()
        move(camera, 1)
        camera.OrthogonalizeViewUp()
        expected, depth_b, clip_b = view.capture()
        errors = [ref.relative_rms_error(carry(picture, clip_a, depth_b, clip_b, surface),
                                         expected)[0] for surface in (True, False)]
        errors.append(ref.relative_rms_error(picture, expected)[0])
        rows.append(f"| {name} | " + " | ".join(f"{100 * e:.2f}%" for e in errors) + " |")
        print(rows[-1], flush=True)
        move(camera, -1)
        camera.OrthogonalizeViewUp()
    w, h = args.size
    text = "\n".join([
        "# Reprojecting the in-scatter picture: what one frame's move costs",
        "",
        f"Window scene at {w}x{h}; float64 references (vtkLightShaftReference) before and "
        "after one move, the first carried to the second. Relative RMS against the second "
        "(pixels above 1% of its peak). Command: "
        "`tools/measure.sh reprojection` (tests/benchmarks/reprojection_bound.py).",
        "",
        "| move | through the surface | along the ray direction | not moved |",
        "|---|---:|---:|---:|",
        *rows, ""])
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
