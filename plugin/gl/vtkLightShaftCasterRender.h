/**
 * @file   vtkLightShaftCasterRender.h
 * @brief  Rendering shadow casters from another camera (private, not installed): what the
 *         shadow map and the translucent casters' layers both do.
 */
#ifndef vtkLightShaftCasterRender_h
#define vtkLightShaftCasterRender_h

#include <vector> // For the casters

class vtkCamera;
class vtkCameraPass;
class vtkOpenGLFramebufferObject;
class vtkProp;
struct vtkLightShaftFrame;

namespace vtkLightShaftCasterRender
{
/**
 * Render `pass` (a camera pass over one of VTK's steps) over `casters` into `target`, seen by
 * `camera` (the scene's camera and automatic light creation are restored after).
 */
void Render(vtkLightShaftFrame& frame,
  std::vector<vtkProp*>& casters,
  vtkCamera* camera,
  vtkOpenGLFramebufferObject* target,
  vtkCameraPass* pass);
}

#endif
