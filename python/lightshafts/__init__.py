"""LightShafts: volumetric light shafts for VTK scenes.

    from lightshafts import vtkLightShaftPass
    renderer.SetPass(vtkLightShaftPass())
"""

# The wrapped classes derive from VTK's OpenGL render passes: load those modules first so the
# base classes are registered with VTK's Python wrapping.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingCore  # noqa: F401

from .vtkLightShafts import vtkLightShaftPass, vtkLightShaftReference  # noqa: F401

__all__ = ["vtkLightShaftPass", "vtkLightShaftReference", "write_png"]


def write_png(window, filename):
    """Write what `window` rendered last (its back buffer) to a PNG file."""
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(str(filename))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
