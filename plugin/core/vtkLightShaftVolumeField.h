/**
 * @file   vtkLightShaftVolumeField.h
 * @brief  What a vtkVolume does to the light, as a field on its image: its extinction, or its
 *         opacity as a medium's density, for vtkLightShaftPass and vtkLightShaftReference
 *         (private, not installed, no GL).
 */

#ifndef vtkLightShaftVolumeField_h
#define vtkLightShaftVolumeField_h

#include "vtkType.h" // For vtkMTimeType

#include <string> // For the reason a volume cannot be used

class vtkDataArray;
class vtkImageData;
class vtkVolume;

/**
 * @class   vtkLightShaftVolumeField
 * @brief   A vtkVolume's image mapped through its scalar opacity, placed in world coordinates.
 *
 * The rule, in one place (docs/translucent-and-volumes.md#volumes): VTK's volume mappers
 * composite a sample of opacity alpha = OTF(s) over a step d as 1 - (1 - alpha)^(d / u), u the
 * property's ScalarOpacityUnitDistance: light crossing the volume is dimmed as by an
 * extinction coefficient kappa = -ln(1 - alpha) / u per world unit, the same for every channel
 * and for both legs (the camera's and the light's). kappa is evaluated at the image's samples
 * (the scalars the mapper renders: its scalar mode and array, first component, with the
 * property's first scalar opacity function; alpha held below 1 - 1e-6) and interpolated
 * trilinearly between them, where VTK's mappers interpolate the scalar and then map it: the
 * two differ only where the opacity function bends within a cell. Gradient opacity, 2D
 * transfer functions and the volume's colour are not in the rule.
 *
 * As a medium (vtkLightShaftMedium::SetDensityVolume) the density is alpha = OTF(s) itself at
 * the samples.
 *
 * The image keeps the mapper's input's samples (point or cell data), with its origin, spacing
 * and direction composed with the volume's matrix (vtkProp3D::GetMatrix).
 */
class vtkLightShaftVolumeField
{
public:
  /// What the samples hold: kappa (per world unit), or alpha.
  enum class Quantity
  {
    Extinction,
    Opacity
  };

  /**
   * Fill `out` with `volume`'s field (the array "Extinction" or "Opacity", as its scalars).
   * Returns "" or the reason the volume gives no field (no mapper, no image input, no scalars,
   * no opacity function, a matrix that is not invertible); `out` is then emptied.
   */
  static std::string Build(vtkVolume* volume, Quantity quantity, vtkImageData* out);

  /**
   * The scalars `volume`'s mapper renders (its scalar mode and array; point or cell data,
   * `cells`), of its image input `input`: nullptr with the reason in `why` when there is no
   * volume mapper, no image input or no scalars to render (an empty image has none).
   */
  static vtkDataArray* RenderedScalars(vtkVolume* volume,
    vtkImageData*& input,
    bool& cells,
    std::string& why);

  /// The latest MTime of what Build reads: the volume (its matrix), its mapper, the mapper's
  /// input and its data, its property and the opacity function.
  static vtkMTimeType Time(vtkVolume* volume);
};

#endif
