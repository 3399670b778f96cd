#include "vtkLightShaftGeometryLitVolume.h"

#include <algorithm>
#include <array>
#include <limits>

namespace vtkLightShaftGeometry
{
//------------------------------------------------------------------------------
namespace
{
// The part of `polytope` inside the view volume, and its view-depth range.
LitVolume ClipToViewVolume(ConvexPolytope polytope, const CameraFrame& camera)
{
  // Clipped to the view volume: the four sides, the far depth (where rays that hit nothing
  // end), and a depth just in front of the camera plane (slabs must project).
  const glm::dmat4 clipT = glm::transpose(camera.ViewToClip); // rows of the projection
  const glm::dvec4 row0 = clipT[0];
  const glm::dvec4 row1 = clipT[1];
  const glm::dvec4 row3 = clipT[3];
  const double minimumDepth = camera.FarDepth * 1e-7;
  LitVolume lit;
  lit.Polytope = std::move(polytope);
  for (const glm::dvec4& plane : { row3 + row0,
         row3 - row0,
         row3 + row1,
         row3 - row1,
         glm::dvec4(0.0, 0.0, 1.0, camera.FarDepth),
         glm::dvec4(0.0, 0.0, -1.0, -minimumDepth) })
  {
    lit.Polytope.Clip(plane);
  }
  if (lit.Polytope.Empty())
  {
    return lit;
  }
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  for (const auto& face : lit.Polytope.Faces)
  {
    for (const auto& p : face)
    {
      nearest = std::min(nearest, -p.z);
      deepest = std::max(deepest, -p.z);
    }
  }
  lit.Nearest = std::max(nearest, minimumDepth);
  lit.Deepest = deepest;
  return lit;
}

// An axis-aligned cube of half-side `half` about `centre`, as a polytope.
ConvexPolytope Cube(const glm::dvec3& centre, double half)
{
  glm::dvec3 c[8];
  for (int corner = 0; corner < 8; ++corner)
  {
    c[corner] = centre + half * glm::dvec3((corner & 1) ? 1.0 : -1.0,
                                  (corner & 2) ? 1.0 : -1.0,
                                  (corner & 4) ? 1.0 : -1.0);
  }
  ConvexPolytope cube;
  cube.Faces = { { c[0], c[2], c[3], c[1] },
    { c[4], c[5], c[7], c[6] },
    { c[0], c[1], c[5], c[4] },
    { c[2], c[6], c[7], c[3] },
    { c[0], c[4], c[6], c[2] },
    { c[1], c[3], c[7], c[5] } };
  return cube;
}
}

//------------------------------------------------------------------------------
LitVolume ComputeLitVolume(const LightFrame& light, const CameraFrame& camera)
{
  if (light.Model.Kind != vtkLightShaftModel::LightKind::Spot)
  {
    // The view volume (inside a cube about the eye that holds it), beyond a directional
    // light's plane.
    const double reach = std::max(FarthestViewPoint(camera, glm::dvec3(0.0)), 1e-30) * 1.01;
    ConvexPolytope volume = Cube(glm::dvec3(0.0), reach);
    if (light.Model.Kind == vtkLightShaftModel::LightKind::Directional)
    {
      volume.Clip(glm::dvec4(light.AxisVC, -glm::dot(light.AxisVC, light.PositionVC)));
    }
    return ClipToViewVolume(std::move(volume), camera);
  }
  const Pyramid& pyramid = light.BoundsVC;

  // The pyramid, its base beyond everything the view can see.
  const double reach = std::max(FarthestViewPoint(camera, pyramid.Apex), 1e-30);
  const double halfSide = reach * pyramid.Tangent;
  const glm::dvec3& u = pyramid.U;
  const glm::dvec3& v = pyramid.V;
  const glm::dvec3 baseCentre = pyramid.Apex + reach * pyramid.Axis;
  const std::array<glm::dvec3, 4> base = { baseCentre + halfSide * (u + v),
    baseCentre + halfSide * (-u + v),
    baseCentre + halfSide * (-u - v),
    baseCentre + halfSide * (u - v) };
  ConvexPolytope polytope;
  polytope.Faces.push_back({ base[3], base[2], base[1], base[0] });
  for (int i = 0; i < 4; ++i)
  {
    polytope.Faces.push_back({ pyramid.Apex, base[i], base[(i + 1) % 4] });
  }
  return ClipToViewVolume(std::move(polytope), camera);
}
}
