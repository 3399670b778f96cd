#!/usr/bin/python3
"""Sunlight through a window: a directional light (a sun) behind a wall with a four-pane window.

    /usr/bin/python3 examples/sun_through_window.py                # writes sun_through_window.png
    /usr/bin/python3 examples/sun_through_window.py -o out.png --size 1280 720
    /usr/bin/python3 examples/sun_through_window.py --interactive  # needs a display

A directional light lights the half-space beyond the plane through its Position (perpendicular
to its direction); the pass uses it because it is given (SetLight): VTK's default lights are
directional, so directional lights never scatter unless given. Offscreen rendering needs an X
server; without a display run it under `xvfb-run -a`.
"""

import argparse

import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="sun_through_window.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.02)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    info = scenes.sun_room(renderer)
    scenes.add_fill_light(renderer, 0.1)

    shafts = vtkLightShaftPass()
    shafts.SetLight(info.light)  # the sun
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.047, 0.043)  # per world unit
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.4)
    shafts.SetExposure(40.0)
    shafts.SetQualityToFinal()
    shafts.ShadowSurfacesOn()  # the floor shows the window's pattern too
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if not args.interactive:
        print(f"wrote {args.output}: {shafts.GetLastFrame().GetNumberOfSlicesDrawn()} slices, "
              f"light kind {shafts.GetLastFrame().GetLightKind(0)} (0 spot, 1 point, 2 directional)")


if __name__ == "__main__":
    main()
