#include "vtkLightShaftTranslucentLayers.h"

#include "vtkLightShaftCasterRender.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftTranslucentPeel.h"

#include "vtkCameraPass.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftTranslucentLayers::vtkLightShaftTranslucentLayers()
{
  this->CameraPass->SetDelegatePass(this->Peel);
}

vtkLightShaftTranslucentLayers::~vtkLightShaftTranslucentLayers() = default;

//------------------------------------------------------------------------------
int vtkLightShaftTranslucentLayers::Render(vtkLightShaftFrame& frame,
  vtkTextureObject* opaque,
  bool cube,
  int maximumLayers,
  const CameraSetter& setCamera)
{
  this->Result = nullptr;
  this->UsedLayers = 0;
  // The translucent casters of each view (a prop with both parts renders its translucent one).
  std::vector<std::vector<vtkProp*>> casters(frame.Light.Views.size());
  bool any = false;
  for (size_t v = 0; v < casters.size(); ++v)
  {
    for (vtkProp* prop : frame.Light.Views[v].Casters)
    {
      if (prop->HasTranslucentPolygonalGeometry())
      {
        casters[v].push_back(prop);
        any = true;
      }
    }
  }
  if (!any)
  {
    return 0;
  }
  this->Peel->SetRule(vtkLightShaftTranslucentPeel::LIGHT);
  return this->PeelViews(frame, casters, opaque, cube, maximumLayers, setCamera);
}

//------------------------------------------------------------------------------
int vtkLightShaftTranslucentLayers::RenderCamera(vtkLightShaftFrame& frame,
  std::vector<vtkProp*> props,
  vtkTextureObject* opaque,
  int maximumLayers,
  vtkCamera* camera)
{
  this->Result = nullptr;
  this->UsedLayers = 0;
  if (props.empty())
  {
    // (Layers of an earlier frame are not kept for later ones.)
    for (auto& layer : this->Layers)
    {
      layer.Release(frame.Window);
    }
    this->Layers.clear();
    this->Atlas.Release(frame.Window);
    return 0;
  }
  std::vector<std::vector<vtkProp*>> views{ std::move(props) };
  this->Peel->SetRule(vtkLightShaftTranslucentPeel::CAMERA);
  return this->PeelViews(
    frame, views, opaque, false, maximumLayers, [camera](int) { return camera; });
}

