#include "vtkLightShaftVolumeField.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace
{
// alpha is held below 1: an opaque sample is a very large, finite kappa.
constexpr double MostOpacity = 1.0 - 1.0e-6;

// The image's placement (index to world: origin + direction * spacing * index) composed with
// the prop's matrix; false when the result is not invertible.
bool Place(vtkImageData* input, vtkMatrix4x4* matrix, vtkImageData* out)
{
  double origin[3];
  double spacing[3];
  input->GetOrigin(origin);
  input->GetSpacing(spacing);
  const double* direction = input->GetDirectionMatrix()->GetData();
  double placed[4] = { 0.0, 0.0, 0.0, 1.0 };
  const double point[4] = { origin[0], origin[1], origin[2], 1.0 };
  matrix->MultiplyPoint(point, placed);
  // Column k of M * D * diag(spacing): its length is the new spacing, its direction the new
  // direction's column.
  vtkNew<vtkMatrix3x3> newDirection;
  double newSpacing[3];
  for (int k = 0; k < 3; ++k)
  {
    double column[3] = { 0.0, 0.0, 0.0 };
    for (int row = 0; row < 3; ++row)
    {
      for (int j = 0; j < 3; ++j)
      {
        column[row] += matrix->GetElement(row, j) * direction[3 * j + k] * spacing[k];
      }
    }
    newSpacing[k] =
      std::sqrt(column[0] * column[0] + column[1] * column[1] + column[2] * column[2]);
    if (!(newSpacing[k] > 0.0) || !std::isfinite(newSpacing[k]))
    {
      return false;
    }
    for (int row = 0; row < 3; ++row)
    {
      newDirection->SetElement(row, k, column[row] / newSpacing[k]);
    }
  }
  if (!(std::abs(newDirection->Determinant()) > 1e-12))
  {
    return false;
  }
  out->SetExtent(input->GetExtent());
  out->SetOrigin(placed[0] / placed[3], placed[1] / placed[3], placed[2] / placed[3]);
  out->SetSpacing(newSpacing);
  out->SetDirectionMatrix(newDirection);
  return true;
}
}

//------------------------------------------------------------------------------
std::string vtkLightShaftVolumeField::Build(vtkVolume* volume, Quantity quantity, vtkImageData* out)
{
  out->Initialize();
  vtkImageData* input = nullptr;
  bool cells = false;
  std::string why;
  vtkDataArray* scalars = RenderedScalars(volume, input, cells, why);
  if (!scalars)
  {
    return why;
  }
  vtkVolumeProperty* property = volume->GetProperty();
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  if (!opacity)
  {
    return "has no scalar opacity function";
  }
  if (!Place(input, volume->GetMatrix(), out))
  {
    return "has a placement (matrix, spacing or direction) that is not invertible";
  }
  const double unit = std::max(property->GetScalarOpacityUnitDistance(0), 1e-30);
  const vtkIdType n = scalars->GetNumberOfTuples();
  vtkNew<vtkFloatArray> values;
  values->SetName(quantity == Quantity::Extinction ? "Extinction" : "Opacity");
  values->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double alpha =
      std::min(std::max(opacity->GetValue(scalars->GetComponent(i, 0)), 0.0), MostOpacity);
    const double value = quantity == Quantity::Extinction ? -std::log1p(-alpha) / unit : alpha;
    values->SetValue(i, static_cast<float>(value));
  }
  if (cells)
  {
    out->GetCellData()->SetScalars(values);
  }
  else
  {
    out->GetPointData()->SetScalars(values);
  }
  return "";
}

//------------------------------------------------------------------------------
vtkDataArray* vtkLightShaftVolumeField::RenderedScalars(vtkVolume* volume,
  vtkImageData*& input,
  bool& cells,
  std::string& why)
{
  input = nullptr;
  cells = false;
  auto* mapper = volume ? vtkAbstractVolumeMapper::SafeDownCast(volume->GetMapper()) : nullptr;
  if (!mapper)
  {
    why = "has no volume mapper";
    return nullptr;
  }
  input = vtkImageData::SafeDownCast(mapper->GetDataSetInput());
  if (!input)
  {
    why = "has no image data as its mapper's input";
    return nullptr;
  }
  int association = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(input,
    mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(),
    mapper->GetArrayId(),
    mapper->GetArrayName(),
    association);
  if (!scalars || association > 1 || scalars->GetNumberOfTuples() == 0)
  {
    why = "has no point or cell scalars to render";
    return nullptr;
  }
  cells = association == 1;
  return scalars;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightShaftVolumeField::Time(vtkVolume* volume)
{
  vtkMTimeType time = volume->GetMTime();
  if (vtkAbstractVolumeMapper* mapper = vtkAbstractVolumeMapper::SafeDownCast(volume->GetMapper()))
  {
    time = std::max(time, mapper->GetMTime());
    if (vtkDataSet* input = mapper->GetDataSetInput())
    {
      time = std::max(time, input->GetMTime());
    }
  }
  if (vtkVolumeProperty* property = volume->GetProperty())
  {
    time = std::max(time, property->GetMTime());
    if (vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0))
    {
      time = std::max(time, opacity->GetMTime());
    }
  }
  return time;
}
