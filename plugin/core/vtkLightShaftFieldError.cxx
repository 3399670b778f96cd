#include "vtkLightShaftFieldError.h"

#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftGeometryClipping.h"
#include "vtkLightShaftGeometryLitVolume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vtkLightShaftFieldError
{
namespace
{
constexpr int Offsets = 4;
// Samples of the exact mean along a probe ray (midpoints): past every ladder setting's steps.
constexpr int Fine = 4096;
// TableError: the lattice's points per axis at most, and the points looked up.
constexpr int Lattice = 32;
constexpr int Points = 256;

// Points spread over the lit volume: its centroid, and halfway from it to each vertex.
std::vector<glm::dvec3> SpreadPoints(const vtkLightShaftGeometry::ConvexPolytope& polytope)
{
  // Each vertex once (faces share them).
  std::vector<glm::dvec3> vertices;
  for (const auto& face : polytope.Faces)
  {
    for (const glm::dvec3& v : face)
    {
      const bool seen = std::any_of(vertices.begin(),
        vertices.end(),
        [&](const glm::dvec3& w) { return glm::distance(v, w) <= 1e-9 * (1.0 + glm::length(v)); });
      if (!seen)
      {
        vertices.push_back(v);
      }
    }
  }
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& v : vertices)
  {
    centroid += v / static_cast<double>(vertices.size());
  }
  std::vector<glm::dvec3> points{ centroid };
  for (const glm::dvec3& v : vertices)
  {
    points.push_back(0.5 * (centroid + v));
  }
  return points;
}

// Whether `light`, at `position` pointing along `axis` (in x's coordinates), reaches x: a
// spot's cone, a directional light's side of its plane, everywhere for a point light.
bool Reaches(const vtkLightShaftModel::Light& light,
  const glm::dvec3& position,
  const glm::dvec3& axis,
  const glm::dvec3& x)
{
  const glm::dvec3 d = x - position;
  const double along = glm::dot(d, axis);
  switch (light.Kind)
  {
    case vtkLightShaftModel::LightKind::Spot:
      return along >= std::cos(light.ConeHalfAngle) * glm::length(d);
    case vtkLightShaftModel::LightKind::Directional:
      return along >= 0.0;
    default:
      return true;
  }
}

// Cuts the segment [a, b] (view coordinates) to the part the light reaches, as each pixel's
// march does (a spot's cone; the side of a directional light's plane it shines on); false
// when none.
bool LitPart(const vtkLightShaftGeometry::LightFrame& light, glm::dvec3& a, glm::dvec3& b)
{
  auto lit = [&](const glm::dvec3& x)
  { return Reaches(light.Model, light.PositionVC, light.AxisVC, x); };
  // The lit set along a line is one interval (a convex cone, a half-space): its ends found on
  // a scan, fine enough for the step the march takes.
  constexpr int Scan = 512;
  int first = -1;
  int last = -1;
  for (int i = 0; i <= Scan; ++i)
  {
    if (lit(a + (b - a) * (double(i) / Scan)))
    {
      first = first < 0 ? i : first;
      last = i;
    }
  }
  if (first < 0 || last == first)
  {
    return false;
  }
  const glm::dvec3 from = a + (b - a) * (double(first) / Scan);
  b = a + (b - a) * (double(last) / Scan);
  a = from;
  return true;
}

// The variable a view ray's march steps evenly in (vtkLightShaftSegment.glsl's
// lightShaftVariable): the distance along the ray where the light's attenuation is constant
// (a directional light's, or VTK's default), else the equiangular angle seen from the light,
// along which the light's falloff times the step's length is constant (for constant and
// quadratic terms: the shader's angle scale), so that the field's own variation is what the
// march's samples miss.
class MarchVariable
{
public:
  MarchVariable(const vtkLightShaftModel::Light& light, const glm::dvec3& a, const glm::dvec3& b)
    : A(a)
    , Direction(glm::normalize(b - a))
  {
    const double length = glm::length(b - a);
    this->Uniform =
      light.Kind == vtkLightShaftModel::LightKind::Directional || !light.FallingAttenuation();
    if (this->Uniform)
    {
      this->U0 = 0.0;
      this->U1 = length;
      return;
    }
    // x: along the ray from the foot of the perpendicular from the light.
    this->Foot = glm::dot(light.Position - a, this->Direction);
    const glm::dvec3 foot = a + this->Direction * this->Foot;
    const double h2 = glm::dot(light.Position - foot, light.Position - foot);
    const double c0 = light.Attenuation[0];
    const double c2 = light.Attenuation[2];
    const double x0 = -this->Foot;
    const double x1 = length - this->Foot;
    this->H = std::max(std::sqrt(h2 + (c2 > 0.0 ? c0 / c2 : 0.0)),
      1e-6 * std::max(std::abs(x0), std::abs(x1)) + 1e-30);
    this->U0 = std::atan2(x0, this->H);
    this->U1 = std::atan2(x1, this->H);
  }

  /// The distance along the ray at `fraction` of the variable's range.
  double T(double fraction) const
  {
    const double u = this->U0 + (this->U1 - this->U0) * fraction;
    return this->Uniform ? u : this->H * std::tan(u) + this->Foot;
  }
  /// The point there.
  glm::dvec3 At(double fraction) const { return this->A + this->Direction * this->T(fraction); }

private:
  glm::dvec3 A;
  glm::dvec3 Direction;
  bool Uniform = true;
  double Foot = 0.0;
  double H = 1.0;
  double U0 = 0.0;
  double U1 = 1.0;
};

// Cuts the segment [a, b] (world) where it leaves `bounds`, where they are set: a view ray
// that reaches the scene's box ends on a surface within it (a ray that misses the box goes on
// to the backdrop). The medium in front of the box is seen (a floor's box is flat: the air
// above it is all in front). False when the segment starts past the box: the ray ended on a
// surface before it.
bool WithinBounds(const double bounds[6], const glm::dvec3& a, glm::dvec3& b)
{
  if (bounds[0] > bounds[1])
  {
    return true;
  }
  // The line's interval in the box (t along a + t (b - a)), a slab at a time.
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  const glm::dvec3 d = b - a;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (a[k] < bounds[2 * k] || a[k] > bounds[2 * k + 1])
      {
        return true; // parallel to the slab, outside it: the box is missed
      }
      continue;
    }
    const double u = (bounds[2 * k] - a[k]) / d[k];
    const double v = (bounds[2 * k + 1] - a[k]) / d[k];
    t0 = std::max(t0, std::min(u, v));
    t1 = std::min(t1, std::max(u, v));
  }
  if (t1 < t0 || t0 >= 1.0)
  {
    return true; // the box is missed, or lies beyond the segment
  }
  if (t1 <= 0.0)
  {
    return false;
  }
  b = a + d * std::min(t1, 1.0);
  return true;
}

