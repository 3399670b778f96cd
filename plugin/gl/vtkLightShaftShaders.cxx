#include "vtkLightShaftShaders.h"

#include "vtkLightShaftFieldTableTexture.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftMediumTexture.h"
#include "vtkLightShaftShaderText.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftShaders
{
//------------------------------------------------------------------------------
void Variant::Feature(bool on, const char* define, const char* name)
{
  if (on)
  {
    this->Defines.emplace_back(define);
    this->Description += std::string(" ") + name;
  }
}

void AddLightKind(Variant& variant, const vtkLightShaftModel::Light& light)
{
  switch (light.Kind)
  {
    case vtkLightShaftModel::LightKind::Point:
      variant.Defines.emplace_back("LIGHTSHAFT_POINT");
      variant.Description += " light=point";
      break;
    case vtkLightShaftModel::LightKind::Directional:
      variant.Defines.emplace_back("LIGHTSHAFT_DIRECTIONAL");
      variant.Description += " light=directional";
      break;
    default:
      variant.Description += " light=spot";
      break;
  }
}

Variant IntegrandVariant(const char* methodName,
  const char* methodDefine,
  const vtkLightShaftFrame& frame,
  bool shadows)
{
  Variant variant;
  if (methodDefine)
  {
    variant.Defines.emplace_back(methodDefine);
  }
  variant.Description = std::string("method=") + methodName + " ";
  switch (frame.Medium.Phase)
  {
    case vtkLightShaftMedium::HENYEY_GREENSTEIN:
      variant.Defines.emplace_back("LIGHTSHAFT_PHASE_HG");
      variant.Description += "phase=henyey-greenstein";
      break;
    case vtkLightShaftMedium::RAYLEIGH:
      variant.Defines.emplace_back("LIGHTSHAFT_PHASE_RAYLEIGH");
      variant.Description += "phase=rayleigh";
      break;
    default:
      variant.Description += "phase=isotropic";
      break;
  }
  AddLightKind(variant, frame.Light.Model);
  variant.Feature(shadows, "LIGHTSHAFT_SHADOW", "shadow");
  variant.Feature(shadows && frame.Translucency, "LIGHTSHAFT_TRANSLUCENT", "translucent");
  variant.Feature(frame.CameraLayers != nullptr, "LIGHTSHAFT_CAMERA_LAYERS", "camera-layers");
  variant.Feature(frame.Cookie != nullptr, "LIGHTSHAFT_COOKIE", "cookie");
  variant.Feature(frame.Noise != nullptr, "LIGHTSHAFT_NOISE", "noise");
  variant.Feature(frame.Density != nullptr, "LIGHTSHAFT_FIELD", "field");
  variant.Feature(frame.FieldShadow != nullptr, "LIGHTSHAFT_FIELD_SHADOW", "field-shadow");
  variant.Feature(frame.VolumeShadow != nullptr, "LIGHTSHAFT_VOLUME", "volume");
  // Progressive refinement moves the lookups within each piece (none: nothing to move).
  const bool lookups = shadows || frame.Cookie != nullptr || frame.Noise != nullptr;
  variant.Feature(lookups && frame.LookupFraction != 0.5, "LIGHTSHAFT_REFINE", "refine");
  return variant;
}

//------------------------------------------------------------------------------
vtkShaderProgram* Program::Ready(vtkOpenGLRenderWindow* window,
  const char* vertex,
  const char* fragment,
  const Variant& variant)
{
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  const std::string key = vtkLightShaftShaderText::JoinDefines(variant.Defines);
  if (this->Shader && key == this->Key)
  {
    return cache->ReadyShaderProgram(this->Shader);
  }
  this->FragmentSource = vtkLightShaftShaderText::WithFeatures(fragment, variant.Defines);
  const std::string vertexSource = vtkLightShaftShaderText::WithFeatures(vertex, variant.Defines);
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
  program->SetUniformf("backdropDepthVC", static_cast<float>(camera.FarDepth));
  const float targetSize[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("targetSize", targetSize);
}

void SetLightUniforms(vtkShaderProgram* program, const vtkLightShaftGeometry::LightFrame& light)
{
  program->SetUniform3f(
    "lightPositionVC", vtkLightShaftGeometry::ToFloat3(light.PositionVC).data());
  program->SetUniform3f("lightAxisVC", vtkLightShaftGeometry::ToFloat3(light.AxisVC).data());
  if (light.Model.Kind == vtkLightShaftModel::LightKind::Spot)
  {
    program->SetUniformf("cosConeAngle", static_cast<float>(std::cos(light.Model.ConeHalfAngle)));
  }
}

void SetIntegrandUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  SetLightUniforms(program, light);
  if (light.Model.Kind == vtkLightShaftModel::LightKind::Spot)
  {
    program->SetUniformf("spotExponent", static_cast<float>(light.Model.Exponent));
  }
  program->SetUniform3f("attenuationCoefficients", light.Model.Attenuation);
  program->SetUniform3f("lightRadiantIntensity", light.Model.RadiantIntensity);
  program->SetUniform3f("sigmaS", frame.Medium.SigmaS);
  program->SetUniform3f("sigmaT", frame.Medium.SigmaT);
  if (frame.LookupFraction != 0.5)
  {
    program->SetUniformf("lookupFraction", static_cast<float>(frame.LookupFraction));
  }
  if (frame.Medium.Phase == vtkLightShaftMedium::HENYEY_GREENSTEIN)
  {
    program->SetUniformf("anisotropy", static_cast<float>(frame.Medium.Anisotropy));
  }
  if (frame.Density)
  {
    SetDensityUniforms(program, frame);
  }
  if (frame.CameraLayers)
  {
    SetCameraLayerUniforms(program, frame);
  }
  if (frame.VolumeShadow)
  {
    SetVolumeUniforms(program, frame);
  }
}

void SetVolumeUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  const glm::dmat4 tcFromVC =
    frame.VolumeField->TextureFromWorld() * glm::inverse(frame.Camera.WorldToView);
  program->SetUniformMatrix4x4(
    "volumeTCFromVC", vtkLightShaftGeometry::ToFloatColumnMajor(tcFromVC).data());
  float low[3];
  float high[3];
  frame.VolumeField->TextureBounds(low, high);
  program->SetUniform3f("volumeLowTC", low);
  program->SetUniform3f("volumeHighTC", high);
  program->SetUniformi("volumeSteps", DensitySteps(frame.Parameters.NumberOfSteps));
  frame.Volume->Activate();
  program->SetUniformi("volumeTexture", frame.Volume->GetTextureUnit());
  SetTableUniforms(program, "volumeShadow", *frame.VolumeShadowLayout, frame);
  frame.VolumeShadow->Activate();
  program->SetUniformi("volumeShadowTexture", frame.VolumeShadow->GetTextureUnit());
}

void SetCameraLayerUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  frame.CameraLayers->Activate();
  program->SetUniformi("cameraLayers", frame.CameraLayers->GetTextureUnit());
  program->SetUniformi("cameraLayerCount", frame.CameraLayerCount);
}

int DensitySteps(int viewSteps)
{
  // A quarter of the view ray's steps, in [16, 32] (measured, tests/python/test_medium_field.py
  // and tests/benchmarks/medium_field_cost.py: through a sharp layer 16 samples are 0.04% from
  // the reference, 8 are 0.22%, 4 are 1.3%; 16 cost 2.4-2.9 times the homogeneous frame at 64
  // steps, 64 cost 6-8 times). And within Mesa's llvmpipe's limit, whatever the GPU: it ends
  // every loop of an invocation once the invocation has run 65535 loop iterations in all
  // (measured: a uniform field came out 4x too dark at 1024 steps x 64). Each step also runs
  // about 12 iterations of the other loops (smooth factors, attenuation, the bounds' test).
  const int wanted = std::min(std::max(viewSteps / 4, 16), 32);
  return std::max(1, std::min(wanted, 65535 / (viewSteps + 1) - 12));
}

void SetDensityUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  const glm::dmat4 tcFromVC =
    frame.DensityField->TextureFromWorld() * glm::inverse(frame.Camera.WorldToView);
  program->SetUniformMatrix4x4(
    "densityTCFromVC", vtkLightShaftGeometry::ToFloatColumnMajor(tcFromVC).data());
  float low[3];
  float high[3];
  frame.DensityField->TextureBounds(low, high);
  program->SetUniform3f("densityLowTC", low);
  program->SetUniform3f("densityHighTC", high);
  program->SetUniformf("densityScale", static_cast<float>(frame.DensityScale));
  program->SetUniformf("densityBackground", static_cast<float>(frame.DensityBackground));
  program->SetUniformi("densitySteps", DensitySteps(frame.Parameters.NumberOfSteps));
  frame.Density->Activate();
  program->SetUniformi("densityTexture", frame.Density->GetTextureUnit());
  if (frame.FieldShadow)
  {
    SetFieldShadowUniforms(program, frame);
  }
}

void SetTableUniforms(vtkShaderProgram* program,
  const std::string& name,
  const vtkLightShaftFieldTableTexture& table,
  const vtkLightShaftFrame& frame)
{
  const vtkLightShaftFieldTableTexture::Layout& layout = table.GetLayout();
  // View coordinates -> world -> the face's frame (origin at the light).
  glm::dmat4 toFace(glm::dmat3(layout.ToFace));
  toFace[3] = glm::dvec4(-(layout.ToFace * layout.Origin), 1.0);
  const glm::dmat4 fromVC = toFace * glm::inverse(frame.Camera.WorldToView);
  program->SetUniformMatrix4x4(
    (name + ".fromVC").c_str(), vtkLightShaftGeometry::ToFloatColumnMajor(fromVC).data());
  program->SetUniformi((name + ".faces").c_str(), layout.Faces);
  // Texel centres at the range's ends: tc = (0.5 + (x - low) / (high - low) * (n - 1)) / n.
  float scale[3];
  float offset[3];
  for (int k = 0; k < 3; ++k)
  {
    const double n = (k < 2) ? layout.Lateral : layout.Depth;
    const double s = (n - 1.0) / (n * (layout.High[k] - layout.Low[k]));
    scale[k] = static_cast<float>(s);
    offset[k] = static_cast<float>(0.5 / n - layout.Low[k] * s);
  }
  program->SetUniform3f((name + ".scale").c_str(), scale);
  program->SetUniform3f((name + ".offset").c_str(), offset);
  const float lateral[4] = { static_cast<float>(layout.Low[0]),
    static_cast<float>(layout.Low[1]),
    static_cast<float>(layout.High[0]),
    static_cast<float>(layout.High[1]) };
  program->SetUniform4f((name + ".lateral").c_str(), lateral);
  program->SetUniformf((name + ".lateralTexels").c_str(), static_cast<float>(layout.Lateral));
  program->SetUniformf((name + ".depth").c_str(), static_cast<float>(layout.Depth));
}

void SetFieldShadowUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame)
{
  SetTableUniforms(program, "fieldShadow", *frame.FieldShadowLayout, frame);
  frame.FieldShadow->Activate();
  program->SetUniformi("fieldShadowTexture", frame.FieldShadow->GetTextureUnit());
}

void SetLightSpaceUniforms(vtkShaderProgram* program,
  const vtkLightShaftFrame& frame,
  int width,
  vtkTextureObject* shadowMap)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  const glm::dvec2 footprint = frame.Camera.PixelFootprint(width);
  const float pixelFootprint[2] = { static_cast<float>(footprint.x),
    static_cast<float>(footprint.y) };
  program->SetUniform2f("pixelFootprint", pixelFootprint);
  const glm::dvec2 squareWidth = light.Model.SquareWidth();
  const float lightSquareWidth[2] = { static_cast<float>(squareWidth.x),
    static_cast<float>(squareWidth.y) };
  program->SetUniform2f("lightSquareWidth", lightSquareWidth);
  const bool point = light.Model.Kind == vtkLightShaftModel::LightKind::Point;
  if (!point)
  {
    auto square = vtkLightShaftGeometry::ToFloatColumnMajor(light.ViewToLightSquare);
    program->SetUniformMatrix4x4("lightSquareFromVC", square.data());
  }
  else
  {
    float worldFromVC[9];
    for (int column = 0; column < 3; ++column)
    {
      for (int row = 0; row < 3; ++row)
      {
        worldFromVC[3 * column + row] = static_cast<float>(light.ViewToWorld[column][row]);
      }
    }
    program->SetUniformMatrix3x3("worldFromVC", worldFromVC);
  }
  if (!shadowMap)
  {
    return;
  }
  shadowMap->Activate();
  program->SetUniformi("shadowMap", shadowMap->GetTextureUnit());
  if (frame.Translucency)
  {
    frame.Translucency->Activate();
    program->SetUniformi("translucentLayers", frame.Translucency->GetTextureUnit());
    program->SetUniformi("translucentLayerCount", frame.TranslucentLayers);
    // The bias is in the map's texels; layers held to their memory budget are coarser.
    program->SetUniformf("translucentBiasScale",
      static_cast<float>(shadowMap->GetHeight()) /
        static_cast<float>(std::max(frame.Translucency->GetHeight(), 1u)));
  }
  const float depthRange[2] = { static_cast<float>(light.Near), static_cast<float>(light.Far) };
  program->SetUniform2f("lightDepthRange", depthRange);
  if (point)
  {
    std::vector<float> faces;
    for (const vtkLightShaftGeometry::LightView& view : light.Views)
    {
      const auto face = vtkLightShaftGeometry::ToFloatColumnMajor(view.ViewToClip);
      faces.insert(faces.end(), face.begin(), face.end());
    }
    program->SetUniformMatrix4x4v("faceClipFromVC", 6, faces.data());
    program->SetUniformf("shadowFaceSize", static_cast<float>(shadowMap->GetHeight() / 2));
  }
  else
  {
    auto lightMatrix = vtkLightShaftGeometry::ToFloatColumnMajor(light.ViewToLightClip);
    program->SetUniformMatrix4x4("lightClipFromVC", lightMatrix.data());
  }
}

void SetCookieUniforms(vtkShaderProgram* program,
  vtkTextureObject* cookie,
  const vtkLightShaftModel::Light& light)
{
  // A spot's cookie covers its square (clamped beyond, where the cone ends anyway); a
  // directional light's tiles its plane.
  const int wrap = light.Kind == vtkLightShaftModel::LightKind::Directional
                     ? vtkTextureObject::Repeat
                     : vtkTextureObject::ClampToEdge;
  if (cookie->GetWrapS() != wrap)
  {
    cookie->SetWrapS(wrap);
    cookie->SetWrapT(wrap);
    cookie->Activate();
    cookie->SendParameters();
  }
  cookie->Activate();
  program->SetUniformi("cookieTexture", cookie->GetTextureUnit());
  program->SetUniformf(
    "cookieSize", static_cast<float>(std::max(cookie->GetWidth(), cookie->GetHeight())));
}
}
