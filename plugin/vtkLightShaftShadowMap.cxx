#include "vtkLightShaftShadowMap.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftGeometry.h"

#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

//------------------------------------------------------------------------------
vtkLightShaftShadowMap::vtkLightShaftShadowMap()
{
  this->CameraPass->SetDelegatePass(this->OpaquePass);
}

vtkLightShaftShadowMap::~vtkLightShaftShadowMap() = default;

vtkCamera* vtkLightShaftShadowMap::GetLightCamera()
{
  return this->LightCamera;
}

vtkTextureObject* vtkLightShaftShadowMap::GetTexture()
{
  return this->Map.Object;
}

vtkTextureObject* vtkLightShaftShadowMap::GetEventTexture()
{
  return this->EventTexture;
}

//------------------------------------------------------------------------------
bool vtkLightShaftShadowMap::Render(vtkLightShaftFrame& frame, unsigned long eventId)
{
  if (!frame.Light.ShadowsPossible)
  {
    return false; // nothing can shadow the light's volume
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  const int size =
    std::min(frame.Parameters.ShadowMapSize, vtkTextureObject::GetMaximumTextureSize(window));
  vtkTextureObject* map =
    this->Map.Ensure(window, vtkLightShaftResources::TextureKind::Depth32F, size, size);
  this->RenderCasters(frame, this->LightCamera, this->Framebuffer, map);

  // Observers may read and rewrite the map now (distributed processes combine theirs).
  this->EventTexture = map;
  frame.Owner->InvokeEvent(eventId);
  this->EventTexture = nullptr;

  this->Valid = true;
  this->WorldToLightClip = frame.Light.WorldToLightClip;
  frame.Statistics.ShadowMapRendered = true;
  frame.Statistics.LightDepthRange[0] = frame.Light.Near;
  frame.Statistics.LightDepthRange[1] = frame.Light.Far;
  frame.Statistics.ShadowBias = this->GetBias(frame);
  return true;
}

//------------------------------------------------------------------------------
double vtkLightShaftShadowMap::GetBias(const vtkLightShaftFrame& frame)
{
  const double texelAngle = 2.0 * frame.Light.BoundsVC.Tangent / this->Map.Object->GetWidth();
  return static_cast<float>(2.0 * texelAngle + 1e-4);
}

//------------------------------------------------------------------------------
void vtkLightShaftShadowMap::RenderCasters(vtkLightShaftFrame& frame,
  vtkCamera* camera,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& target,
  vtkTextureObject* depth)
{
  // A depth-only target, cleared, with the depth test of an opaque step.
  vtkOpenGLFramebufferObject* fbo = vtkLightShaftResources::EnsureFramebuffer(target, frame.Window);
  vtkLightShaftResources::BindTargets(
    fbo, {}, depth, static_cast<int>(depth->GetWidth()), static_cast<int>(depth->GetHeight()));
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);

  vtkRenderer* ren = frame.Renderer;
  std::vector<vtkProp*>& casters = frame.Light.Casters;
  vtkRenderState casterState(ren);
  casterState.SetPropArrayAndCount(casters.data(), static_cast<int>(casters.size()));
  casterState.SetFrameBuffer(fbo);

  // Render the opaque step of the casters with another camera, as vtkShadowMapBakerPass does.
  vtkSmartPointer<vtkCamera> sceneCamera = ren->GetActiveCamera();
  const vtkTypeBool automaticLights = ren->GetAutomaticLightCreation();
  ren->SetAutomaticLightCreation(false);
  ren->SetActiveCamera(camera);
  this->CameraPass->Render(&casterState);
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

//------------------------------------------------------------------------------
bool vtkLightShaftShadowMap::ReadBack(vtkOpenGLRenderWindow* window,
  vtkImageData* depths,
  vtkMatrix4x4* worldToLightClip)
{
  vtkTextureObject* map = this->Map.Object;
  if (!this->Valid || !window || !map || !this->Framebuffer)
  {
    return false;
  }
  const int size = static_cast<int>(map->GetWidth());
  depths->Initialize();
  depths->SetDimensions(size, size, 1);
  vtkNew<vtkFloatArray> values;
  values->SetName("Depth");
  values->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  window->MakeCurrent();
  vtkOpenGLState* ostate = window->GetState();
  ostate->PushFramebufferBindings();
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, values->GetPointer(0));
  ostate->PopFramebufferBindings();
  depths->GetPointData()->SetScalars(values);
  vtkLightShaftGeometry::ToVTKMatrix(this->WorldToLightClip, worldToLightClip);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftShadowMap::ReleaseGraphicsResources(vtkWindow* window)
{
  this->CameraPass->ReleaseGraphicsResources(window);
  this->Map.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  this->Valid = false;
}
