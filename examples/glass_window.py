#!/usr/bin/python3
"""Coloured glass: shafts through a window of four translucent panes, tinted by each pane.

    /usr/bin/python3 examples/glass_window.py -o glass_window.png
    /usr/bin/python3 examples/glass_window.py --opacity 0.8     # deeper colours

The panes are ordinary props (vtkActor, opacity below 1, a colour each): the pass peels them in
each light's view and passes 1 - a (1 - c) of the light through a pane of opacity a and colour c
(docs/translucent-and-volumes.md), in the shafts and, with ShadowSurfaces, on the floor. Unlike a
cookie, the glass belongs to the scene: move the light or the panes and the colours follow.
Without a display, run it under `xvfb-run -a`.
"""

import argparse

import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (
    vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer)

from lightshafts import scenes, show_or_save, vtkLightShaftPass

# The window of scenes.window_room (wall at x = -3): its four openings, (y0, y1, z0, z1), and
# the colour of the glass in each.
PANES = [((1.5, 3.125, -1.5, -0.125), (0.95, 0.2, 0.15)),
         ((1.5, 3.125, 0.125, 1.5), (0.2, 0.4, 0.95)),
         ((3.375, 5.0, -1.5, -0.125), (0.95, 0.8, 0.15)),
         ((3.375, 5.0, 0.125, 1.5), (0.2, 0.85, 0.35))]


def add_glass(renderer, opacity):
    """A translucent pane in each opening of the window, at the wall's inner face."""
    for (y0, y1, z0, z1), colour in PANES:
        pane = vtkPlaneSource()
        pane.SetOrigin(-2.95, y0, z0)
        pane.SetPoint1(-2.95, y1, z0)
        pane.SetPoint2(-2.95, y0, z1)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(pane.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*colour)
        actor.GetProperty().SetOpacity(opacity)
        renderer.AddActor(actor)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="glass_window.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--opacity", type=float, default=0.7)
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
    add_glass(renderer, args.opacity)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.GetMedium().SetAbsorptionCoefficient(0.004)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.3)
    shafts.SetExposure(40.0)
    shafts.SetNumberOfSlices(192)
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()  # the glass tints the floor as it tints the shafts
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if args.interactive:
        return
    print(f"wrote {args.output} ({shafts.GetLastFrame().GetLightTranslucentLayers(0)} translucent layer(s), "
          f"{shafts.GetLastFrame().GetShaderVariant()})")


if __name__ == "__main__":
    main()
