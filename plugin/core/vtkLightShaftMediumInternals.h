/**
 * @file   vtkLightShaftMediumInternals.h
 * @brief  What vtkLightShaftMedium holds besides its parameters (private, not installed): the
 *         density field's source, and the field its setter read, for the first pass's texture
 *         to take instead of reading the image again.
 */
#ifndef vtkLightShaftMediumInternals_h
#define vtkLightShaftMediumInternals_h

#include "vtkLightShaftMedium.h"

#include "vtkAlgorithm.h"              // For the field's pipeline
#include "vtkImageData.h"              // For the field's image
#include "vtkLightShaftDensityField.h" // For the field read by the setter
#include "vtkSmartPointer.h"           // For vtkSmartPointer
#include "vtkTexture.h"                // For the noise image
#include "vtkTimeStamp.h"              // For the coefficients' time
#include "vtkVolume.h"                 // For the density volume

#include <string> // For the array name and the last error

class vtkLightShaftMedium::Internals
{
public:
  vtkSmartPointer<vtkImageData> Density; ///< SetDensityField's image (checked when set)
  std::string ArrayName;
  /// SetDensityFieldConnection's producer and port, and its last output that was an image.
  vtkSmartPointer<vtkAlgorithm> Producer;
  int Port = 0;
  vtkSmartPointer<vtkImageData> Output;
  std::string OutputError;
  vtkSmartPointer<vtkTexture> NoiseTexture;
  /// SetDensityVolume's volume, its opacity image and what it was built from.
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkImageData> VolumeDensity;
  vtkMTimeType VolumeTime = 0;
  std::string VolumeArrayName;
  std::string VolumeError;
  vtkTimeStamp CoefficientsSet; ///< the coefficient setters' last call

  /// The density volume's opacity image, built again when the volume changed (the last usable
  /// one kept, with one error from `caller`, when it gives none).
  vtkImageData* UpdateVolumeDensity(vtkObject* caller);

  /// The field a setter read from `image` (as it was then) with `arrayName`.
  void Keep(vtkImageData* image, const std::string& arrayName, vtkLightShaftDensityField&& field)
  {
    this->ReadField = std::move(field);
    this->ReadImage = image;
    this->ReadTime = image ? image->GetMTime() : 0;
    this->ReadName = arrayName;
  }

  /// Moves the kept field into `field` when it was read from `image` as it is now with
  /// `arrayName` (true), and forgets it either way.
  bool Take(vtkImageData* image, const std::string& arrayName, vtkLightShaftDensityField& field)
  {
    const bool same = image && image == this->ReadImage && image->GetMTime() == this->ReadTime &&
                      arrayName == this->ReadName;
    if (same)
    {
      field = std::move(this->ReadField);
    }
    this->ReadImage = nullptr;
    this->ReadField = vtkLightShaftDensityField();
    return same;
  }

private:
  vtkLightShaftDensityField ReadField;
  vtkImageData* ReadImage = nullptr; ///< (only compared)
  vtkMTimeType ReadTime = 0;
  std::string ReadName;
};

#endif