//------------------------------------------------------------------------------
int vtkLightShaftTranslucentLayers::PeelViews(vtkLightShaftFrame& frame,
  std::vector<std::vector<vtkProp*>>& casters,
  vtkTextureObject* opaque,
  bool cube,
  int maximumLayers,
  const CameraSetter& setCamera)
{
  if (maximumLayers < 1 || !opaque)
  {
    return 0;
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  int size[2];
  const int most = vtkLightShaftTranslucentLayers::LayerSize(static_cast<int>(opaque->GetWidth()),
    static_cast<int>(opaque->GetHeight()),
    cube,
    maximumLayers,
    vtkTextureObject::GetMaximumTextureSize(window),
    size);
  const int width = size[0];
  const int height = size[1];
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  this->Opaque = opaque;
  if (static_cast<int>(this->Layers.size()) < most)
  {
    this->Layers.resize(most);
  }
  vtkOpenGLState* ostate = window->GetState();
  // (The caller's framebuffer is bound again after the peel, so that its targets can go.)
  ostate->PushFramebufferBindings();
  for (int k = 0; k < most; ++k)
  {
    // The layer starts empty: everything passes, nothing stored.
    vtkTextureObject* layer = this->Layers[k].Ensure(window, TextureKind::RGBA32F, width, height);
    vtkLightShaftResources::BindTargets(
      vtkLightShaftResources::EnsureFramebuffer(this->LayerFramebuffer, window),
      { layer },
      nullptr,
      width,
      height);
    ostate->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    bool surfaces = false;
    for (size_t v = 0; v < casters.size(); ++v)
    {
      if (casters[v].empty())
      {
        continue;
      }
      const int f = static_cast<int>(v);
      const float rect[4] = { cube ? (f % 3) / 3.0f : 0.0f,
        cube ? (f / 3) / 2.0f : 0.0f,
        cube ? 1.0f / 3.0f : 1.0f,
        cube ? 0.5f : 1.0f };
      surfaces = this->PeelFace(frame, casters[v], setCamera(f), k, rect) || surfaces;
    }
    if (!surfaces)
    {
      break;
    }
    this->UsedLayers = k + 1;
  }
  // Layers no longer needed (and the empty one that ended the peeling) are freed.
  for (size_t k = this->UsedLayers; k < this->Layers.size(); ++k)
  {
    this->Layers[k].Release(window);
  }
  this->Layers.resize(this->UsedLayers);
  if (this->UsedLayers > 0)
  {
    this->Assemble(frame, this->UsedLayers);
  }
  ostate->PopFramebufferBindings();
  // The peel's targets (one layer's face) are freed: the layers are kept until they change.
  vtkLightShaftResources::ReleaseFramebuffer(this->FaceFramebuffer, window);
  this->FaceColor.Release(window);
  this->FaceDepth.Release(window);
  return this->UsedLayers;
}

//------------------------------------------------------------------------------
int vtkLightShaftTranslucentLayers::LayerSize(int width,
  int height,
  bool cube,
  int maximumLayers,
  int maximumTexture,
  int size[2])
{
  const int most = std::max(1, std::min(maximumLayers, maximumTexture / std::max(width, 1)));
  const double bytes = vtkLightShaftTranslucentLayers::TexelBytes * most * width * height;
  const double scale =
    std::min(1.0, std::sqrt(vtkLightShaftTranslucentLayers::BudgetBytes / bytes));
  // Whole faces (a point light's 3 x 2), so that the layers' faces line up with the map's.
  const int across = cube ? 3 : 1;
  const int down = cube ? 2 : 1;
  size[0] = across * std::max(1, static_cast<int>(scale * (width / across)));
  size[1] = down * std::max(1, static_cast<int>(scale * (height / down)));
  return most;
}

//------------------------------------------------------------------------------
// One view's casters peeled behind layer `layer` - 1 into the face target, then copied into
// that view's rectangle of layer `layer`. Whether any surface was kept.
bool vtkLightShaftTranslucentLayers::PeelFace(vtkLightShaftFrame& frame,
  std::vector<vtkProp*>& casters,
  vtkCamera* camera,
  int layer,
  const float rect[4])
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int width = static_cast<int>(this->Layers[layer].Object->GetWidth());
  const int height = static_cast<int>(this->Layers[layer].Object->GetHeight());
  const int w = std::max(1, static_cast<int>(rect[2] * width + 0.5f));
  const int h = std::max(1, static_cast<int>(rect[3] * height + 0.5f));
  vtkTextureObject* color = this->FaceColor.Ensure(window, TextureKind::RGBA32F, w, h);
  vtkTextureObject* depth = this->FaceDepth.Ensure(window, TextureKind::Depth32F, w, h);
  vtkOpenGLFramebufferObject* face =
    vtkLightShaftResources::EnsureFramebuffer(this->FaceFramebuffer, window);
  vtkLightShaftResources::BindTargets(face, { color }, depth, w, h);

  this->Peel->SetOpaqueDepth(this->Opaque, rect);
  this->Peel->SetPreviousLayer(layer > 0 ? this->Layers[layer - 1].Object.Get() : nullptr, rect);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, this->Query);
  vtkLightShaftCasterRender::Render(frame, casters, camera, face, this->CameraPass);
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  GLuint passed = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &passed);
  if (!passed)
  {
    return false;
  }
  // Into the view's rectangle of the layer.
  const int x = static_cast<int>(rect[0] * width + 0.5f);
  const int y = static_cast<int>(rect[1] * height + 0.5f);
  ostate->PushFramebufferBindings();
  vtkLightShaftResources::BindTargets(
    this->LayerFramebuffer, { this->Layers[layer].Object }, nullptr, width, height);
  face->Bind(GL_READ_FRAMEBUFFER);
  face->ActivateReadBuffer(0);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglBlitFramebuffer(0, 0, w, h, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ostate->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
// The layers side by side in one texture (the one layer itself when there is one).
void vtkLightShaftTranslucentLayers::Assemble(vtkLightShaftFrame& frame, int layers)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  if (layers == 1)
  {
    this->Atlas.Release(window);
    this->Result = this->Layers[0].Object;
    return;
  }
  const int width = static_cast<int>(this->Layers[0].Object->GetWidth());
  const int height = static_cast<int>(this->Layers[0].Object->GetHeight());
  vtkTextureObject* atlas =
    this->Atlas.Ensure(window, TextureKind::RGBA32F, layers * width, height);
  vtkOpenGLState* ostate = window->GetState();
  // (The face's framebuffer reads each layer: it is set up again for the next peel.)
  vtkOpenGLFramebufferObject* source = this->FaceFramebuffer;
  for (int k = 0; k < layers; ++k)
  {
    ostate->PushFramebufferBindings();
    vtkLightShaftResources::BindTargets(source, { this->Layers[k].Object }, nullptr, width, height);
    vtkLightShaftResources::BindTargets(
      this->LayerFramebuffer, { atlas }, nullptr, layers * width, height);
    source->Bind(GL_READ_FRAMEBUFFER);
    source->ActivateReadBuffer(0);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglBlitFramebuffer(
      0, 0, width, height, k * width, 0, (k + 1) * width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    ostate->PopFramebufferBindings();
  }
  // The layers live on in the atlas only (half the memory; the next peel allocates them again).
  for (auto& layer : this->Layers)
  {
    layer.Release(window);
  }
  this->Result = atlas;
}

//------------------------------------------------------------------------------
double vtkLightShaftTranslucentLayers::GetBytes() const
{
  double bytes = 0.0;
  for (const auto& layer : this->Layers)
  {
    if (layer.Object)
    {
      bytes += vtkLightShaftTranslucentLayers::TexelBytes * layer.Object->GetWidth() *
               layer.Object->GetHeight();
    }
  }
  if (this->Atlas.Object)
  {
    bytes += vtkLightShaftTranslucentLayers::TexelBytes * this->Atlas.Object->GetWidth() *
             this->Atlas.Object->GetHeight();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkLightShaftTranslucentLayers::ReleaseGraphicsResources(vtkWindow* window)
{
  this->CameraPass->ReleaseGraphicsResources(window);
  this->Peel->ReleaseGraphicsResources(window);
  for (auto& layer : this->Layers)
  {
    layer.Release(window);
  }
  this->Layers.clear();
  this->Atlas.Release(window);
  this->FaceColor.Release(window);
  this->FaceDepth.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->FaceFramebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->LayerFramebuffer, window);
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  this->Opaque = nullptr;
  this->Result = nullptr;
  this->UsedLayers = 0;
}
