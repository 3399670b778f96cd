#include "vtkLightShaftShadowMap.h"

#include "vtkLightShaftCasterRender.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftGeometry.h"

#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"

#include <algorithm>

using vtkLightShaftModel::LightKind;
using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftShadowMap::vtkLightShaftShadowMap()
{
  this->CameraPass->SetDelegatePass(this->OpaquePass);
}

vtkLightShaftShadowMap::~vtkLightShaftShadowMap() = default;

vtkTextureObject* vtkLightShaftShadowMap::GetTexture()
{
  return this->Map.Object;
}

vtkTextureObject* vtkLightShaftShadowMap::GetEventTexture()
{
  return this->EventTexture;
}

//------------------------------------------------------------------------------
bool vtkLightShaftShadowMap::Signature::operator==(const Signature& other) const
{
  return this->Cameras == other.Cameras && this->Casters == other.Casters &&
         this->Range[0] == other.Range[0] && this->Range[1] == other.Range[1] &&
         this->Size == other.Size && this->TranslucentLayers == other.TranslucentLayers;
}

vtkLightShaftShadowMap::Signature vtkLightShaftShadowMap::Sign(vtkLightShaftFrame& frame,
  int size) const
{
  Signature signature;
  for (const vtkLightShaftGeometry::LightView& view : frame.Light.Views)
  {
    signature.Cameras.push_back(view.WorldToClip);
    for (vtkProp* caster : view.Casters)
    {
      signature.Casters.emplace_back(caster, caster->GetRedrawMTime());
    }
  }
  signature.Range[0] = frame.Light.Near;
  signature.Range[1] = frame.Light.Far;
  signature.Size = size;
  signature.TranslucentLayers = frame.Parameters.TranslucentLayers;
  return signature;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftShadowMap::Ready(vtkLightShaftFrame& frame)
{
  vtkLightShaftLightStatistics& stats = *frame.LightStatistics;
  frame.Translucency = nullptr;
  frame.TranslucentLayers = 0;
  if (!frame.Light.ShadowsPossible)
  {
    return nullptr; // nothing can shadow the light's volume
  }
  if (this->Valid && this->RenderedFrame == frame.Number)
  {
    this->PublishTranslucency(frame);
    return this->Map.Object; // already readied this frame
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  const bool cube = frame.Light.Model.Kind == LightKind::Point;
  const int maximum = vtkTextureObject::GetMaximumTextureSize(window) / (cube ? 3 : 1);
  const int size = std::max(1, std::min(frame.Parameters.ShadowMapSize, maximum));
  Signature signature = this->Sign(frame, size);
  bool reuse = this->Valid && this->Cube == cube && signature == this->Rendered;
  if (frame.Owner->HasObserver(vtkLightShaftEnums::ShadowMapRenderedEvent))
  {
    // The map's observers rewrite it (distributed processes combine theirs): it is rendered
    // again, unless an observer of ShadowMapReuseEvent agrees that it can be reused (every
    // process's map unchanged: the combined one the texture holds is still right).
    int agreed = reuse ? 1 : 0;
    const bool asked = frame.Owner->HasObserver(vtkLightShaftEnums::ShadowMapReuseEvent);
    if (asked)
    {
      frame.Owner->InvokeEvent(vtkLightShaftEnums::ShadowMapReuseEvent, &agreed);
    }
    reuse = asked && reuse && agreed == 1;
  }
  if (reuse)
  {
    stats.ShadowMapReused = true;
  }
  else
  {
    if (cube)
    {
      this->RenderCube(frame, size);
    }
    else
    {
      vtkTextureObject* map = this->Map.Ensure(window, TextureKind::Depth32F, size, size);
      this->SetCamera(frame.Light.Views[0]);
      this->RenderCasters(
        frame, frame.Light.Views[0].Casters, this->LightCamera, this->Framebuffer, map);
    }
    // Observers may read and rewrite the map now (distributed processes combine theirs).
    this->EventTexture = this->Map.Object;
    frame.Owner->InvokeEvent(vtkLightShaftEnums::ShadowMapRenderedEvent);
    this->EventTexture = nullptr;
    // The translucent casters in front of the (combined) opaque ones.
    this->TranslucentLayerCount = this->Translucent.Render(frame,
      this->Map.Object,
      cube,
      frame.Parameters.TranslucentLayers,
      [this, &frame](int v)
      {
        this->SetCamera(frame.Light.Views[v]);
        return this->LightCamera.Get();
      });
    stats.TranslucentLayersRendered = this->TranslucentLayerCount > 0;
    // (Signed again: the translucent step gives each of its props information keys the first
    // time, which moves their MTime, not what the map holds.)
    signature = this->Sign(frame, size);
    this->Rendered = std::move(signature);
    this->Cube = cube;
    this->Valid = true;
    this->WorldToLightClip = frame.Light.WorldToLightClip;
    stats.ShadowMapRendered = true;
  }
  this->RenderedFrame = frame.Number;
  stats.LightDepthRange[0] = frame.Light.Near;
  stats.LightDepthRange[1] = frame.Light.Far;
  stats.ShadowBias = this->GetBias(frame);
  this->PublishTranslucency(frame);
  return this->Map.Object;
}

//------------------------------------------------------------------------------
void vtkLightShaftShadowMap::PublishTranslucency(vtkLightShaftFrame& frame)
{
  const bool layers = this->TranslucentLayerCount > 0;
  frame.Translucency = layers ? this->Translucent.GetTexture() : nullptr;
  frame.TranslucentLayers = this->TranslucentLayerCount;
  frame.LightStatistics->TranslucentLayers = this->TranslucentLayerCount;
  frame.LightStatistics->TranslucentBytes = layers ? this->Translucent.GetBytes() : 0.0;
}

//------------------------------------------------------------------------------
// A point light's six faces, each rendered on its own and copied into its cell of the atlas
// (faces without casters stay cleared).
void vtkLightShaftShadowMap::RenderCube(vtkLightShaftFrame& frame, int size)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  vtkTextureObject* atlas = this->Map.Ensure(window, TextureKind::Depth32F, 3 * size, 2 * size);
  vtkOpenGLFramebufferObject* atlasTarget =
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window);
  vtkLightShaftResources::BindTargets(atlasTarget, {}, atlas, 3 * size, 2 * size);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  vtkTextureObject* face = this->Face.Ensure(window, TextureKind::Depth32F, size, size);
  for (int f = 0; f < 6; ++f)
  {
    vtkLightShaftGeometry::LightView& view = frame.Light.Views[f];
    if (view.Casters.empty())
    {
      continue;
    }
    this->SetCamera(view);
    this->RenderCasters(frame, view.Casters, this->LightCamera, this->FaceFramebuffer, face);
    const int x = (f % 3) * size;
    const int y = (f / 3) * size;
    ostate->PushFramebufferBindings();
    this->FaceFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    atlasTarget->Bind(GL_DRAW_FRAMEBUFFER);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglBlitFramebuffer(
      0, 0, size, size, x, y, x + size, y + size, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    ostate->PopFramebufferBindings();
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftShadowMap::SetCamera(const vtkLightShaftGeometry::LightView& view)
{
  vtkCamera* camera = this->LightCamera;
  camera->SetPosition(view.Position.x, view.Position.y, view.Position.z);
  camera->SetFocalPoint(view.FocalPoint.x, view.FocalPoint.y, view.FocalPoint.z);
  camera->SetViewUp(view.ViewUp.x, view.ViewUp.y, view.ViewUp.z);
  vtkNew<vtkMatrix4x4> projection;
  vtkLightShaftGeometry::ToVTKMatrix(view.Projection, projection);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);
}

//------------------------------------------------------------------------------
double vtkLightShaftShadowMap::GetBias(const vtkLightShaftFrame& frame)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  const int texels = static_cast<int>(this->Map.Object->GetHeight()) / (this->Cube ? 2 : 1);
  const double texel = light.MapExtent / std::max(texels, 1);
  if (light.Model.Kind == LightKind::Directional)
  {
    return 2.0 * texel + 1e-4 * (light.Far - light.Near);
  }
  return static_cast<float>(2.0 * texel + 1e-4);
}

//------------------------------------------------------------------------------
void vtkLightShaftShadowMap::RenderCasters(vtkLightShaftFrame& frame,
  std::vector<vtkProp*>& casters,
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

  // The opaque step of the casters with another camera, as vtkShadowMapBakerPass does.
  vtkLightShaftCasterRender::Render(frame, casters, camera, fbo, this->CameraPass);
}

//------------------------------------------------------------------------------
bool vtkLightShaftShadowMap::ReadBack(vtkOpenGLRenderWindow* window,
  vtkImageData* depths,
  vtkMatrix4x4* worldToLightClip)
{
  vtkTextureObject* map = this->Map.Object;
  if (!this->Valid || this->Cube || !window || !map || !this->Framebuffer)
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
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER); // still holds the map (RenderCasters)
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
  this->Face.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->FaceFramebuffer, window);
  this->Translucent.ReleaseGraphicsResources(window);
  this->TranslucentLayerCount = 0;
  this->Valid = false;
  this->RenderedFrame = -1;
}
