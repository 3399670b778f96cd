#include "vtkLightShaftLightTextures.h"

#include "vtkLightShaftNoise.h"
#include "vtkLightShaftResources.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

namespace
{
// The latest modification of a texture and of its input image.
vtkMTimeType ImageTime(vtkTexture* texture)
{
  vtkDataObject* input = texture->GetInputDataObject(0, 0);
  return std::max(texture->GetMTime(), input ? input->GetMTime() : 0);
}

// Why `which` texture's image is not used ("cookie", "noise"; `unusable` from
// vtkLightShaftImageToRGB, empty: no image) and what is done instead, said once: `last` holds
// the warning last given.
void WarnUnusable(vtkObject* owner,
  const char* which,
  const std::string& unusable,
  const char* instead,
  std::string& last)
{
  const std::string warning =
    "The " + std::string(which) + " texture" +
    (unusable.empty() ? " has no image" : "'s image cannot be used (" + unusable + ")") + ": " +
    instead + ".";
  if (warning != last)
  {
    vtkWarningWithObjectMacro(owner, "" << warning);
    last = warning;
  }
}
}

//------------------------------------------------------------------------------
vtkLightShaftLightTextures::vtkLightShaftLightTextures() = default;
vtkLightShaftLightTextures::~vtkLightShaftLightTextures() = default;

//------------------------------------------------------------------------------
void vtkLightShaftLightTextures::SetCookie(vtkTexture* cookie)
{
  this->Cookie = cookie;
  this->CookieUploadTime = 0;
  this->CookieWarning.clear();
}

vtkTexture* vtkLightShaftLightTextures::GetCookie() const
{
  return this->Cookie;
}

void vtkLightShaftLightTextures::SetNoiseImage(vtkTexture* noise)
{
  this->NoiseImage = noise;
  this->NoiseUploadTime = 0;
  this->NoiseWarning.clear();
}

vtkTexture* vtkLightShaftLightTextures::GetNoiseImage() const
{
  return this->NoiseImage;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftLightTextures::ReadyCookie(vtkOpenGLRenderWindow* window,
  vtkObject* owner)
{
  vtkTexture* cookie = this->Cookie;
  if (!cookie)
  {
    return nullptr;
  }
  if (cookie->GetNumberOfInputPorts() > 0 && cookie->GetNumberOfInputConnections(0) > 0)
  {
    cookie->GetInputAlgorithm()->Update();
  }
  const vtkMTimeType time = ImageTime(cookie);
  if (this->CookieTexture && time <= this->CookieUploadTime)
  {
    return this->CookieTexture;
  }
  std::vector<float> rgb;
  int width = 0;
  int height = 0;
  std::string unusable;
  if (!vtkLightShaftImageToRGB(cookie, rgb, width, height, &unusable))
  {
    // No cookie this frame: drop the texture of an earlier image so that nothing uses it.
    if (this->CookieTexture)
    {
      this->CookieTexture->ReleaseGraphicsResources(window);
      this->CookieTexture = nullptr;
    }
    this->CookieUploadTime = 0;
    WarnUnusable(owner, "cookie", unusable, "no cookie is applied", this->CookieWarning);
    return nullptr;
  }
  this->CookieWarning.clear();
  vtkLightShaftResources::UploadMipmapped(
    this->CookieTexture, window, rgb, width, height, 3, false);
  this->CookieUploadTime = time;
  return this->CookieTexture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftLightTextures::ReadyNoise(vtkOpenGLRenderWindow* window,
  vtkObject* owner)
{
  if (this->NoiseImage)
  {
    const vtkMTimeType time = ImageTime(this->NoiseImage);
    if (this->NoiseTexture && !this->NoiseIsGenerated && time <= this->NoiseUploadTime)
    {
      return this->NoiseTexture;
    }
    std::vector<float> rgb;
    int width = 0;
    int height = 0;
    std::string unusable;
    if (vtkLightShaftImageToRGB(this->NoiseImage, rgb, width, height, &unusable))
    {
      this->NoiseWarning.clear();
      std::vector<float> texels(static_cast<size_t>(width) * height);
      for (size_t i = 0; i < texels.size(); ++i)
      {
        texels[i] = rgb[3 * i];
      }
      vtkLightShaftNormalizeNoise(texels);
      vtkLightShaftResources::UploadMipmapped(
        this->NoiseTexture, window, texels, width, height, 1, true);
      this->NoiseUploadTime = time;
      this->NoiseIsGenerated = false;
      return this->NoiseTexture;
    }
    WarnUnusable(owner, "noise", unusable, "using the generated noise", this->NoiseWarning);
  }
  if (!this->NoiseTexture || !this->NoiseIsGenerated)
  {
    constexpr int size = 256;
    vtkLightShaftResources::UploadMipmapped(
      this->NoiseTexture, window, vtkLightShaftTileableNoise(size, 5, 2004u), size, size, 1, true);
    this->NoiseIsGenerated = true;
  }
  return this->NoiseTexture;
}

//------------------------------------------------------------------------------
void vtkLightShaftLightTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* texture : { &this->CookieTexture, &this->NoiseTexture })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
    }
    *texture = nullptr;
  }
  this->CookieUploadTime = 0;
  this->NoiseUploadTime = 0;
}
