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
constexpr int NumberOfVariables = 8;
struct Row
{
  vtkLightShaftErrorModel::Setting Ladder;
  double Coefficients[NumberOfVariables];
  double Margin;
};
// clang-format off
constexpr Row Rows[] = {
  { { "S32 j b2 d2 m512", vtkLightShaftPass::SLICES, 32, true, 2, 2, 512, 1 }, { -3.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
  { { "S64 j b2 d1 m1024", vtkLightShaftPass::SLICES, 64, true, 2, 1, 1024, 1 }, { -4.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
  { { "S512 b0 d1 m2048", vtkLightShaftPass::SLICES, 512, false, 0, 1, 2048, 1 }, { -6.0, 0, 0, 0, 0, 0, 0, 0 }, 0.0 },
};
// clang-format on
}

#endif
