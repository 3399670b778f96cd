/**
 * @file   vtkLightShaftModel.h
 * @brief  The physical model's rules, in one place for vtkLightShaftPass and
 *         vtkLightShaftReference (private, not installed): which light scatters, what it emits,
 *         the light's square (cookie, noise and shadow-map coordinates), the medium.
 *
 * Everything here is in world coordinates and double precision, and touches no GL.
 */

#ifndef vtkLightShaftModel_h
#define vtkLightShaftModel_h

#include "vtkMath.h" // For vtkMath::Pi

#include <glm/glm.hpp> // For glm::dvec3

class vtkLight;
class vtkRenderer;

namespace vtkLightShaftModel
{
/// The light's square (and its bounding pyramid) spans at most this half-angle; wider cones are
/// bounded by the view volume instead (the integrand still clips to the true cone).
constexpr double MaximumSquareHalfAngle = vtkMath::Pi() * 89.9 / 180.0;

/// A spotlight: positional with a cone half-angle below 90 degrees.
bool IsSpotLight(vtkLight* light);

/**
 * The light that scatters: `requested` when it is a spotlight (nullptr when it is not), or with
 * no light requested the renderer's first switched-on spotlight (nullptr when there is none).
 */
vtkLight* FindLight(vtkLight* requested, vtkRenderer* renderer);

/**
 * A spotlight as the model sees it, in world coordinates.
 */
struct Light
{
  glm::dvec3 Position{ 0.0 };
  glm::dvec3 Axis{ 0.0, 0.0, -1.0 }; ///< unit, from the position towards the focal point
  double ConeHalfAngle = 0.0;        ///< radians
  double Exponent = 0.0;             ///< spot exponent: S = cos(angle to the axis)^Exponent
  /// A(r) = 1 / (c0 + c1 r + c2 r^2); all zero is taken as no falloff (1, 0, 0), since VTK's
  /// lighting would divide by zero.
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  double RadiantIntensity[3] = { 0.0, 0.0, 0.0 }; ///< intensity * diffuse colour; 0 when off
  /// The light's square (cookie, noise, shadow map): rows along Up (world +Y projected on the
  /// light's plane, or +X for a light within ~8 degrees of +-Y), columns along Right.
  glm::dvec3 Right{ 1.0, 0.0, 0.0 };
  glm::dvec3 Up{ 0.0, 1.0, 0.0 };
  /// The world direction the light camera's view-up is set to (+Y, or +X near +-Y).
  glm::dvec3 ViewUp{ 0.0, 1.0, 0.0 };
  /// tan of the square's half-angle (the cone's, clamped to MaximumSquareHalfAngle).
  double SquareTangent = 1.0;

  /// Whether A(r) falls off with distance.
  bool FallingAttenuation() const
  {
    return this->Attenuation[1] != 0.0 || this->Attenuation[2] != 0.0;
  }
};

/// `light` (a spotlight) as the model sees it.
Light DescribeLight(vtkLight* light);

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
}

#endif
