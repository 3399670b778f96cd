/**
 * @file   vtkLightShaftGeometryClipping.h
 * @brief  Convex clipping without GL (private, not installed): a convex polytope clipped by
 *         half-spaces, a polygon clipped to a convex window, a convex hull (part of the
 *         namespace vtkLightShaftGeometry, vtkLightShaftGeometry.h).
 */

#ifndef vtkLightShaftGeometryClipping_h
#define vtkLightShaftGeometryClipping_h

#include <glm/glm.hpp> // For glm vectors

#include <vector> // For polygons and faces

namespace vtkLightShaftGeometry
{
/**
 * A convex polytope as a list of convex faces, clipped by half-spaces.
 */
struct ConvexPolytope
{
  std::vector<std::vector<glm::dvec3>> Faces;

  /// Keep the part where dot(plane.xyz, p) + plane.w >= 0.
  void Clip(const glm::dvec4& plane);
  bool Empty() const { return this->Faces.empty(); }
};

/// The part of a convex polygon inside a counter-clockwise convex polygon (Sutherland-Hodgman).
std::vector<glm::dvec2> ClipToConvex(std::vector<glm::dvec2> polygon,
  const std::vector<glm::dvec2>& window);

/// Counter-clockwise convex hull (Andrew's monotone chain); fewer than 3 points: empty.
std::vector<glm::dvec2> ConvexHull(std::vector<glm::dvec2> points);

}

#endif
