/**
 * @file   vtkLightShaftReferenceModel.h
 * @brief  The float64 reference's model of one light in the medium, in world coordinates
 *         (private, not installed): the light per kind (spot, point, directional), its cookie
 *         and noise, the medium's coefficients, phase function, density field, bounds and the
 *         scene's volume, evaluated at a point; and the interval of a ray the light reaches.
 */

#ifndef vtkLightShaftReferenceModel_h
#define vtkLightShaftReferenceModel_h

#include "vtkLightShaftModel.h" // For LightKind

#include <array>  // For Vec and RGB
#include <cmath>  // For std::sqrt
#include <memory> // For the density field shared by the lights' models
#include <vector> // For the cookie and noise texels

class vtkLight;
class vtkLightShaftDensityField;
struct vtkLightShaftReferenceInput;

namespace vtkLightShaftReferenceIntegrator
{
using Vec = std::array<double, 3>;
using RGB = std::array<double, 3>;

inline Vec operator+(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Vec operator-(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec operator*(double s, const Vec& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
inline Vec Normalized(const Vec& a)
{
  const double n = Norm(a);
  return n > 0.0 ? (1.0 / n) * a : a;
}

/**
 * Everything one ray's integral needs for one light, in world coordinates, double precision.
 * Per kind (P = Light, a = Axis):
 * - Spot: r = |x - P|, lit inside the cone's forward nappe, S = cos(angle to a)^Exponent,
 *   A = 1 / (c0 + c1 r + c2 r^2), light direction l = (x - P) / r.
 * - Point: as a spot without the cone (S = 1).
 * - Directional: r = (x - P) . a, the distance from the plane through P perpendicular to a;
 *   lit where r >= 0; S = A = 1; l = a everywhere.
 */
struct Model
{
  vtkLightShaftModel::LightKind Kind = vtkLightShaftModel::LightKind::Spot;
  Vec Light{}; ///< the light's position (directional: a point of its plane)
  Vec Axis{};  ///< unit: the spot's axis, the direction a directional light travels
  double CosCone = 1.0;
  double Exponent = 1.0;
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  RGB Intensity{};
  RGB SigmaS{};
  RGB SigmaT{};
  int Phase = 0;
  double Anisotropy = 0.0;

  // The light's square as vtkLightShaftPass lays it out, for cookie and noise coordinates.
  Vec Right{ 1.0, 0.0, 0.0 };
  Vec Up{ 0.0, 1.0, 0.0 };
  double SquareTangent = 1.0; ///< spot: tan of the square's half-angle
  double SquareSide = 1.0;    ///< directional: the square's side (cookie and noise period)
  std::vector<float> Cookie;  // RGB, row 0 at the bottom; empty: no cookie (always, for a point)
  int CookieWidth = 0;
  int CookieHeight = 0;
  std::vector<float> Noise; // mean 1, tiled; empty: homogeneous
  int NoiseWidth = 0;
  int NoiseHeight = 0;
  double NoiseAmplitude = 0.0;
  double NoiseScale = 1.0;
  double NoiseShift[4] = { 0.0, 0.0, 0.0, 0.0 };
  /// A medium from data (null: homogeneous): sigma_s and sigma_t at x are scaled by
  /// Density(x) = BackgroundDensity + DensityScale * rho(x), and the extinction of both legs
  /// is sigma_t times the exact integral of Density along them.
  std::shared_ptr<const vtkLightShaftDensityField> Field;
  double DensityScale = 1.0;
  double BackgroundDensity = 0.0;
  /// The scene's vtkVolume (null: none): its extinction kappa per world unit
  /// (vtkLightShaftVolumeField) dims both legs by exp(-its exact integral along them), every
  /// channel alike.
  std::shared_ptr<const vtkLightShaftDensityField> Extinction;

  bool Directional() const { return this->Kind == vtkLightShaftModel::LightKind::Directional; }
  /// Whether the medium scatters this light at all (any sigma_s and intensity above 0).
  bool Scatters() const;
  /// r at x: the distance from the light, or from a directional light's plane (signed).
  double Distance(const Vec& x) const;
  /**
   * Cookie colour times noise density at x (1 when neither is in use). Spot: the light's
   * square in perspective, the cookie clamped to its edge. Directional: the square of side
   * SquareSide centred on the axis through Light, the cookie repeating. Point: no cookie; the
   * noise projected triplanar on the unit sphere of directions, in world axes.
   */
  RGB Modulation(const Vec& x, bool withNoise = true) const;
  /**
   * What reaches a surface at x of the light VTK's lighting gives it, besides the scene's
   * shadows (vtkLightShaftPass::ShadowSurfaces): the cookie's colour (not the noise, which
   * modulates the scattering, not the extinction), the medium's transmittance along the light
   * leg, exp(-sigma_t OpticalDepth(x, the light or its plane)), and the scene's volume's.
   */
  RGB SurfaceLight(const Vec& x) const;
  double PhaseValue(double cosTheta) const;
  /// The medium's density at x (1 without a field).
  double Density(const Vec& x) const;
  /// The integral of Density along the segment from a to b (its length without a field).
  double OpticalDepth(const Vec& a, const Vec& b) const;
  bool FallingAttenuation() const;
  /// Whether the ray is integrated in the equiangular angle about the light: A falls off (so
  /// never for a directional light).
  bool Equiangular() const;
  /**
   * Whether the closed forms hold: no cookie, no noise and no density field, and for a spot or
   * point light a plain cone or none (exponent 0), isotropic phase and A = 1 / r^2 ((A), (B)); a
   * directional light's unshadowed integral is exact for any phase (theta is constant).
   */
  bool ClosedFormsHold() const;
  /// The integrand at parameter t of the ray origin + t dir (visibility excluded).
  RGB Integrand(const Vec& origin, const Vec& dir, double t) const;

private:
  double NoiseLayers(double u, double v) const;
};

/**
 * The model of `light` with the `input`'s medium, cookie and noise, read and laid out as the
 * pass reads and lays them out (level 0 of their images, bilinear; the pass pre-filters by
 * footprint, which differs only where the texture varies within a pixel's footprint).
 */
Model MakeModel(vtkLight* light,
  const vtkLightShaftReferenceInput& input,
  std::shared_ptr<const vtkLightShaftDensityField> field = nullptr);

/**
 * The parameter interval of origin + t dir where the light shines (t0 > t1: none; infinite
 * ends where it is unbounded): inside a spot's cone (its forward nappe), everywhere for a point
 * light, in the half-space beyond a directional light's plane.
 */
void LitInterval(const Model& model, const Vec& origin, const Vec& dir, double& t0, double& t1);

}

#endif
