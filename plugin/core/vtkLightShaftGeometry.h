/**
 * @file   vtkLightShaftGeometry.h
 * @brief  The geometry of a light-shaft frame, without GL (private, not installed): the scene
 *         camera and each light in view coordinates, the light's bounding pyramid and the
 *         cameras of its shadow map, as data.
 *
 * The namespace vtkLightShaftGeometry spans the files named after it, one job each:
 * vtkLightShaftGeometryClipping.h (convex clipping in 2D and 3D), vtkLightShaftGeometryLitVolume.h
 * (the part of the view volume a light reaches), vtkLightShaftGeometryLights.h (each light's frame:
 * casters and shadow cameras), vtkLightShaftGeometrySlabs.h (the slabs' screen footprints and
 * their lattice) and vtkLightShaftGeometryBudget.h (what one frame may afford). Double
 * precision throughout; unit-tested on the CPU (tests/cxx/TestLightShaftGeometry.cxx).
 */

#ifndef vtkLightShaftGeometry_h
#define vtkLightShaftGeometry_h

#include "vtkLightShaftModel.h" // For vtkLightShaftModel::Light

#include <glm/glm.hpp> // For glm vectors and matrices

#include <array>  // For the float conversions
#include <string> // For the reason a camera is unusable
#include <vector> // For the views, the casters and the image pieces' rows

class vtkCamera;
class vtkMatrix4x4;
class vtkProp;

namespace vtkLightShaftGeometry
{
/// VTK's key matrices (stored transposed for OpenGL) are glm's column-major layout.
glm::dmat4 FromKeyMatrix(vtkMatrix4x4* key);
/// A vtkMatrix4x4 (row-major, mathematical) to glm.
glm::dmat4 FromVTKMatrix(vtkMatrix4x4* m);
void ToVTKMatrix(const glm::dmat4& m, vtkMatrix4x4* out);
std::array<float, 16> ToFloatColumnMajor(const glm::dmat4& m);
std::array<float, 3> ToFloat3(const glm::dvec3& v);

/// A box's corner (index bits: x, y, z).
glm::dvec3 BoxCorner(const double bounds[6], int corner);

/**
 * The scene camera exactly as the mappers see it (VTK's key matrices), in double precision.
 */
struct CameraFrame
{
  glm::dmat4 WorldToView{ 1.0 };
  glm::dmat4 ViewToClip{ 1.0 };
  glm::dmat4 ClipToView{ 1.0 };
  bool Perspective = true; ///< else parallel (orthographic)
  /// The view depth where the medium seen ends, for rays that hit nothing too: the far
  /// clipping plane's from FromMatrices; the pass sets the scene's backdrop
  /// (vtkLightShaftModel::BackdropDepth), which no clipping range changes.
  double FarDepth = 1.0;

  static CameraFrame FromMatrices(const glm::dmat4& worldToView, const glm::dmat4& viewToClip);

  /**
   * What makes the camera unusable for the shafts, as "its clipping range is (nan, 10)" (empty
   * when it is usable): a position equal to its focal point, a parallel scale that is not
   * finite and positive under parallel projection, a clipping range that is not finite and
   * increasing, or matrices (this frame's) that are not finite or not invertible. (VTK clamps
   * view angles to [1e-8, 179] degrees: those are usable.)
   */
  std::string UnusableValue(vtkCamera* camera) const;

  /// Width of a pixel of a `width`-pixel target at view depth z, as x * z + y (view units).
  glm::dvec2 PixelFootprint(int width) const;
};

/**
 * The light's bounding pyramid: apex at the light, square cross-section of half-angle
 * atan(Tangent) about Axis, its sides facing +-U and +-V. In view coordinates (VC) for the slabs
 * and in world coordinates (WC) for the casters: the same pyramid.
 */
struct Pyramid
{
  glm::dvec3 Apex{ 0.0 };
  glm::dvec3 Axis{ 0.0, 0.0, -1.0 };
  glm::dvec3 U{ 1.0, 0.0, 0.0 };
  glm::dvec3 V{ 0.0, 1.0, 0.0 };
  double Tangent = 1.0;

