/**
 * @file   vtkLightShaftErrorModelTable.h
 * @brief  The error model's ladder and coefficients (private, not installed). Written by
 *         tests/benchmarks/fit_error_model.py: do not edit by hand.
 */
#ifndef vtkLightShaftErrorModelTable_h
#define vtkLightShaftErrorModelTable_h

#include "vtkLightShaftErrorModel.h" // For vtkLightShaftErrorModel::Setting
#include "vtkLightShaftPass.h"       // For the methods

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
  { { "S16 j b2 d2 m512", vtkLightShaftPass::SLICES, 16, true, 2, 2, 512, 1 }, { 2.25931, -0.437163, -1.16919, 1.02836, 1.21954, -2.49629, -0.818429, -0.269141, 1.08816, 0.278341, 0.222249 }, 1.83421 },
  { { "S32 j b2 d2 m512", vtkLightShaftPass::SLICES, 32, true, 2, 2, 512, 1 }, { 1.5686, -0.447614, -1.08456, 1.04643, 1.42975, -2.14929, -0.789773, -0.282091, 0.958716, 0.229452, 0.125487 }, 1.79921 },
  { { "S32 j b1 d2 m1024", vtkLightShaftPass::SLICES, 32, true, 1, 2, 1024, 1 }, { 1.81818, -0.486288, -1.13277, 1.05809, 1.15847, -2.43691, -0.754938, -0.255786, 1.05441, 0.298716, 0.25985 }, 2.02561 },
  { { "S64 b0 d2 m1024", vtkLightShaftPass::SLICES, 64, false, 0, 2, 1024, 1 }, { 1.51516, -0.42888, -1.09726, 1.06498, 1.06935, -2.19108, -0.73824, -0.199296, 1.02951, 0.274351, 0.331794 }, 2.00353 },
  { { "S32 b0 d1 m1024", vtkLightShaftPass::SLICES, 32, false, 0, 1, 1024, 1 }, { 2.69995, -0.384261, -1.21702, 0.695671, -0.0581437, 0.958179, -1.77654, -0.0145795, 0.707828, -0.223272, 0.82193 }, 2.11052 },
  { { "S64 b0 d1 m1024", vtkLightShaftPass::SLICES, 64, false, 0, 1, 1024, 1 }, { 1.49323, -0.335481, -1.09385, 0.620059, 0.11195, 0.695211, -1.59542, 0.0389699, 0.721241, -0.18358, 0.77824 }, 1.85179 },
  { { "M64 i1 m2048", vtkLightShaftPass::RAY_MARCH, 64, false, 0, 1, 2048, 1 }, { -4.10222, -0.293396, -0.278932, -0.131548, -1.6965, 1.32282, -0.566857, -0.279366, 0.927213, -0.213637, 0.23875 }, 1.7454 },
  { { "M128 i1 m2048", vtkLightShaftPass::RAY_MARCH, 128, false, 0, 1, 2048, 1 }, { -5.23708, -0.200527, -0.151341, -0.151272, -1.4996, 1.25897, -0.556646, -0.189882, 1.00321, -0.217949, 0.183532 }, 1.66783 },
  { { "M256 i1 m2048", vtkLightShaftPass::RAY_MARCH, 256, false, 0, 1, 2048, 1 }, { -5.86612, -0.142646, -0.0824899, -0.166112, -1.41491, 1.1784, -0.571966, -0.0902672, 1.0979, -0.218366, 0.174355 }, 1.62473 },
};

/// The presets (Rows' indices): the cheapest setting whose training p90 meets each aim.
constexpr int DraftSetting = 5; // S64 b0 d1 m1024, aim p90 <= 5%
constexpr int InteractiveSetting = 6; // M64 i1 m2048, aim p90 <= 2%
constexpr int FinalSetting = 8; // M256 i1 m2048, aim p90 <= 0.5%
// clang-format on
}

#endif
