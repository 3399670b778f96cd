#include "vtkLightShaftFieldTable.h"

#include "vtkLightShaftDensityField.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace
{
// A unit vector perpendicular to `axis` (unit), from the world axis least aligned with it.
glm::dvec3 Perpendicular(const glm::dvec3& axis)
{
  const glm::dvec3 a = glm::abs(axis);
  const glm::dvec3 helper = (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1.0, 0.0, 0.0)
                            : (a.y <= a.z)             ? glm::dvec3(0.0, 1.0, 0.0)
                                                       : glm::dvec3(0.0, 0.0, 1.0);
  return glm::normalize(glm::cross(helper, axis));
}

// Rows right, up, forward: world directions to the face's frame.
glm::dmat3 FaceFrame(const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& forward)
{
  return glm::transpose(glm::dmat3(right, up, forward));
}
}

//------------------------------------------------------------------------------
void vtkLightShaftFieldTable::Layout::Column(int face,
  int i,
  int j,
  glm::dvec3& origin,
  glm::dvec3& direction) const
{
  const double u = this->Low[0] + (this->High[0] - this->Low[0]) * i / (this->Lateral - 1);
  const double v = this->Low[1] + (this->High[1] - this->Low[1]) * j / (this->Lateral - 1);
  const glm::dmat3 fromFace = glm::transpose(this->ToFace);
  if (this->Orthographic)
  {
    origin = this->Origin + fromFace * glm::dvec3(u, v, 0.0);
    direction = fromFace[2];
    return;
  }
  origin = this->Origin;
  if (this->Faces == 1)
  {
    direction = glm::normalize(fromFace * glm::dvec3(u, v, 1.0));
    return;
  }
  const int k = face / 2;
  glm::dvec3 q(0.0);
  q[k] = (face % 2) ? -1.0 : 1.0;
  q[(k + 1) % 3] = u;
  q[(k + 2) % 3] = v;
  direction = glm::normalize(q);
}

double vtkLightShaftFieldTable::Layout::DepthAt(int k) const
{
  return this->Low[2] + (this->High[2] - this->Low[2]) * k / (this->Depth - 1);
}

//------------------------------------------------------------------------------
namespace
{
// The distance from `point` to the field's box (0 inside it).
double DistanceToBox(const vtkLightShaftDensityField& field, const glm::dvec3& point)
{
  double corners[8][3];
  field.Corners(corners);
  const glm::dvec3 origin(corners[0][0], corners[0][1], corners[0][2]);
  double distance2 = 0.0;
  const glm::dvec3 offset = point - origin;
  for (int k = 0; k < 3; ++k)
  {
    // Edge k of the box from corner 0 (corner 1 << k): its axis and length.
    const glm::dvec3 edge(corners[1 << k][0] - corners[0][0],
      corners[1 << k][1] - corners[0][1],
      corners[1 << k][2] - corners[0][2]);
    const double length = glm::length(edge);
    const double along = length > 0.0 ? glm::dot(offset, edge) / length : 0.0;
    const double outside = along < 0.0 ? -along : std::max(along - length, 0.0);
    distance2 += outside * outside;
  }
  return std::sqrt(distance2);
}
}

vtkLightShaftFieldTable::Layout vtkLightShaftFieldTable::Plan(
  const vtkLightShaftDensityField& field,
  const vtkLightShaftModel::Light& light,
  int resolution,
  int maximumDepth)
{
  Layout layout;
  layout.Lateral = std::max(resolution, 2);
  layout.Origin = light.Position;
  double corners[8][3];
  field.Corners(corners);
  auto project = [&](bool perspective, double low[3], double high[3])
  {
    bool inFront = true;
    for (int k = 0; k < 3; ++k)
    {
      low[k] = HUGE_VAL;
      high[k] = -HUGE_VAL;
    }
    for (const double* corner : corners)
    {
      const glm::dvec3 q =
        layout.ToFace * (glm::dvec3(corner[0], corner[1], corner[2]) - layout.Origin);
      inFront = inFront && q.z > 0.0;
      const glm::dvec3 uvw = perspective ? glm::dvec3(q.x / q.z, q.y / q.z, glm::length(q)) : q;
      for (int k = 0; k < 3; ++k)
      {
        low[k] = std::min(low[k], uvw[k]);
        high[k] = std::max(high[k], uvw[k]);
      }
      // (The box is convex: no point of it is nearer the light than its corners' least q.z.)
      low[2] = std::min(low[2], perspective ? q.z : uvw.z);
    }
    return inFront;
  };
  double farthest = 0.0;
  for (const double* corner : corners)
  {
    farthest =
      std::max(farthest, glm::length(glm::dvec3(corner[0], corner[1], corner[2]) - layout.Origin));
  }

  if (light.Kind == vtkLightShaftModel::LightKind::Directional)
  {
    // From the light's plane (q.z = 0) or the box, whichever is later, to the box's far side.
    layout.Orthographic = true;
    layout.ToFace = FaceFrame(light.Right, light.Up, light.Axis);
    project(false, layout.Low, layout.High);
    layout.Low[2] = std::max(layout.Low[2], 0.0);
  }
  else
  {
    glm::dvec3 centre(0.0);
    for (const double* corner : corners)
    {
      centre += glm::dvec3(corner[0], corner[1], corner[2]) / 8.0;
    }
    const glm::dvec3 toCentre = centre - layout.Origin;
    const double distance = glm::length(toCentre);
    bool single = distance > 0.0;
    double area = HUGE_VAL; // the single face's (u, v) area
    if (single)
    {
      const glm::dvec3 forward = toCentre / distance;
      const glm::dvec3 right = Perpendicular(forward);
      layout.ToFace = FaceFrame(right, glm::cross(forward, right), forward);
      single = project(true, layout.Low, layout.High) &&
               std::max({ -layout.Low[0], -layout.Low[1], layout.High[0], layout.High[1] }) <=
                 MaximumFaceTangent;
      area = (layout.High[0] - layout.Low[0]) * (layout.High[1] - layout.Low[1]);
    }
    // A spot lights its cone only: a face over the cone where that is smaller than the box's
    // (a light inside the box, or a box wider than the cone).
    const double cone = light.Kind == vtkLightShaftModel::LightKind::Spot
                          ? std::tan(std::min(light.ConeHalfAngle, 1.5))
                          : HUGE_VAL;
    if (cone <= MaximumFaceTangent && (!single || 4.0 * cone * cone < area))
    {
      single = true;
      layout.ToFace = FaceFrame(light.Right, light.Up, light.Axis);
      layout.Low[0] = layout.Low[1] = -cone;
      layout.High[0] = layout.High[1] = cone;
      layout.Low[2] = DistanceToBox(field, layout.Origin);
      layout.High[2] = farthest;
    }
    if (!single)
    {
      layout.Faces = 6;
      layout.ToFace = glm::dmat3(1.0);
      layout.Lateral = std::max(resolution / 2, 2);
      layout.Low[0] = layout.Low[1] = -1.0;
      layout.High[0] = layout.High[1] = 1.0;
      layout.Low[2] = 0.0;
      layout.High[2] = farthest;
    }
  }
  // A box behind a directional light's plane, or flat: keep a non-empty range.
  for (int k = 0; k < 3; ++k)
  {
    const double scale = std::max(std::abs(layout.Low[k]), std::abs(layout.High[k]));
    layout.High[k] = std::max(layout.High[k], layout.Low[k] + 1e-9 * scale + 1e-30);
  }
  Resolve(field, layout, maximumDepth);
  return layout;
}

