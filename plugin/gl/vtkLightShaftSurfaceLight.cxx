#include "vtkLightShaftSurfaceLight.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftSceneRenderer.h"
#include "vtkLightShaftShaders.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftSurfaceLightFS.h"

#include <string>
#include <vector>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftSurfaceLight::vtkLightShaftSurfaceLight() = default;
vtkLightShaftSurfaceLight::~vtkLightShaftSurfaceLight() = default;

void vtkLightShaftSurfaceLight::Begin()
{
  this->Added = false;
}

vtkTextureObject* vtkLightShaftSurfaceLight::GetCorrection()
{
  return this->Added ? this->Correction.Object.Get() : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightShaftSurfaceLight::Add(vtkLightShaftFrame& frame,
  vtkLightShaftSceneRenderer& scene,
  vtkRenderPass* delegate,
  vtkLight* light,
  vtkTextureObject* shadowMap,
  bool lightLeg)
{
  if (!shadowMap && !frame.Cookie && !lightLeg)
  {
    return;
  }
  vtkTextureObject* unlit = scene.RenderWithout(frame, delegate, light);

  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const vtkLightShaftSceneImage& image = frame.Scene;
  const bool multisample = image.Samples > 0;
  vtkTextureObject* correction =
    this->Correction.Ensure(window, TextureKind::RGBA16F, w, h, image.Samples);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window),
    { correction },
    nullptr,
    w,
    h);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (!this->Added)
  {
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->Added = true;
  }

  vtkLightShaftShaders::Variant variant;
  vtkLightShaftShaders::AddLightKind(variant, frame.Light.Model);
  variant.Feature(shadowMap != nullptr, "LIGHTSHAFT_SHADOW", "shadow");
  variant.Feature(
    shadowMap != nullptr && frame.Translucency, "LIGHTSHAFT_TRANSLUCENT", "translucent");
  variant.Feature(frame.VolumeShadow != nullptr, "LIGHTSHAFT_VOLUME_SHADOW", "volume");
  variant.Feature(frame.Cookie != nullptr, "LIGHTSHAFT_COOKIE", "cookie");
  variant.Feature(lightLeg, "LIGHTSHAFT_LIGHT_LEG", "light-leg");
  variant.Feature(lightLeg && frame.Density, "LIGHTSHAFT_FIELD", "field");
  variant.Feature(
    lightLeg && frame.Density && frame.FieldShadow, "LIGHTSHAFT_FIELD_SHADOW", "field-shadow");
  variant.Feature(multisample, "LIGHTSHAFT_MULTISAMPLE", "multisample");
  vtkLightShaftResources::FullScreenPass& pass =
    this->Pass[static_cast<int>(frame.Light.Model.Kind)];
  vtkShaderProgram* program = pass.Ready(window, vtkLightShaftSurfaceLightFS, variant.Defines);
  if (!program)
  {
    vtkErrorWithObjectMacro(frame.Owner, "Could not build the light-shaft surface-light shader.");
    return;
  }
  // Multisampled scene textures are read per sample (their uniforms have a "Samples" suffix).
  const std::string suffix = multisample ? "Samples" : "";
  std::vector<vtkTextureObject*> active = { image.Color, unlit, image.Depth };
  for (vtkTextureObject* t : active)
  {
    t->Activate();
  }
  program->SetUniformi(("sceneColor" + suffix).c_str(), image.Color->GetTextureUnit());
  program->SetUniformi(("sceneColorUnlit" + suffix).c_str(), unlit->GetTextureUnit());
  program->SetUniformi(("sceneDepth" + suffix).c_str(), image.Depth->GetTextureUnit());
  vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, w, h);
  vtkLightShaftShaders::SetLightUniforms(program, frame.Light);
  vtkLightShaftShaders::SetLightSpaceUniforms(program, frame, w, shadowMap);
  if (shadowMap)
  {
    active.push_back(shadowMap);
    if (frame.Translucency)
    {
      active.push_back(frame.Translucency);
    }
    const vtkLightShaftGeometry::LightFrame& lightFrame = frame.Light;
    const bool cube = lightFrame.Model.Kind == vtkLightShaftModel::LightKind::Point;
    const double texels = shadowMap->GetHeight() / (cube ? 2.0 : 1.0);
    const bool directional = lightFrame.Model.Kind == vtkLightShaftModel::LightKind::Directional;
    program->SetUniformf("shadowTexel", static_cast<float>(lightFrame.MapExtent / texels));
    program->SetUniformf("shadowFloor",
      static_cast<float>(directional ? 1e-4 * (lightFrame.Far - lightFrame.Near) : 1e-4));
  }
  if (frame.VolumeShadow)
  {
    active.push_back(frame.VolumeShadow);
    vtkLightShaftShaders::SetTableUniforms(
      program, "volumeShadow", *frame.VolumeShadowLayout, frame);
    frame.VolumeShadow->Activate();
    program->SetUniformi("volumeShadowTexture", frame.VolumeShadow->GetTextureUnit());
  }
  if (lightLeg)
  {
    program->SetUniform3f("sigmaT", frame.Medium.SigmaT);
    if (frame.Density)
    {
      vtkLightShaftShaders::SetDensityUniforms(program, frame); // (activates its textures)
      active.push_back(frame.Density);
      if (frame.FieldShadow)
      {
        active.push_back(frame.FieldShadow);
      }
    }
  }
  if (frame.Cookie)
  {
    active.push_back(frame.Cookie);
    vtkLightShaftShaders::SetCookieUniforms(program, frame.Cookie, frame.Light.Model);
  }

  // Add into the correction, per sample when multisampled (the shader reads gl_SampleID).
  if (multisample)
  {
    ostate->vtkglEnable(GL_MULTISAMPLE);
  }
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  pass.Render();
  ostate->vtkglDisable(GL_BLEND);
  for (auto it = active.rbegin(); it != active.rend(); ++it)
  {
    (*it)->Deactivate();
  }
  ++frame.Statistics.PostPasses;
}

//------------------------------------------------------------------------------
void vtkLightShaftSurfaceLight::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Correction.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  for (auto& pass : this->Pass)
  {
    pass.Release(window);
  }
  this->Added = false;
}
