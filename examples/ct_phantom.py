#!/usr/bin/python3
"""Shafts through a CT-like volume: a spotlight through a 3D head phantom given as data.

    /usr/bin/python3 examples/ct_phantom.py                # writes ct_phantom.png
    /usr/bin/python3 examples/ct_phantom.py -o out.png --size 1280 720
    /usr/bin/python3 examples/ct_phantom.py --interactive  # needs a display

The volume is the 3D Shepp-Logan head phantom (Kak & Slaney's ellipsoids, the contrast of the
"modified" version), sampled on 96^3 points as a scanner would hand it over: a vtkImageData
with an "attenuation" array, turned by its direction matrix as a scan of a tilted head is.
vtkLightShaftPass::SetMediumDensity makes it the medium, in a faint haze: the light scatters in
the head as in a lamp-lit fog, and the shafts behind it carry its shadow, the skull's rim, the
brain's shade and the lighter ventricles. An outline shows the scan's box. RAY_MARCH renders a
medium from data. Offscreen rendering needs an X server; without a display run it under
`xvfb-run -a`.
"""

import argparse
import math

import numpy as np
import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL back end)
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkOutlineSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer)

from lightshafts import scenes, show_or_save, vtkLightShaftPass

SAMPLES = 96
HALF = 2.4                         # the scan's half-width, world units
CENTRE = np.array([0.0, 3.0, 0.0])
TILT_DEGREES = 20.0                # the head's tilt about the scan's x axis

# (value, semi-axes a b c, centre x y z, turn about z in degrees), in the unit cube's
# coordinates: the skull, the brain, the ventricles and the small features.
ELLIPSOIDS = [
    (1.0, (0.69, 0.92, 0.81), (0.0, 0.0, 0.0), 0.0),
    (-0.8, (0.6624, 0.874, 0.78), (0.0, -0.0184, 0.0), 0.0),
    (-0.2, (0.11, 0.31, 0.22), (0.22, 0.0, 0.0), -18.0),
    (-0.2, (0.16, 0.41, 0.28), (-0.22, 0.0, 0.0), 18.0),
    (0.1, (0.21, 0.25, 0.41), (0.0, 0.35, -0.15), 0.0),
    (0.1, (0.046, 0.046, 0.05), (0.0, 0.1, 0.25), 0.0),
    (0.1, (0.046, 0.046, 0.05), (0.0, -0.1, 0.25), 0.0),
    (0.1, (0.046, 0.023, 0.05), (-0.08, -0.605, 0.0), 0.0),
    (0.1, (0.023, 0.023, 0.02), (0.0, -0.606, 0.0), 0.0),
    (0.1, (0.023, 0.046, 0.02), (0.06, -0.605, 0.0), 0.0),
]


def phantom():
    """The phantom's attenuation on SAMPLES^3 points, as a tilted scan of the head."""
    u = np.linspace(-1.0, 1.0, SAMPLES)
    z, y, x = np.meshgrid(u, u, u, indexing="ij")  # x fastest when raveled
    values = np.zeros_like(x)
    for value, (a, b, c), (x0, y0, z0), turn in ELLIPSOIDS:
        co, si = math.cos(math.radians(turn)), math.sin(math.radians(turn))
        dx, dy, dz = x - x0, y - y0, z - z0
        xr, yr = co * dx + si * dy, -si * dx + co * dy
        values += value * (((xr / a) ** 2 + (yr / b) ** 2 + (dz / c) ** 2) <= 1.0)
    values = np.maximum(values, 0.0)  # (rounding at the rims)
    image = vtkImageData()
    image.SetDimensions(SAMPLES, SAMPLES, SAMPLES)
    spacing = 2.0 * HALF / (SAMPLES - 1)
    image.SetSpacing(spacing, spacing, spacing)
    co, si = math.cos(math.radians(TILT_DEGREES)), math.sin(math.radians(TILT_DEGREES))
    direction = np.array([[1.0, 0.0, 0.0], [0.0, co, -si], [0.0, si, co]])
    image.SetDirectionMatrix(*direction.ravel())
    image.SetOrigin(*(CENTRE - direction @ np.full(3, HALF)))
    array = numpy_to_vtk(values.ravel(), deep=True)
    array.SetName("attenuation")
    image.GetPointData().AddArray(array)
    return image


def add(renderer, source, color):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    renderer.AddActor(actor)
    return actor


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="ct_phantom.png")
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
    floor.SetOrigin(-7.0, 0.0, -7.0)
    floor.SetPoint1(-7.0, 0.0, 7.0)
    floor.SetPoint2(7.0, 0.0, -7.0)
    add(renderer, floor, (0.6, 0.6, 0.62))
    scan = phantom()
    outline = vtkOutlineSource()  # the scan's box, turned as the scan is
    outline.SetBoxTypeToOriented()
    corners = []
    for k in range(8):
        index = [(SAMPLES - 1) * ((k >> axis) & 1) for axis in range(3)]
        point = [0.0, 0.0, 0.0]
        scan.TransformIndexToPhysicalPoint(*index, point)
        corners.extend(point)
    outline.SetCorners(corners)
    add(renderer, outline, (0.35, 0.55, 0.8)).GetProperty().LightingOff()
    scenes.add_spotlight(renderer, (-8.0, 5.5, -1.0), (6.0, 1.5, 0.5), cone_angle=22.0,
                         color=(1.0, 0.95, 0.88))
    scenes.add_fill_light(renderer, 0.06)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(1.5, 4.0, 14.0)
    camera.SetFocalPoint(1.0, 2.8, 0.0)
    camera.SetViewAngle(40.0)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.25, 0.24, 0.22)
    shafts.GetMedium().SetAbsorptionCoefficient(0.1)
    shafts.GetMedium().SetDensityArrayName("attenuation")  # (first: the image has no scalars)
    shafts.GetMedium().SetDensityField(scan)
    shafts.GetMedium().SetDensityScale(6.0)
    shafts.GetMedium().SetBackgroundDensity(0.05)  # the haze the shafts show in
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetNumberOfSteps(192)
    shafts.SetExposure(45.0)
    renderer.SetPass(shafts)

    show_or_save(window, args.output, args.interactive)
    if not args.interactive:
        print(f"wrote {args.output}: RAY_MARCH {shafts.GetLastFrame().GetNumberOfSteps()} steps through "
              f"a {SAMPLES}^3 phantom (light leg: a "
              f"{shafts.GetLastFrame().GetLightFieldShadowBytes(0) / 2 ** 20:.1f} MiB table)")


if __name__ == "__main__":
    main()
