#include "vtkLightShaftReferenceIntegrator.h"

#include "vtkLightShaftDensityField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vtkLightShaftReferenceIntegrator
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

// Gauss-Kronrod 7/15 nodes and weights on [-1, 1].
constexpr double KronrodNodes[8] = { 0.991455371120812639,
  0.949107912342758525,
  0.864864423359769073,
  0.741531185599394440,
  0.586087235467691130,
  0.405845151377397167,
  0.207784955007898468,
  0.0 };
constexpr double KronrodWeights[8] = { 0.022935322010529225,
  0.063092092629978553,
  0.104790010322250184,
  0.140653259715525919,
  0.169004726639267903,
  0.190350578064785410,
  0.204432940075298892,
  0.209482141084727828 };
constexpr double GaussWeights[4] = { 0.129484966168869693,
  0.279705391489276668,
  0.381830050505118945,
  0.417959183673469388 };

/**
 * F(u, v) = int_0^v exp(-u tan xi) d xi (Sun et al. 2005), by adaptive quadrature.
 */
double SunF(double u, double v, double tolerance, Effort& effort)
{
  RGB sum{};
  RGB error{};
  Integrate(
    [u](double xi)
    {
      const double value = std::exp(-u * std::tan(xi));
      return RGB{ value, 0.0, 0.0 };
    },
    0.0,
    v,
    tolerance,
    effort,
    sum,
    error);
  return sum[0];
}
}

