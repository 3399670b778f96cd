/**
 * @file   vtkLightShaftModel.h
 * @brief  The physical model's rules, in one place for vtkLightShaftPass and
 *         vtkLightShaftReference (private, not installed): which lights scatter, what kind each
 *         is, what it emits, the light's square (cookie, noise coordinates), the medium.
 *
 * Everything here is in world coordinates and double precision, and touches no GL.
 */

#ifndef vtkLightShaftModel_h
#define vtkLightShaftModel_h

#include "vtkMath.h" // For vtkMath::Pi

#include <glm/glm.hpp> // For glm::dvec3

#include <string> // For the reason a light is unusable
#include <vector> // For the lights chosen

class vtkImageData;
class vtkLight;
class vtkRenderer;

namespace vtkLightShaftModel
{
/// The light's square (and its bounding pyramid) spans at most this half-angle; wider cones are
/// bounded by the view volume instead (the integrand still clips to the true cone).
constexpr double MaximumSquareHalfAngle = vtkMath::Pi() * 89.9 / 180.0;

/**
 * The kinds of light VTK has, as the model treats them (the values are
 * vtkLightShaftPass::LightKindType's):
 * - Spot: positional, cone half-angle below 90 degrees: I S(x) A(r) from the position, inside
 *   the cone.
 * - Point: positional, cone angle of 90 degrees or more (VTK then applies no cone): I A(r) from
 *   the position, in every direction.
 * - Directional: not positional: parallel light travelling from Position towards FocalPoint,
 *   lighting the half-space beyond the plane through Position perpendicular to that direction,
 *   with no falloff; its r (the extinction leg) is the distance from that plane.
 */
enum class LightKind
{
  Spot = 0,
  Point = 1,
  Directional = 2
};

/// The kind of `light` (see LightKind).
LightKind KindOf(vtkLight* light);

/// A spotlight: positional with a cone half-angle below 90 degrees.
bool IsSpotLight(vtkLight* light);

/**
 * The lights that scatter: the switched-on lights of `requested` (any kind; switched-off ones
 * contribute nothing and are left out), or with none requested every switched-on spot and point
 * light of `renderer`, in the renderer's order (directional lights only when requested: VTK's
 * default headlight and light kits are directional).
 */
std::vector<vtkLight*> FindLights(const std::vector<vtkLight*>& requested, vtkRenderer* renderer);

/**
 * What makes `light` unusable for the shafts, as "its exponent is nan" (empty when it is
 * usable): a position or focal point that is not finite (a transform matrix with NaN), a spot or
 * directional light whose position equals its focal point (no direction), an intensity, colour
 * or attenuation that is not finite or is negative, a positional light's cone angle that is not
 * finite, a spot's exponent that is not finite or is negative. VTK's vtkLight takes them all.
 */
std::string UnusableLightValue(vtkLight* light);

/// Whether the six bounds are all finite and initialised (min <= max).
bool UsableBounds(const double bounds[6]);

/**
 * The box of the scene the medium is seen in: the visible props' bounds of `renderer`, grown
 * to hold `given` (the whole distributed scene's bounds, when set; else nullptr) and `field`
 * (the medium's density image, or nullptr). False when there is none (no visible 3D prop and
 * nothing given): the pass then leaves the picture as it is.
 */
bool SceneBounds(vtkRenderer* renderer, const double* given, vtkImageData* field, double bounds[6]);

/**
 * The backdrop: the view depth where a ray that hits no surface ends, the deepest corner of
 * the scene's box `bounds` as `worldToView` sees it (at most 0 when the whole box is behind the
 * camera). What shows where nothing is drawn (the renderer's background) stands there: the
 * medium in front of it scatters into the ray and dims it, and no clipping range changes it.
 */
double BackdropDepth(const glm::dmat4& worldToView, const double bounds[6]);

/**
 * A light as the model sees it, in world coordinates.
 */
struct Light
{
  LightKind Kind = LightKind::Spot;
  /// Spot and point: the light's position. Directional: a point of the plane where the light
  /// starts (the light's Position).
  glm::dvec3 Position{ 0.0 };
  /// Unit, from the position towards the focal point: the spot's axis, the direction a
  /// directional light travels (a point light's is unused but defined).
  glm::dvec3 Axis{ 0.0, 0.0, -1.0 };
  double ConeHalfAngle = 0.0; ///< radians; spot only (pi for the others: no cone)
  double Exponent = 0.0;      ///< spot exponent: S = cos(angle to the axis)^Exponent (0: none)
  /// A(r) = 1 / (c0 + c1 r + c2 r^2); all zero is taken as no falloff (1, 0, 0), since VTK's
  /// lighting would divide by zero. Directional lights have none (1, 0, 0), as in VTK.
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  double RadiantIntensity[3] = { 0.0, 0.0, 0.0 }; ///< intensity * diffuse colour; 0 when off
  /// The light's square (cookie, noise, the spot's shadow map): rows along Up (world +Y
  /// projected on the light's plane, or +X for a light within ~8 degrees of +-Y), columns
  /// along Right.
  glm::dvec3 Right{ 1.0, 0.0, 0.0 };
  glm::dvec3 Up{ 0.0, 1.0, 0.0 };
  /// The world direction the light camera's view-up is set to (+Y, or +X near +-Y).
  glm::dvec3 ViewUp{ 0.0, 1.0, 0.0 };
  /// Spot: tan of the square's half-angle (the cone's, clamped to MaximumSquareHalfAngle).
  double SquareTangent = 1.0;
  /// Directional: the side of the light's square, |FocalPoint - Position| (cookie and noise
  /// tile the light's plane with this period), centred on the axis through Position.
  double SquareSide = 1.0;

