#!/usr/bin/python3
"""Light shafts through a window: a spotlight behind a wall with a four-pane window.

    /usr/bin/python3 examples/window_shafts.py                 # writes window_shafts.png
    /usr/bin/python3 examples/window_shafts.py -o out.png --size 1280 720 --slices 256
    /usr/bin/python3 examples/window_shafts.py --interactive   # needs a display

Offscreen rendering needs an X server; without a display run it under `xvfb-run -a`.
"""

import argparse

import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.vtkRenderingCore import (
    vtkRenderWindow, vtkRenderer)

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="window_shafts.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--slices", type=int, default=192)
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.02)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    scenes.window_room(renderer)
    scenes.add_fill_light(renderer, 0.12)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.047, 0.043)  # per world unit
    shafts.GetMedium().SetAbsorptionCoefficient(0.005)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.3)
    shafts.SetExposure(45.0)
    shafts.SetNumberOfSlices(args.slices)
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()  # the floor shows the window's pattern too
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if args.interactive:
        return
    print(f"wrote {args.output}: {shafts.GetLastFrame().GetNumberOfSlicesDrawn()} slices, "
          f"shadow map {'rendered' if shafts.GetLastFrame().GetShadowMapRendered() else 'skipped'}")


if __name__ == "__main__":
    main()
