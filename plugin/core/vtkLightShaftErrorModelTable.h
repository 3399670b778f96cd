/**
 * @file   vtkLightShaftErrorModelTable.h
 * @brief  The error model's ladder and coefficients (private, not installed). Written by
 *         tests/benchmarks/fit_error_model.py: do not edit by hand.
 */
#ifndef vtkLightShaftErrorModelTable_h
#define vtkLightShaftErrorModelTable_h

#include "vtkLightShaftEnums.h"      // For the methods
#include "vtkLightShaftErrorModel.h" // For vtkLightShaftErrorModel::Setting

namespace vtkLightShaftErrorModelTable
{
/// 1, log depth range in beam widths, log beam width in pixels, log(1 + optical depth),
/// light in view with falling attenuation, light in view, point light, directional light,
/// light in view times the two logs, log shadow-map texel in pixels (0: no map).
constexpr int NumberOfVariables = 11;

struct Row
{
  vtkLightShaftErrorModel::Setting Ladder;
  double Coefficients[NumberOfVariables]; ///< of the log of the relative RMS error
  double Margin; ///< the 90th percentile of the fit's leave-one-out residuals (log)
};

// clang-format off
constexpr Row Rows[] = {
  { { "E16 l128 s256 k8 m512", vtkLightShaftEnums::EPIPOLAR, 16, false, 0, 1, 512, 1, 128, 256, 8 }, { -2.4766, -0.121309, -0.375438, 0.430772, -0.394413, 0.447823, -1.08366, -0.517195, 0.881889, -0.123584, 0.0810453 }, 1.53684 },
  { { "E32 l256 s256 k8 m1024", vtkLightShaftEnums::EPIPOLAR, 32, false, 0, 1, 1024, 1, 256, 256, 8 }, { -3.47812, 0.106222, -0.311202, 0.501811, -0.108131, 0.486414, -1.07668, -0.256139, 0.637982, -0.122264, 0.0760101 }, 1.38556 },
  { { "V128 m512", vtkLightShaftEnums::LIGHT_VOLUME, 128, false, 0, 1, 512, 1, 0, 0, 0 }, { -0.866033, -0.433127, -0.633498, -0.0225109, -2.15436, -0.553467, -0.75721, -0.522347, 1.09067, 0.0192875, 0.638693 }, 1.95586 },
  { { "V256 m1024", vtkLightShaftEnums::LIGHT_VOLUME, 256, false, 0, 1, 1024, 1, 0, 0, 0 }, { -2.15025, -0.310476, -0.503498, -0.101246, -1.92808, -0.547418, -0.615714, -0.407731, 1.14561, 0.0132883, 0.549546 }, 1.76773 },
  { { "V512 m2048", vtkLightShaftEnums::LIGHT_VOLUME, 512, false, 0, 1, 2048, 1, 0, 0, 0 }, { -3.85328, -0.129636, -0.311109, -0.11727, -1.73938, -0.431609, -0.502927, -0.291007, 1.15187, 0.00252519, 0.434652 }, 1.64773 },
  { { "V1024 m2048", vtkLightShaftEnums::LIGHT_VOLUME, 1024, false, 0, 1, 2048, 1, 0, 0, 0 }, { -4.67747, -0.0211167, -0.220663, -0.106395, -1.5227, -0.429201, -0.483219, -0.22315, 1.07803, 0.00539053, 0.312982 }, 1.54426 },
  { { "M128 i1 m2048", vtkLightShaftEnums::RAY_MARCH, 128, false, 0, 1, 2048, 1, 0, 0, 0 }, { -5.23708, -0.200527, -0.151341, -0.151272, -1.4996, 1.25897, -0.556646, -0.189882, 1.00321, -0.217949, 0.183532 }, 1.66783 },
  { { "M256 i1 m2048", vtkLightShaftEnums::RAY_MARCH, 256, false, 0, 1, 2048, 1, 0, 0, 0 }, { -5.86612, -0.142646, -0.0824899, -0.166112, -1.41491, 1.1784, -0.571966, -0.0902672, 1.0979, -0.218366, 0.174355 }, 1.62473 },
};

/// The presets (Rows' indices): the cheapest setting whose training p90 meets each aim.
constexpr int DraftSetting = 0; // E16 l128 s256 k8 m512, aim p90 <= 5%
constexpr int InteractiveSetting = 3; // V256 m1024, aim p90 <= 2%
constexpr int FinalSetting = 7; // M256 i1 m2048, aim p90 <= 0.5%
// clang-format on
}

#endif
