#include "vtkLightShaftRadialBlurMethod.h"

#include "vtkLightShaftAnalyticMethod.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"
#include "vtkLightShaftShaders.h"
#include "vtkLightShaftShadowMap.h"

#include "vtkCamera.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkMath.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftOcclusionFS.h"
#include "vtkLightShaftRadialBlurFS.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftRadialBlurMethod::vtkLightShaftRadialBlurMethod(
  vtkLightShaftAnalyticMethod& unshadowed)
  : Unshadowed(unshadowed)
{
}

vtkLightShaftRadialBlurMethod::~vtkLightShaftRadialBlurMethod() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftRadialBlurMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  vtkTextureObject* unshadowed =
    this->Unshadowed.RenderUnshadowed(frame, lit, target, this->GetName());
  // Nothing reaches into the light's volume: nothing to blur, the unshadowed integral is exact.
  if (!unshadowed || !frame.Light.ShadowsPossible || frame.Parameters.Weight <= 0.0)
  {
    return unshadowed;
  }

  float lightUV[2];
  double fade = 1.0;
  if (!LightOnScreen(frame, lightUV, fade))
  {
    return unshadowed;
  }
  const double guard = this->GuardBand(frame);
  vtkTextureObject* occlusion = this->RenderOcclusion(frame, target.GetDepth(), guard);
  if (!occlusion)
  {
    return unshadowed;
  }
  return this->Blur(frame, unshadowed, occlusion, lightUV, fade, guard);
}

//------------------------------------------------------------------------------
// Where the light projects (texture coordinates, clamped far outside the screen: the walk is
// cut at the screen's edge anyway), and how much to trust it: the blur fades out as the light
// nears the camera plane (its projection runs off to infinity, then mirrors behind the camera).
// A directional light projects where its direction's vanishing point is (perspective), or far
// along its direction across the screen (parallel). False when there is no blur to do.
bool vtkLightShaftRadialBlurMethod::LightOnScreen(const vtkLightShaftFrame& frame,
  float lightUV[2],
  double& fade)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  const bool directional = light.Model.Kind == vtkLightShaftModel::LightKind::Directional;
  const glm::dvec3& lightVC = light.PositionVC;
  glm::dvec4 lightClip = frame.Camera.ViewToClip *
                         (directional ? glm::dvec4(-light.AxisVC, 0.0) : glm::dvec4(lightVC, 1.0));
  fade = 1.0;
  if (frame.Camera.Perspective)
  {
    const double inFront =
      directional ? light.AxisVC.z : -lightVC.z / std::max(glm::length(lightVC), 1e-30);
    fade = vtkMath::ClampValue(inFront / 0.1, 0.0, 1.0);
  }
  else if (directional)
  {
    // Parallel rays on the screen: the light lies at infinity along its screen direction.
    const glm::dvec2 across = glm::dvec2(lightClip);
    if (glm::length(across) < 1e-9)
    {
      return false;
    }
    lightClip = glm::dvec4(1e6 * glm::normalize(across), 0.0, 1.0);
  }
  if (fade <= 0.0 || !(std::abs(lightClip.w) > 0.0))
  {
    return false;
  }
  for (int i = 0; i < 2; ++i)
  {
    lightUV[i] =
      static_cast<float>(vtkMath::ClampValue(0.5 * lightClip[i] / lightClip.w + 0.5, -1e6, 1e6));
  }
  return true;
}

//------------------------------------------------------------------------------
// The occlusion buffer's extent relative to the screen: RadialGuardBand, except 1 for cameras
// with an explicit projection or an off-centre window, and kept below a 178-degree view.
double vtkLightShaftRadialBlurMethod::GuardBand(const vtkLightShaftFrame& frame)
{
  vtkCamera* sceneCamera = frame.Renderer->GetActiveCamera();
  double guard = frame.Parameters.RadialGuardBand;
  const double* windowCenter = sceneCamera->GetWindowCenter();
  if (sceneCamera->GetUseExplicitProjectionTransformMatrix() || windowCenter[0] != 0.0 ||
      windowCenter[1] != 0.0 || sceneCamera->GetUseOffAxisProjection())
  {
    guard = 1.0;
  }
  const double halfAngleTangent =
    std::tan(vtkMath::RadiansFromDegrees(sceneCamera->GetViewAngle()) / 2.0);
  if (frame.Camera.Perspective && halfAngleTangent * guard > 57.0)
  {
    guard = std::max(1.0, 57.0 / halfAngleTangent);
  }
  return guard;
}

