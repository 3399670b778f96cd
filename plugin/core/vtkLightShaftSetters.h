/**
 * @file   vtkLightShaftSetters.h
 * @brief  The rule every floating-point setter of the public classes follows (private, not
 *         installed): NaN and infinities refused with an error naming the parameter (the
 *         previous value kept), other values clamped into the parameter's range.
 */
#ifndef vtkLightShaftSetters_h
#define vtkLightShaftSetters_h

#include "vtkMath.h"   // For vtkMath::ClampValue
#include "vtkObject.h" // For vtkErrorWithObjectMacro and Modified

#include <algorithm>        // For std::all_of
#include <cmath>            // For std::isfinite
#include <cstddef>          // For size_t
#include <initializer_list> // For the values

namespace vtkLightShaftSetters
{
/// True (and one error naming `parameter`) when any of `values` is NaN or infinite.
inline bool RefuseNonFinite(vtkObject* self,
  const char* parameter,
  std::initializer_list<double> values)
{
  if (std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
  {
    return false;
  }
  vtkErrorWithObjectMacro(
    self, << parameter << ": non-finite value refused; the previous value is kept.");
  return true;
}

/// Clamp `values` into [low, high] and store them in `target`; Modified() when they changed.
inline void SetClamped(vtkObject* self,
  const char* parameter,
  double* target,
  std::initializer_list<double> values,
  double low,
  double high)
{
  if (RefuseNonFinite(self, parameter, values))
  {
    return;
  }
  bool changed = false;
  size_t i = 0;
  for (double value : values)
  {
    const double clamped = vtkMath::ClampValue(value, low, high);
    changed = changed || target[i] != clamped;
    target[i++] = clamped;
  }
  if (changed)
  {
    self->Modified();
  }
}
} // namespace vtkLightShaftSetters

#endif