// The light leg's table (vtkLightShaftFieldTable) at world point x, as the shader looks it
// up: the trilinear interpolation of the exact integrals from the light at the eight texel
// nodes around x.
bool TableAt(const vtkLightShaftDensityField& field,
  const vtkLightShaftFieldTable::Layout& t,
  const glm::dvec3& x,
  double& value)
{
  value = 0.0;
  const glm::dvec3 q = t.ToFace * (x - t.Origin);
  glm::dvec3 uvw = q;
  int face = 0;
  if (t.Faces == 6)
  {
    const glm::dvec3 a = glm::abs(q);
    const int k = (a.x >= a.y && a.x >= a.z) ? 0 : ((a.y >= a.z) ? 1 : 2);
    const double major = std::max(a[k], 1e-30);
    uvw = glm::dvec3(q[(k + 1) % 3] / major, q[(k + 2) % 3] / major, glm::length(q));
    face = 2 * k + (q[k] < 0.0 ? 1 : 0);
  }
  else if (!t.Orthographic)
  {
    if (q.z <= 0.0)
    {
      return false;
    }
    uvw = glm::dvec3(q.x / q.z, q.y / q.z, glm::length(q));
  }
  if (t.Faces == 1 &&
      (uvw.x < t.Low[0] || uvw.x > t.High[0] || uvw.y < t.Low[1] || uvw.y > t.High[1]))
  {
    return false; // (outside the face: a spot's cone, or rays that miss the box)
  }
  const int counts[3] = { t.Lateral, t.Lateral, t.Depth };
  int first[3];
  double fraction[3];
  for (int k = 0; k < 3; ++k)
  {
    const double span = t.High[k] - t.Low[k];
    const double f =
      span > 0.0 ? std::clamp((uvw[k] - t.Low[k]) / span * (counts[k] - 1), 0.0, counts[k] - 1.0)
                 : 0.0;
    first[k] = std::min(static_cast<int>(f), std::max(counts[k] - 2, 0));
    fraction[k] = std::min(f - first[k], 1.0);
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    double weight = 1.0;
    int index[3];
    for (int k = 0; k < 3; ++k)
    {
      const int step = (corner >> k) & 1;
      index[k] = std::min(first[k] + step, counts[k] - 1);
      weight *= step ? fraction[k] : 1.0 - fraction[k];
    }
    if (weight <= 0.0)
    {
      continue;
    }
    glm::dvec3 origin;
    glm::dvec3 direction;
    t.Column(face, index[0], index[1], origin, direction);
    const glm::dvec3 end = origin + direction * t.DepthAt(index[2]);
    const double a[3] = { origin.x, origin.y, origin.z };
    const double b[3] = { end.x, end.y, end.z };
    value += weight * field.Integral(a, b);
  }
  return true;
}

