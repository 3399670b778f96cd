/**
 * @file   vtkLightShaftOpenGL.h
 * @brief  The OpenGL API, through the loader of the VTK the pass is built against (private, not
 *         installed).
 *
 * VTK up to 9.3 loads OpenGL with GLEW (VTK::glew, vtk_glew.h); VTK 9.4 replaced it with glad
 * (VTK::glad, vtk_glad.h), which also lets VTK choose X, EGL or OSMesa at run time. The modules
 * list both as optional dependencies (plugin/vtk.module, paraview/plugin/module/vtk.module), and
 * VTK's module system defines VTK_MODULE_ENABLE_VTK_glad to 1 when VTK has glad: the one place
 * where the pass's sources choose between them.
 */

#ifndef vtkLightShaftOpenGL_h
#define vtkLightShaftOpenGL_h

#if VTK_MODULE_ENABLE_VTK_glad
#include "vtk_glad.h" // For the OpenGL API (VTK >= 9.4)
#else
#include "vtk_glew.h" // For the OpenGL API (VTK <= 9.3)
#endif

#endif
