#include "vtkLightShaftDensityField.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
bool Finite3(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The trilinear neighbours of point index p (relative to the image's first point) in an image of
// `points` points and `samples` samples per axis (cell centres: half a cell further on): the
// lower sample and the fraction towards the next, per axis; false outside the bounds.
bool Neighbours(const double p[3],
  const int points[3],
  const int samples[3],
  bool cellCentred,
  int base[3],
  double fraction[3])
{
  for (int k = 0; k < 3; ++k)
  {
    if (!(p[k] >= 0.0 && p[k] <= points[k] - 1))
    {
      return false;
    }
    const double c =
      std::min(std::max(cellCentred ? p[k] - 0.5 : p[k], 0.0), static_cast<double>(samples[k] - 1));
    base[k] = std::min(static_cast<int>(c), std::max(samples[k] - 2, 0));
    fraction[k] = c - base[k];
  }
  return true;
}

// The weighted sum of the eight neighbours (a single sample along an axis: no second corner);
// value(i, j, k) is the sample at those sample indices.
template<typename Value>
double Trilinear(const int base[3], const double fraction[3], const int samples[3], Value value)
{
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    double weight = 1.0;
    int at[3];
    for (int k = 0; k < 3; ++k)
    {
      const int step = (corner >> k) & 1;
      if (step && samples[k] == 1)
      {
        weight = 0.0;
        break;
      }
      weight *= step ? fraction[k] : 1.0 - fraction[k];
      at[k] = base[k] + step;
    }
    if (weight != 0.0)
    {
      sum += weight * value(at[0], at[1], at[2]);
    }
  }
  return sum;
}
}

//------------------------------------------------------------------------------
vtkDataArray* vtkLightShaftDensityField::FindArray(vtkImageData* image,
  const char* name,
  bool& cells,
  std::string& why)
{
  vtkDataArray* array = nullptr;
  if (name && *name)
  {
    array = image->GetPointData()->GetArray(name);
    cells = !array;
    if (!array)
    {
      array = image->GetCellData()->GetArray(name);
    }
    if (!array)
    {
      why = std::string("has no numeric point or cell array named \"") + name + "\"";
    }
    return array;
  }
  array = image->GetPointData()->GetScalars();
  cells = !array;
  if (!array)
  {
    array = image->GetCellData()->GetScalars();
  }
  if (!array)
  {
    why = "has no point or cell scalars (name its array with SetMediumDensityArrayName before "
          "setting it)";
  }
  return array;
}

//------------------------------------------------------------------------------
std::string vtkLightShaftDensityField::Read(vtkImageData* image, const char* arrayName)
{
  if (!image)
  {
    return "is null";
  }
  int points[3];
  image->GetDimensions(points);
  if (points[0] < 2 || points[1] < 2 || points[2] < 2)
  {
    std::ostringstream why;
    why << "is not a 3D image (" << points[0] << " x " << points[1] << " x " << points[2]
        << " points; a density field needs at least 2 along each axis)";
    return why.str();
  }
  bool cells = false;
  std::string why;
  vtkDataArray* array = FindArray(image, arrayName, cells, why);
  if (!array)
  {
    return why;
  }
  int samples[3];
  std::size_t count = 1;
  for (int k = 0; k < 3; ++k)
  {
    samples[k] = cells ? points[k] - 1 : points[k];
    count *= static_cast<std::size_t>(samples[k]);
  }
  if (count > MaximumSamples)
  {
    std::ostringstream text;
    text << "has " << count << " samples, more than the " << MaximumSamples
         << " (512^3) a density field may have (resample it, e.g. with vtkImageResample)";
    return text.str();
  }
  if (static_cast<std::size_t>(array->GetNumberOfTuples()) != count)
  {
    return std::string("array \"") + (array->GetName() ? array->GetName() : "") +
           "\" has a number of values that does not match the image's dimensions";
  }

  // Placement: x = origin + D S (p + extent start) for point index p.
  double spacing[3];
  double origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  double indexToWorld[9];
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      indexToWorld[3 * r + c] = direction->GetElement(r, c) * spacing[c];
    }
  }
  const double determinant = vtkMatrix3x3::Determinant(indexToWorld);
  if (!Finite3(spacing) || !Finite3(origin) || !std::isfinite(determinant) ||
      std::abs(determinant) < 1e-300)
  {
    return "has a spacing, origin or direction matrix that is not finite or not invertible";
  }

  std::vector<float> values(count);
  double maximum = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double value = array->GetComponent(static_cast<vtkIdType>(i), 0);
    if (!std::isfinite(value) || value < 0.0)
    {
      std::ostringstream text;
      text << "has the value " << value << " at index " << i
           << " (a density must be finite and not negative)";
      return text.str();
    }
    values[i] = static_cast<float>(value);
    maximum = std::max(maximum, static_cast<double>(values[i]));
  }

  double worldToIndex[9];
  vtkMatrix3x3::Invert(indexToWorld, worldToIndex);
  const int* extent = image->GetExtent();
  for (int r = 0; r < 3; ++r)
  {
    this->Origin[r] = origin[r];
    for (int c = 0; c < 3; ++c)
    {
      this->Origin[r] += indexToWorld[3 * r + c] * extent[2 * c];
      this->WorldToIndex[r][c] = worldToIndex[3 * r + c];
      this->IndexToWorld[r][c] = indexToWorld[3 * r + c];
    }
    this->Samples[r] = samples[r];
    this->Points[r] = points[r];
  }
  this->CellCentred = cells;
  this->Maximum = maximum;
  this->Values.swap(values);
  return "";
}

