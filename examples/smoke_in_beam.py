#!/usr/bin/python3
"""Smoke in a beam: a volume-rendered puff and a tinted pane in a spotlight's shafts.

    /usr/bin/python3 examples/smoke_in_beam.py -o smoke_in_beam.png
    /usr/bin/python3 examples/smoke_in_beam.py --as-medium     # the smoke scatters the light
    /usr/bin/python3 examples/smoke_in_beam.py --no-pane

The puff is an ordinary vtkVolume (a GPU ray-cast mapper, a colour and an opacity transfer
function): the pass dims the shafts behind it as VTK composites the volume over them, and the
light that crosses it by its opacity (its shadow in the beam). The pane in front of the beam is
a translucent vtkActor: the shafts seen through it are dimmed by 1 - opacity, as the floor
behind it is. With --as-medium the volume is the medium (vtkLightShaftMedium.SetDensityVolume):
its opacity transfer function is the density that scatters the light
(docs/translucent-and-volumes.md). Without a display, run it under `xvfb-run -a`.
"""

import argparse

import numpy as np
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (
    vtkActor, vtkColorTransferFunction, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer,
    vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper

from lightshafts import scenes, show_or_save, vtkLightShaftPass


def smoke_image(n=48, seed=7):
    """A puff of smoke: a lumpy Gaussian over [-1.6, 1.6] x [1.6, 4.0] x [-1.2, 1.2]."""
    rng = np.random.default_rng(seed)
    x = np.linspace(-1.6, 1.6, n)
    y = np.linspace(1.6, 4.0, n)
    z = np.linspace(-1.2, 1.2, n)
    zz, yy, xx = np.meshgrid(z, y, x, indexing="ij")
    density = np.zeros_like(xx)
    for _ in range(9):  # a few blobs make it lumpy
        c = rng.uniform([-0.8, 2.3, -0.5], [0.8, 3.3, 0.5])
        r = rng.uniform(0.35, 0.7)
        density += np.exp(-((xx - c[0]) ** 2 + (yy - c[1]) ** 2 + (zz - c[2]) ** 2) / r ** 2)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(x[0], y[0], z[0])
    image.SetSpacing(x[1] - x[0], y[1] - y[0], z[1] - z[0])
    scalars = numpy_to_vtk((density / density.max()).ravel().astype(np.float32), deep=True)
    scalars.SetName("smoke")
    image.GetPointData().SetScalars(scalars)
    return image


def add_smoke(renderer):
    mapper = vtkGPUVolumeRayCastMapper()
    mapper.SetInputData(smoke_image())
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.15, 0.0)
    opacity.AddPoint(1.0, 0.8)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, 0.8, 0.55, 0.35)
    colour.AddRGBPoint(1.0, 1.0, 0.9, 0.7)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(0.3)
    prop.SetInterpolationTypeToLinear()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    return volume


def add_pane(renderer):
    """A blue-grey pane between the camera and the beam, over the left of the view."""
    pane = vtkPlaneSource()
    pane.SetOrigin(-4.0, 0.0, 6.0)
    pane.SetPoint1(-0.6, 0.0, 6.0)
    pane.SetPoint2(-4.0, 5.0, 6.0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(pane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.35, 0.45, 0.6)
    actor.GetProperty().SetOpacity(0.5)
    renderer.AddActor(actor)
    return actor


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="smoke_in_beam.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--as-medium", action="store_true",
                        help="the smoke is the medium: it scatters the light")
    parser.add_argument("--no-pane", action="store_true")
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.02)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    renderer.RemoveActor(info.actors[0])  # the smoke takes the sphere's place
    info.light.SetPosition(0.6, 7.0, 0.0)
    info.light.SetConeAngle(24.0)
    info.light.SetIntensity(1.5)
    scenes.add_fill_light(renderer, 0.15)
    renderer.GetActiveCamera().SetPosition(0.0, 3.2, 10.0)
    renderer.GetActiveCamera().SetFocalPoint(0.0, 2.2, 0.0)
    renderer.ResetCameraClippingRange()
    smoke = add_smoke(renderer)
    if not args.no_pane:
        add_pane(renderer)

    shafts = vtkLightShaftPass()
    shafts.SetLight(info.light)
    medium = shafts.GetMedium()
    if args.as_medium:
        medium.SetDensityVolume(smoke)
        medium.SetScatteringCoefficient(0.6)
        medium.SetAbsorptionCoefficient(0.05)
        medium.SetBackgroundDensity(0.05)
        shafts.SetExposure(6.0)
    else:
        medium.SetScatteringCoefficient(0.06)
        medium.SetAbsorptionCoefficient(0.005)
        shafts.SetExposure(12.0)
    shafts.SetQualityToFinal()
    shafts.ShadowSurfacesOn()  # the smoke's shadow on the floor too
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)


if __name__ == "__main__":
    main()
