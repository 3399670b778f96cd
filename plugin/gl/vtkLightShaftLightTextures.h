/**
 * @file   vtkLightShaftLightTextures.h
 * @brief  The light's textures for vtkLightShaftPass (private, not installed): the cookie and
 *         the density noise, uploaded (mipmapped) when their image changes.
 */

#ifndef vtkLightShaftLightTextures_h
#define vtkLightShaftLightTextures_h

#include "vtkSmartPointer.h" // For the textures held
#include "vtkType.h"         // For vtkMTimeType

#include <algorithm> // For std::max
#include <string>    // For the last warnings

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

/**
 * @class   vtkLightShaftLightTextures
 * @brief   The cookie and noise textures of vtkLightShaftPass.
 *
 * The images are the user's vtkTexture objects (or the project's generated noise); the GL
 * textures are uploaded only when an image changes (its texture's or its data's MTime).
 */
class vtkLightShaftLightTextures
{
public:
  vtkLightShaftLightTextures();
  ~vtkLightShaftLightTextures();

  void SetCookie(vtkTexture* cookie);
  vtkTexture* GetCookie() const;
  void SetNoiseImage(vtkTexture* noise);
  vtkTexture* GetNoiseImage() const;

  /**
   * The cookie's texture for this frame, nullptr when there is no cookie or its texture has no
   * image (then one warning from `owner` until the cookie changes, and no texture of an earlier
   * image is kept).
   */
  vtkTextureObject* ReadyCookie(vtkOpenGLRenderWindow* window, vtkObject* owner);

  /**
   * The noise texture: the user's image rescaled to mean 1, or the generated tileable noise
   * (also when the user's texture has no image: one warning from `owner`).
   */
  vtkTextureObject* ReadyNoise(vtkOpenGLRenderWindow* window, vtkObject* owner);

  /// When the cookie and noise images in use were last uploaded (they change with them).
  vtkMTimeType GetImagesTime() const
  {
    return std::max(this->CookieUploadTime, this->NoiseUploadTime);
  }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftLightTextures(const vtkLightShaftLightTextures&) = delete;
  void operator=(const vtkLightShaftLightTextures&) = delete;

  vtkSmartPointer<vtkTexture> Cookie;
  vtkSmartPointer<vtkTexture> NoiseImage;
  vtkSmartPointer<vtkTextureObject> CookieTexture;
  vtkSmartPointer<vtkTextureObject> NoiseTexture;
  vtkMTimeType CookieUploadTime = 0;
  vtkMTimeType NoiseUploadTime = 0;
  bool NoiseIsGenerated = false;
  /// The last warning about each image (empty: none since it was set or last usable): said
  /// once until it changes.
  std::string CookieWarning;
  std::string NoiseWarning;
};

#endif
