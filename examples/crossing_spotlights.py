#!/usr/bin/python3
"""Two coloured spotlights crossing over a stage, with pillars and a ball in their beams.

    /usr/bin/python3 examples/crossing_spotlights.py                # writes crossing_spotlights.png
    /usr/bin/python3 examples/crossing_spotlights.py -o out.png --size 1280 720
    /usr/bin/python3 examples/crossing_spotlights.py --interactive  # needs a display

Both spots scatter (the pass's automatic choice: every switched-on spot and point light); their
in-scatter adds up in one target, each light with its own shadow map. Offscreen rendering needs
an X server; without a display run it under `xvfb-run -a`.
"""

import argparse

import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="crossing_spotlights.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.005, 0.005, 0.01)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    scenes.crossing_spotlights(renderer)
    scenes.add_fill_light(renderer, 0.06)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.25)
    shafts.SetExposure(35.0)
    shafts.SetQualityToFinal()
    shafts.ShadowSurfacesOn()
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if not args.interactive:
        times = ", ".join(f"{shafts.GetLastFrame().GetLightTime(i):.1f}"
                          for i in range(shafts.GetLastFrame().GetNumberOfUsedLights()))
        print(f"wrote {args.output}: {shafts.GetLastFrame().GetNumberOfUsedLights()} lights, "
              f"GPU ms per light {times}")


if __name__ == "__main__":
    main()
