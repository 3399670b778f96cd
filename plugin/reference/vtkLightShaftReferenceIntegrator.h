/**
 * @file   vtkLightShaftReferenceIntegrator.h
 * @brief  vtkLightShaftReference's integral along one view ray for one light, in float64
 *         (private, not installed): the model at a point for each kind of light (spot, point,
 *         directional), the lit interval, the lit pieces found by sampling and bisecting the
 *         visibility, and their integrals (closed forms or adaptive Gauss-Kronrod).
 */

#ifndef vtkLightShaftReferenceIntegrator_h
#define vtkLightShaftReferenceIntegrator_h

#include "vtkLightShaftModel.h" // For LightKind

#include <array>      // For Vec and RGB
#include <atomic>     // For the cancel request an effort watches
#include <cmath>      // For std::sqrt
#include <functional> // For the visibility and integrand callbacks
#include <memory>     // For the density field shared by the lights' models
#include <vector>     // For the cookie and noise texels

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
 * What one ray's integration may spend, and what it spent: integrand evaluations, bounded by
 * Limit (0: no bound), and a request to stop, looked at between quadrature panels (15
 * evaluations) and visibility samples, so that a ray returns within a few milliseconds of it.
 * Where either ends a piece's refinement, the panels not refined are kept with their error
 * estimates (Exhausted), or the whole ray is to be discarded (Cancelled).
 */
struct Effort
{
  long long Limit = 0;
  const std::atomic<bool>* Cancel = nullptr;
  long long Evaluations = 0;
  bool Exhausted = false;
  bool Cancelled = false;

  /// Whether the ray is to be discarded now (recorded).
  bool CancelRequested()
  {
    if (this->Cancel && this->Cancel->load(std::memory_order_relaxed))
    {
      this->Cancelled = true;
    }
    return this->Cancelled;
  }
  /// Whether the ray should stop refining now (and why, recorded).
  bool Spent()
  {
    if (!this->CancelRequested() && this->Limit > 0 && this->Evaluations >= this->Limit)
    {
      this->Exhausted = true;
    }
    return this->Cancelled || this->Exhausted;
  }
};

/**
 * Adaptive Gauss-Kronrod (7/15) of a vector-valued f over [a, b]; adds the integral to `sum`
 * and the estimated absolute error to `error`. A panel is accepted when its error is within
 * `relativeTolerance` of its integral (or at 40 halvings); the panel of largest error is split
 * first, so that where `effort` ends the refinement, the error left is as small as its
 * evaluations allow.
 */
void Integrate(const std::function<RGB(double)>& f,
  double a,
  double b,
  double relativeTolerance,
  Effort& effort,
  RGB& sum,
  RGB& error);

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

/// One ray's in-scattered radiance, its estimated quadrature error, and whether a closed form
/// computed it.
struct Result
{
  RGB Radiance{};
  RGB Error{};
  bool ClosedForm = false;
};

/// The light's transmittance to a point, per channel: 0 where an opaque surface shadows it, 1
/// where nothing does, the product of the translucent surfaces in between otherwise.
using Transmittance = std::function<RGB(const Vec&)>;

/**
 * Where the transmittance changes along the ray origin + t dir between tFrom and tTo, where it
 * differs: a t in (tFrom, tTo) just before which it is as at tFrom and just after which it is as
 * at tTo, computed exactly (the ray clipped by the occluders' shadow volumes); false where it
 * cannot say, and the change is then bisected.
 */
using Transition =
  std::function<bool(const Vec& origin, const Vec& dir, double tFrom, double tTo, double& t)>;

/**
 * The integral along origin + t dir over [t0, t1] (inside the lit interval, in front of the
 * surface): the transmittance sampled at `samples` points (in the equiangular angle when A
 * falls off, else in t) and every change placed by `transition` (when given and it can) or
 * bisected to 1e-12 of the interval; each piece where
 * it is not zero integrated by the closed forms (when `closedForms`) or adaptive Gauss-Kronrod
 * to `tolerance`, times the piece's transmittance. In t, the
 * pieces of a spot or point light are split where the ray passes closest to the light (the
 * phase function's peak); a ray through (within 1e-6 of its length of) a light whose A is
 * finite there (c0 > 0) is integrated in t, since the angle would crowd it into the ends.
 * `effort` bounds the work (its evaluations accumulate over calls: one per ray and light).
 */
Result IntegrateRay(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double t0,
  double t1,
  const Transmittance& transmittance,
  int samples,
  double tolerance,
  bool closedForms,
  Effort& effort,
  const Transition& transition = nullptr);
}

#endif
