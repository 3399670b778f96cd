/**
 * @file   vtkLightShaftVolumeTexture.h
 * @brief  The extinction of the scene's vtkVolume as a 3D texture, for vtkLightShaftPass
 *         (private, not installed).
 */

#ifndef vtkLightShaftVolumeTexture_h
#define vtkLightShaftVolumeTexture_h

#include "vtkLightShaftDensityField.h" // For the field held
#include "vtkSmartPointer.h"           // For the texture held
#include "vtkType.h"                   // For vtkMTimeType
#include "vtkVolume.h"                 // For the volume last read (weak pointer)
#include "vtkWeakPointer.h"            // For the volume last read

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftVolumeTexture
 * @brief   Finds the visible vtkVolume among the frame's props and holds its extinction kappa
 *          (vtkLightShaftVolumeField's rule) as float32 samples in a 3D texture, filtered
 *          linearly: the shafts behind it and the light through it are dimmed by it.
 *
 * It is read again when the volume, its mapper, input, property or opacity function changed
 * (vtkLightShaftVolumeField::Time). One volume is modelled: with several, the first in the
 * renderer's order, and a warning once. A volume that gives no field is said once (a warning)
 * and models nothing; one that is transparent everywhere (kappa 0) models nothing either.
 */
class vtkLightShaftVolumeTexture
{
public:
  vtkLightShaftVolumeTexture();
  ~vtkLightShaftVolumeTexture();

  /**
   * The texture of the frame's volume (the first of frame.Props; nullptr: none in view), leaving
   * out `medium`'s volume (it scatters: it is the medium's field).
   */
  vtkTextureObject* Ready(vtkLightShaftFrame& frame, vtkVolume* medium);

  /// The field the texture holds, and a count of its uploads (what derives from it is stale
  /// when it changed).
  const vtkLightShaftDensityField& GetField() const { return this->Field; }
  vtkMTimeType GetVersion() const { return this->Version; }
  /// The volume modelled in the last frame (nullptr: none).
  vtkVolume* GetVolume() const { return this->Volume; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftVolumeTexture(const vtkLightShaftVolumeTexture&) = delete;
  void operator=(const vtkLightShaftVolumeTexture&) = delete;

  vtkLightShaftDensityField Field;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkWeakPointer<vtkVolume> Volume;
  vtkMTimeType ReadTime = 0;
  vtkMTimeType Version = 0;
  bool WarnedSeveral = false;
  vtkVolume* Refused = nullptr; ///< (only compared: said once)
  vtkMTimeType RefusedTime = 0;
};

#endif
