#include "vtkLightShaftReferenceIntegrator.h"

#include "vtkLight.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftNoise.h"
#include "vtkLightShaftReferenceInput.h"

#include <algorithm>
#include <limits>
#include <utility>

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

// Bilinear lookup as GL does it (texel centres at (i + 0.5) / size), clamped or repeated.
double Lookup(const std::vector<float>& texels,
  int width,
  int height,
  int components,
  int component,
  double u,
  double v,
  bool repeat)
{
  double x = u * width - 0.5;
  double y = v * height - 0.5;
  if (!repeat)
  {
    x = std::min(std::max(x, 0.0), width - 1.0);
    y = std::min(std::max(y, 0.0), height - 1.0);
  }
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const double ax = x - fx;
  const double ay = y - fy;
  auto texel = [&](long i, long j)
  {
    if (repeat)
    {
      i = ((i % width) + width) % width;
      j = ((j % height) + height) % height;
    }
    else
    {
      i = std::min(std::max(i, 0L), static_cast<long>(width) - 1);
      j = std::min(std::max(j, 0L), static_cast<long>(height) - 1);
    }
    return static_cast<double>(
      texels[(static_cast<size_t>(j) * width + i) * components + component]);
  };
  const long i0 = static_cast<long>(fx);
  const long j0 = static_cast<long>(fy);
  return (1.0 - ay) * ((1.0 - ax) * texel(i0, j0) + ax * texel(i0 + 1, j0)) +
         ay * ((1.0 - ax) * texel(i0, j0 + 1) + ax * texel(i0 + 1, j0 + 1));
}

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