//------------------------------------------------------------------------------
void vtkLightShaftFieldTable::Resolve(const vtkLightShaftDensityField& field,
  Layout& layout,
  int maximumDepth)
{
  // The most sample planes a unit length of a column crosses, over a grid of columns of each
  // face (the edges included): tau bends at each plane, so a texel per plane holds its
  // interpolation error to about an eighth of a cell's density step times its length.
  constexpr int Probes = 5;
  double planes = 0.0;
  Layout probe = layout;
  probe.Lateral = Probes;
  for (int face = 0; face < layout.Faces; ++face)
  {
    for (int j = 0; j < Probes; ++j)
    {
      for (int i = 0; i < Probes; ++i)
      {
        glm::dvec3 origin;
        glm::dvec3 direction;
        probe.Column(face, i, j, origin, direction);
        const double d[3] = { direction.x, direction.y, direction.z };
        planes = std::max(planes, field.PlanesPerLength(d));
      }
    }
  }
  double lateral = layout.Lateral;
  double depth = std::max(std::ceil(planes * (layout.High[2] - layout.Low[2])) + 1.0, lateral);
  depth = std::min<double>(depth, std::max(maximumDepth, 2));
  // Over MaximumValues both shrink by the same factor (their errors fall alike).
  const double values = lateral * lateral * depth * layout.Faces;
  if (values > static_cast<double>(MaximumValues))
  {
    const double shrink = std::cbrt(static_cast<double>(MaximumValues) / values);
    lateral = std::max(2.0, std::floor(lateral * shrink));
    depth = std::max(
      2.0, std::floor(static_cast<double>(MaximumValues) / (lateral * lateral * layout.Faces)));
    depth = std::min<double>(depth, std::max(maximumDepth, 2));
  }
  layout.Lateral = static_cast<int>(lateral);
  layout.Depth = static_cast<int>(depth);
}

//------------------------------------------------------------------------------
std::vector<float> vtkLightShaftFieldTable::Integrate(const vtkLightShaftDensityField& field,
  const Layout& layout)
{
  std::vector<float> values(layout.Values());
  const int n = layout.Lateral;
  const int columns = layout.Faces * n * n;
  std::vector<double> depths(layout.Depth);
  for (int k = 0; k < layout.Depth; ++k)
  {
    depths[k] = layout.DepthAt(k);
  }
  const int perFace = n * n;
  const std::size_t row = static_cast<std::size_t>(n) * layout.Faces; // faces side by side
  const int stride = static_cast<int>(row * n);                       // one depth texel
  vtkSMPTools::For(0,
    columns,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType column = first; column < last; ++column)
      {
        const int face = static_cast<int>(column / perFace);
        const int j = static_cast<int>(column % perFace) / n;
        const int i = static_cast<int>(column % n);
        glm::dvec3 origin;
        glm::dvec3 direction;
        layout.Column(face, i, j, origin, direction);
        const double o[3] = { origin.x, origin.y, origin.z };
        const double d[3] = { direction.x, direction.y, direction.z };
        float* out = values.data() + static_cast<std::size_t>(j) * row +
                     static_cast<std::size_t>(face) * n + i;
        field.Cumulative(o, d, 0.0, depths.data(), layout.Depth, out, stride);
      }
    });
  return values;
}
