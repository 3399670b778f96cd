/**
 * @class   vtkLightShaftMedium
 * @brief   The participating medium the light shafts scatter in: what it is, apart from how
 *          vtkLightShaftPass computes the shafts.
 *
 * Its scattering and absorption coefficients (sigma_s, sigma_a per world unit and colour
 * channel; extinction sigma_t = sigma_s + sigma_a), its phase function, the scrolling noise
 * that varies its density, and a density field from data. Every pass has one
 * (vtkLightShaftPass::GetMedium); several passes, in one window or in several, may share one
 * (vtkLightShaftPass::SetMedium): a change shows in all of them at their next render.
 * @code{.cpp}
 *   vtkNew<vtkLightShaftPass> shafts;
 *   shafts->GetMedium()->SetScatteringCoefficient(0.2);
 *   shafts->GetMedium()->SetPhaseFunctionToHenyeyGreenstein();
 * @endcode
 *
 * Floating-point setters refuse NaN and infinities with an error naming the parameter (the
 * previous value is kept) and clamp other values into their range (docs/medium.md).
 *
 * @sa vtkLightShaftPass vtkLightShaftReference
 */

#ifndef vtkLightShaftMedium_h
#define vtkLightShaftMedium_h

#include "vtkLightShaftsCoreModule.h" // For the export macro
#include "vtkObject.h"                // For the base class

#include <memory> // For std::unique_ptr (the density field's source)

class vtkAlgorithmOutput;
class vtkImageData;
class vtkTexture;
class vtkVolume;

