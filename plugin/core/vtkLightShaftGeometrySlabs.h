/**
 * @file   vtkLightShaftGeometrySlabs.h
 * @brief  The slabs' screen footprints and their lattice, without GL (private, not installed;
 *         part of the namespace vtkLightShaftGeometry, vtkLightShaftGeometry.h).
 */

#ifndef vtkLightShaftGeometrySlabs_h
#define vtkLightShaftGeometrySlabs_h

#include "vtkLightShaftGeometryLitVolume.h" // For LitVolume and CameraFrame

#include <glm/glm.hpp> // For glm vectors

#include <vector> // For the footprints, hulls and vertices

namespace vtkLightShaftGeometry
{

/**
 * One slab to draw: its index (the shader's slab boundaries), its near view depth, and the
 * convex hull of its screen footprint (NDC).
 */
struct SlabFootprint
{
  int Index;
  double NearDepth;
  std::vector<glm::dvec2> Hull;
};

/**
 * The footprints of `slabs` slabs of the lit volume's depth range; with `jitter` each pixel's
 * slab k spans [k - 1 + o, k + o] thicknesses (o in (0, 1)): one more slab, and footprints
 * covering two thicknesses. Slabs with an empty footprint are left out. A split setting's share
 * takes slabs `part`, `part` + `share`, ... only.
 */
std::vector<SlabFootprint> ComputeSlabFootprints(const LitVolume& lit,
  const CameraFrame& camera,
  int slabs,
  bool jitter,
  int share = 1,
  int part = 0);

/**
 * Append the triangles covering `slab` to `vertices` (x, y in NDC, slab index, near depth per
 * vertex): the hull as a fan, or with lattice > 0 an n x n lattice over the hull's bounding
 * rectangle with each cell clipped to the hull, so that no more fragments are drawn than
 * without the lattice.
 */
void AppendSlabTriangles(const SlabFootprint& slab, int lattice, std::vector<float>& vertices);
}

#endif
