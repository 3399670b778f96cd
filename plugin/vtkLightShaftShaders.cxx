#include "vtkLightShaftShaders.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftPass.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftCommon.h"
#include "vtkLightShaftIntegrand.h"
#include "vtkLightShaftSegment.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftShaders
{
//------------------------------------------------------------------------------
std::string JoinDefines(const std::vector<std::string>& defines)
{
  std::string features;
  for (const auto& define : defines)
  {
    features += "#define " + define + "\n";
  }
  return features;
}

std::string WithFeatures(const char* source, const std::vector<std::string>& defines)
{
  std::string out = source;
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Features", JoinDefines(defines));
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Common", vtkLightShaftCommon);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Integrand", vtkLightShaftIntegrand);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Segment", vtkLightShaftSegment);
  return out;
}

//------------------------------------------------------------------------------
void Variant::Feature(bool on, const char* define, const char* name)
{
  if (on)
  {
    this->Defines.emplace_back(define);
    this->Description += std::string(" ") + name;
  }
}

Variant IntegrandVariant(const char* methodName,
  const char* methodDefine,
  int phase,
  bool shadows,
  bool cookie,
  bool noise)
{
  Variant variant;
  if (methodDefine)
  {
    variant.Defines.emplace_back(methodDefine);
  }
  variant.Description = std::string("method=") + methodName + " ";
  switch (phase)
  {
    case vtkLightShaftPass::HENYEY_GREENSTEIN:
      variant.Defines.emplace_back("LIGHTSHAFT_PHASE_HG");
      variant.Description += "phase=henyey-greenstein";
      break;
    case vtkLightShaftPass::RAYLEIGH:
      variant.Defines.emplace_back("LIGHTSHAFT_PHASE_RAYLEIGH");
      variant.Description += "phase=rayleigh";
      break;
    default:
      variant.Description += "phase=isotropic";
      break;
  }
  variant.Feature(shadows, "LIGHTSHAFT_SHADOW", "shadow");
  variant.Feature(cookie, "LIGHTSHAFT_COOKIE", "cookie");
  variant.Feature(noise, "LIGHTSHAFT_NOISE", "noise");
  return variant;
}

//------------------------------------------------------------------------------
vtkShaderProgram* Program::Ready(vtkOpenGLRenderWindow* window,
  const char* vertex,
  const char* fragment,
  const Variant& variant)
{
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  const std::string key = JoinDefines(variant.Defines);
  if (this->Shader && key == this->Key)
  {
    return cache->ReadyShaderProgram(this->Shader);
  }
  this->FragmentSource = WithFeatures(fragment, variant.Defines);
  const std::string vertexSource = WithFeatures(vertex, variant.Defines);
  this->Shader = cache->ReadyShaderProgram(vertexSource.c_str(), this->FragmentSource.c_str(), "");
  this->Key = key;
  if (!this->Shader || !this->Shader->GetCompiled())
  {
    this->Release();
    return nullptr;
  }
  return this->Shader;
}

void Program::Release()
{
  this->Shader = nullptr;
  this->Key.clear();
  this->FragmentSource.clear();
}

//------------------------------------------------------------------------------
void SetViewUniforms(vtkShaderProgram* program,
  const vtkLightShaftGeometry::CameraFrame& camera,
  int width,
  int height)
{
  auto invProjection = vtkLightShaftGeometry::ToFloatColumnMajor(camera.ClipToView);
  program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
  const float targetSize[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("targetSize", targetSize);
}

void SetIntegrandUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  program->SetUniform3f(
    "lightPositionVC", vtkLightShaftGeometry::ToFloat3(light.PositionVC).data());
  program->SetUniform3f("lightAxisVC", vtkLightShaftGeometry::ToFloat3(light.AxisVC).data());
  program->SetUniformf("cosConeAngle", static_cast<float>(std::cos(light.Model.ConeHalfAngle)));
  program->SetUniformf("spotExponent", static_cast<float>(light.Model.Exponent));
  program->SetUniform3f("attenuationCoefficients", light.Model.Attenuation);
  program->SetUniform3f("lightRadiantIntensity", light.Model.RadiantIntensity);
  program->SetUniform3f("sigmaS", frame.Medium.SigmaS);
  program->SetUniform3f("sigmaT", frame.Medium.SigmaT);
  if (frame.Medium.Phase == vtkLightShaftPass::HENYEY_GREENSTEIN)
  {
    program->SetUniformf("anisotropy", static_cast<float>(frame.Medium.Anisotropy));
  }
}

void SetLightSpaceUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame, int width)
{
  auto lightMatrix = vtkLightShaftGeometry::ToFloatColumnMajor(frame.Light.ViewToLightClip);
  program->SetUniformMatrix4x4("lightClipFromVC", lightMatrix.data());
  const glm::dvec2 footprint = frame.Camera.PixelFootprint(width);
  const float pixelFootprint[2] = { static_cast<float>(footprint.x),
    static_cast<float>(footprint.y) };
  program->SetUniform2f("pixelFootprint", pixelFootprint);
  program->SetUniformf("lightTexelAngle", static_cast<float>(2.0 * frame.Light.BoundsVC.Tangent));
}

void SetCookieUniforms(vtkShaderProgram* program, vtkTextureObject* cookie)
{
  cookie->Activate();
  program->SetUniformi("cookieTexture", cookie->GetTextureUnit());
  program->SetUniformf(
    "cookieSize", static_cast<float>(std::max(cookie->GetWidth(), cookie->GetHeight())));
}
}
