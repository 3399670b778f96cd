/**
 * @file   vtkLightShaftErrorModel.h
 * @brief  The measured error model of the SLICES method (private, not installed): what a
 *         frame's geometry says about how hard its shafts are to sample, the error each setting
 *         of the ladder is predicted to make there, and the cheapest setting that meets a
 *         target.
 *
 * The ladder and the model's coefficients are fitted on random scenes by
 * tests/benchmarks/fit_error_model.py, which writes vtkLightShaftErrorModelTable.h; the model
 * is validated on other seeds (docs/quality-and-cost.md).
 */
#ifndef vtkLightShaftErrorModel_h
#define vtkLightShaftErrorModel_h

#include "vtkLightShaftFieldError.h" // For a medium from data
#include "vtkLightShaftGeometry.h"   // For the light and camera frames
#include "vtkLightShaftModel.h"      // For the medium

#include <vector> // For the lights' features

namespace vtkLightShaftErrorModel
{
/**
 * What one light's shafts ask of the sampling, from the geometry the frame already has:
 * the lit part of the view volume (its depth range and its centre) and the beam there.
 */
struct Features
{
  bool Lit = false; ///< the light reaches the view volume (else nothing to predict)
  /// The lit volume's view-depth range over the beam's width at its centre (spot: the width
  /// of the cone, or of the half-intensity cone of its exponent; point: the distance from the
  /// light; directional: the depth range itself, 1).
  double DepthRangeInBeamWidths = 0.0;
  /// That beam width over the width of a pixel at the same depth.
  double BeamWidthInPixels = 0.0;
  /// The medium's largest sigma_t times the depth range.
  double OpticalDepth = 0.0;
  /// The width of a texel of a 1024^2 shadow map at the lit volume's centre over the width of
  /// a pixel there (0 when nothing can shadow the light: no map).
  double ShadowTexelInPixels = 0.0;
  /// The light (a directional light: its direction) projects inside the view, in front.
  bool LightInView = false;
  bool FallingAttenuation = false;
  vtkLightShaftModel::LightKind Kind = vtkLightShaftModel::LightKind::Spot;
  /// A medium from data: for each setting of the ladder, the relative error of its samples'
  /// evenly spaced samples' integral of the density along view rays through the lit volume (empty:
  /// none).
  std::vector<double> FieldError;
  /// The light leg's table's own error, one of FieldError's terms (0: none, or marched).
  double LightLegError = 0.0;
};

/**
 * The features of `light` seen by `camera` in a viewport `width` pixels wide; with `density`
 * (a medium from data), OpticalDepth along view rays through its field, measured, and the
 * field's quadrature error at each setting's samples.
 */
Features Describe(const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  const vtkLightShaftModel::Medium& medium,
  int width,
  const vtkLightShaftFieldError::Density* density = nullptr);

/**
 * A medium from data's error. The homogeneous fit misses what a field does to the picture (its
 * density gathers the light where the shadows' and the steps' errors are, a layer's edge is
 * seen across the shafts): its prediction is scaled by FieldFactor (EPIPOLAR's own, whose
 * interpolation along its lines smears a field's edges, FieldFactorEpipolar), and FieldMargin
 * times the field's quadrature error at a setting's steps is added. Both measured on random
 * field scenes, nine in ten predicted (tests/benchmarks/field_error_model.py: see
 * docs/medium-field.md).
 */
constexpr double FieldFactor = 1.5;
constexpr double FieldFactorEpipolar = 4.0;
constexpr double FieldMargin = 0.5;

/**
 * One setting of the ladder: a method (SLICES with a fixed slice count, RAY_MARCH, EPIPOLAR or
 * LIGHT_VOLUME) and the parameters it sets (32-bit float accumulation).
 */
struct Setting
{
  const char* Name;
  int Method;  ///< vtkLightShaftEnums::SLICES, RAY_MARCH, EPIPOLAR or LIGHT_VOLUME
  int Samples; ///< slices, ray-march steps (EPIPOLAR: per sample), or light-volume cells
  bool Jitter; ///< SLICES
  int BlurRadius;
  int DownsampleFactor;
  int ShadowMapSize;
  int InterleaveSize;    ///< RAY_MARCH
  int EpipolarLines = 0; ///< EPIPOLAR
  int EpipolarSamples = 0;
  int EpipolarStep = 0;
};

/// The ladder's settings, cheapest first.
int GetNumberOfSettings();
const Setting& GetSetting(int index);
/// A setting's name ("M256 i1 m2048", ...; "none" for an index off the ladder).
const char* GetSettingName(int index);
/// The quality presets: each the cheapest setting of the ladder whose training 90th-percentile
/// error meets the preset's aim (Draft 5%, Interactive 2%, Final 0.5%).
enum class Preset
{
  Draft,
  Interactive,
  Final
};
const Setting& GetPreset(Preset preset);

/// The index of the ladder's setting that `setting` equals (its name aside), else -1.
int FindSetting(const Setting& setting);

/**
 * The relative RMS error setting `index` is predicted to make on a light with `features`
 * (an upper estimate: the fit's residuals' 90th percentile above the fit, plus a field's
 * term); 0 for an unlit light.
 */
double Predict(int index, const Features& features);
/// The largest prediction over the lights.
double Predict(int index, const std::vector<Features>& lights);
/// The largest prediction over the lights, their light leg's table's term left out: what the
/// setting's samples make, the table aside.
double PredictApartFromLightLeg(int index, const std::vector<Features>& lights);
/// Replace the light leg's table's term of `features` (another resolution, or 0: marched).
void SetLightLegError(Features& features, double error);

/**
 * The cheapest setting predicted to make at most `target` on every light (the most accurate
 * one when none is), and its prediction in `predicted`. Without `closedForm` (a cookie or
 * noise) the LIGHT_VOLUME settings are left out: they would give way to RAY_MARCH.
 */
int Choose(double target, const std::vector<Features>& lights, bool closedForm, double& predicted);
}

#endif