// The exact integral of the field from the light to world point x along the table's own
// column through it (from the light, or back to a directional light's plane).
double LegAt(const vtkLightShaftDensityField& field,
  const vtkLightShaftFieldTable::Layout& t,
  const glm::dvec3& x)
{
  glm::dvec3 origin = t.Origin;
  if (t.Orthographic)
  {
    const glm::dvec3 q = t.ToFace * (x - t.Origin);
    if (q.z <= 0.0)
    {
      return 0.0;
    }
    origin = t.Origin + glm::transpose(t.ToFace) * glm::dvec3(q.x, q.y, 0.0);
  }
  const double a[3] = { origin.x, origin.y, origin.z };
  const double b[3] = { x.x, x.y, x.z };
  return field.Integral(a, b);
}

// What the probe rays add up.
struct Sums
{
  explicit Sums(std::size_t settings)
    : InScatter(settings, 0.0)
    , Extinction(settings, 0.0)
  {
  }
  std::vector<double> InScatter;  ///< squared errors of the density's mean along the variable
  std::vector<double> Extinction; ///< squared errors of the optical depth
  double Exact = 0.0;             ///< squared exact means
  int Rays = 0;
};

// One probe ray's segment [aW, bW] (world): its march at each sample count, and the table.
void MeasureRay(const Density& density,
  const vtkLightShaftModel::Light& light,
  const glm::dvec3& aW,
  const glm::dvec3& bW,
  const std::vector<int>& samples,
  Sums& sums)
{
  const MarchVariable u(light, aW, bW);
  // The density along the march's variable, and its exact mean there (finely sampled).
  auto rho = [&](double fraction)
  {
    const glm::dvec3 x = u.At(fraction);
    const double at[3] = { x.x, x.y, x.z };
    return density.Scale * density.Field->Density(at) + density.Background;
  };
  double exact = 0.0;
  for (int i = 0; i < Fine; ++i)
  {
    exact += rho((i + 0.5) / Fine) / Fine;
  }
  const double from[3] = { aW.x, aW.y, aW.z };
  const double to[3] = { bW.x, bW.y, bW.z };
  const double depth =
    density.Scale * density.Field->Integral(from, to) + density.Background * glm::length(bW - aW);
  sums.Exact += exact * exact;
  ++sums.Rays;
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const int n = samples[s];
    if (n <= 0 || std::find(samples.begin(), samples.begin() + s, n) != samples.begin() + s)
    {
      continue; // (not measured, or a count already measured: copied by Measure)
    }
    // The march's pieces: boundaries at (j + offset) / n of the variable (the first and last
    // pieces partial), the density at each piece's middle. Its offset within a step varies
    // from pixel to pixel (jitter, interleaving): the mean squared error over Offsets of them.
    for (int o = 0; o < Offsets; ++o)
    {
      const double offset = (o + 0.5) / Offsets;
      double mean = 0.0;
      double optical = 0.0;
      double previous = 0.0;
      for (int j = 0; j <= n; ++j)
      {
        const double next = j == n ? 1.0 : std::min(1.0, (j + offset) / n);
        const double sample = rho(0.5 * (previous + next));
        mean += sample * (next - previous);
        optical += sample * (u.T(next) - u.T(previous));
        previous = next;
      }
      sums.InScatter[s] += (mean - exact) * (mean - exact) / Offsets;
      sums.Extinction[s] += (optical - depth) * (optical - depth) / Offsets;
    }
  }
}
}

