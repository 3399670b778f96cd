"""Offscreen rendering helpers shared by the Python tests and the accuracy measurement."""

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import lightshaft_reference as ref


_shared_window = None


def make_window(width=320, height=240):
    """A fresh renderer in the session's one offscreen window.

    One window serves every test: Mesa 22's llvmpipe under Xvfb intermittently fails to open a
    new X display right after a window that rendered heavy shaders is destroyed (see README,
    Known issues), so the tests do not create and destroy windows one after another.
    """
    global _shared_window
    if _shared_window is None:
        _shared_window = vtkRenderWindow()
        _shared_window.SetOffScreenRendering(1)
        _shared_window.SetMultiSamples(0)
    window = _shared_window
    renderers = window.GetRenderers()
    while renderers.GetNumberOfItems() > 0:
        window.RemoveRenderer(renderers.GetFirstRenderer())
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    window.SetSize(width, height)
    return renderer, window


def in_scatter(shaft_pass):
    """The pass's last L_in as (height, width, 3), row 0 at the bottom."""
    image = vtkImageData()
    assert shaft_pass.GetInScatteredRadiance(image)
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3).astype(np.float64)


def screenshot(window):
    """The window's RGB pixels as (height, width, 3) uint8, row 0 at the bottom."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3).copy()


def reference_for(renderer, window, info, shaft_pass, panels=4):
    """The float64 reference L_in for a scenes.* scene as the pass is set up."""
    cam = renderer.GetActiveCamera()
    w, h = window.GetSize()
    camera = ref.Camera(cam.GetPosition(), cam.GetFocalPoint(), cam.GetViewUp(),
                        cam.GetViewAngle(), cam.GetClippingRange(), w, h)
    L = info.light
    light = ref.Spotlight(L.GetPosition(), L.GetFocalPoint(), L.GetConeAngle(), L.GetExponent(),
                          L.GetAttenuationValues(), L.GetIntensity(), L.GetDiffuseColor())
    medium = ref.Medium(shaft_pass.GetScatteringCoefficient(),
                        shaft_pass.GetAbsorptionCoefficient(), shaft_pass.GetPhaseFunction(),
                        shaft_pass.GetAnisotropy())
    scene = ref.Scene(spheres=info.spheres, floors=info.floors)
    return ref.in_scattered_radiance(camera, light, medium, scene, panels=panels)
