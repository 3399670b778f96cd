#!/usr/bin/python3
"""Shafts through a smoke plume: a spotlight through a density field from data.

    /usr/bin/python3 examples/smoke_plume.py                # writes smoke_plume.png
    /usr/bin/python3 examples/smoke_plume.py -o out.png --size 1280 720
    /usr/bin/python3 examples/smoke_plume.py --interactive  # needs a display

The plume is a vtkImageData of 64^3 samples, made here as a simulation would hand it over: a
column of smoke rising from the floor and widening, its density modulated by VTK's wavelet
(vtkRTAnalyticSource). vtkLightShaftPass::SetMediumDensity makes it the medium (on top of a
faint haze everywhere, MediumBackgroundDensity): the light scatters where the smoke is, the
smoke shadows the light beyond it, and a ball in the beam shadows both. RAY_MARCH renders a
medium from data. Offscreen rendering needs an X server; without a display run it under
`xvfb-run -a`.
"""

import argparse

import numpy as np
import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer)

from lightshafts import scenes, show_or_save, vtkLightShaftPass

SAMPLES = 64
LOW = np.array([-3.0, 0.0, -3.0])   # the plume's box, world units
HIGH = np.array([3.0, 8.0, 3.0])


def plume():
    """The plume's density (mean about 1 in its core) on SAMPLES^3 points over LOW..HIGH."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(0, SAMPLES - 1, 0, SAMPLES - 1, 0, SAMPLES - 1)
    wavelet.SetCenter(SAMPLES / 2, SAMPLES / 2, SAMPLES / 2)
    wavelet.Update()
    turbulence = vtk_to_numpy(wavelet.GetOutput().GetPointData().GetScalars())
    turbulence = turbulence.reshape(SAMPLES, SAMPLES, SAMPLES)  # (z, y, x)
    turbulence = (turbulence - turbulence.min()) / np.ptp(turbulence)
    axis = [np.linspace(LOW[k], HIGH[k], SAMPLES) for k in range(3)]
    z, y, x = np.meshgrid(axis[2], axis[1], axis[0], indexing="ij")
    drift = 0.08 * y * y          # the column leans as it rises
    width = 0.35 + 0.22 * y       # and widens
    radius2 = (x - drift) ** 2 + z ** 2
    column = np.exp(-radius2 / (2.0 * width ** 2)) * np.exp(-0.12 * y)
    density = column * (0.4 + 1.2 * turbulence)
    image = vtkImageData()
    image.SetDimensions(SAMPLES, SAMPLES, SAMPLES)
    image.SetOrigin(*LOW)
    image.SetSpacing(*((HIGH - LOW) / (SAMPLES - 1)))
    values = numpy_to_vtk(density.ravel(), deep=True)
    values.SetName("smoke")
    image.GetPointData().SetScalars(values)
    return image


def add(renderer, source, color):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    renderer.AddActor(actor)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="smoke_plume.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.015)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    floor = vtkPlaneSource()
    floor.SetOrigin(-8.0, 0.0, -8.0)
    floor.SetPoint1(-8.0, 0.0, 8.0)
    floor.SetPoint2(8.0, 0.0, -8.0)
    add(renderer, floor, (0.7, 0.68, 0.65))
    ball = vtkSphereSource()
    ball.SetCenter(-1.6, 4.2, 0.6)
    ball.SetRadius(0.6)
    ball.SetThetaResolution(48)
    ball.SetPhiResolution(48)
    add(renderer, ball, (0.8, 0.45, 0.3))
    scenes.add_spotlight(renderer, (-4.5, 9.0, 1.5), (0.5, 1.0, 0.0), cone_angle=24.0,
                         color=(1.0, 0.95, 0.85))
    scenes.add_fill_light(renderer, 0.08)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.5, 4.0, 15.0)
    camera.SetFocalPoint(0.0, 3.2, 0.0)
    camera.SetViewAngle(38.0)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.3, 0.28, 0.26)
    shafts.GetMedium().SetAbsorptionCoefficient(0.05)
    shafts.GetMedium().SetDensityField(plume())
    shafts.GetMedium().SetDensityScale(3.0)
    shafts.GetMedium().SetBackgroundDensity(0.08)  # the haze around the plume
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetNumberOfSteps(128)
    shafts.SetExposure(25.0)
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if not args.interactive:
        print(f"wrote {args.output}: RAY_MARCH {shafts.GetLastFrame().GetNumberOfSteps()} steps through "
              f"a {SAMPLES}^3 density field")


if __name__ == "__main__":
    main()
