#include "vtkLightShaftFieldTableTexture.h"

#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftResources.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <chrono>

vtkLightShaftFieldTableTexture::vtkLightShaftFieldTableTexture() = default;
vtkLightShaftFieldTableTexture::~vtkLightShaftFieldTableTexture() = default;

std::size_t vtkLightShaftFieldTableTexture::GetBytes() const
{
  return this->Texture ? this->Current.Bytes() : 0;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftFieldTableTexture::Ready(vtkOpenGLRenderWindow* window,
  const vtkLightShaftDensityField& field,
  vtkMTimeType fieldTime,
  const vtkLightShaftModel::Light& light,
  int resolution)
{
  const int kind = static_cast<int>(light.Kind);
  const bool directional = light.Kind == vtkLightShaftModel::LightKind::Directional;
  // (A directional light's position matters only through its plane, a positional one's axis
  // not at all; comparing both is simpler and only rebuilds in those rare cases.)
  if (this->Texture && fieldTime == this->FieldTime && kind == this->Kind &&
      resolution == this->Resolution && light.Position == this->Position &&
      (!directional || light.Axis == this->Axis))
  {
    this->BuildTime = 0.0;
    return this->Texture;
  }
  const auto start = std::chrono::steady_clock::now();
  const int maximumDepth = std::min(
    vtkLightShaftFieldTable::MaximumDepth, vtkTextureObject::GetMaximumTextureSize3D(window));
  this->Current = vtkLightShaftFieldTable::Plan(field, light, resolution, maximumDepth);
  const std::vector<float> values = vtkLightShaftFieldTable::Integrate(field, this->Current);
  vtkLightShaftResources::UploadFloatVolume(this->Texture,
    window,
    values.data(),
    this->Current.Lateral * this->Current.Faces,
    this->Current.Lateral,
    this->Current.Depth);
  this->FieldTime = fieldTime;
  this->Kind = kind;
  this->Resolution = resolution;
  this->Position = light.Position;
  this->Axis = light.Axis;
  this->BuildTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return this->Texture;
}

void vtkLightShaftFieldTableTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = nullptr;
  this->Kind = -1;
}
