/**
 * @file   vtkLightShaftMediumTexture.h
 * @brief  The medium's density field as a 3D texture for vtkLightShaftPass (private, not
 *         installed), uploaded when its image or array changes.
 */

#ifndef vtkLightShaftMediumTexture_h
#define vtkLightShaftMediumTexture_h

#include "vtkLightShaftDensityField.h" // For the field held
#include "vtkSmartPointer.h"           // For the texture held
#include "vtkType.h"                   // For vtkMTimeType

#include <glm/glm.hpp> // For the texture's placement

#include <string> // For the array name and the last error

class vtkImageData;
class vtkLightShaftMedium;
class vtkObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

/**
 * @class   vtkLightShaftMediumTexture
 * @brief   vtkLightShaftMedium's density field on the GPU: float32 samples in a 3D texture,
 * filtered linearly and clamped to its edge (vtkLightShaftDensityField's trilinear rule).
 *
 * The image is read again when its MTime (or its data's) or the array name changes. An image
 * that became unusable since it was set is reported once (error from the owner) and the last
 * usable field stays in use.
 */
class vtkLightShaftMediumTexture
{
public:
  vtkLightShaftMediumTexture();
  ~vtkLightShaftMediumTexture();

  /**
   * The texture of the medium's density field for this render (nullptr when it has none, or no
   * usable field was ever read from its image). The field the medium's setter read is taken
   * instead of reading the image again.
   */
  vtkTextureObject* Ready(vtkOpenGLRenderWindow* window,
    vtkObject* owner,
    vtkLightShaftMedium* medium);

  /// The field the texture holds.
  const vtkLightShaftDensityField& GetField() const { return this->Field; }

  /**
   * World coordinates to the texture's coordinates, and the field's bounds there (the image's
   * box of points; outside it the density is 0).
   */
  glm::dmat4 TextureFromWorld() const;
  void TextureBounds(float low[3], float high[3]) const;

  /// When the field in use was last uploaded (a still picture changes with it).
  vtkMTimeType GetUploadTime() const { return this->UploadTime; }

  /// Counts the uploads: what is derived from the field is stale when it changed.
  vtkMTimeType GetVersion() const { return this->Version; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftMediumTexture(const vtkLightShaftMediumTexture&) = delete;
  void operator=(const vtkLightShaftMediumTexture&) = delete;

  vtkLightShaftDensityField Field;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkImageData* Image = nullptr; ///< (only compared: which image the texture came from)
  std::string ArrayName;
  int Resolution = 0; ///< the FieldResolution the texture was made at
  vtkMTimeType UploadTime = 0;
  vtkMTimeType Version = 0;
  vtkImageData* Resampled = nullptr; ///< the image last said to be resampled (only compared)
  /// The image last refused, as it was then (only compared: refused once, not read again).
  vtkImageData* Refused = nullptr;
  vtkMTimeType RefusedTime = 0;
  std::string RefusedName;
};

#endif
