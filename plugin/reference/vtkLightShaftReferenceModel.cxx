#include "vtkLightShaftReferenceModel.h"

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

Vec ToVec(const glm::dvec3& v)
{
  return { v.x, v.y, v.z };
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
}