  /// Whether A(r) falls off with distance.
  bool FallingAttenuation() const
  {
    return this->Attenuation[1] != 0.0 || this->Attenuation[2] != 0.0;
  }

  /// Whether it emits at all (switched on, some intensity).
  bool Radiates() const
  {
    return this->RadiantIntensity[0] > 0.0 || this->RadiantIntensity[1] > 0.0 ||
           this->RadiantIntensity[2] > 0.0;
  }

  /**
   * The width of the light's square (the span of cookie and noise coordinates 0..1) at
   * distance r from the light, as (a, b) in a r + b: spot (2 tan, 0); directional (0, side);
   * point (2, 0) (its noise is projected on the planes across the unit sphere of directions).
   */
  glm::dvec2 SquareWidth() const;

  /// r of a world point: the distance from the light, or from a directional light's plane.
  double Distance(const glm::dvec3& point) const;
};

/// `light` as the model sees it.
Light DescribeLight(vtkLight* light);

/**
 * The medium chosen from the scene (vtkLightShaftPass::FitMediumToScene), so that a scene 1,
 * 100 or 10,000 units across gives the same picture up to scale. FittedScattering: the grey
 * sigma_s whose optical depth across the scene's box `bounds` (its diagonal; the box grown to
 * hold a positional light) is FittedOpticalDepth. FittedExposure: the exposure that brings the
 * in-scatter of a ray crossing `light`'s beam through the box's centre, in a medium of
 * `sigmaS`, to FittedInScatter: sigma_s / (4 pi) I A(d) w, with I the brightest channel of the
 * light's radiant intensity, A(d) its falloff at the centre's distance d and w the beam's width
 * there (a spot's 2 d tan(cone), at most the diagonal; the diagonal for the other kinds). Both
 * are 0 where they cannot be chosen (a flat or empty box, a dark light).
 */
constexpr double FittedOpticalDepth = 0.9;
constexpr double FittedInScatter = 0.6;
double FittedScattering(const double bounds[6], const Light& light);
double FittedExposure(const double bounds[6], const Light& light, double sigmaS);

/**
 * The participating medium: sigma_t = sigma_s + sigma_a per colour channel, and the phase.
 */
struct Medium
{
  double SigmaS[3] = { 0.0, 0.0, 0.0 };
  double SigmaT[3] = { 0.0, 0.0, 0.0 };
  int Phase = 0;           ///< vtkLightShaftPass::PhaseFunctionType
  double Anisotropy = 0.0; ///< Henyey-Greenstein g

  bool Scatters() const;     ///< any sigma_s > 0
  bool Extinguishes() const; ///< any sigma_t > 0
  double MaximumSigmaT() const;
};

Medium DescribeMedium(const double sigmaS[3], const double sigmaA[3], int phase, double g);

/**
 * The two scrolling noise layers' offsets at `time` (velocities in tiles per unit of time),
 * wrapped to one tile in double precision so that large times stay exact: (u1, v1, u2, v2);
 * layer 2 starts at (0.37, 0.61).
 */
void NoiseShifts(const double velocity1[2],
  const double velocity2[2],
  double time,
  double shifts[4]);

/**
 * A point light's noise weights over the three planes across the unit sphere of directions
 * (x = 0, y = 0, z = 0), for a unit direction `d` from the light: w_i = d_i^4 / sum d_j^4
 * (triplanar: seamless over the sphere, one plane dominating near each axis).
 */
glm::dvec3 TriplanarWeights(const glm::dvec3& d);
}

#endif
