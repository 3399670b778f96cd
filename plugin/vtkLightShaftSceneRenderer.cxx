#include "vtkLightShaftSceneRenderer.h"

#include "vtkLightShaftFrame.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkLightShaftDepthResolveFS.h"

#include <algorithm>
#include <functional>
#include <vector>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftSceneRenderer::vtkLightShaftSceneRenderer()
{
  // Shadowed opaque step: bake the lights' shadow maps, then render the opaque props with them.
  vtkNew<vtkRenderPassCollection> shadowedOpaque;
  shadowedOpaque->AddItem(this->SurfaceShadows->GetShadowMapBakerPass());
  shadowedOpaque->AddItem(this->SurfaceShadows);
  vtkNew<vtkSequencePass> shadowedSequence;
  shadowedSequence->SetPasses(shadowedOpaque);
  this->ShadowedDelegate->SetOpaquePass(shadowedSequence);
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
vtkRenderPass* vtkLightShaftSceneRenderer::ChooseDelegate(vtkRenderPass* userDelegate,
  bool shadowSurfaces,
  int shadowMapSize,
  vtkOpenGLRenderWindow* window)
{
  if (userDelegate)
  {
    return userDelegate;
  }
  if (shadowSurfaces)
  {
    // VTK's baker does not check the size against the GL's limit: the pass does.
    this->SurfaceShadows->GetShadowMapBakerPass()->SetResolution(
      std::min(shadowMapSize, vtkTextureObject::GetMaximumTextureSize(window)));
    return this->ShadowedDelegate;
  }
  return this->DefaultDelegate;
}

//------------------------------------------------------------------------------
// VTK 9.1's shadow-map baker gives its light cameras the renderer's aspect ratio, so on a
// non-square viewport the surface shadows come out squeezed. Its cameras persist between
// frames: pin their aspect to the square shadow map's. Returns true when a camera had to be
// fixed (its shadow map, baked this frame, was wrong).
bool vtkLightShaftSceneRenderer::FixSurfaceShadowCameras()
{
  bool fixed = false;
  if (auto* cameras = this->SurfaceShadows->GetShadowMapBakerPass()->GetLightCameras())
  {
    for (auto& camera : *cameras)
    {
      if (camera &&
          (!camera->GetUseExplicitAspectRatio() || camera->GetExplicitAspectRatio() != 1.0))
      {
        camera->SetExplicitAspectRatio(1.0);
        camera->SetUseExplicitAspectRatio(true);
        fixed = true;
      }
    }
  }
  return fixed;
}

//------------------------------------------------------------------------------
// Render `delegate` with state `s` (`prepare` before each render); with the shadowed delegate,
// make sure its shadow maps were baked with square cameras (re-render once when they were not).
void vtkLightShaftSceneRenderer::RenderDelegate(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  const vtkRenderState* s,
  const std::function<void()>& prepare)
{
  const bool shadowed = delegate == this->ShadowedDelegate.Get();
  if (shadowed)
  {
    this->FixSurfaceShadowCameras();
  }
  prepare();
  delegate->Render(s);
  if (shadowed && this->FixSurfaceShadowCameras())
  {
    frame.Renderer->GetLights()->Modified(); // make the baker bake again
    prepare();
    delegate->Render(s);
  }
  frame.Statistics.RenderedProps += delegate->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneRenderer::RenderUnchanged(vtkLightShaftFrame& frame, vtkRenderPass* delegate)
{
  this->RenderDelegate(frame, delegate, frame.State, []() {});
  frame.Statistics.SceneRenders = 1;
}

//------------------------------------------------------------------------------
vtkRenderPass* vtkLightShaftSceneRenderer::HoldOverlay(vtkRenderPass* delegate)
{
  this->OverlayOwner = vtkRenderStepsPass::SafeDownCast(delegate);
  this->HeldOverlay = this->OverlayOwner ? this->OverlayOwner->GetOverlayPass() : nullptr;
  if (this->HeldOverlay)
  {
    this->OverlayOwner->SetOverlayPass(nullptr);
  }
  return this->HeldOverlay;
}

void vtkLightShaftSceneRenderer::RestoreOverlay()
{
  if (this->HeldOverlay)
  {
    this->OverlayOwner->SetOverlayPass(this->HeldOverlay);
  }
  this->OverlayOwner = nullptr;
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneRenderer::Render(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  vtkLight* light,
  bool twice)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const int samples = frame.Scene.Samples;
  vtkLightShaftSceneImage& scene = frame.Scene;
  scene.Color = this->Color.Ensure(window, TextureKind::RGBA8, w, h, samples);
  scene.Depth = this->Depth.Ensure(window, TextureKind::Depth, w, h, samples);
  scene.ColorUnlit =
    twice ? this->ColorUnlit.Ensure(window, TextureKind::RGBA8, w, h, samples) : nullptr;

  vtkOpenGLFramebufferObject* fbo =
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window);
  scene.Framebuffer = fbo;
  vtkRenderState sceneState(frame.Renderer);
  sceneState.SetPropArrayAndCount(frame.State->GetPropArray(), frame.State->GetPropArrayCount());
  sceneState.SetFrameBuffer(fbo);
  auto renderInto = [&](vtkTextureObject* target)
  {
    vtkLightShaftResources::BindTargets(fbo, { target }, scene.Depth, w, h);
    // Renderers that do not erase (layers) would otherwise see the previous frame.
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClearDepth(1.0);
    this->RenderDelegate(frame,
      delegate,
      &sceneState,
      [&]()
      {
        ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        ostate->vtkglEnable(GL_DEPTH_TEST);
      });
    ++frame.Statistics.SceneRenders;
  };
  if (twice)
  {
    // Without the spotlight: the composite puts its light back through the cookie. (Zero
    // intensity rather than switching it off: with no light on, VTK would add a headlight.)
    const double intensity = light->GetIntensity();
    light->SetIntensity(0.0);
    renderInto(scene.ColorUnlit);
    light->SetIntensity(intensity);
  }
  renderInto(scene.Color);
  scene.ShaftDepth = samples > 0 ? this->ResolveDepth(frame, scene.Depth) : scene.Depth;
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
  this->ShadowedDelegate->ReleaseGraphicsResources(window);
  for (auto* texture : { &this->Color, &this->ColorUnlit, &this->Depth, &this->ResolvedDepth })
  {
    texture->Release(window);
  }
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->ResolveFramebuffer, window);
  this->DepthResolve.Release(window);
}