//------------------------------------------------------------------------------
void vtkLightShaftDensityField::ToIndex(const double x[3], double p[3]) const
{
  const double d[3] = { x[0] - this->Origin[0], x[1] - this->Origin[1], x[2] - this->Origin[2] };
  for (int r = 0; r < 3; ++r)
  {
    p[r] = this->WorldToIndex[r][0] * d[0] + this->WorldToIndex[r][1] * d[1] +
           this->WorldToIndex[r][2] * d[2];
  }
}

double vtkLightShaftDensityField::Density(const double x[3]) const
{
  double p[3];
  this->ToIndex(x, p);
  return this->DensityAtIndex(p);
}

double vtkLightShaftDensityField::DensityAtIndex(const double p[3]) const
{
  if (this->Values.empty())
  {
    return 0.0;
  }
  int base[3];
  double fraction[3];
  if (!Neighbours(p, this->Points, this->Samples, this->CellCentred, base, fraction))
  {
    return 0.0; // outside the bounds (or not a number)
  }
  const std::size_t nx = this->Samples[0];
  const std::size_t nxy = nx * this->Samples[1];
  return Trilinear(base,
    fraction,
    this->Samples,
    [this, nx, nxy](int i, int j, int k) { return this->Values[i + nx * j + nxy * k]; });
}

//------------------------------------------------------------------------------
void vtkLightShaftDensityField::IndexBreakpoints(const double pa[3],
  const double pb[3],
  std::vector<double>& s) const
{
  const double shift = this->CellCentred ? 0.5 : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double delta = pb[k] - pa[k];
    if (delta == 0.0)
    {
      continue;
    }
    auto add = [&](double plane)
    {
      const double at = (plane - pa[k]) / delta;
      if (at > 0.0 && at < 1.0)
      {
        s.push_back(at);
      }
    };
    add(0.0);
    add(this->Points[k] - 1.0);
    // The sample planes inside the bounds crossed by the segment.
    const double lo = std::max(std::min(pa[k], pb[k]) - shift, 0.0);
    const double hi = std::min(std::max(pa[k], pb[k]) - shift, this->Samples[k] - 1.0);
    for (double plane = std::ceil(lo); plane <= hi; plane += 1.0)
    {
      add(plane + shift);
    }
  }
  std::sort(s.begin(), s.end());
}

double vtkLightShaftDensityField::Integral(const double a[3], const double b[3]) const
{
  if (this->Values.empty())
  {
    return 0.0;
  }
  double pa[3];
  double pb[3];
  this->ToIndex(a, pa);
  this->ToIndex(b, pb);
  const double length = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  std::vector<double> s{ 0.0 };
  this->IndexBreakpoints(pa, pb, s);
  s.push_back(1.0);
  // Two-point Gauss-Legendre per piece: exact for the cubic rho is along a line in one cell.
  const double node = 0.5 / std::sqrt(3.0);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i)
  {
    const double width = s[i + 1] - s[i];
    if (width <= 0.0)
    {
      continue;
    }
    const double mid = 0.5 * (s[i] + s[i + 1]);
    double pieceSum = 0.0;
    for (double at : { mid - node * width, mid + node * width })
    {
      const double p[3] = {
        pa[0] + at * (pb[0] - pa[0]), pa[1] + at * (pb[1] - pa[1]), pa[2] + at * (pb[2] - pa[2])
      };
      pieceSum += this->DensityAtIndex(p);
    }
    sum += 0.5 * width * pieceSum;
  }
  return sum * length;
}

