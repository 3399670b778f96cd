#include "vtkLightShaftMediumTexture.h"

#include "vtkImageData.h"
#include "vtkLightShaftMediumInternals.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkLightShaftResources.h"
#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkLightShaftMediumTexture::vtkLightShaftMediumTexture() = default;
vtkLightShaftMediumTexture::~vtkLightShaftMediumTexture() = default;

vtkTextureObject* vtkLightShaftMediumTexture::Ready(vtkOpenGLRenderWindow* window,
  vtkObject* owner,
  vtkLightShaftMedium* medium)
{
  vtkImageData* image = medium->UpdateDensityField(owner);
  const std::string arrayName = medium->GetDensityArrayName();
  if (!image)
  {
    this->ReleaseGraphicsResources(window); // (no field: its texture is not kept)
    this->Refused = nullptr;
    return nullptr;
  }
  const int resolution = medium->GetFieldResolution();
  const bool same =
    image == this->Image && arrayName == this->ArrayName && resolution == this->Resolution;
  if (same && this->Texture && image->GetMTime() <= this->UploadTime)
  {
    return this->Texture;
  }
  if (image == this->Refused && image->GetMTime() == this->RefusedTime &&
      arrayName == this->RefusedName)
  {
    return this->Texture; // (refused as it is: said once, not read again)
  }
  vtkLightShaftDensityField field;
  std::string why;
  if (!medium->Impl->Take(image, arrayName, field)) // (read by the setter: not read twice)
  {
    why = field.Read(image, arrayName.c_str());
  }
  GLint maximum = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maximum);
  const int* samples = field.GetSamples();
  auto exceeds = [&samples](int bound)
  { return samples[0] > bound || samples[1] > bound || samples[2] > bound; };
  if (why.empty() && exceeds(maximum) && resolution > maximum)
  {
    if (image != this->Resampled) // (said once per image, not at each of its updates)
    {
      vtkWarningWithObjectMacro(owner,
        "DensityField: the image has " << samples[0] << " x " << samples[1] << " x " << samples[2]
                                       << " samples, more along an axis than this "
                                       << "GL's 3D textures hold (" << maximum
                                       << "): it is resampled to " << maximum
                                       << " along that axis (vtkLightShaftReference integrates "
                                       << "it as it is).");
      this->Resampled = image;
    }
  }
  // The pass's grid: at most FieldResolution samples per axis (and what the GL holds).
  const int bound = std::min<int>(maximum, resolution);
  if (why.empty() && exceeds(bound))
  {
    field = field.Resampled(bound);
    samples = field.GetSamples();
  }
  if (!why.empty())
  {
    // Changed into something unusable since it was set (or a pipeline made it): keep the
    // last usable field.
    vtkErrorWithObjectMacro(
      owner, "DensityField: the image " << why << "; the last usable density field is kept.");
    this->Refused = image;
    this->RefusedTime = image->GetMTime();
    this->RefusedName = arrayName;
    return this->Texture;
  }
  this->Refused = nullptr;
  vtkLightShaftResources::UploadFloatVolume(
    this->Texture, window, field.GetValues().data(), samples[0], samples[1], samples[2]);
  this->Field = std::move(field);
  this->Image = image;
  this->ArrayName = arrayName;
  this->Resolution = resolution;
  this->UploadTime = image->GetMTime();
  ++this->Version;
  return this->Texture;
}

glm::dmat4 vtkLightShaftMediumTexture::TextureFromWorld() const
{
  return this->Field.TextureFromWorld();
}

void vtkLightShaftMediumTexture::TextureBounds(float low[3], float high[3]) const
{
  this->Field.TextureBounds(low, high);
}

void vtkLightShaftMediumTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = nullptr;
  this->Image = nullptr;
  this->UploadTime = 0;
}