Vec ToVec(const glm::dvec3& v)
{
  return { v.x, v.y, v.z };
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
double Model::Distance(const Vec& x) const
{
  return this->Directional() ? Dot(x - this->Light, this->Axis) : Norm(x - this->Light);
}

double Model::NoiseLayers(double u, double v) const
{
  const double s1 = this->NoiseScale;
  const double s2 = 1.37 * this->NoiseScale;
  const double n1 = Lookup(this->Noise,
    this->NoiseWidth,
    this->NoiseHeight,
    1,
    0,
    u * s1 + this->NoiseShift[0],
    v * s1 + this->NoiseShift[1],
    true);
  const double n2 = Lookup(this->Noise,
    this->NoiseWidth,
    this->NoiseHeight,
    1,
    0,
    u * s2 + this->NoiseShift[2],
    v * s2 + this->NoiseShift[3],
    true);
  return n1 * n2;
}

RGB Model::Modulation(const Vec& x, bool withNoise) const
{
  RGB out{ 1.0, 1.0, 1.0 };
  if (this->Cookie.empty() && (this->Noise.empty() || !withNoise))
  {
    return out;
  }
  const Vec d = x - this->Light;
  if (this->Kind == vtkLightShaftModel::LightKind::Point)
  {
    // No cookie; the noise on the three planes across the unit sphere of directions.
    const double r = Norm(d);
    if (this->Noise.empty() || !withNoise || r <= 0.0)
    {
      return out;
    }
    const Vec n = (1.0 / r) * d;
    const glm::dvec3 w = vtkLightShaftModel::TriplanarWeights(glm::dvec3(n[0], n[1], n[2]));
    const double layers = w.x * this->NoiseLayers(0.5 * n[1] + 0.5, 0.5 * n[2] + 0.5) +
                          w.y * this->NoiseLayers(0.5 * n[2] + 0.5, 0.5 * n[0] + 0.5) +
                          w.z * this->NoiseLayers(0.5 * n[0] + 0.5, 0.5 * n[1] + 0.5);
    const double density = 1.0 + this->NoiseAmplitude * (layers - 1.0);
    return { density, density, density };
  }
  // The light's square: in perspective from a spot, tiling a directional light's plane.
  double u;
  double v;
  if (this->Directional())
  {
    u = Dot(d, this->Right) / this->SquareSide + 0.5;
    v = Dot(d, this->Up) / this->SquareSide + 0.5;
  }
  else
  {
    const double depth = Dot(d, this->Axis);
    if (depth <= 0.0)
    {
      return out;
    }
    u = 0.5 * Dot(d, this->Right) / (depth * this->SquareTangent) + 0.5;
    v = 0.5 * Dot(d, this->Up) / (depth * this->SquareTangent) + 0.5;
  }
  if (!this->Cookie.empty())
  {
    const bool repeat = this->Directional();
    const double cu = repeat ? u - std::floor(u) : u;
    const double cv = repeat ? v - std::floor(v) : v;
    for (int c = 0; c < 3; ++c)
    {
      out[c] = Lookup(this->Cookie, this->CookieWidth, this->CookieHeight, 3, c, cu, cv, repeat);
    }
  }
  if (!this->Noise.empty() && withNoise)
  {
    const double density = 1.0 + this->NoiseAmplitude * (this->NoiseLayers(u, v) - 1.0);
    for (double& channel : out)
    {
      channel *= density;
    }
  }
  return out;
}

bool Model::Scatters() const
{
  for (int c = 0; c < 3; ++c)
  {
    if (this->SigmaS[c] > 0.0 && this->Intensity[c] > 0.0)
    {
      return true;
    }
  }
  return false;
}

RGB Model::SurfaceLight(const Vec& x) const
{
  RGB out = this->Modulation(x, false);
  const double r = std::max(this->Distance(x), 0.0);
  const Vec source = this->Directional() ? x - r * this->Axis : this->Light;
  const double volume =
    this->Extinction ? this->Extinction->Integral(x.data(), source.data()) : 0.0;
  const double depth = this->OpticalDepth(x, source);
  for (int c = 0; c < 3; ++c)
  {
    out[c] *= std::exp(-(this->SigmaT[c] * depth + volume));
  }
  return out;
}

double Model::PhaseValue(double cosTheta) const
{
  switch (this->Phase)
  {
    case vtkLightShaftMedium::HENYEY_GREENSTEIN:
    {
      const double g = this->Anisotropy;
      const double denominator = 1.0 + g * g - 2.0 * g * cosTheta;
      return (1.0 - g * g) / (4.0 * Pi * denominator * std::sqrt(denominator));
    }
    case vtkLightShaftMedium::RAYLEIGH:
      return 3.0 / (16.0 * Pi) * (1.0 + cosTheta * cosTheta);
    default:
      return 1.0 / (4.0 * Pi);
  }
}

bool Model::FallingAttenuation() const
{
  return this->Attenuation[1] != 0.0 || this->Attenuation[2] != 0.0;
}

bool Model::Equiangular() const
{
  return !this->Directional() && this->FallingAttenuation();
}

double Model::Density(const Vec& x) const
{
  return this->Field ? this->BackgroundDensity + this->DensityScale * this->Field->Density(x.data())
                     : 1.0;
}

double Model::OpticalDepth(const Vec& a, const Vec& b) const
{
  const double length = Norm(b - a);
  return this->Field ? this->BackgroundDensity * length +
                         this->DensityScale * this->Field->Integral(a.data(), b.data())
                     : length;
}

bool Model::ClosedFormsHold() const
{
  if (!this->Cookie.empty() || !this->Noise.empty() || this->Field || this->Extinction)
  {
    return false;
  }
  if (this->Directional())
  {
    return true;
  }
  return this->Attenuation[0] == 0.0 && this->Attenuation[1] == 0.0 && this->Attenuation[2] > 0.0 &&
         this->Exponent == 0.0 && this->Phase == vtkLightShaftMedium::ISOTROPIC;
}

RGB Model::Integrand(const Vec& origin, const Vec& dir, double t) const
{
  const Vec x = origin + t * dir;
  RGB out{};
  double r;
  Vec lightDir;
  double factor = 1.0; // S(x) A(r)
  if (this->Directional())
  {
    r = Dot(x - this->Light, this->Axis);
    if (r < 0.0)
    {
      return out;
    }
    lightDir = this->Axis;
  }
  else
  {
    const Vec toPoint = x - this->Light;
    r = Norm(toPoint);
    if (r <= 0.0)
    {
      return out;
    }
    lightDir = (1.0 / r) * toPoint;
    if (this->Kind == vtkLightShaftModel::LightKind::Spot)
    {
      const double cosAxis = Dot(lightDir, this->Axis);
      if (cosAxis < this->CosCone)
      {
        return out;
      }
      factor = this->Exponent == 0.0 ? 1.0 : std::pow(cosAxis, this->Exponent);
    }
    factor /= this->Attenuation[0] + r * (this->Attenuation[1] + this->Attenuation[2] * r);
  }
  double scalar = this->PhaseValue(-Dot(dir, lightDir)) * factor;
  // The optical depth of both legs in units of sigma_t: the eye (origin) to x, and x to the
  // light (a directional light: back along its direction to its plane).
  double depth = r + t;
  if (this->Field)
  {
    scalar *= this->Density(x);
    if (scalar == 0.0)
    {
      return out;
    }
    const Vec source = this->Directional() ? x - r * this->Axis : this->Light;
    depth = this->OpticalDepth(origin, x) + this->OpticalDepth(x, source);
  }
  if (this->Extinction)
  {
    // Both legs through the volume: the eye to x, x to the light (or its plane).
    const Vec source = this->Directional() ? x - r * this->Axis : this->Light;
    scalar *= std::exp(-(this->Extinction->Integral(origin.data(), x.data()) +
                         this->Extinction->Integral(x.data(), source.data())));
  }
  const RGB modulation = this->Modulation(x);
  for (int c = 0; c < 3; ++c)
  {
    out[c] = this->SigmaS[c] * this->Intensity[c] * scalar * modulation[c] *
             std::exp(-this->SigmaT[c] * depth);
  }
  return out;
}

//------------------------------------------------------------------------------
Model MakeModel(vtkLight* light,
  const vtkLightShaftReferenceInput& input,
  std::shared_ptr<const vtkLightShaftDensityField> field)
{
  const vtkLightShaftModel::Light described = vtkLightShaftModel::DescribeLight(light);
  vtkLightShaftMedium* given = input.Medium;
  const vtkLightShaftModel::Medium medium =
    vtkLightShaftModel::DescribeMedium(given->GetScatteringCoefficient(),
      given->GetAbsorptionCoefficient(),
      given->GetPhaseFunction(),
      given->GetAnisotropy());
  Model model;
  model.Kind = described.Kind;
  model.Light = ToVec(described.Position);
  model.Axis = ToVec(described.Axis);
  model.CosCone = std::cos(described.ConeHalfAngle);
  model.Exponent = described.Exponent;
  std::copy(described.Attenuation, described.Attenuation + 3, model.Attenuation);
  for (int c = 0; c < 3; ++c)
  {
    model.Intensity[c] = described.RadiantIntensity[c];
    model.SigmaS[c] = medium.SigmaS[c];
    model.SigmaT[c] = medium.SigmaT[c];
  }
  model.Phase = medium.Phase;
  model.Anisotropy = medium.Anisotropy;
  if (field && !field->Empty())
  {
    model.Field = std::move(field);
    model.DensityScale = given->GetDensityScale();
    model.BackgroundDensity = given->GetBackgroundDensity();
  }
  model.Right = ToVec(described.Right);
  model.Up = ToVec(described.Up);
  model.SquareTangent = described.SquareTangent;
  model.SquareSide = described.SquareSide;

  // A point light ignores the cookie (the pass says so once).
  if (model.Kind != vtkLightShaftModel::LightKind::Point && input.Cookie &&
      !vtkLightShaftImageToRGB(input.Cookie, model.Cookie, model.CookieWidth, model.CookieHeight))
  {
    model.Cookie.clear(); // the pass ignores a cookie without an image too
  }
  if (given->GetNoiseAmplitude() > 0.0)
  {
    std::vector<float> rgb;
    if (given->GetNoiseTexture() &&
        vtkLightShaftImageToRGB(given->GetNoiseTexture(), rgb, model.NoiseWidth, model.NoiseHeight))
    {
      model.Noise.resize(static_cast<size_t>(model.NoiseWidth) * model.NoiseHeight);
      for (size_t i = 0; i < model.Noise.size(); ++i)
      {
        model.Noise[i] = rgb[3 * i];
      }
      vtkLightShaftNormalizeNoise(model.Noise);
    }
    else
    {
      model.NoiseWidth = model.NoiseHeight = 256; // the pass's generated noise
      model.Noise = vtkLightShaftTileableNoise(256, 5, 2004u);
    }
    model.NoiseAmplitude = given->GetNoiseAmplitude();
    model.NoiseScale = given->GetNoiseScale();
    vtkLightShaftModel::NoiseShifts(
      given->GetNoiseVelocity1(), given->GetNoiseVelocity2(), given->GetTime(), model.NoiseShift);
  }
  return model;
}

//------------------------------------------------------------------------------
namespace
{
// The spot cone's forward nappe.
void ConeInterval(const Model& model, const Vec& origin, const Vec& dir, double& t0, double& t1)
{
  const Vec m = origin - model.Light;
  const double b = Dot(m, dir);
  const Vec foot = m - b * dir; // work from the foot of the perpendicular: x = t + b
  const double c2 = model.CosCone * model.CosCone;
  const double da = Dot(dir, model.Axis);
  const double ma = Dot(foot, model.Axis);
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  if (da > 0.0)
  {
    lo = -ma / da;
  }
  else if (da < 0.0)
  {
    hi = -ma / da;
  }
  else if (ma < 0.0)
  {
    t0 = 1.0;
    t1 = 0.0;
    return;
  }
  const double qa = da * da - c2;
  const double qb = 2.0 * (da * ma - c2 * Dot(dir, foot));
  const double qc = ma * ma - c2 * Dot(foot, foot);
  bool empty = false;
  if (qa == 0.0)
  {
    if (qb > 0.0)
    {
      lo = std::max(lo, -qc / qb);
    }
    else if (qb < 0.0)
    {
      hi = std::min(hi, -qc / qb);
    }
    else if (qc < 0.0)
    {
      empty = true;
    }
  }
  else
  {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0)
    {
      empty = qa < 0.0;
    }
    else
    {
      const double q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * std::sqrt(disc));
      const double r1 = q / qa;
      const double r2 = q != 0.0 ? qc / q : r1;
      const double tin = std::min(r1, r2);
      const double tout = std::max(r1, r2);
      if (qa < 0.0)
      {
        lo = std::max(lo, tin);
        hi = std::min(hi, tout);
      }
      else
      {
        const bool before = lo <= tin;
        const bool after = hi >= tout;
        if (before && !after)
        {
          hi = std::min(hi, tin);
        }
        else if (after && !before)
        {
          lo = std::max(lo, tout);
        }
        else if (!before && !after)
        {
          empty = true;
        }
      }
    }
  }
  if (empty)
  {
    t0 = 1.0;
    t1 = 0.0;
    return;
  }
  t0 = lo - b;
  t1 = hi - b;
}
}

void LitInterval(const Model& model, const Vec& origin, const Vec& dir, double& t0, double& t1)
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  switch (model.Kind)
  {
    case vtkLightShaftModel::LightKind::Spot:
      ConeInterval(model, origin, dir, t0, t1);
      return;
    case vtkLightShaftModel::LightKind::Point:
      t0 = -infinity;
      t1 = infinity;
      return;
    default:
      break;
  }
  // Directional: r(t) = r0 + t k >= 0 (a ray parallel to the plane: all or nothing).
  const double k = Dot(dir, model.Axis);
  const double r0 = Dot(origin - model.Light, model.Axis);
  t0 = -infinity;
  t1 = infinity;
  if (k > 0.0)
  {
    t0 = -r0 / k;
  }
  else if (k < 0.0)
  {
    t1 = -r0 / k;
  }
  else if (r0 < 0.0)
  {
    t0 = 1.0;
    t1 = 0.0;
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
