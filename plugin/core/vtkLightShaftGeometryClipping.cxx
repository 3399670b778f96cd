#include "vtkLightShaftGeometryClipping.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftGeometry
{
//------------------------------------------------------------------------------
void ConvexPolytope::Clip(const glm::dvec4& plane)
{
  const glm::dvec3 n(plane);
  const double scale = glm::length(n);
  if (scale == 0.0)
  {
    return;
  }
  std::vector<std::vector<glm::dvec3>> kept;
  std::vector<glm::dvec3> cut;
  for (const auto& face : this->Faces)
  {
    std::vector<glm::dvec3> out;
    const size_t count = face.size();
    for (size_t i = 0; i < count; ++i)
    {
      const glm::dvec3& a = face[i];
      const glm::dvec3& b = face[(i + 1) % count];
      const double da = (glm::dot(n, a) + plane.w) / scale;
      const double db = (glm::dot(n, b) + plane.w) / scale;
      if (da >= 0.0)
      {
        out.push_back(a);
      }
      if ((da >= 0.0) != (db >= 0.0))
      {
        const glm::dvec3 p = a + (b - a) * (da / (da - db));
        out.push_back(p);
        cut.push_back(p);
      }
    }
    if (out.size() >= 3)
    {
      kept.push_back(std::move(out));
    }
  }
  if (cut.size() >= 3)
  {
    // The cap: the cut points ordered around their centroid in the clipping plane.
    glm::dvec3 centre(0.0);
    for (const auto& p : cut)
    {
      centre += p;
    }
    centre /= static_cast<double>(cut.size());
    const glm::dvec3 axis = n / scale;
    glm::dvec3 u =
      glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    u = glm::normalize(u);
    const glm::dvec3 v = glm::cross(axis, u);
    std::sort(cut.begin(),
      cut.end(),
      [&](const glm::dvec3& p, const glm::dvec3& q)
      {
        return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
               std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
      });
    kept.push_back(std::move(cut));
  }
  this->Faces = std::move(kept);
}

//------------------------------------------------------------------------------
std::vector<glm::dvec2> ClipToConvex(std::vector<glm::dvec2> polygon,
  const std::vector<glm::dvec2>& window)
{
  std::vector<glm::dvec2> next;
  for (size_t e = 0; e < window.size() && !polygon.empty(); ++e)
  {
    const glm::dvec2 a = window[e];
    const glm::dvec2 edge = window[(e + 1) % window.size()] - a;
    auto side = [&](const glm::dvec2& p) { return edge.x * (p.y - a.y) - edge.y * (p.x - a.x); };
    next.clear();
    for (size_t i = 0; i < polygon.size(); ++i)
    {
      const glm::dvec2& p = polygon[i];
      const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
      const double sp = side(p);
      const double sq = side(q);
      if (sp >= 0.0)
      {
        next.push_back(p);
      }
      if ((sp >= 0.0) != (sq >= 0.0))
      {
        next.push_back(p + (q - p) * (sp / (sp - sq)));
      }
    }
    polygon.swap(next);
  }
  return polygon;
}

//------------------------------------------------------------------------------
std::vector<glm::dvec2> ConvexHull(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(),
    points.end(),
    [](const glm::dvec2& a, const glm::dvec2& b)
    { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3)
  {
    return points;
  }
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
  { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i > 0; --i)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}
}
