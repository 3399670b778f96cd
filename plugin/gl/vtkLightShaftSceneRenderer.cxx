#include "vtkLightShaftSceneRenderer.h"

#include "vtkLightShaftFrame.h"

#include "vtkCameraPass.h"
#include "vtkFXAAOptions.h"
#include "vtkImageProcessingPass.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkLightShaftRendererStep.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftDepthResolveFS.h"

#include <algorithm>
#include <vector>

using vtkLightShaftResources::TextureKind;

namespace
{
// The scene's colour, with and without a light: float while the surface light is taken from them
// (vtkLightShaftSceneImage::HighRange), else as the window's.
TextureKind ColorKind(const vtkLightShaftSceneImage& scene)
{
  return scene.HighRange ? TextureKind::RGBA32F : TextureKind::RGBA8;
}
}

//------------------------------------------------------------------------------
vtkLightShaftSceneRenderer::vtkLightShaftSceneRenderer()
{
  // VTK's default steps, with each step drawn as the renderer draws it.
  this->DefaultOpaque->SetStage(vtkLightShaftRendererStep::OPAQUE);
  this->DefaultTranslucent->SetStage(vtkLightShaftRendererStep::TRANSLUCENT);
  this->DefaultVolumes->SetStage(vtkLightShaftRendererStep::VOLUMETRIC, this->DefaultTranslucent);
  this->DefaultDelegate->SetOpaquePass(this->DefaultOpaque);
  this->DefaultDelegate->SetTranslucentPass(this->DefaultTranslucent);
  this->DefaultDelegate->SetVolumetricPass(this->DefaultVolumes);
}

vtkLightShaftSceneRenderer::~vtkLightShaftSceneRenderer() = default;

//------------------------------------------------------------------------------
bool vtkLightShaftSceneRenderer::NeedsPlainScene(const vtkRenderState* s)
{
  if (s->GetRenderer()->GetSelector() != nullptr || s->GetRequiredKeys() != nullptr)
  {
    return true;
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkInformation* keys = s->GetPropArray()[i]->GetPropertyKeys();
    if (keys && keys->Length(vtkOpenGLRenderPass::RenderPasses()) > 0)
    {
      return true;
    }
  }
  GLint drawBuffer = GL_NONE;
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
  return drawBuffer == GL_NONE;
}

