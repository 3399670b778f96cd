#!/usr/bin/python3
"""A stained-glass cookie: coloured shafts through a leaded window, and the same colours on the floor.

    /usr/bin/python3 examples/stained_glass.py -o stained_glass.png
    /usr/bin/python3 examples/stained_glass.py --cookie my_gobo.png   # any PNG/JPEG as the cookie

The cookie is projected from the spotlight through its cone (vtkLightShaftPass.SetCookie): it
colours the shafts and the pool of light it casts on the floor. Without a display, run it under
`xvfb-run -a`.
"""

import argparse

import numpy as np
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkImageReader2Factory
from vtkmodules.vtkRenderingCore import (
    vtkRenderWindow, vtkRenderer, vtkTexture)

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def stained_glass(size=256, panes=4):
    """A leaded window: panes x panes coloured diamonds, dark lead lines between them."""
    palette = np.array([[0.95, 0.25, 0.2], [0.2, 0.45, 0.95], [0.95, 0.8, 0.2],
                        [0.25, 0.8, 0.35], [0.7, 0.3, 0.85], [0.95, 0.55, 0.15]])
    y, x = np.mgrid[0:size, 0:size] / size * panes
    u, v = x + y, x - y  # diamond lattice
    cell = (np.floor(u).astype(int) * 7 + np.floor(v).astype(int) * 3) % len(palette)
    colour = palette[cell]
    lead = np.minimum(np.abs(u - np.round(u)), np.abs(v - np.round(v))) < 0.05
    frame = (np.minimum(x, panes - x) < 0.06) | (np.minimum(y, panes - y) < 0.06)
    colour[lead | frame] = 0.03
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    texels = (255 * colour).astype(np.uint8).reshape(-1, 3)
    image.GetPointData().SetScalars(numpy_to_vtk(texels, deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


def read_cookie(path):
    reader = vtkImageReader2Factory.CreateImageReader2(path)
    if reader is None:
        raise SystemExit(f"cannot read {path}")
    reader.SetFileName(path)
    texture = vtkTexture()
    texture.SetInputConnection(reader.GetOutputPort())
    return texture


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="stained_glass.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--cookie", help="an image file to use as the cookie")
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.02)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    info = scenes.window_room(renderer)
    info.light.SetColor(1.0, 1.0, 1.0)
    info.light.SetIntensity(1.6)
    scenes.add_fill_light(renderer, 0.1)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.GetMedium().SetAbsorptionCoefficient(0.004)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.3)
    shafts.SetExposure(40.0)
    shafts.SetNumberOfSlices(192)
    shafts.SetShadowMapSize(2048)
    shafts.SetCookie(read_cookie(args.cookie) if args.cookie else stained_glass())
    shafts.ShadowSurfacesOn()  # the window frame shadows the floor as it does the shafts
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if args.interactive:
        return
    print(f"wrote {args.output} ({shafts.GetLastFrame().GetShaderVariant()})")


if __name__ == "__main__":
    main()