  /// Whether an axis-aligned box can reach into the pyramid (false when all its corners lie
  /// outside one of the pyramid's planes).
  bool Reaches(const double bounds[6]) const;
};

/**
 * One camera of a light's shadow map: where it looks from, along what, and its projection
 * (perspective for spot and point lights, orthographic for a directional one), with the
 * casters it sees.
 */
struct LightView
{
  glm::dvec3 Position{ 0.0 };
  glm::dvec3 FocalPoint{ 0.0, 0.0, -1.0 };
  glm::dvec3 ViewUp{ 0.0, 1.0, 0.0 };
  glm::dmat4 Projection{ 1.0 };
  glm::dmat4 WorldToClip{ 1.0 };
  glm::dmat4 ViewToClip{ 1.0 };  ///< from the scene camera's view coordinates
  std::vector<vtkProp*> Casters; ///< the casters whose bounds reach into this camera's view
};

/**
 * The light in the scene camera's view coordinates, its casters and the cameras that render
 * their depth (the shadow map): everything the shafts need of one light this frame.
 */
struct LightFrame
{
  vtkLightShaftModel::Light Model; ///< the light in world coordinates
  glm::dvec3 PositionVC{ 0.0 };    ///< a directional light: a point of its plane
  glm::dvec3 AxisVC{ 0.0, 0.0, -1.0 };
  Pyramid BoundsVC; ///< a spot's bounding pyramid in view coordinates
  Pyramid BoundsWC; ///< the same pyramid in world coordinates
  /// The rotation from the scene camera's view coordinates to world coordinates.
  glm::dmat3 ViewToWorld{ 1.0 };

  std::vector<vtkProp*> Casters; ///< visible props that can shadow the lit part of the view
  bool ShadowsPossible = false;  ///< casters reach into the light's volume (here or elsewhere)

  /**
   * The shadow map's cameras: one (spot: perspective over the light's square; directional:
   * orthographic over the part of the light's plane whose light reaches the view volume and
   * meets a caster) or six (point: the cube's faces +X, -X, +Y, -Y, +Z, -Z, 90 degrees each,
   * laid out in a 3 x 2 atlas, face f in column f % 3, row f / 3). Their depth range: the
   * casters' (else of the view volume), distances from the light (spot, point) or from its
   * plane (directional).
   */
  std::vector<LightView> Views;
  double Near = 0.0;
  double Far = 1.0;
  /// The map's extent across one of its cameras: at unit distance for spot (2 tan) and point
  /// (2), in world units for directional (the larger side of its rectangle).
  double MapExtent = 1.0;
  /// Views[0]'s matrices (the one camera of spot and directional lights).
  glm::dmat4 Projection{ 1.0 };
  glm::dmat4 WorldToLightClip{ 1.0 };
  glm::dmat4 ViewToLightClip{ 1.0 };
  /// View coordinates to the light's square (cookie, noise) as clip coordinates: u = 0.5 x / w
  /// + 0.5, v likewise (spot: the shadow map's projection; directional: the square of side
  /// SquareSide centred on the axis through Position; point: unused).
  glm::dmat4 ViewToLightSquare{ 1.0 };
};

/// The farthest point of the view volume (camera plane to the camera's FarDepth) from `pointVC`.
double FarthestViewPoint(const CameraFrame& camera, const glm::dvec3& pointVC);

/// Rows [First, End) of an image.
struct RowBlock
{
  int First = 0;
  int End = 0;
};

/**
 * The rows of an image `height` rows high whose in-scatter piece `piece` of `pieces` computes
 * (distributed rendering: vtkLightShaftPass::SetImagePiece): blocks of ImagePieceBlockRows rows
 * dealt out in turn, block b to piece b mod pieces, so that each piece has rows all over the
 * picture (a shaft's cost differs from row to row). Every row belongs to exactly one piece.
 */
std::vector<RowBlock> ImagePieceRows(int piece, int pieces, int height);
/// The rows of a block: a sixteenth of a piece's share of the rows, at least 4 and at most 16
/// (the smaller, the more evenly a beam's rows are shared; measured in docs/paraview-mpi.md).
int ImagePieceBlockRows(int pieces, int height);
/// `rows` grown by `margin` rows on each side, within [0, height), blocks that meet merged.
std::vector<RowBlock> GrowRows(const std::vector<RowBlock>& rows, int margin, int height);
}

#endif