Probe Measure(const Density& density,
  const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  const std::vector<int>& samples)
{
  Probe probe;
  probe.QuadratureError.assign(samples.size(), 0.0);
  const vtkLightShaftGeometry::LitVolume lit =
    vtkLightShaftGeometry::ComputeLitVolume(light, camera);
  if (!density.Field || density.Field->Empty() || lit.Empty())
  {
    return probe;
  }
  probe.Lit = true;
  const glm::dmat4 viewToWorld = glm::inverse(camera.WorldToView);
  const bool perspective = camera.ViewToClip[2][3] != 0.0;
  Sums sums(samples.size());
  for (const glm::dvec3& point : SpreadPoints(lit.Polytope))
  {
    // The view ray through the point (view coordinates look down -z), between the lit
    // volume's view depths.
    const glm::dvec3 originVC = perspective ? glm::dvec3(0.0) : glm::dvec3(point.x, point.y, 0.0);
    const glm::dvec3 directionVC = perspective ? glm::normalize(point) : glm::dvec3(0.0, 0.0, -1.0);
    if (!(directionVC.z < 0.0))
    {
      continue;
    }
    glm::dvec3 a = originVC + directionVC * (lit.Nearest / -directionVC.z);
    glm::dvec3 b = originVC + directionVC * (lit.Deepest / -directionVC.z);
    if (!LitPart(light, a, b))
    {
      continue;
    }
    glm::dvec3 aW(viewToWorld * glm::dvec4(a, 1.0));
    glm::dvec3 bW(viewToWorld * glm::dvec4(b, 1.0));
    if (!WithinBounds(density.SceneBounds, aW, bW))
    {
      continue;
    }
    const double from[3] = { aW.x, aW.y, aW.z };
    const double to[3] = { bW.x, bW.y, bW.z };
    probe.DensityDepth = std::max(probe.DensityDepth,
      density.Scale * density.Field->Integral(from, to) +
        density.Background * glm::length(bW - aW));
    MeasureRay(density, light.Model, aW, bW, samples, sums);
  }
  const double sigma2 = density.SigmaT * density.SigmaT;
  probe.LightLegError = density.TableError;
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    if (samples[s] <= 0 || sums.Rays == 0)
    {
      continue;
    }
    const std::size_t first =
      std::find(samples.begin(), samples.end(), samples[s]) - samples.begin();
    const double inScatter = sums.Exact > 0.0 ? sums.InScatter[first] / sums.Exact : 0.0;
    const double extinction = sigma2 * sums.Extinction[first] / sums.Rays;
    probe.QuadratureError[s] =
      std::sqrt(inScatter + extinction + probe.LightLegError * probe.LightLegError);
  }
  return probe;
}

