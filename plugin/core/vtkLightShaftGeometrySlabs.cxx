#include "vtkLightShaftGeometrySlabs.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vtkLightShaftGeometry
{

//------------------------------------------------------------------------------
std::vector<SlabFootprint> ComputeSlabFootprints(const LitVolume& lit,
  const CameraFrame& camera,
  int slabs,
  bool jitter,
  int share,
  int part)
{
  const double nearest = lit.Nearest;
  const double deepest = lit.Deepest;
  const double thickness = (deepest - nearest) / slabs;
  const int drawnSlabs = jitter ? slabs + 1 : slabs;
  std::vector<SlabFootprint> footprints;
  std::vector<glm::dvec2> footprint;
  for (int k = part; k < drawnSlabs; k += std::max(share, 1))
  {
    const double za = std::max(nearest, nearest + (jitter ? k - 1 : k) * thickness);
    const double zb = std::min(deepest, nearest + (k + 1) * thickness);
    footprint.clear();
    auto addPoint = [&](const glm::dvec3& p)
    {
      const glm::dvec4 c = camera.ViewToClip * glm::dvec4(p, 1.0);
      footprint.emplace_back(c.x / c.w, c.y / c.w);
    };
    for (const auto& face : lit.Polytope.Faces)
    {
      const size_t count = face.size();
      for (size_t i = 0; i < count; ++i)
      {
        const glm::dvec3& a = face[i];
        const glm::dvec3& b = face[(i + 1) % count];
        const double da = -a.z;
        const double db = -b.z;
        if (da >= za && da <= zb)
        {
          addPoint(a);
        }
        for (double plane : { za, zb })
        {
          if ((da - plane) * (db - plane) < 0.0)
          {
            addPoint(a + (b - a) * ((plane - da) / (db - da)));
          }
        }
      }
    }
    std::vector<glm::dvec2> hull = ConvexHull(footprint);
    if (hull.size() >= 3)
    {
      footprints.push_back({ k, za, std::move(hull) });
    }
  }
  return footprints;
}

//------------------------------------------------------------------------------
void AppendSlabTriangles(const SlabFootprint& slab, int lattice, std::vector<float>& vertices)
{
  const std::vector<glm::dvec2>& hull = slab.Hull;
  glm::dvec2 low = hull[0];
  glm::dvec2 high = hull[0];
  for (const glm::dvec2& p : hull)
  {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  // The hull without its near-coincident vertices: the direction of an edge a rounding error
  // long is noise (its half-plane would cut a sliver out of the slab), and a triangle with
  // two such vertices is degenerate once in float (llvmpipe was seen to drop a whole draw of a
  // fan ending in one).
  const double tiny = 1e-9 * glm::length(high - low);
  std::vector<glm::dvec2> window;
  for (const glm::dvec2& p : hull)
  {
    if (window.empty() || glm::length(p - window.back()) > tiny)
    {
      window.push_back(p);
    }
  }
  while (window.size() > 1 && glm::length(window.front() - window.back()) <= tiny)
  {
    window.pop_back();
  }
  // Triangles with a positive area in float, as the GL will see them.
  auto emit = [&](const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
  {
    const std::array<float, 6> f = { static_cast<float>(a.x),
      static_cast<float>(a.y),
      static_cast<float>(b.x),
      static_cast<float>(b.y),
      static_cast<float>(c.x),
      static_cast<float>(c.y) };
    const double area = (static_cast<double>(f[2]) - f[0]) * (static_cast<double>(f[5]) - f[1]) -
                        (static_cast<double>(f[3]) - f[1]) * (static_cast<double>(f[4]) - f[0]);
    if (!(area > 0.0))
    {
      return;
    }
    for (int v = 0; v < 3; ++v)
    {
      vertices.insert(vertices.end(),
        { f[2 * v],
          f[2 * v + 1],
          static_cast<float>(slab.Index),
          static_cast<float>(slab.NearDepth) });
    }
  };
  auto fan = [&](const std::vector<glm::dvec2>& polygon)
  {
    for (size_t i = 1; i + 1 < polygon.size(); ++i)
    {
      emit(polygon[0], polygon[i], polygon[i + 1]);
    }
  };
  if (lattice <= 0)
  {
    fan(window);
    return;
  }
  auto corner = [&](int i, int j)
  { return low + (high - low) * glm::dvec2(double(i) / lattice, double(j) / lattice); };
  for (int j = 0; j < lattice; ++j)
  {
    for (int i = 0; i < lattice; ++i)
    {
      fan(ClipToConvex(
        { corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1) }, window));
    }
  }
}
}
