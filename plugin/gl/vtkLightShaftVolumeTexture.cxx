#include "vtkLightShaftVolumeTexture.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftResources.h"
#include "vtkLightShaftVolumeField.h"

#include "vtkImageData.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProp.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"

#include <string>

vtkLightShaftVolumeTexture::vtkLightShaftVolumeTexture() = default;
vtkLightShaftVolumeTexture::~vtkLightShaftVolumeTexture() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftVolumeTexture::Ready(vtkLightShaftFrame& frame, vtkVolume* medium)
{
  vtkVolume* volume = nullptr;
  int volumes = 0;
  for (vtkProp* prop : frame.Props)
  {
    auto* candidate = vtkVolume::SafeDownCast(prop);
    if (candidate && candidate != medium && candidate->GetVisibility())
    {
      volume = volume ? volume : candidate;
      ++volumes;
    }
  }
  if (volumes > 1 && !this->WarnedSeveral)
  {
    vtkWarningWithObjectMacro(frame.Owner,
      "The shafts are dimmed and shadowed by one vtkVolume, the first of the renderer's "
        << volumes << ": the others are rendered but dim nothing.");
    this->WarnedSeveral = true;
  }
  if (!volume)
  {
    this->ReleaseGraphicsResources(frame.Window); // (none: its texture is not kept)
    return nullptr;
  }
  const vtkMTimeType time = vtkLightShaftVolumeField::Time(volume);
  if (volume == this->Volume && this->Texture && time <= this->ReadTime)
  {
    return this->Texture;
  }
  if (volume == this->Refused && time == this->RefusedTime)
  {
    return nullptr; // (said once, or transparent: not read again)
  }
  vtkNew<vtkImageData> image;
  std::string why =
    vtkLightShaftVolumeField::Build(volume, vtkLightShaftVolumeField::Quantity::Extinction, image);
  vtkLightShaftDensityField field;
  if (why.empty())
  {
    why = field.Read(image, nullptr);
  }
  if (!why.empty())
  {
    vtkWarningWithObjectMacro(
      frame.Owner, "vtkVolume " << volume << " " << why << ": it dims and shadows nothing.");
    this->Refused = volume;
    this->RefusedTime = time;
    this->ReleaseGraphicsResources(frame.Window);
    return nullptr;
  }
  if (!(field.GetMaximum() > 0.0))
  {
    // A volume that is transparent everywhere dims nothing: nothing to compute.
    this->ReleaseGraphicsResources(frame.Window);
    this->Refused = volume;
    this->RefusedTime = time;
    return nullptr;
  }
  GLint maximum = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maximum);
  const int* samples = field.GetSamples();
  if (samples[0] > maximum || samples[1] > maximum || samples[2] > maximum)
  {
    field = field.Resampled(maximum);
    samples = field.GetSamples();
  }
  this->Refused = nullptr;
  vtkLightShaftResources::UploadFloatVolume(
    this->Texture, frame.Window, field.GetValues().data(), samples[0], samples[1], samples[2]);
  this->Field = std::move(field);
  this->Volume = volume;
  this->ReadTime = time;
  ++this->Version;
  return this->Texture;
}

//------------------------------------------------------------------------------
void vtkLightShaftVolumeTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  this->Texture = nullptr;
  this->Volume = nullptr;
  this->ReadTime = 0;
}