void vtkLightShaftDensityField::Cumulative(const double origin[3],
  const double dir[3],
  double t0,
  const double* t,
  int n,
  float* out,
  int stride) const
{
  if (n <= 0)
  {
    return;
  }
  const double t1 = t[n - 1];
  std::vector<double> breaks;
  this->Breakpoints(origin, dir, t0, t1, breaks);
  double p0[3];
  this->ToIndex(origin, p0);
  double d[3];
  for (int r = 0; r < 3; ++r)
  {
    d[r] = this->WorldToIndex[r][0] * dir[0] + this->WorldToIndex[r][1] * dir[1] +
           this->WorldToIndex[r][2] * dir[2];
  }
  // Two-point Gauss-Legendre over each piece between consecutive breakpoints and targets.
  const double node = 0.5 / std::sqrt(3.0);
  auto piece = [&](double a, double b)
  {
    double sum = 0.0;
    for (double at : { 0.5 * (a + b) - node * (b - a), 0.5 * (a + b) + node * (b - a) })
    {
      const double p[3] = { p0[0] + at * d[0], p0[1] + at * d[1], p0[2] + at * d[2] };
      sum += this->DensityAtIndex(p);
    }
    return 0.5 * (b - a) * sum;
  };
  double total = 0.0;
  double at = t0;
  std::size_t next = 0;
  for (int k = 0; k < n; ++k)
  {
    for (; next < breaks.size() && breaks[next] < t[k]; ++next)
    {
      if (breaks[next] > at)
      {
        total += piece(at, breaks[next]);
        at = breaks[next];
      }
    }
    if (t[k] > at)
    {
      total += piece(at, t[k]);
      at = t[k];
    }
    out[static_cast<std::size_t>(k) * stride] = static_cast<float>(total);
  }
}

double vtkLightShaftDensityField::PlanesPerLength(const double dir[3]) const
{
  double planes = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    planes += std::abs(this->WorldToIndex[r][0] * dir[0] + this->WorldToIndex[r][1] * dir[1] +
                       this->WorldToIndex[r][2] * dir[2]);
  }
  return planes;
}

vtkLightShaftDensityField vtkLightShaftDensityField::Resampled(int maximum) const
{
  vtkLightShaftDensityField out;
  double step[3]; // this field's point index per point of the resampled one
  ResampledGrid(this->Points, this->Samples, maximum, out.Points, step);
  for (int k = 0; k < 3; ++k)
  {
    out.Samples[k] = out.Points[k];
    out.Origin[k] = this->Origin[k];
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.IndexToWorld[r][c] = this->IndexToWorld[r][c] * step[c];
      out.WorldToIndex[r][c] = this->WorldToIndex[r][c] / step[r];
    }
  }
  out.Values.resize(std::size_t(out.Samples[0]) * out.Samples[1] * out.Samples[2]);
  std::size_t i = 0;
  for (int z = 0; z < out.Samples[2]; ++z)
  {
    for (int y = 0; y < out.Samples[1]; ++y)
    {
      for (int x = 0; x < out.Samples[0]; ++x, ++i)
      {
        // (The last point lands on the far bound exactly, not an ulp beyond.)
        const double p[3] = { std::min(x * step[0], this->Points[0] - 1.0),
          std::min(y * step[1], this->Points[1] - 1.0),
          std::min(z * step[2], this->Points[2] - 1.0) };
        out.Values[i] = static_cast<float>(this->DensityAtIndex(p));
        out.Maximum = std::max(out.Maximum, static_cast<double>(out.Values[i]));
      }
    }
  }
  return out;
}

void vtkLightShaftDensityField::ResampledGrid(const int points[3],
  const int samples[3],
  int maximum,
  int out[3],
  double step[3])
{
  for (int k = 0; k < 3; ++k)
  {
    // (Cell data whose cells fit may have one point more than `maximum`: capped too, so that
    // the grid, read again as an image, is not resampled a second time.)
    out[k] = std::max(std::min(samples[k] > maximum ? maximum : points[k], maximum), 2);
    step[k] = (points[k] - 1.0) / (out[k] - 1.0);
  }
}

