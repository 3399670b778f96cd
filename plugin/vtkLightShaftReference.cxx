#include "vtkLightShaftReference.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightShaftNoise.h"
#include "vtkLightShaftPass.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkModifiedBSPTree.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkLightShaftReference);

namespace
{
using Vec = std::array<double, 3>;
using RGB = std::array<double, 3>;

Vec operator+(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
Vec operator-(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec operator*(double s, const Vec& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
Vec Normalized(const Vec& a)
{
  const double n = Norm(a);
  return n > 0.0 ? (1.0 / n) * a : a;
}

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
 * Adaptive Gauss-Kronrod (7/15) of a vector-valued f over [a, b]; adds the integral to `sum`
 * and the estimated absolute error to `error`.
 */
void Integrate(const std::function<RGB(double)>& f,
  double a,
  double b,
  double relativeTolerance,
  int depth,
  RGB& sum,
  RGB& error)
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
  bool converged = true;
  for (int c = 0; c < 3; ++c)
  {
    kronrod[c] *= half;
    gauss[c] *= half;
    const double e = std::abs(kronrod[c] - gauss[c]);
    if (e > relativeTolerance * std::abs(kronrod[c]) && e > 1e-300)
    {
      converged = false;
    }
  }
  if (converged || depth >= 40)
  {
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += kronrod[c];
      error[c] += std::abs(kronrod[c] - gauss[c]);
    }
    return;
  }
  Integrate(f, a, centre, relativeTolerance, depth + 1, sum, error);
  Integrate(f, centre, b, relativeTolerance, depth + 1, sum, error);
}

/// Everything one ray's integral needs, in world coordinates, double precision.
struct Model
{
  Vec Light;
  Vec Axis;
  double CosCone = 1.0;
  double Exponent = 1.0;
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  RGB Intensity{};
  RGB SigmaS{};
  RGB SigmaT{};
  int Phase = vtkLightShaftPass::ISOTROPIC;
  double Anisotropy = 0.0;

  // The light camera as vtkLightShaftPass builds it, for cookie and noise coordinates.
  Vec Right{ 1.0, 0.0, 0.0 };
  Vec Up{ 0.0, 1.0, 0.0 };
  double SquareTangent = 1.0; // tan of the (clamped) cone half-angle
  std::vector<float> Cookie;  // RGB, row 0 at the bottom; empty: no cookie
  int CookieWidth = 0;
  int CookieHeight = 0;
  std::vector<float> Noise; // mean 1, tiled; empty: homogeneous
  int NoiseWidth = 0;
  int NoiseHeight = 0;
  double NoiseAmplitude = 0.0;
  double NoiseScale = 1.0;
  double NoiseShift[4] = { 0.0, 0.0, 0.0, 0.0 };

  // Bilinear lookup as GL does it (texel centres at (i + 0.5) / size), clamped or repeated.
  static double Lookup(const std::vector<float>& texels,
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

  // Cookie colour times noise density at x (1 when neither is in use).
  RGB Modulation(const Vec& x) const
  {
    RGB out{ 1.0, 1.0, 1.0 };
    if (this->Cookie.empty() && this->Noise.empty())
    {
      return out;
    }
    const Vec d = x - this->Light;
    const double depth = Dot(d, this->Axis);
    if (depth <= 0.0)
    {
      return out;
    }
    const double u = 0.5 * Dot(d, this->Right) / (depth * this->SquareTangent) + 0.5;
    const double v = 0.5 * Dot(d, this->Up) / (depth * this->SquareTangent) + 0.5;
    if (!this->Cookie.empty())
    {
      for (int c = 0; c < 3; ++c)
      {
        out[c] = Lookup(this->Cookie, this->CookieWidth, this->CookieHeight, 3, c, u, v, false);
      }
    }
    if (!this->Noise.empty())
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
      const double density = 1.0 + this->NoiseAmplitude * (n1 * n2 - 1.0);
      for (double& channel : out)
      {
        channel *= density;
      }
    }
    return out;
  }

  double PhaseValue(double cosTheta) const
  {
    switch (this->Phase)
    {
      case vtkLightShaftPass::HENYEY_GREENSTEIN:
      {
        const double g = this->Anisotropy;
        const double denominator = 1.0 + g * g - 2.0 * g * cosTheta;
        return (1.0 - g * g) / (4.0 * Pi * denominator * std::sqrt(denominator));
      }
      case vtkLightShaftPass::RAYLEIGH:
        return 3.0 / (16.0 * Pi) * (1.0 + cosTheta * cosTheta);
      default:
        return 1.0 / (4.0 * Pi);
    }
  }

  bool FallingAttenuation() const
  {
    return this->Attenuation[1] != 0.0 || this->Attenuation[2] != 0.0;
  }

  // The integrand at parameter t of the ray origin + t dir (visibility excluded).
  RGB Integrand(const Vec& origin, const Vec& dir, double t) const
  {
    const Vec x = origin + t * dir;
    const Vec toPoint = x - this->Light;
    const double r = Norm(toPoint);
    RGB out{};
    if (r <= 0.0)
    {
      return out;
    }
    const Vec lightDir = (1.0 / r) * toPoint;
    const double cosAxis = Dot(lightDir, this->Axis);
    if (cosAxis < this->CosCone)
    {
      return out;
    }
    const double spot = this->Exponent == 0.0 ? 1.0 : std::pow(cosAxis, this->Exponent);
    const double a =
      1.0 / (this->Attenuation[0] + r * (this->Attenuation[1] + this->Attenuation[2] * r));
    const double scalar = this->PhaseValue(-Dot(dir, lightDir)) * spot * a;
    const RGB modulation = this->Modulation(x);
    for (int c = 0; c < 3; ++c)
    {
      out[c] = this->SigmaS[c] * this->Intensity[c] * scalar * modulation[c] *
               std::exp(-this->SigmaT[c] * (r + t));
    }
    return out;
  }
};

/// The parameter interval of origin + t dir inside the cone's forward nappe (t0 > t1: none).
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

/**
 * F(u, v) = int_0^v exp(-u tan xi) d xi (Sun et al. 2005), by adaptive quadrature.
 */
double SunF(double u, double v, double tolerance)
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
    0,
    sum,
    error);
  return sum[0];
}
} // namespace