//------------------------------------------------------------------------------
// Occlusion pre-pass at half the in-scatter resolution, over a guard band `guard` times the
// screen's extent: the casters' depth is rendered again with the scene camera's frustum widened
// about its axis (same view, projection scaled by 1 / g in x and y), so that occluders off the
// screen still cut the shafts on it.
vtkTextureObject* vtkLightShaftRadialBlurMethod::RenderOcclusion(vtkLightShaftFrame& frame,
  vtkTextureObject* depth,
  double guard)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const int mw = std::max(1, static_cast<int>(std::lround(0.5 * frame.Reduced[0] * guard)));
  const int mh = std::max(1, static_cast<int>(std::lround(0.5 * frame.Reduced[1] * guard)));
  vtkTextureObject* occluderDepth = depth;
  vtkLightShaftGeometry::CameraFrame occluderCamera = frame.Camera;
  if (guard > 1.0)
  {
    vtkCamera* sceneCamera = frame.Renderer->GetActiveCamera();
    vtkCamera* guardCamera = this->GuardCamera;
    guardCamera->DeepCopy(sceneCamera);
    if (sceneCamera->GetParallelProjection())
    {
      guardCamera->SetParallelScale(sceneCamera->GetParallelScale() * guard);
    }
    else
    {
      const double halfAngle = vtkMath::RadiansFromDegrees(sceneCamera->GetViewAngle()) / 2.0;
      guardCamera->SetViewAngle(
        vtkMath::DegreesFromRadians(2.0 * std::atan(std::tan(halfAngle) * guard)));
    }
    occluderDepth = this->GuardDepth.Ensure(window, TextureKind::Depth, mw, mh);
    frame.ShadowMap->RenderCasters(
      frame, frame.Light.Casters, guardCamera, this->GuardFramebuffer, occluderDepth);
    window->GetState()->vtkglDisable(GL_DEPTH_TEST);
    // The same view; x and y of the projection scaled by 1 / g.
    const glm::dmat4 scale = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / guard, 1.0 / guard, 1.0));
    occluderCamera.ClipToView = glm::inverse(scale * frame.Camera.ViewToClip);
    ++frame.Statistics.PostPasses;
  }
  frame.Statistics.RadialGuardBand = guard;
  vtkTextureObject* mask = this->OcclusionMask.Ensure(window, TextureKind::RGBA32F, mw, mh);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window),
    { mask },
    nullptr,
    mw,
    mh);
  vtkLightShaftShaders::Variant kind;
  vtkLightShaftShaders::AddLightKind(kind, frame.Light.Model);
  vtkShaderProgram* program = this->Occlusion.Ready(window, vtkLightShaftOcclusionFS, kind.Defines);
  if (!program)
  {
    return nullptr;
  }
  occluderDepth->Activate();
  program->SetUniformi("sceneDepth", occluderDepth->GetTextureUnit());
  vtkLightShaftShaders::SetViewUniforms(program, occluderCamera, mw, mh);
  vtkLightShaftShaders::SetLightUniforms(program, frame.Light);
  this->Occlusion.Render();
  occluderDepth->Deactivate();
  return mask;
}

//------------------------------------------------------------------------------
// The weights' sum over a walk of `samples` samples: decay^0 + ... + decay^(samples - 1) (the
// same for every pixel, in double: a split setting's shares each take part of them).
double vtkLightShaftRadialBlurMethod::DecayTotal(double decay, int samples)
{
  double total = 0.0;
  double weight = 1.0;
  for (int i = 0; i < samples; ++i)
  {
    total += weight;
    weight *= decay;
  }
  return total;
}

//------------------------------------------------------------------------------
// The radial walk from each pixel towards the light's screen position over the occlusion
// buffer, darkening the unshadowed integral.
vtkTextureObject* vtkLightShaftRadialBlurMethod::Blur(vtkLightShaftFrame& frame,
  vtkTextureObject* unshadowed,
  vtkTextureObject* occlusion,
  const float lightUV[2],
  double fade,
  double guard)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int lw = frame.Reduced[0];
  const int lh = frame.Reduced[1];
  vtkTextureObject* output = this->Output.Ensure(frame.Window, TextureKind::RGBA32F, lw, lh);
  vtkLightShaftResources::BindTargets(this->Framebuffer, { output }, nullptr, lw, lh);
  vtkShaderProgram* program = this->RadialBlur.Ready(frame.Window, vtkLightShaftRadialBlurFS);
  if (!program)
  {
    return unshadowed;
  }
  unshadowed->Activate();
  occlusion->Activate();
  program->SetUniformi("unshadowed", unshadowed->GetTextureUnit());
  program->SetUniformi("occlusion", occlusion->GetTextureUnit());
  program->SetUniform2f("lightUV", lightUV);
  program->SetUniformf("fade", static_cast<float>(fade));
  program->SetUniformi("samples", p.RadialSamples);
  program->SetUniformi("sampleShare", frame.RefinementSplit);
  program->SetUniformi("samplePart", frame.SamplePart);
  program->SetUniformf("decay", static_cast<float>(p.Decay));
  program->SetUniformf("decayTotal", static_cast<float>(DecayTotal(p.Decay, p.RadialSamples)));
  program->SetUniformf("weight", static_cast<float>(p.Weight));
  program->SetUniformf("density", static_cast<float>(p.Density));
  program->SetUniformi("stochastic", p.RadialJitter ? 1 : 0);
  program->SetUniformf("guardBand", static_cast<float>(guard));
  this->RadialBlur.Render();
  occlusion->Deactivate();
  unshadowed->Deactivate();
  frame.Statistics.PostPasses += 2;
  return output;
}

//------------------------------------------------------------------------------
void vtkLightShaftRadialBlurMethod::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* texture : { &this->GuardDepth, &this->OcclusionMask, &this->Output })
  {
    texture->Release(window);
  }
  this->Occlusion.Release(window);
  this->RadialBlur.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->GuardFramebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
