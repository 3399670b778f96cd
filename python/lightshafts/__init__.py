"""LightShafts: volumetric light shafts for VTK scenes.

    from lightshafts import vtkLightShaftPass
    renderer.SetPass(vtkLightShaftPass())
"""

# The wrapped classes derive from VTK's OpenGL render passes: load those modules first so the
# base classes are registered with VTK's Python wrapping.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingCore  # noqa: F401

from .vtkLightShafts import vtkLightShaftPass  # noqa: F401

__all__ = ["vtkLightShaftPass"]