//------------------------------------------------------------------------------
vtkLightShaftReference::vtkLightShaftReference()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkLightShaftReference::~vtkLightShaftReference() = default;

void vtkLightShaftReference::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkLightShaftReference::GetRenderer()
{
  return this->Renderer;
}

void vtkLightShaftReference::SetLightShaftPass(vtkLightShaftPass* pass)
{
  if (this->Pass != pass)
  {
    this->Pass = pass;
    this->Modified();
  }
}

vtkLightShaftPass* vtkLightShaftReference::GetLightShaftPass()
{
  return this->Pass;
}

void vtkLightShaftReference::SetRelativeTolerance(double tolerance)
{
  if (!std::isfinite(tolerance))
  {
    vtkErrorMacro("RelativeTolerance: non-finite value refused; the previous value is kept.");
    return;
  }
  tolerance = std::min(std::max(tolerance, 1e-14), 1e-2);
  if (tolerance != this->RelativeTolerance)
  {
    this->RelativeTolerance = tolerance;
    this->Modified();
  }
}

vtkMTimeType vtkLightShaftReference::GetMTime()
{
  // The scene changes without telling us: any change of the renderer, its camera, lights or
  // props, or of the pass, makes the next Update() recompute.
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Pass)
  {
    time = std::max(time, this->Pass->GetMTime());
  }
  if (vtkRenderer* ren = this->Renderer)
  {
    time = std::max({ time,
      ren->GetMTime(),
      ren->GetActiveCamera()->GetMTime(),
      ren->GetLights()->GetMTime(),
      ren->GetViewProps()->GetMTime() });
    vtkCollectionSimpleIterator it;
    ren->GetLights()->InitTraversal(it);
    while (vtkLight* light = ren->GetLights()->GetNextLight(it))
    {
      time = std::max(time, light->GetMTime());
    }
    ren->GetViewProps()->InitTraversal(it);
    while (vtkProp* prop = ren->GetViewProps()->GetNextProp(it))
    {
      time = std::max(time, prop->GetMTime());
    }
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkLightShaftReference::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  int size[2] = { 0, 0 };
  if (this->Renderer)
  {
    const int* rendererSize = this->Renderer->GetSize();
    size[0] = rendererSize[0];
    size[1] = rendererSize[1];
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, std::max(size[0], 1) - 1, 0, std::max(size[1], 1) - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_DOUBLE, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightShaftReference::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  vtkRenderer* ren = this->Renderer;
  vtkLightShaftPass* pass = this->Pass;
  this->LastClosedFormPixels = 0;
  if (!ren || !pass)
  {
    vtkErrorMacro("SetRenderer and SetLightShaftPass are required.");
    return 0;
  }
  const int width = std::max(ren->GetSize()[0], 1);
  const int height = std::max(ren->GetSize()[1], 1);
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName("InScatteredRadiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(vtkIdType(width) * height);
  radiance->Fill(0.0);
  vtkNew<vtkDoubleArray> errors;
  errors->SetName("ErrorEstimate");
  errors->SetNumberOfComponents(3);
  errors->SetNumberOfTuples(vtkIdType(width) * height);
  errors->Fill(0.0);
  output->GetPointData()->SetScalars(radiance);
  output->GetPointData()->AddArray(errors);

  // The light, chosen as the pass chooses it.
  vtkLight* light = pass->GetLight();
  if (!light)
  {
    vtkCollectionSimpleIterator it;
    ren->GetLights()->InitTraversal(it);
    while (vtkLight* candidate = ren->GetLights()->GetNextLight(it))
    {
      if (candidate->GetSwitch() && candidate->GetPositional() && candidate->GetConeAngle() < 90.0)
      {
        light = candidate;
        break;
      }
    }
  }
  if (!light || !light->GetPositional() || light->GetConeAngle() >= 90.0 || !light->GetSwitch())
  {
    return 1; // no usable light: no in-scatter
  }
  Model model;
  const double* position = light->GetTransformedPosition();
  const double* focal = light->GetTransformedFocalPoint();
  model.Light = { position[0], position[1], position[2] };
  model.Axis = Normalized(Vec{ focal[0], focal[1], focal[2] } - model.Light);
  model.CosCone = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
  model.Exponent = light->GetExponent();
  light->GetAttenuationValues(model.Attenuation);
  if (model.Attenuation[0] <= 0.0 && model.Attenuation[1] <= 0.0 && model.Attenuation[2] <= 0.0)
  {
    model.Attenuation[0] = 1.0; // as the pass does
  }
  const double* colour = light->GetDiffuseColor();
  const double* sigmaS = pass->GetScatteringCoefficient();
  const double* sigmaA = pass->GetAbsorptionCoefficient();
  for (int c = 0; c < 3; ++c)
  {
    model.Intensity[c] = light->GetIntensity() * colour[c];
    model.SigmaS[c] = sigmaS[c];
    model.SigmaT[c] = sigmaS[c] + sigmaA[c];
  }
  model.Phase = pass->GetPhaseFunction();
  model.Anisotropy = pass->GetAnisotropy();

  // Cookie and noise, read and laid out as the pass reads and lays them out (level 0 of their
  // textures, bilinear; the pass pre-filters by footprint, which differs only where the texture
  // varies within a pixel's footprint).
  const Vec lightUp = std::abs(model.Axis[1]) < 0.99 ? Vec{ 0.0, 1.0, 0.0 } : Vec{ 1.0, 0.0, 0.0 };
  model.Right = Normalized(Cross(model.Axis, lightUp));
  model.Up = Cross(model.Right, model.Axis);
  model.SquareTangent = std::tan(
    std::min(vtkMath::RadiansFromDegrees(light->GetConeAngle()), vtkMath::Pi() * 89.9 / 180.0));
  if (pass->GetCookie() &&
      !vtkLightShaftImageToRGB(
        pass->GetCookie(), model.Cookie, model.CookieWidth, model.CookieHeight))
  {
    model.Cookie.clear(); // the pass ignores an empty cookie too
  }
  if (pass->GetNoiseAmplitude() > 0.0)
  {
    std::vector<float> rgb;
    if (pass->GetNoiseTexture() &&
        vtkLightShaftImageToRGB(pass->GetNoiseTexture(), rgb, model.NoiseWidth, model.NoiseHeight))
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
    model.NoiseAmplitude = pass->GetNoiseAmplitude();
    model.NoiseScale = pass->GetNoiseScale();
    const double* v1 = pass->GetNoiseVelocity1();
    const double* v2 = pass->GetNoiseVelocity2();
    const double time = pass->GetTime();
    auto wrap = [](double value) { return value - std::floor(value); };
    model.NoiseShift[0] = wrap(v1[0] * time);
    model.NoiseShift[1] = wrap(v1[1] * time);
    model.NoiseShift[2] = wrap(v2[0] * time + 0.37);
    model.NoiseShift[3] = wrap(v2[1] * time + 0.61);
  }

  // The opaque polygonal props, in world coordinates, for surfaces and shadows: one mesh and
  // bounding box per prop (the boxes reject most queries before any tree is searched).
  struct Occluder
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    double Bounds[6];
  };
  std::vector<Occluder> occluders;
  vtkCollectionSimpleIterator pit;
  ren->GetViewProps()->InitTraversal(pit);
  while (vtkProp* prop = ren->GetViewProps()->GetNextProp(pit))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility() || !actor->GetMapper() ||
        actor->GetProperty()->GetOpacity() < 1.0)
    {
      continue;
    }
    actor->GetMapper()->Update();
    auto* polydata = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
    if (!polydata || polydata->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(actor->GetMatrix());
    vtkNew<vtkTransformPolyDataFilter> toWorld;
    toWorld->SetInputData(polydata);
    toWorld->SetTransform(transform);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(toWorld->GetOutputPort());
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    if (triangles->GetOutput()->GetNumberOfCells() == 0)
    {
      continue;
    }
    Occluder occluder;
    occluder.Mesh = vtkSmartPointer<vtkPolyData>::New();
    occluder.Mesh->DeepCopy(triangles->GetOutput());
    occluder.Mesh->BuildCells(); // read-only from the threads afterwards
    occluder.Mesh->GetBounds(occluder.Bounds);
    occluders.push_back(occluder);
  }
  // VTK 9.1's vtkModifiedBSPTree keeps a scratch cell per tree, so each thread gets its own.
  vtkSMPThreadLocal<std::vector<vtkSmartPointer<vtkModifiedBSPTree>>> threadLocators;

  // SHADOW_MAP visibility: the pass's own depth map and light camera.
  vtkNew<vtkImageData> shadowDepths;
  vtkNew<vtkMatrix4x4> worldToLightClip;
  const bool useShadowMap = this->VisibilityMode == SHADOW_MAP;
  int shadowSize = 0;
  const float* shadowTexels = nullptr;
  double lightNear = 0.0;
  double lightFar = 0.0;
  double shadowBias = 0.0;
  if (useShadowMap)
  {
    if (!pass->GetLastShadowMap(shadowDepths, worldToLightClip))
    {
      vtkErrorMacro("SHADOW_MAP visibility: the pass rendered no shadow map in its last frame.");
      return 0;
    }
    shadowSize = shadowDepths->GetDimensions()[0];
    shadowTexels =
      vtkFloatArray::SafeDownCast(shadowDepths->GetPointData()->GetScalars())->GetPointer(0);
    lightNear = pass->GetLastLightDepthRange()[0];
    lightFar = pass->GetLastLightDepthRange()[1];
    shadowBias = pass->GetLastShadowBias();
  }
  auto shadowMapVisible = [&](const Vec& x)
  {
    double clip[4];
    const double point[4] = { x[0], x[1], x[2], 1.0 };
    worldToLightClip->MultiplyPoint(point, clip);
    if (clip[3] <= 0.0)
    {
      return true;
    }
    const double u = clip[0] / clip[3];
    const double v = clip[1] / clip[3];
    if (std::abs(u) > 1.0 || std::abs(v) > 1.0)
    {
      return true;
    }
    const int i = std::min(static_cast<int>((0.5 * u + 0.5) * shadowSize), shadowSize - 1);
    const int j = std::min(static_cast<int>((0.5 * v + 0.5) * shadowSize), shadowSize - 1);
    const double stored = shadowTexels[static_cast<size_t>(j) * shadowSize + i];
    if (stored >= 1.0)
    {
      return true;
    }
    const double caster = 2.0 * lightNear * lightFar /
                          ((lightFar + lightNear) - (2.0 * stored - 1.0) * (lightFar - lightNear));
    return clip[3] <= caster * (1.0 + shadowBias);
  };

  // The camera's pixel-centre rays (independent of VTK's matrices).
  vtkCamera* camera = ren->GetActiveCamera();
  const double* eye = camera->GetPosition();
  const double* cfocal = camera->GetFocalPoint();
  const Vec eyeWC{ eye[0], eye[1], eye[2] };
  const Vec forward = Normalized(Vec{ cfocal[0], cfocal[1], cfocal[2] } - eyeWC);
  const double* viewUp = camera->GetViewUp();
  const Vec right = Normalized(Cross(forward, Vec{ viewUp[0], viewUp[1], viewUp[2] }));
  const Vec up = Cross(right, forward);
  const double farDistance = camera->GetClippingRange()[1];
  const bool parallel = camera->GetParallelProjection() != 0;
  const double halfHeight = parallel
                              ? camera->GetParallelScale()
                              : std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
  const double aspect = static_cast<double>(width) / height;

  const double tolerance = this->RelativeTolerance;
  const int samples = this->VisibilitySamples;
  const bool closedForms = this->UseClosedForms && model.Cookie.empty() && model.Noise.empty() &&
                           model.Attenuation[0] == 0.0 && model.Attenuation[1] == 0.0 &&
                           model.Attenuation[2] > 0.0 && model.Exponent == 0.0 &&
                           model.Phase == vtkLightShaftPass::ISOTROPIC;
  std::atomic<vtkIdType> closedFormPixels(0);
  vtkSMPThreadLocalObject<vtkGenericCell> cells;
  double* radianceOut = radiance->GetPointer(0);
  double* errorOut = errors->GetPointer(0);

  vtkSMPTools::For(0,
    vtkIdType(width) * height,
    [&](vtkIdType first, vtkIdType last)
    {
      vtkGenericCell* cell = cells.Local();
      std::vector<vtkSmartPointer<vtkModifiedBSPTree>>& locators = threadLocators.Local();
      if (locators.size() != occluders.size())
      {
        locators.clear();
        for (const Occluder& occluder : occluders)
        {
          auto locator = vtkSmartPointer<vtkModifiedBSPTree>::New();
          locator->SetDataSet(occluder.Mesh);
          locator->BuildLocator();
          locators.push_back(locator);
        }
      }
      // Whether the segment from -> to meets an axis-aligned box (slab test, slightly padded).
      auto segmentMeetsBox = [](const Vec& from, const Vec& to, const double bounds[6])
      {
        double lo = 0.0;
        double hi = 1.0;
        for (int axis = 0; axis < 3; ++axis)
        {
          const double pad =
            1e-9 * (std::abs(bounds[2 * axis]) + std::abs(bounds[2 * axis + 1]) + 1.0);
          const double d = to[axis] - from[axis];
          const double a = bounds[2 * axis] - pad - from[axis];
          const double b = bounds[2 * axis + 1] + pad - from[axis];
          if (d == 0.0)
          {
            if (a > 0.0 || b < 0.0)
            {
              return false;
            }
            continue;
          }
          double t0 = a / d;
          double t1 = b / d;
          if (t0 > t1)
          {
            std::swap(t0, t1);
          }
          lo = std::max(lo, t0);
          hi = std::min(hi, t1);
          if (lo > hi)
          {
            return false;
          }
        }
        return true;
      };
      // The nearest hit of the segment (as a fraction of it), over all occluders.
      auto firstHit = [&](const Vec& from, const Vec& to, double& nearest)
      {
        bool any = false;
        nearest = 1.0;
        for (size_t k = 0; k < occluders.size(); ++k)
        {
          if (!segmentMeetsBox(from, to, occluders[k].Bounds))
          {
            continue;
          }
          double t;
          double x[3];
          double pcoords[3];
          int subId;
          vtkIdType cellId;
          if (locators[k]->IntersectWithLine(
                from.data(), to.data(), 0.0, t, x, pcoords, subId, cellId, cell) &&
              t < nearest)
          {
            nearest = t;
            any = true;
          }
        }
        return any;
      };
      auto visible = [&](const Vec& x)
      {
        if (useShadowMap)
        {
          return shadowMapVisible(x);
        }
        const Vec toLight = model.Light - x;
        const double distance = Norm(toLight);
        const Vec step = (1e-9 * (distance + 1.0) / std::max(distance, 1e-300)) * toLight;
        double t;
        return !firstHit(x + step, model.Light - step, t);
      };
      vtkIdType closedHere = 0;
      for (vtkIdType pixel = first; pixel < last; ++pixel)
      {
        const int i = static_cast<int>(pixel % width);
        const int j = static_cast<int>(pixel / width);
        const double sx = (2.0 * (i + 0.5) / width - 1.0) * halfHeight * aspect;
        const double sy = (2.0 * (j + 0.5) / height - 1.0) * halfHeight;
        Vec origin = eyeWC;
        Vec dir = forward;
        double tFar = farDistance;
        if (parallel)
        {
          origin = eyeWC + sx * right + sy * up;
        }
        else
        {
          dir = Normalized(forward + sx * right + sy * up);
          tFar = farDistance / Dot(dir, forward);
        }
        // The first surface along the ray, else the far plane.
        double tSurface = tFar;
        double hit;
        if (firstHit(origin, origin + tFar * dir, hit))
        {
          tSurface = hit * tFar;
        }
        double t0;
        double t1;
        ConeInterval(model, origin, dir, t0, t1);
        t0 = std::max(t0, 0.0);
        t1 = std::min(t1, tSurface);
        if (!(t1 > t0))
        {
          continue;
        }
        // Integration variable: the equiangular angle when A falls off, else t.
        const Vec m = origin - model.Light;
        const double b = Dot(m, dir);
        const double h = std::max(std::sqrt(std::max(Dot(m, m) - b * b, 0.0)), 1e-300);
        const bool angle = model.FallingAttenuation();
        auto toU = [&](double t) { return angle ? std::atan2(t + b, h) : t; };
        auto toT = [&](double u) { return angle ? h * std::tan(u) - b : u; };
        const double u0 = toU(t0);
        const double u1 = toU(t1);

        // Lit pieces: visibility sampled, transitions bisected.
        std::vector<std::pair<double, double>> lit;
        bool previous = visible(origin + t0 * dir);
        double start = u0;
        double uPrevious = u0;
        for (int k = 1; k <= samples; ++k)
        {
          const double u = u0 + (u1 - u0) * k / samples;
          const bool now = visible(origin + toT(u) * dir);
          if (now != previous)
          {
            double lo = uPrevious;
            double hi = u;
            for (int iteration = 0;
                 iteration < 60 && hi - lo > 1e-12 * (std::abs(u1 - u0) + 1e-300);
                 ++iteration)
            {
              const double mid = 0.5 * (lo + hi);
              (visible(origin + toT(mid) * dir) == previous ? lo : hi) = mid;
            }
            const double transition = 0.5 * (lo + hi);
            if (previous)
            {
              lit.emplace_back(start, transition);
            }
            start = transition;
            previous = now;
          }
          uPrevious = u;
        }
        if (previous)
        {
          lit.emplace_back(start, u1);
        }

        RGB sum{};
        RGB error{};
        bool usedClosedForm = false;
        for (const auto& piece : lit)
        {
          const double ta = toT(piece.first);
          const double tb = toT(piece.second);
          if (closedForms)
          {
            const Vec s = model.Light;
            const Vec toLight = s - origin;
            const double distance = Norm(toLight);
            const double cosGamma = Dot(dir, toLight) / distance;
            const double sinGamma = std::sqrt(std::max(1.0 - cosGamma * cosGamma, 0.0));
            if (sinGamma > 1e-9)
            {
              usedClosedForm = true;
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
                  const double a0 = model.SigmaT[c] * std::exp(-T * cosGamma) / (2.0 * Pi * a1) *
                                    (4.0 * Pi * scale);
                  sum[c] += a0 * (SunF(a1, v(tb), tolerance) - SunF(a1, v(ta), tolerance));
                }
              }
              continue;
            }
          }
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
            piece.first,
            piece.second,
            tolerance,
            0,
            sum,
            error);
        }
        closedHere += usedClosedForm ? 1 : 0;
        for (int c = 0; c < 3; ++c)
        {
          radianceOut[3 * pixel + c] = sum[c];
          errorOut[3 * pixel + c] = error[c];
        }
      }
      closedFormPixels += closedHere;
    });
  this->LastClosedFormPixels = closedFormPixels;
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightShaftReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer.Get() << "\n";
  os << indent << "LightShaftPass: " << this->Pass.Get() << "\n";
  os << indent << "VisibilityMode: " << this->VisibilityMode << "\n";
  os << indent << "RelativeTolerance: " << this->RelativeTolerance << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "UseClosedForms: " << this->UseClosedForms << "\n";
}