//------------------------------------------------------------------------------
namespace
{
/// One Gauss-Kronrod panel: its interval, halvings, estimates and their difference.
struct Panel
{
  double A;
  double B;
  int Depth;
  RGB Kronrod;
  RGB Error;
  double Worst; ///< the largest channel's error: the panel split first is the worst
};

Panel EvaluatePanel(const std::function<RGB(double)>& f, double a, double b, int depth)
{
  const double half = 0.5 * (b - a);
  const double centre = 0.5 * (a + b);
  RGB kronrod{};
  RGB gauss{};
  const RGB fc = f(centre);
  for (int c = 0; c < 3; ++c)
  {
    kronrod[c] = KronrodWeights[7] * fc[c];
    gauss[c] = GaussWeights[3] * fc[c];
  }
  for (int i = 0; i < 7; ++i)
  {
    const RGB f1 = f(centre - half * KronrodNodes[i]);
    const RGB f2 = f(centre + half * KronrodNodes[i]);
    for (int c = 0; c < 3; ++c)
    {
      kronrod[c] += KronrodWeights[i] * (f1[c] + f2[c]);
      if (i % 2 == 1)
      {
        gauss[c] += GaussWeights[i / 2] * (f1[c] + f2[c]);
      }
    }
  }
  Panel panel{ a, b, depth, {}, {}, 0.0 };
  for (int c = 0; c < 3; ++c)
  {
    panel.Kronrod[c] = kronrod[c] * half;
    panel.Error[c] = std::abs(kronrod[c] - gauss[c]) * std::abs(half);
    panel.Worst = std::max(panel.Worst, panel.Error[c]);
  }
  return panel;
}

bool Converged(const Panel& panel, double relativeTolerance)
{
  for (int c = 0; c < 3; ++c)
  {
    const double e = panel.Error[c];
    if (e > relativeTolerance * std::abs(panel.Kronrod[c]) && e > 1e-300)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
void Integrate(const std::function<RGB(double)>& f,
  double a,
  double b,
  double relativeTolerance,
  Effort& effort,
  RGB& sum,
  RGB& error)
{
  constexpr int PanelEvaluations = 15;
  constexpr int MaximumDepth = 40;
  auto accept = [&](const Panel& panel)
  {
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += panel.Kronrod[c];
      error[c] += panel.Error[c];
    }
  };
  auto worse = [](const Panel& x, const Panel& y) { return x.Worst < y.Worst; };
  // The panels still to refine, worst on top.
  std::vector<Panel> open;
  auto consider = [&](Panel&& panel)
  {
    effort.Evaluations += PanelEvaluations;
    if (Converged(panel, relativeTolerance) || panel.Depth >= MaximumDepth)
    {
      accept(panel);
      return;
    }
    open.push_back(std::move(panel));
    std::push_heap(open.begin(), open.end(), worse);
  };
  consider(EvaluatePanel(f, a, b, 0));
  while (!open.empty() && !effort.Spent())
  {
    std::pop_heap(open.begin(), open.end(), worse);
    const Panel worst = open.back();
    open.pop_back();
    const double centre = 0.5 * (worst.A + worst.B);
    consider(EvaluatePanel(f, worst.A, centre, worst.Depth + 1));
    consider(EvaluatePanel(f, centre, worst.B, worst.Depth + 1));
  }
  // Where the effort ended it: the panels as they are, with their errors.
  for (const Panel& panel : open)
  {
    accept(panel);
  }
}

//------------------------------------------------------------------------------
namespace
{
// A piece of the ray, [First, Second] in the integration variable, with the light's
// transmittance to it (the same all along it).
struct Piece
{
  double First;
  double Second;
  RGB Transmittance;
};

bool Dark(const RGB& transmittance)
{
  return transmittance[0] == 0.0 && transmittance[1] == 0.0 && transmittance[2] == 0.0;
}

// The lit pieces of [u0, u1] (in the integration variable; toT maps it to the ray's t, toU
// back): the transmittance sampled at `samples` points, every change placed by `transition` or
// else bisected to 1e-12 of the interval; the pieces it is zero on left out.
std::vector<Piece> FindLitPieces(const Transmittance& transmittance,
  const Transition& transition,
  const std::function<double(double)>& toT,
  const std::function<double(double)>& toU,
  const Vec& origin,
  const Vec& dir,
  double u0,
  double u1,
  int samples,
  Effort& effort)
{
  std::vector<Piece> lit;
  RGB previous = transmittance(origin + toT(u0) * dir);
  double start = u0;
  double uPrevious = u0;
  auto close = [&](double end)
  {
    if (!Dark(previous))
    {
      lit.push_back({ start, end, previous });
    }
  };
  for (int k = 1; k <= samples; ++k)
  {
    if (effort.CancelRequested())
    {
      return lit; // the ray is discarded: what is lit no longer matters
    }
    const double u = u0 + (u1 - u0) * k / samples;
    const RGB now = transmittance(origin + toT(u) * dir);
    double lo = uPrevious;
    double tChange;
    if (now != previous && transition && transition(origin, dir, toT(lo), toT(u), tChange))
    {
      const double change = std::min(std::max(toU(tChange), lo), u);
      close(change);
      start = change;
      previous = now;
    }
    while (now != previous)
    {
      // The first change in (lo, u] (a sample may step over more than one).
      double hi = u;
      RGB beyond = now;
      for (int iteration = 0; iteration < 60 && hi - lo > 1e-12 * (std::abs(u1 - u0) + 1e-300);
           ++iteration)
      {
        const double mid = 0.5 * (lo + hi);
        const RGB middle = transmittance(origin + toT(mid) * dir);
        if (middle == previous)
        {
          lo = mid;
        }
        else
        {
          hi = mid;
          beyond = middle;
        }
      }
      const double transition = 0.5 * (lo + hi);
      close(transition);
      start = transition;
      previous = beyond;
      lo = hi;
    }
    uPrevious = u;
  }
  close(u1);
  return lit;
}

// The closed forms (A) and (B) of a spot or point light over [ta, tb] (A = 1 / (c2 r^2),
// isotropic, no cone inside the piece); false when the ray runs along the line to the light.
bool PositionalClosedForm(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double ta,
  double tb,
  double tolerance,
  Effort& effort,
  RGB& sum)
{
  const Vec m = origin - model.Light;
  const double b = Dot(m, dir);
  const double h = std::max(std::sqrt(std::max(Dot(m, m) - b * b, 0.0)), 1e-300);
  const Vec toLight = model.Light - origin;
  const double distance = Norm(toLight);
  const double cosGamma = Dot(dir, toLight) / distance;
  const double sinGamma = std::sqrt(std::max(1.0 - cosGamma * cosGamma, 0.0));
  if (!(sinGamma > 1e-9))
  {
    return false;
  }
  const double c2 = model.Attenuation[2];
  const double x0 = ta + b;
  const double x1 = tb + b;
  for (int c = 0; c < 3; ++c)
  {
    const double scale = model.SigmaS[c] * model.Intensity[c] / (4.0 * Pi * c2);
    if (model.SigmaT[c] == 0.0)
    {
      // (A): int dt / r^2 = atan2(h (x1 - x0), h^2 + x0 x1) / h.
      sum[c] += scale * std::atan2(h * (x1 - x0), h * h + x0 * x1) / h;
    }
    else
    {
      // (B): Sun et al. 2005.
      const double T = model.SigmaT[c] * distance;
      const double a1 = T * sinGamma;
      auto v = [&](double t)
      { return Pi / 4.0 + 0.5 * std::atan((model.SigmaT[c] * t - T * cosGamma) / a1); };
      const double a0 =
        model.SigmaT[c] * std::exp(-T * cosGamma) / (2.0 * Pi * a1) * (4.0 * Pi * scale);
      sum[c] += a0 * (SunF(a1, v(tb), tolerance, effort) - SunF(a1, v(ta), tolerance, effort));
    }
  }
  return true;
}

// A directional light's exact integral over [ta, tb] (beyond its plane): theta is constant and
// r(t) + t = r(ta) + ta + (1 + k)(t - ta) with k = dir . axis, so
// int exp(-sigma_t (r + t)) dt = exp(-sigma_t (r(ta) + ta)) (1 - exp(-kappa L)) / kappa,
// kappa = sigma_t (1 + k), L = tb - ta (L itself when kappa = 0: looking into the light).
void DirectionalClosedForm(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double ta,
  double tb,
  RGB& sum)
{
  const double k = Dot(dir, model.Axis);
  const double ra = std::max(Dot(origin + ta * dir - model.Light, model.Axis), 0.0);
  const double phase = model.PhaseValue(-k);
  const double length = tb - ta;
  for (int c = 0; c < 3; ++c)
  {
    const double kappa = model.SigmaT[c] * (1.0 + k);
    const double integral = kappa > 0.0 ? -std::expm1(-kappa * length) / kappa : length;
    sum[c] += model.SigmaS[c] * model.Intensity[c] * phase *
              std::exp(-model.SigmaT[c] * (ra + ta)) * integral;
  }
}
}

//------------------------------------------------------------------------------
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
  const Transition& transition)
{
  // Integration variable: the equiangular angle about the light when A falls off, else t. A
  // ray through the light (h tiny) with a finite A there goes in t: the angle would put the
  // whole integrand within h of its ends.
  const Vec m = origin - model.Light;
  const double b = model.Directional() ? 0.0 : Dot(m, dir);
  const double h = std::max(std::sqrt(std::max(Dot(m, m) - b * b, 0.0)), 1e-300);
  const double extent = std::max({ std::abs(t0 + b), std::abs(t1 + b), h });
  const bool angle = model.Equiangular() && !(model.Attenuation[0] > 0.0 && h < 1e-6 * extent);
  const std::function<double(double)> toU = [&](double t)
  { return angle ? std::atan2(t + b, h) : t; };
  const std::function<double(double)> toT = [&](double u)
  { return angle ? h * std::tan(u) - b : u; };

  std::vector<Piece> lit = FindLitPieces(
    transmittance, transition, toT, toU, origin, dir, toU(t0), toU(t1), samples, effort);
  if (model.Field || model.Extinction)
  {
    // Split where the density (or the volume's extinction) stops being one cubic along the ray
    // (its sample planes).
    std::vector<Piece> split;
    for (const Piece& piece : lit)
    {
      std::vector<double> breaks;
      for (const auto* field : { model.Field.get(), model.Extinction.get() })
      {
        if (field)
        {
          field->Breakpoints(
            origin.data(), dir.data(), toT(piece.First), toT(piece.Second), breaks);
        }
      }
      std::sort(breaks.begin(), breaks.end());
      double start = piece.First;
      for (double t : breaks)
      {
        const double u = std::min(std::max(toU(t), start), piece.Second);
        split.push_back({ start, u, piece.Transmittance });
        start = u;
      }
      split.push_back({ start, piece.Second, piece.Transmittance });
    }
    lit.swap(split);
  }
  if (!angle && !model.Directional())
  {
    // In t, split at the point closest to the light (the phase function's and A's peak).
    const double closest = -b;
    for (size_t k = 0; k < lit.size(); ++k)
    {
      if (lit[k].First < closest && closest < lit[k].Second)
      {
        lit.insert(lit.begin() + k + 1, { closest, lit[k].Second, lit[k].Transmittance });
        lit[k].Second = closest;
        ++k;
      }
    }
  }

  RGB sum{};
  RGB error{};
  bool usedClosedForm = false;
  for (const Piece& piece : lit)
  {
    if (effort.Cancelled)
    {
      break; // the ray is discarded
    }
    // Each piece's integral, times the light's transmittance to it.
    RGB pieceSum{};
    RGB pieceError{};
    const double ta = toT(piece.First);
    const double tb = toT(piece.Second);
    if (closedForms && model.Directional())
    {
      DirectionalClosedForm(model, origin, dir, ta, tb, pieceSum);
      usedClosedForm = true;
    }
    else if (closedForms &&
             PositionalClosedForm(model, origin, dir, ta, tb, tolerance, effort, pieceSum))
    {
      usedClosedForm = true;
    }
    else
    {
      Integrate(
        [&](double u)
        {
          RGB value = model.Integrand(origin, dir, toT(u));
          if (angle)
          {
            const double jacobian = h / (std::cos(u) * std::cos(u));
            for (double& channel : value)
            {
              channel *= jacobian;
            }
          }
          return value;
        },
        piece.First,
        piece.Second,
        tolerance,
        effort,
        pieceSum,
        pieceError);
    }
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += piece.Transmittance[c] * pieceSum[c];
      error[c] += piece.Transmittance[c] * pieceError[c];
    }
  }
  Result result;
  result.Radiance = sum;
  result.Error = error;
  result.ClosedForm = usedClosedForm;
  return result;
}
}
