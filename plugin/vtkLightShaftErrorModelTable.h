/**
 * @file   vtkLightShaftErrorModelTable.h
 * @brief  The error model's ladder and coefficients (private, not installed). Written by
 *         tests/benchmarks/fit_error_model.py: do not edit by hand.
 */
#ifndef vtkLightShaftErrorModelTable_h
#define vtkLightShaftErrorModelTable_h

#include "vtkLightShaftErrorModel.h" // For vtkLightShaftErrorModel::Setting

namespace vtkLightShaftErrorModelTable
{
/// 1, log depth range in beam widths, log beam width in pixels, log(1 + optical depth),
/// light in view with falling attenuation, light in view, point light, directional light.
constexpr int NumberOfVariables = 8;

struct Row
{
  vtkLightShaftErrorModel::Setting Ladder;
  double Coefficients[NumberOfVariables]; ///< of the log of the relative RMS error
  double Margin; ///< the 90th percentile of the fit's leave-one-out residuals (log)
};

// clang-format off
constexpr Row Rows[] = {
  { { "S32 j b2 d2 m512", 32, true, 2, 2, 512 }, { -3.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
  { { "S64 j b2 d1 m1024", 64, true, 2, 1, 1024 }, { -4.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
  { { "S512 b0 d1 m2048", 512, false, 0, 1, 2048 }, { -6.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
};
// clang-format on
}

#endif