void vtkLightShaftDensityField::ResamplePiece(int maximum,
  const int offset[3],
  const int wholePoints[3],
  const int planes[2],
  float* slab) const
{
  int wholeSamples[3];
  for (int k = 0; k < 3; ++k)
  {
    wholeSamples[k] = this->CellCentred ? std::max(wholePoints[k] - 1, 1) : wholePoints[k];
  }
  int grid[3];
  double step[3];
  ResampledGrid(wholePoints, wholeSamples, maximum, grid, step);
  const std::size_t nx = this->Samples[0];
  const std::size_t nxy = nx * this->Samples[1];
  auto value = [this, offset, nx, nxy](int i, int j, int k)
  { return this->Values[(i - offset[0]) + nx * (j - offset[1]) + nxy * (k - offset[2])]; };
  std::size_t at = 0;
  for (int z = planes[0]; z < planes[1]; ++z)
  {
    for (int y = 0; y < grid[1]; ++y)
    {
      for (int x = 0; x < grid[0]; ++x, ++at)
      {
        // As Resampled: the point's index in the whole image, its neighbours there.
        const double p[3] = { std::min(x * step[0], wholePoints[0] - 1.0),
          std::min(y * step[1], wholePoints[1] - 1.0),
          std::min(z * step[2], wholePoints[2] - 1.0) };
        int base[3];
        double fraction[3];
        bool held = Neighbours(p, wholePoints, wholeSamples, this->CellCentred, base, fraction);
        for (int k = 0; k < 3 && held; ++k)
        {
          const int last = base[k] + (wholeSamples[k] > 1 ? 1 : 0);
          held = base[k] >= offset[k] && last < offset[k] + this->Samples[k];
        }
        if (held)
        {
          slab[at] = static_cast<float>(Trilinear(base, fraction, wholeSamples, value));
        }
      }
    }
  }
}

void vtkLightShaftDensityField::ResampledPlaneSamples(int maximum,
  const int wholePoints[3],
  bool cellCentred,
  int plane,
  int range[2])
{
  int wholeSamples[3];
  for (int k = 0; k < 3; ++k)
  {
    wholeSamples[k] = cellCentred ? std::max(wholePoints[k] - 1, 1) : wholePoints[k];
  }
  int grid[3];
  double step[3];
  ResampledGrid(wholePoints, wholeSamples, maximum, grid, step);
  // As ResamplePiece: the plane's neighbours along z (x and y at the grid's first point).
  const double p[3] = { 0.0, 0.0, std::min(plane * step[2], wholePoints[2] - 1.0) };
  int base[3] = { 0, 0, 0 };
  double fraction[3];
  Neighbours(p, wholePoints, wholeSamples, cellCentred, base, fraction);
  range[0] = base[2];
  range[1] = base[2] + (wholeSamples[2] > 1 ? 1 : 0);
}

void vtkLightShaftDensityField::Corners(double corners[8][3]) const
{
  for (int c = 0; c < 8; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      corners[c][r] = this->Origin[r];
      for (int k = 0; k < 3; ++k)
      {
        corners[c][r] += this->IndexToWorld[r][k] * (((c >> k) & 1) ? this->Points[k] - 1.0 : 0.0);
      }
    }
  }
}

void vtkLightShaftDensityField::Breakpoints(const double origin[3],
  const double dir[3],
  double t0,
  double t1,
  std::vector<double>& breaks) const
{
  if (this->Values.empty() || !(t1 > t0))
  {
    return;
  }
  const double a[3] = { origin[0] + t0 * dir[0], origin[1] + t0 * dir[1], origin[2] + t0 * dir[2] };
  const double b[3] = { origin[0] + t1 * dir[0], origin[1] + t1 * dir[1], origin[2] + t1 * dir[2] };
  double pa[3];
  double pb[3];
  this->ToIndex(a, pa);
  this->ToIndex(b, pb);
  std::vector<double> s;
  this->IndexBreakpoints(pa, pb, s);
  for (double at : s)
  {
    breaks.push_back(t0 + at * (t1 - t0));
  }
}

//------------------------------------------------------------------------------
glm::dmat4 vtkLightShaftDensityField::TextureFromWorld() const
{
  // Point index p = A x + c (the field's placement), then texture coordinate (p + offset) / N:
  // texel centres sit at the samples (points, or cell centres half a cell on).
  const double zero[3] = { 0.0, 0.0, 0.0 };
  double c[3];
  this->ToIndex(zero, c);
  const int* samples = this->GetSamples();
  const double offset = this->GetCellCentred() ? 0.0 : 0.5;
  glm::dmat4 m(1.0);
  for (int col = 0; col < 3; ++col)
  {
    double unit[3] = { 0.0, 0.0, 0.0 };
    unit[col] = 1.0;
    double p[3];
    this->ToIndex(unit, p);
    for (int row = 0; row < 3; ++row)
    {
      m[col][row] = (p[row] - c[row]) / samples[row];
    }
  }
  for (int row = 0; row < 3; ++row)
  {
    m[3][row] = (c[row] + offset) / samples[row];
  }
  return m;
}

void vtkLightShaftDensityField::TextureBounds(float low[3], float high[3]) const
{
  const int* samples = this->GetSamples();
  const bool cells = this->GetCellCentred();
  const double offset = cells ? 0.0 : 0.5;
  for (int k = 0; k < 3; ++k)
  {
    const int points = cells ? samples[k] + 1 : samples[k];
    low[k] = static_cast<float>(offset / samples[k]);
    high[k] = static_cast<float>((points - 1 + offset) / samples[k]);
  }
}