class VTKLIGHTSHAFTSCORE_EXPORT vtkLightShaftMedium : public vtkObject
{
public:
  static vtkLightShaftMedium* New();
  vtkTypeMacro(vtkLightShaftMedium, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Phase functions, normalised over the sphere.
  enum PhaseFunctionType
  {
    ISOTROPIC = 0,         ///< 1 / (4 pi)
    HENYEY_GREENSTEIN = 1, ///< (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^1.5)
    RAYLEIGH = 2           ///< 3 / (16 pi) (1 + cos^2 theta)
  };

  ///@{
  /**
   * Scattering coefficient sigma_s per world unit, per colour channel, in [0, 1e6]. The
   * one-argument form sets all three channels. Both coefficients zero: the pass renders the
   * scene unchanged. Default is (0.1, 0.1, 0.1).
   */
  void SetScatteringCoefficient(double r, double g, double b);
  void SetScatteringCoefficient(const double rgb[3]);
  void SetScatteringCoefficient(double grey);
  vtkGetVector3Macro(ScatteringCoefficient, double);
  ///@}

  ///@{
  /**
   * Absorption coefficient sigma_a per world unit, per colour channel, in [0, 1e6]; the
   * extinction is sigma_t = sigma_s + sigma_a. Default is (0, 0, 0).
   */
  void SetAbsorptionCoefficient(double r, double g, double b);
  void SetAbsorptionCoefficient(const double rgb[3]);
  void SetAbsorptionCoefficient(double grey);
  vtkGetVector3Macro(AbsorptionCoefficient, double);
  ///@}

  /**
   * When a coefficient setter (SetScatteringCoefficient, SetAbsorptionCoefficient) was last
   * called, whatever the value, as a VTK modification time (0: never): a pass choosing the
   * medium from the scene keeps coefficients set after it was asked to
   * (vtkLightShaftPass::SetFitMediumToScene).
   */
  vtkMTimeType GetCoefficientsSetTime();

  ///@{
  /**
   * Phase function: ISOTROPIC, HENYEY_GREENSTEIN or RAYLEIGH (values outside are clamped).
   * The scattering angle is between the light's propagation and the direction to the eye.
   * Default is ISOTROPIC.
   */
  vtkSetClampMacro(PhaseFunction, int, ISOTROPIC, RAYLEIGH);
  vtkGetMacro(PhaseFunction, int);
  void SetPhaseFunctionToIsotropic() { this->SetPhaseFunction(ISOTROPIC); }
  void SetPhaseFunctionToHenyeyGreenstein() { this->SetPhaseFunction(HENYEY_GREENSTEIN); }
  void SetPhaseFunctionToRayleigh() { this->SetPhaseFunction(RAYLEIGH); }
  ///@}

  ///@{
  /**
   * Henyey-Greenstein anisotropy g in [-0.99, 0.99]: g > 0 scatters forward (brightest looking
   * into the light), g < 0 backward. Used only by HENYEY_GREENSTEIN. Default is 0.
   */
  void SetAnisotropy(double g);
  vtkGetMacro(Anisotropy, double);
  ///@}

  ///@{
  /**
   * Scrolling-noise density (the GDC 2004 talk's two scrolling layers): sigma_s at x is
   * sigma_s * (1 + NoiseAmplitude * (N1 * N2 - 1)), N1 and N2 two tileable noise layers of mean
   * 1 projected from each light (a spot's and a directional light's square, as the cookie; a
   * point light's sphere of directions, triplanar), NoiseScale tiles across the light's square,
   * moved by NoiseVelocity1 and NoiseVelocity2 (tiles per unit of Time). The mean density, and
   * the extinction, stay those of the coefficients. NoiseAmplitude in [0, 1] (0: homogeneous,
   * no noise code runs), NoiseScale in [0.01, 1000], each velocity component in [-1e3, 1e3].
   * Defaults are 0, 3, (0.04, 0.01) and (-0.015, 0.03).
   */
  void SetNoiseAmplitude(double amplitude);
  vtkGetMacro(NoiseAmplitude, double);
  void SetNoiseScale(double scale);
  vtkGetMacro(NoiseScale, double);
  void SetNoiseVelocity1(double u, double v);
  vtkGetVector2Macro(NoiseVelocity1, double);
  void SetNoiseVelocity2(double u, double v);
  vtkGetVector2Macro(NoiseVelocity2, double);
  ///@}

  ///@{
  /**
   * Your own noise instead of the generated one (256x256 five-octave gradient noise): the
   * image's first component, tiled, rescaled to mean 1. nullptr: the generated noise. Default
   * is nullptr.
   */
  void SetNoiseTexture(vtkTexture* noise);
  vtkTexture* GetNoiseTexture();
  ///@}

  ///@{
  /**
   * Animation time, any finite value, in the units of the noise velocities: the noise is a
   * pure function of it, so the same Time renders the same picture. Default is 0.
   */
  void SetTime(double time);
  vtkGetMacro(Time, double);
  ///@}

  ///@{
  /**
   * A medium from data: sigma_s and sigma_a at x are scaled by BackgroundDensity +
   * DensityScale * rho(x), rho the first component of the array named DensityArrayName (point
   * or cell data; the scalars when no name), trilinear inside the image's bounds (placed by its
   * origin, spacing and direction matrix) and 0 outside. An image that cannot be one (no such
   * array, not 3D, over 2^27 samples, NaN or negative values) is refused with an error saying
   * why, and the previous field is kept. SetDensityFieldConnection takes the field from a
   * pipeline instead (brought up to date at each render; an output that cannot be a field gets
   * one error and the last usable field is kept); each setter replaces the other's source.
   * GetDensityField is the image in use (a pipeline's last usable output). Defaults are
   * nullptr (homogeneous), nullptr and "" (the scalars).
   */
  void SetDensityField(vtkImageData* density);
  vtkImageData* GetDensityField();
  void SetDensityFieldConnection(vtkAlgorithmOutput* output);
  vtkAlgorithmOutput* GetDensityFieldConnection();
  void SetDensityArrayName(const char* name);
  const char* GetDensityArrayName();
  ///@}

  ///@{
  /**
   * A volume of the scene as the medium: rho is its opacity alpha = OTF(s) at its image's
   * samples (its mapper's scalars, first component, through the property's first scalar
   * opacity function), placed as the volume renders it (its matrix too), read again when the
   * volume, its mapper, input, property or opacity function change: the smoke the scene renders
   * is what scatters the light (docs/translucent-and-volumes.md#a-volume-as-the-medium). It
   * replaces SetDensityField's and SetDensityFieldConnection's source (and they replace it);
   * the volume then dims the shafts as the medium, not as a volume in the medium. A volume
   * that gives no field gets one error and the last usable field is kept. Default is nullptr.
   */
  void SetDensityVolume(vtkVolume* volume);
  vtkVolume* GetDensityVolume();
  ///@}

  ///@{
  /**
   * The field's scale and the density added everywhere (also outside the field), each in
   * [0, 1e6]. Defaults are 1 and 0.
   */
  void SetDensityScale(double scale);
  vtkGetMacro(DensityScale, double);
  void SetBackgroundDensity(double density);
  vtkGetMacro(BackgroundDensity, double);
  ///@}

  ///@{
  /**
   * The light leg through the field: texels per axis of each light's table of the field's
   * optical depth from the light (half as many per face of a cube around a light inside the
   * field), built on the CPU when the field or the light moves; 0 marches the leg at every
   * sample instead (slower). In [0, 256]. Default is 64.
   */
  vtkSetClampMacro(FieldShadowResolution, int, 0, 256);
  vtkGetMacro(FieldShadowResolution, int);
  ///@}

  ///@{
  /**
   * The most samples per axis the shafts read from a field: a field with more along an axis is
   * resampled (trilinear) to this many points spanning its bounds, so that the pass's grid
   * stays bounded whatever the data's size (also by the GL's largest 3D texture;
   * vtkLightShaftReference integrates the field as it is). Under ParaView's MPI each process
   * resamples its piece (docs/paraview-mpi.md). In [16, 16384]. Default is 2048.
   */
  vtkSetClampMacro(FieldResolution, int, 16, 16384);
  vtkGetMacro(FieldResolution, int);
  ///@}

  /**
   * The density image of this render: SetDensityField's image, the pipeline's output
   * brought up to date (an output that is not an image: one error from `caller`, and the last
   * one that was stays in use), or the density volume's opacity image. nullptr: a homogeneous
   * medium.
   */
  vtkImageData* UpdateDensityField(vtkObject* caller);

protected:
  vtkLightShaftMedium();
  ~vtkLightShaftMedium() override;

  double ScatteringCoefficient[3] = { 0.1, 0.1, 0.1 };
  double AbsorptionCoefficient[3] = { 0.0, 0.0, 0.0 };
  int PhaseFunction = ISOTROPIC;
  double Anisotropy = 0.0;
  double NoiseAmplitude = 0.0;
  double NoiseScale = 3.0;
  double NoiseVelocity1[2] = { 0.04, 0.01 };
  double NoiseVelocity2[2] = { -0.015, 0.03 };
  double Time = 0.0;
  double DensityScale = 1.0;
  double BackgroundDensity = 0.0;
  int FieldShadowResolution = 64;
  int FieldResolution = 2048;

private:
  vtkLightShaftMedium(const vtkLightShaftMedium&) = delete;
  void operator=(const vtkLightShaftMedium&) = delete;

  // The texture of a pass takes the field the setter read (not read twice).
  friend class vtkLightShaftMediumTexture;
  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
