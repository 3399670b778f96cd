#include "vtkLightShaftCasterRender.h"

#include "vtkLightShaftFrame.h"

#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVersionMacros.h"

//------------------------------------------------------------------------------
void vtkLightShaftCasterRender::Render(vtkLightShaftFrame& frame,
  std::vector<vtkProp*>& casters,
  vtkCamera* camera,
  vtkOpenGLFramebufferObject* target,
  vtkCameraPass* pass)
{
  vtkRenderer* ren = frame.Renderer;
  vtkRenderState casterState(ren);
  casterState.SetPropArrayAndCount(casters.data(), static_cast<int>(casters.size()));
  casterState.SetFrameBuffer(target);
  vtkSmartPointer<vtkCamera> sceneCamera = ren->GetActiveCamera();
  if (camera == sceneCamera)
  {
    // The scene's own view (the camera leg's translucent layers): nothing to swap or restore.
    pass->Render(&casterState);
    return;
  }
  const vtkTypeBool automaticLights = ren->GetAutomaticLightCreation();
  ren->SetAutomaticLightCreation(false);
  ren->SetActiveCamera(camera);
  pass->Render(&casterState);
  ren->SetActiveCamera(sceneCamera);
  ren->SetAutomaticLightCreation(automaticLights);
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  // The casters' step set the shaders' lighting uniforms in the other camera's frame and
  // stamped them with its MTime; vtkOpenGLRenderer::UpdateLightingUniforms only sets them again
  // when the active camera (or the lights) changed after that stamp. Seen with VTK 9.2
  // (ParaView 5.11): a still scene camera kept the light camera's lighting from the second
  // frame on.
  sceneCamera->Modified();
#endif
}
