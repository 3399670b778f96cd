/**
 * @file   vtkLightShaftReferenceIntegrator.h
 * @brief  vtkLightShaftReference's integral along one view ray for one light, in float64
 *         (private, not installed): the lit pieces of the ray found by sampling and bisecting
 *         the visibility, and their integrals of the model (vtkLightShaftReferenceModel.h) by
 *         closed forms or adaptive Gauss-Kronrod.
 */

#ifndef vtkLightShaftReferenceIntegrator_h
#define vtkLightShaftReferenceIntegrator_h

#include "vtkLightShaftReferenceModel.h" // For the model, Vec and RGB

#include <atomic>     // For the cancel request an effort watches
#include <functional> // For the visibility and integrand callbacks

namespace vtkLightShaftReferenceIntegrator
{
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
