/**
 * @class   vtkLightShaftFieldTable
 * @brief   The light leg's table through a medium from data without GL: its layout in the
 *          light's frame and its values, the density field's integral from the light to every
 *          texel (private, not installed; vtkLightShaftFieldTableTexture uploads it).
 *
 * The extinction of the light that reaches a sample of a view ray is exp(-sigma_t * tau), tau
 * the optical depth from the light to the sample. Marching that leg for every sample costs a
 * loop per step; instead, as Frostbite's and Unreal's volumetric shadows do, tau of the field is
 * tabulated once per light in the light's frame, and each sample looks it up. The texture holds
 * the integral of rho alone: MediumDensityScale and the background (a straight length) are
 * applied in the shader, so changing them rebuilds nothing. It is rebuilt when the field or the
 * light's position or direction changes.
 *
 * Its layout (Plan, no GL):
 * - a directional light: one orthographic face along the light's direction over the field's
 *   box, from the light's plane (or the box, whichever is later) to the box's far side;
 * - a spot or point light outside the field's box, seeing it within MaximumFaceTangent: one
 *   perspective face aimed at the box's centre over the box's projection, radial distance from
 *   the box's nearest to its farthest point;
 * - otherwise (the light inside or next to the box) the six faces of a cube around the light,
 *   world-axis aligned, radial distance from 0.
 * A spot lights its cone only: where a face over the cone is smaller than the box's (the light
 * inside the box, or a box wider than the cone), the face covers the cone instead.
 *
 * Its depth follows the field's own sampling seen along the columns (Resolve): a texel for
 * every sample plane a column crosses, so that a sharp layer in a wide box is resolved, at
 * least as many texels as laterally, at most MaximumDepth; over MaximumValues in all, lateral
 * and depth texels shrink alike.
 *
 * Along a face's lateral axes and its depth the texel centres sit at the grid's ends, so that
 * the texture is interpolated, not extrapolated, over the whole range. Rays outside a single
 * face's range miss the box (tau = 0); beyond the far end tau stays its value at the box's exit.
 *
 * The values are the field's exact integrals (vtkLightShaftDensityField::Cumulative, float64,
 * stored as float32): the only approximation is the texture's trilinear interpolation.
 */

#ifndef vtkLightShaftFieldTable_h
#define vtkLightShaftFieldTable_h

#include "vtkLightShaftModel.h" // For the light

#include <glm/glm.hpp> // For the faces' frames

#include <cstddef> // For std::size_t
#include <vector>  // For the values

class vtkLightShaftDensityField;

class vtkLightShaftFieldTable
{
public:
  /// A single face sees the box within this tangent of its half-angle (63 degrees).
  static constexpr double MaximumFaceTangent = 2.0;
  /// The most depth texels a face has (the texture's own limit may be lower).
  static constexpr int MaximumDepth = 2048;
  /// The most texels a table holds (16 MiB of float32; its build takes about 0.25 s on two
  /// cores).
  static constexpr std::size_t MaximumValues = std::size_t(1) << 22;

  /**
   * Where the texture's values lie. Face coordinates q = ToFace * (x - Origin) (world x); a
   * face's (u, v, w) is (q.x, q.y, q.z) orthographic, (q.x / q.z, q.y / q.z, |q|) perspective.
   * Cube face f = 2 k + (q_k < 0) for the major axis k of q (ToFace the identity), with
   * (u, v, w) = (q_{k+1} / |q_k|, q_{k+2} / |q_k|, |q|). The texture holds the faces side by
   * side along x: Lateral * Faces by Lateral by Depth texels.
   */
  struct Layout
  {
    int Faces = 1; ///< 1 or 6 (cube)
    bool Orthographic = false;
    int Lateral = 0; ///< texels along u and along v
    int Depth = 0;   ///< texels along w, per face
    glm::dvec3 Origin{ 0.0 };
    glm::dmat3 ToFace{ 1.0 };
    double Low[3] = { -1.0, -1.0, 0.0 }; ///< (u, v, w) at the first texel centres
    double High[3] = { 1.0, 1.0, 1.0 };  ///< and at the last

    /// The ray through texel column (face, i, j): its origin and unit direction in world.
    void Column(int face, int i, int j, glm::dvec3& origin, glm::dvec3& direction) const;
    /// w of depth texel k.
    double DepthAt(int k) const;
    std::size_t Bytes() const { return sizeof(float) * Values(); }
    std::size_t Values() const
    {
      return static_cast<std::size_t>(this->Lateral) * this->Lateral * this->Depth * this->Faces;
    }
  };

  /**
   * The layout for `light` over `field`'s box, `resolution` texels along each lateral axis of a
   * single face (half of it for each of a cube's six), its depth from Resolve.
   */
  static Layout Plan(const vtkLightShaftDensityField& field,
    const vtkLightShaftModel::Light& light,
    int resolution,
    int maximumDepth = MaximumDepth);

  /**
   * Sets `layout`'s depth texels (its ranges and faces set): one per sample plane of `field`
   * its most crossed column crosses, at least Lateral, at most `maximumDepth`; over
   * MaximumValues in all, the lateral and depth texels shrink by the same factor.
   */
  static void Resolve(const vtkLightShaftDensityField& field, Layout& layout, int maximumDepth);

  /// The integrals of rho from the light along every texel column (x fastest, then y, then w).
  static std::vector<float> Integrate(const vtkLightShaftDensityField& field, const Layout& layout);
};

#endif
