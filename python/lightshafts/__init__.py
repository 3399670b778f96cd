"""LightShafts: volumetric light shafts for VTK scenes.

    from lightshafts import vtkLightShaftPass
    renderer.SetPass(vtkLightShaftPass())
"""

# The wrapped classes derive from VTK's OpenGL render passes: load those modules first so the
# base classes are registered with VTK's Python wrapping.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingCore  # noqa: F401

from .vtkLightShafts import (  # noqa: F401
    vtkLightShaftFetchFloor, vtkLightShaftPass, vtkLightShaftReference)

__all__ = ["vtkLightShaftPass", "vtkLightShaftReference", "vtkLightShaftFetchFloor", "write_png",
           "show_or_save"]


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


def show_or_save(window, output=None, interactive=False):
    """Open an interactive window (needs a display), or render offscreen and write `output`."""
    if interactive:
        import vtkmodules.vtkInteractionStyle  # noqa: F401  (the default interactor style)
        from vtkmodules.vtkRenderingCore import vtkRenderWindowInteractor

        interactor = vtkRenderWindowInteractor()
        interactor.SetRenderWindow(window)
        window.Render()
        interactor.Start()
        return
    window.SetOffScreenRendering(1)
    window.Render()
    if output:
        write_png(window, output)
