#!/usr/bin/python3
"""A lamp over a table: a point light in an open shade, with things on the table.

    /usr/bin/python3 examples/lamp_over_table.py                # writes lamp_over_table.png
    /usr/bin/python3 examples/lamp_over_table.py -o out.png --size 1280 720
    /usr/bin/python3 examples/lamp_over_table.py --interactive  # needs a display

A point light (positional, cone angle 90 degrees or more) shines in every direction; the pass
shadows it with a cube shadow map. It scatters without being given: every switched-on spot and
point light of the renderer does. Offscreen rendering needs an X server; without a display run
it under `xvfb-run -a`.
"""

import argparse

import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="lamp_over_table.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.015)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    scenes.lamp_over_table(renderer)
    scenes.add_fill_light(renderer, 0.08)

    shafts = vtkLightShaftPass()  # automatic choice: the lamp
    shafts.GetMedium().SetScatteringCoefficient(0.06, 0.055, 0.05)
    shafts.GetMedium().SetAbsorptionCoefficient(0.01)
    shafts.SetExposure(30.0)
    shafts.SetQualityToFinal()
    shafts.ShadowSurfacesOn()  # the table's and the shade's shadows on the surfaces
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if not args.interactive:
        print(f"wrote {args.output}: {shafts.GetLastFrame().GetNumberOfSlicesDrawn()} slices, "
              f"light kind {shafts.GetLastFrame().GetLightKind(0)} (0 spot, 1 point, 2 directional)")


if __name__ == "__main__":
    main()