double TableError(const vtkLightShaftDensityField& field,
  const vtkLightShaftModel::Light& light,
  int resolution,
  double extinction)
{
  if (field.Empty() || resolution <= 0)
  {
    return 0.0;
  }
  const vtkLightShaftFieldTable::Layout table =
    vtkLightShaftFieldTable::Plan(field, light, resolution);
  if (table.Lateral < 2 || table.Depth < 2)
  {
    return 0.0;
  }
  // The field's box: a lattice over it, its density at each point.
  double corners[8][3];
  field.Corners(corners);
  const glm::dvec3 origin(corners[0][0], corners[0][1], corners[0][2]);
  const glm::dmat3 edges(glm::dvec3(corners[1][0], corners[1][1], corners[1][2]) - origin,
    glm::dvec3(corners[2][0], corners[2][1], corners[2][2]) - origin,
    glm::dvec3(corners[4][0], corners[4][1], corners[4][2]) - origin);
  int m[3];
  for (int k = 0; k < 3; ++k)
  {
    m[k] = std::clamp(field.GetSamples()[k], 2, Lattice);
  }
  // A lattice point's position, shifted off the lattice (and off the table's texels) by a
  // fixed low-discrepancy offset within its cell.
  auto at = [&](int i, int j, int k)
  {
    const double n = i + m[0] * (j + m[1] * double(k));
    const glm::dvec3 jitter(std::fmod(0.5 + 0.7548776662 * n, 1.0),
      std::fmod(0.5 + 0.5698402910 * n, 1.0),
      std::fmod(0.5 + 0.3247179572 * n, 1.0));
    return origin + edges * ((glm::dvec3(i, j, k) + jitter) / glm::dvec3(m[0], m[1], m[2]));
  };
  std::vector<double> cumulative;
  cumulative.reserve(static_cast<std::size_t>(m[0]) * m[1] * m[2]);
  double total = 0.0;
  for (int k = 0; k < m[2]; ++k)
  {
    for (int j = 0; j < m[1]; ++j)
    {
      for (int i = 0; i < m[0]; ++i)
      {
        const glm::dvec3 x = at(i, j, k);
        const double p[3] = { x.x, x.y, x.z };
        total += field.Density(p);
        cumulative.push_back(total);
      }
    }
  }
  if (!(total > 0.0))
  {
    return 0.0;
  }
  // Points drawn in proportion to the density (systematic: evenly along its cumulative sum),
  // where the light's table is looked up: the density-weighted RMS error of its optical depth.
  double squared = 0.0;
  double weights = 0.0;
  // A positional light's falloff, bounded within a lattice cell of the light.
  const bool falls =
    light.Kind != vtkLightShaftModel::LightKind::Directional && light.FallingAttenuation();
  const glm::dvec3 cell(
    glm::length(edges[0]) / m[0], glm::length(edges[1]) / m[1], glm::length(edges[2]) / m[2]);
  const double nearest = glm::dot(cell, cell);
  for (int s = 0; s < Points; ++s)
  {
    const double target = total * (s + 0.5) / Points;
    const std::size_t n =
      std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin();
    const int i = static_cast<int>(n % m[0]);
    const int j = static_cast<int>((n / m[0]) % m[1]);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(m[0]) * m[1]));
    const glm::dvec3 x = at(i, j, k);
    double value = 0.0;
    if (!Reaches(light, light.Position, light.Axis, x) || !TableAt(field, table, x, value))
    {
      continue;
    }
    // The light reaching x is exp(-extinction tau): the table's error dims it by
    // exp(-extinction error), relatively; weighted by the light that scatters there, its
    // falloff with distance included (a face's texels widen with distance, where less light
    // scatters).
    const double exact = LegAt(field, table, x);
    const double error = extinction * (value - exact);
    const glm::dvec3 d = x - light.Position;
    const double r2 = std::max(glm::dot(d, d), nearest);
    const double falloff =
      falls ? 1.0 / std::max(light.Attenuation[0] + light.Attenuation[1] * std::sqrt(r2) +
                               light.Attenuation[2] * r2,
                      1e-300)
            : 1.0;
    const double weight = falloff * std::exp(-extinction * exact);
    squared += weight * error * error;
    weights += weight;
  }
  return weights > 0.0 ? std::sqrt(squared / weights) : 0.0;
}
}