//------------------------------------------------------------------------------
int vtkLightShaftSceneRenderer::RenderPlain(vtkRenderPass* pass,
  vtkRenderPass* userDelegate,
  const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  if (ren->GetSelector() && ren->GetPass() == pass)
  {
    vtkSmartPointer<vtkRenderPass> keep = pass; // the renderer may hold the only reference
    ren->SetPass(nullptr);
    ren->DeviceRender();
    ren->SetPass(pass);
    return ren->GetNumberOfPropsRendered();
  }
  // Nested in another pass: what that pass would have drawn without this one.
  vtkRenderPass* delegate =
    userDelegate ? userDelegate : static_cast<vtkRenderPass*>(this->DefaultDelegate);
  delegate->Render(s);
  return delegate->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkLightShaftSceneRenderer::ChooseDelegate(vtkRenderPass* userDelegate)
{
  return userDelegate ? userDelegate : static_cast<vtkRenderPass*>(this->DefaultDelegate);
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneRenderer::RenderUnchanged(vtkLightShaftFrame& frame, vtkRenderPass* delegate)
{
  delegate->Render(frame.State);
  frame.Statistics.RenderedProps += delegate->GetNumberOfRenderedProps();
  frame.Statistics.SceneRenders = 1;
}

//------------------------------------------------------------------------------
namespace
{
// The first vtkRenderStepsPass in `pass`, through the passes that render the scene with a
// delegate or a sequence.
vtkRenderStepsPass* FindSceneSteps(vtkRenderPass* pass, int depth = 0)
{
  if (!pass || depth > 16)
  {
    return nullptr;
  }
  if (auto* steps = vtkRenderStepsPass::SafeDownCast(pass))
  {
    return steps;
  }
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    return FindSceneSteps(camera->GetDelegatePass(), depth + 1);
  }
  if (auto* processing = vtkImageProcessingPass::SafeDownCast(pass))
  {
    return FindSceneSteps(processing->GetDelegatePass(), depth + 1);
  }
  if (auto* sequence = vtkSequencePass::SafeDownCast(pass))
  {
    vtkRenderPassCollection* passes = sequence->GetPasses();
    if (!passes)
    {
      return nullptr;
    }
    vtkCollectionSimpleIterator it;
    passes->InitTraversal(it);
    while (vtkRenderPass* item = passes->GetNextRenderPass(it))
    {
      if (vtkRenderStepsPass* steps = FindSceneSteps(item, depth + 1))
      {
        return steps;
      }
    }
  }
  return nullptr;
}
}

void vtkLightShaftSceneRenderer::HoldOverlay(vtkRenderPass* delegate)
{
  this->OverlayOwner = FindSceneSteps(delegate);
  this->HeldOverlay = this->OverlayOwner ? this->OverlayOwner->GetOverlayPass() : nullptr;
  if (this->HeldOverlay)
  {
    this->OverlayOwner->SetOverlayPass(nullptr);
  }
}

void vtkLightShaftSceneRenderer::FinishFrame(vtkLightShaftFrame& frame)
{
  if (this->HeldOverlay)
  {
    this->OverlayOwner->SetOverlayPass(this->HeldOverlay);
  }
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(frame.Renderer);
  GLint samples = 0; // of the target: FXAA copies it into a texture, which needs one sample
  glGetIntegerv(GL_SAMPLES, &samples);
  if (renderer && renderer->GetUseFXAA() && samples <= 1)
  {
    if (!this->FXAA)
    {
      this->FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    }
    if (vtkFXAAOptions* options = renderer->GetFXAAOptions())
    {
      this->FXAA->UpdateConfiguration(options);
    }
    this->FXAA->Execute(renderer);
    frame.Statistics.RendererFXAA = true;
  }
  if (this->HeldOverlay)
  {
    // 2D overlays after compositing: on top, unfogged; in the renderer's viewport, as its
    // steps would have drawn them (the pass's own draws changed it).
    vtkOpenGLState* ostate = frame.Window->GetState();
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    ostate->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
    ostate->vtkglScissor(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
    this->HeldOverlay->Render(frame.State);
    frame.Statistics.RenderedProps += this->HeldOverlay->GetNumberOfRenderedProps();
  }
  this->OverlayOwner = nullptr;
  this->HeldOverlay = nullptr;
}

//------------------------------------------------------------------------------
// The delegate's render of the frame's props into `color` and `depth` (cleared).
void vtkLightShaftSceneRenderer::RenderInto(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  vtkTextureObject* color,
  vtkTextureObject* depth)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkOpenGLFramebufferObject* fbo =
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window);
  vtkLightShaftResources::BindTargets(fbo, { color }, depth, frame.Size[0], frame.Size[1]);
  vtkRenderState sceneState(frame.Renderer);
  sceneState.SetPropArrayAndCount(frame.State->GetPropArray(), frame.State->GetPropArrayCount());
  sceneState.SetFrameBuffer(fbo);
  // Renderers that do not erase (layers) would otherwise see the previous frame.
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  delegate->Render(&sceneState);
  frame.Statistics.RenderedProps += delegate->GetNumberOfRenderedProps();
  ++frame.Statistics.SceneRenders;
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneRenderer::Render(vtkLightShaftFrame& frame, vtkRenderPass* delegate)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const int samples = frame.Scene.Samples;
  vtkLightShaftSceneImage& scene = frame.Scene;
  scene.Color = this->Color.Ensure(window, ColorKind(scene), w, h, samples);
  scene.Depth = this->Depth.Ensure(window, TextureKind::Depth, w, h, samples);
  this->RenderInto(frame, delegate, scene.Color, scene.Depth);
  // The composite copies the depth from the framebuffer holding the scene.
  vtkLightShaftResources::BindTargets(this->Framebuffer, { scene.Color }, scene.Depth, w, h);
  scene.Framebuffer = this->Framebuffer;
  scene.ShaftDepth = samples > 0 ? this->ResolveDepth(frame, scene.Depth) : scene.Depth;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftSceneRenderer::RenderWithout(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  vtkLight* light)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const int samples = frame.Scene.Samples;
  vtkTextureObject* unlit = this->ColorUnlit.Ensure(window, ColorKind(frame.Scene), w, h, samples);
  vtkTextureObject* depth = this->DepthUnlit.Ensure(window, TextureKind::Depth, w, h, samples);
  const double intensity = light->GetIntensity();
  light->SetIntensity(0.0);
  this->RenderInto(frame, delegate, unlit, depth);
  light->SetIntensity(intensity);
  // The scene's framebuffer holds the scene again (the composite copies its depth).
  vtkLightShaftResources::BindTargets(
    this->Framebuffer, { frame.Scene.Color }, frame.Scene.Depth, w, h);
  return unlit;
}

//------------------------------------------------------------------------------
// The multisampled depth's nearest sample per pixel, into a single-sample depth texture.
vtkTextureObject* vtkLightShaftSceneRenderer::ResolveDepth(vtkLightShaftFrame& frame,
  vtkTextureObject* depthSamples)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  vtkTextureObject* resolved = this->ResolvedDepth.Ensure(window, TextureKind::Depth, w, h);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->ResolveFramebuffer, window),
    {},
    resolved,
    w,
    h);
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  if (vtkShaderProgram* program = this->DepthResolve.Ready(window, vtkLightShaftDepthResolveFS))
  {
    depthSamples->Activate();
    program->SetUniformi("sceneDepthSamples", depthSamples->GetTextureUnit());
    program->SetUniformi("sampleCount", frame.Scene.Samples);
    this->DepthResolve.Render();
    depthSamples->Deactivate();
  }
  else
  {
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }
  return resolved;
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneRenderer::ReleaseGraphicsResources(vtkWindow* window)
{
  this->DefaultDelegate->ReleaseGraphicsResources(window);
  if (this->FXAA)
  {
    this->FXAA->ReleaseGraphicsResources();
  }
  for (auto* texture :
    { &this->Color, &this->ColorUnlit, &this->Depth, &this->DepthUnlit, &this->ResolvedDepth })
  {
    texture->Release(window);
  }
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->ResolveFramebuffer, window);
  this->DepthResolve.Release(window);
}
