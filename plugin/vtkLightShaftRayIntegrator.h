/**
 * @file   vtkLightShaftRayIntegrator.h
 * @brief  vtkLightShaftReference's integral along one view ray, in float64 (private, not
 *         installed): the model at a point, the cone interval, the lit pieces found by
 *         sampling and bisecting the visibility, and their integrals (closed forms or adaptive
 *         Gauss-Kronrod).
 */

#ifndef vtkLightShaftRayIntegrator_h
#define vtkLightShaftRayIntegrator_h

#include <array>      // For Vec and RGB
#include <cmath>      // For std::sqrt
#include <functional> // For the visibility and integrand callbacks
#include <vector>     // For the cookie and noise texels

class vtkLight;
class vtkLightShaftPass;

namespace vtkLightShaftRayIntegrator
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
 * Adaptive Gauss-Kronrod (7/15) of a vector-valued f over [a, b]; adds the integral to `sum`
 * and the estimated absolute error to `error`.
 */
void Integrate(const std::function<RGB(double)>& f,
  double a,
  double b,
  double relativeTolerance,
  int depth,
  RGB& sum,
  RGB& error);

/// Everything one ray's integral needs, in world coordinates, double precision.
struct Model
{
  Vec Light{};
  Vec Axis{};
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
  double SquareTangent = 1.0;
  std::vector<float> Cookie; // RGB, row 0 at the bottom; empty: no cookie
  int CookieWidth = 0;
  int CookieHeight = 0;
  std::vector<float> Noise; // mean 1, tiled; empty: homogeneous
  int NoiseWidth = 0;
  int NoiseHeight = 0;
  double NoiseAmplitude = 0.0;
  double NoiseScale = 1.0;
  double NoiseShift[4] = { 0.0, 0.0, 0.0, 0.0 };

  /// Cookie colour times noise density at x (1 when neither is in use).
  RGB Modulation(const Vec& x) const;
  double PhaseValue(double cosTheta) const;
  bool FallingAttenuation() const;
  /// Whether the closed forms hold: a plain cone (exponent 0), isotropic phase, A = 1 / r^2,
  /// no cookie and no noise.
  bool ClosedFormsHold() const;
  /// The integrand at parameter t of the ray origin + t dir (visibility excluded).
  RGB Integrand(const Vec& origin, const Vec& dir, double t) const;
};

/**
 * The model of `light` with `pass`'s medium, cookie and noise, read and laid out as the pass
 * reads and lays them out (level 0 of their images, bilinear; the pass pre-filters by
 * footprint, which differs only where the texture varies within a pixel's footprint).
 */
Model MakeModel(vtkLight* light, vtkLightShaftPass* pass);

/// The parameter interval of origin + t dir inside the cone's forward nappe (t0 > t1: none).
void ConeInterval(const Model& model, const Vec& origin, const Vec& dir, double& t0, double& t1);

/// One ray's in-scattered radiance, its estimated quadrature error, and whether a closed form
/// computed it.
struct Result
{
  RGB Radiance{};
  RGB Error{};
  bool ClosedForm = false;
};

/**
 * The integral along origin + t dir over [t0, t1] (inside the cone, in front of the surface):
 * the visibility sampled at `samples` points (in the equiangular angle when A falls off) and
 * every change bisected to 1e-12 of the interval; each lit piece integrated by the closed
 * forms (when `closedForms`) or adaptive Gauss-Kronrod to `tolerance`.
 */
Result IntegrateRay(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double t0,
  double t1,
  const std::function<bool(const Vec&)>& visible,
  int samples,
  double tolerance,
  bool closedForms);
}

#endif
