/**
 * @file   vtkLightShaftGeometry.h
 * @brief  The geometry of a light-shaft frame, without GL (private, not installed): the scene
 *         camera and the light in view coordinates, the light's bounding pyramid and the part
 *         of the view volume it lights, the shadow casters, the slabs' screen footprints and
 *         their lattice.
 *
 * Double precision throughout; unit-tested on the CPU (tests/cxx/TestLightShaftGeometry.cxx).
 */

#ifndef vtkLightShaftGeometry_h
#define vtkLightShaftGeometry_h

#include "vtkLightShaftModel.h" // For vtkLightShaftModel::Light

#include <glm/glm.hpp> // For glm vectors and matrices

#include <array>  // For the float conversions
#include <string> // For the reason a camera is unusable
#include <vector> // For polygons, faces, casters, vertices

class vtkCamera;
class vtkMatrix4x4;
class vtkProp;
class vtkPropCollection;

namespace vtkLightShaftGeometry
{
/// VTK's key matrices (stored transposed for OpenGL) are glm's column-major layout.
glm::dmat4 FromKeyMatrix(vtkMatrix4x4* key);
/// A vtkMatrix4x4 (row-major, mathematical) to glm.
glm::dmat4 FromVTKMatrix(vtkMatrix4x4* m);
void ToVTKMatrix(const glm::dmat4& m, vtkMatrix4x4* out);
std::array<float, 16> ToFloatColumnMajor(const glm::dmat4& m);
std::array<float, 3> ToFloat3(const glm::dvec3& v);

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

/**
 * The light frame of `light` for `camera`: casters among `props` (visible props whose bounds
 * reach into the light's volume, and for a directional light whose shadow can fall in the
 * lit part of the view volume), and the cameras that render their depth. With `casterBounds`
 * (distributed rendering: every process's casters) the cameras' extent and depth range, and
 * whether shadows are possible, come from those bounds instead.
 */
LightFrame ComputeLightFrame(const vtkLightShaftModel::Light& light,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds);

/**
 * Shift the texel grid of `light`'s shadow cameras by (dx, dy) in their normalised device
 * coordinates (a texel of an N^2 map is 2 / N): progressive refinement's estimates render the
 * map shifted by parts of a texel, so that their mean smooths the map's staircase. Every
 * matrix that renders or looks up the map moves together; the cookie's square does not.
 */
void OffsetShadowCameras(LightFrame& light, double dx, double dy);

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

/**
 * The part of the view volume the light reaches (view coordinates): inside a spot's bounding
 * pyramid, beyond a directional light's plane, all of it for a point light; and the view-depth
 * range it spans.
 */
struct LitVolume
{
  ConvexPolytope Polytope;
  double Nearest = 0.0;
  double Deepest = 0.0;

  bool Empty() const { return !(this->Deepest > this->Nearest); }
};

LitVolume ComputeLitVolume(const LightFrame& light, const CameraFrame& camera);

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

/// Lattice cells built and drawn in one frame at most, shared equally by the lights that
/// radiate: the cells are clipped on the CPU, so their number bounds the frame's CPU time
/// (about 1.5 s for 2^21 cells here: docs/any-scene.md).
constexpr long long LatticeCellBudget = 1LL << 21;

/// The lattice resolution that `slabs` slabs of one of `lights` lights can afford within
/// LatticeCellBudget: `requested`, or the largest n with lights * slabs * n^2 within the budget
/// (at least 1).
int AffordableLattice(int requested, int slabs, int lights = 1);

/// Segments (a step of a march, a slab across a pixel: one closed-form integral and one
/// lookup each) a frame's in-scatter integrates at most, counted over the in-scatter's pixels
/// and shared equally by the lights that radiate: the bound of a frame's time at the sampling
/// maxima (about 16 s here, 15 ns a segment on llvmpipe with 2 cores: docs/any-scene.md
/// ).
constexpr long long SegmentBudget = 1LL << 30;

/// Segments one frame integrates at most where a setting's work is spread over frames
/// (vtkLightShaftPass::SplitLongFrames, with progressive refinement): a sixteenth of
/// SegmentBudget, at most about 2 s a frame here (up to 25 ns a segment: RAY_MARCH with four
/// spotlights and 4096² maps at 640x480; docs/robustness.md).
constexpr long long FrameSegmentAllowance = SegmentBudget / 16;

/// RADIAL_BLUR's samples (one occlusion-buffer fetch each) one frame takes at most where a
/// setting's work is spread over frames, counted over the in-scatter's pixels and shared by the
/// lights: 16 FrameSegmentAllowance, a blur sample being about 20 times cheaper than a segment
/// (0.7-0.8 ns on llvmpipe with 2 cores: 1024 samples with eight lights at 1080p, 12.9 s).
constexpr long long FrameRadialSampleAllowance = 16 * FrameSegmentAllowance;

/// LIGHT_VOLUME's mesh cells (over each map, each cube face of a point light's) one frame draws
/// at most where a setting's work is spread over frames (SplitLongFrames, with progressive
/// refinement), shared by the lights that radiate, up to FrameLightVolumePixels in-scatter
/// pixels, and in inverse proportion to them beyond (the cells' fragments): four spotlights'
/// 1024^2 at 640x480 (1.3 s a frame here); at 1080p eight lights' 287^2. Measured on llvmpipe
/// with 2 cores, 1080p, eight spotlights: about 0.7 s each 2^20 cells, and 1.5 s a frame
/// besides. A closed mesh's parts do not add up to pictures a frame could show alone, so it is
/// not split: a frame over it draws a coarser mesh.
constexpr long long FrameLightVolumeCellAllowance = 1LL << 22;
constexpr long long FrameLightVolumePixels = 640 * 480;

/// The light-volume mesh resolution one of `lights` lights with `faces` faces (6: a point
/// light's cube) can afford within FrameLightVolumeCellAllowance over `pixels` in-scatter
/// pixels: `requested`, or the largest n with lights * faces * n^2 within it (at least 8, the
/// parameter's minimum).
int AffordableLightVolume(int requested, int faces, int lights, long long pixels);

/// The steps or slabs per pixel that `pixels` in-scatter pixels of one of `lights` lights can
/// afford within SegmentBudget: `requested`, or fewer (at least 1).
int AffordableSamples(int requested, long long pixels, int lights = 1);

/// The farthest point of the view volume (camera plane to the camera's FarDepth) from `pointVC`.
double FarthestViewPoint(const CameraFrame& camera, const glm::dvec3& pointVC);
}

#endif
