#include "vtkLightShaftErrorModel.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftErrorModelTable.h"
#include "vtkLightShaftGeometryClipping.h"
#include "vtkLightShaftGeometryLitVolume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

namespace vtkLightShaftErrorModel
{
namespace
{
constexpr double ReferenceMapSize = 1024.0; // the map ShadowTexelInPixels is measured for
constexpr int NumberOfSettings = static_cast<int>(std::size(vtkLightShaftErrorModelTable::Rows));

glm::dvec3 Centroid(const vtkLightShaftGeometry::ConvexPolytope& polytope)
{
  glm::dvec3 sum(0.0);
  double count = 0.0;
  for (const auto& face : polytope.Faces)
  {
    for (const glm::dvec3& vertex : face)
    {
      sum += vertex;
      count += 1.0;
    }
  }
  return count > 0.0 ? sum / count : sum;
}

// The angle at which a spot's light falls to half: the cone, or the exponent's half-intensity
// angle when that is narrower.
double BeamHalfAngle(const vtkLightShaftModel::Light& light)
{
  double angle = light.ConeHalfAngle;
  if (light.Exponent > 0.0)
  {
    angle = std::min(angle, std::acos(std::pow(0.5, 1.0 / light.Exponent)));
  }
  return angle;
}

bool InView(const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera)
{
  glm::dvec4 point(light.PositionVC, 1.0);
  if (light.Model.Kind == vtkLightShaftModel::LightKind::Directional)
  {
    point = glm::dvec4(-light.AxisVC, 0.0); // the sun: where its light comes from
  }
  const glm::dvec4 clip = camera.ViewToClip * point;
  const bool ahead = point.z < 0.0; // in front of the camera (view direction -z)
  return ahead && clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
}

// The features as the fit's variables (fit_error_model.variables computes the same): log-scaled,
// clamped so that degenerate geometry (a zero width, an unbounded range) stays finite.
std::array<double, vtkLightShaftErrorModelTable::NumberOfVariables> Variables(const Features& f)
{
  auto logClamped = [](double x) { return std::log(std::clamp(x, 1e-3, 1e6)); };
  const bool point = f.Kind == vtkLightShaftModel::LightKind::Point;
  const bool directional = f.Kind == vtkLightShaftModel::LightKind::Directional;
  const double inView = f.LightInView ? 1.0 : 0.0;
  const double depthRange = logClamped(f.DepthRangeInBeamWidths);
  const double beamPixels = logClamped(f.BeamWidthInPixels);
  // The light in the picture changes how the error scales (rays pass near the light, where
  // the beam is narrowest and brightest): its own intercept and slopes.
  return { 1.0,
    depthRange,
    beamPixels,
    std::log1p(std::clamp(f.OpticalDepth, 0.0, 1e3)),
    f.LightInView && f.FallingAttenuation ? 1.0 : 0.0,
    inView,
    point ? 1.0 : 0.0,
    directional ? 1.0 : 0.0,
    inView * depthRange,
    inView * beamPixels,
    f.ShadowTexelInPixels > 0.0 ? logClamped(f.ShadowTexelInPixels) : 0.0 };
}
}

//------------------------------------------------------------------------------
Features Describe(const vtkLightShaftGeometry::LightFrame& light,
  const vtkLightShaftGeometry::CameraFrame& camera,
  const vtkLightShaftModel::Medium& medium,
  int width,
  const vtkLightShaftFieldError::Density* density)
{
  Features f;
  const vtkLightShaftGeometry::LitVolume lit =
    vtkLightShaftGeometry::ComputeLitVolume(light, camera);
  if (lit.Empty() || width < 1)
  {
    return f;
  }
  f.Lit = true;
  f.Kind = light.Model.Kind;
  f.FallingAttenuation = light.Model.FallingAttenuation();
  f.LightInView = InView(light, camera);
  const double range = lit.Deepest - lit.Nearest;
  const glm::dvec3 centre = Centroid(lit.Polytope);
  double beam = range;
  if (f.Kind != vtkLightShaftModel::LightKind::Directional)
  {
    const double distance = glm::length(centre - light.PositionVC);
    beam = f.Kind == vtkLightShaftModel::LightKind::Spot
             ? 2.0 * distance * std::tan(BeamHalfAngle(light.Model))
             : distance;
  }
  beam = std::max(beam, 1e-12 * std::max(range, 1e-300));
  const glm::dvec2 footprint = camera.PixelFootprint(width);
  const double pixel = std::max(footprint.x * std::max(-centre.z, 0.0) + footprint.y, 1e-300);
  f.DepthRangeInBeamWidths = range / beam;
  f.BeamWidthInPixels = beam / pixel;
  f.OpticalDepth = medium.MaximumSigmaT() * range;
  if (density && density->Field)
  {
    std::vector<int> samples(NumberOfSettings);
    for (int i = 0; i < NumberOfSettings; ++i)
    {
      // (LIGHT_VOLUME gives way to RAY_MARCH with a field: nothing to measure.)
      const bool volume = GetSetting(i).Method == vtkLightShaftEnums::LIGHT_VOLUME;
      samples[i] = volume ? 0 : GetSetting(i).Samples;
    }
    vtkLightShaftFieldError::Density withExtinction = *density;
    withExtinction.SigmaT = medium.MaximumSigmaT();
    const vtkLightShaftFieldError::Probe probe =
      vtkLightShaftFieldError::Measure(withExtinction, light, camera, samples);
    f.OpticalDepth = medium.MaximumSigmaT() * probe.DensityDepth;
    f.FieldError = probe.QuadratureError;
    f.LightLegError = probe.LightLegError;
  }
  if (light.ShadowsPossible)
  {
    // MapExtent: across one map camera at unit distance (spot, point), or in world units.
    const double across = f.Kind == vtkLightShaftModel::LightKind::Directional
                            ? light.MapExtent
                            : light.MapExtent * glm::length(centre - light.PositionVC);
    f.ShadowTexelInPixels = across / ReferenceMapSize / pixel;
  }
  return f;
}

//------------------------------------------------------------------------------
int GetNumberOfSettings()
{
  return NumberOfSettings;
}

const Setting& GetSetting(int index)
{
  return vtkLightShaftErrorModelTable::Rows[std::clamp(index, 0, NumberOfSettings - 1)].Ladder;
}

const char* GetSettingName(int index)
{
  return index >= 0 && index < GetNumberOfSettings() ? GetSetting(index).Name : "none";
}

const Setting& GetPreset(Preset preset)
{
  const int index[] = { vtkLightShaftErrorModelTable::DraftSetting,
    vtkLightShaftErrorModelTable::InteractiveSetting,
    vtkLightShaftErrorModelTable::FinalSetting };
  return GetSetting(index[static_cast<int>(preset)]);
}

int FindSetting(const Setting& setting)
{
  for (int i = 0; i < NumberOfSettings; ++i)
  {
    const Setting& s = GetSetting(i);
    const bool slices = s.Method == vtkLightShaftEnums::SLICES;
    const bool marched = s.Method == vtkLightShaftEnums::RAY_MARCH;
    const bool epipolar = s.Method == vtkLightShaftEnums::EPIPOLAR;
    if (s.Method == setting.Method && s.Samples == setting.Samples &&
        s.BlurRadius == setting.BlurRadius && s.DownsampleFactor == setting.DownsampleFactor &&
        s.ShadowMapSize == setting.ShadowMapSize && (!slices || s.Jitter == setting.Jitter) &&
        (!marched || s.InterleaveSize == setting.InterleaveSize) &&
        (!epipolar || (s.EpipolarLines == setting.EpipolarLines &&
                        s.EpipolarSamples == setting.EpipolarSamples &&
                        s.EpipolarStep == setting.EpipolarStep)))
    {
      return i;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
double Predict(int index, const Features& features)
{
  if (!features.Lit)
  {
    return 0.0;
  }
  const auto& row = vtkLightShaftErrorModelTable::Rows[std::clamp(index, 0, NumberOfSettings - 1)];
  const auto x = Variables(features);
  double logError = row.Margin;
  for (size_t j = 0; j < x.size(); ++j)
  {
    logError += row.Coefficients[j] * x[j];
  }
  if (features.FieldError.empty())
  {
    return std::exp(logError);
  }
  const double factor =
    GetSetting(std::clamp(index, 0, NumberOfSettings - 1)).Method == vtkLightShaftEnums::EPIPOLAR
      ? FieldFactorEpipolar
      : FieldFactor;
  const std::size_t setting = std::min<std::size_t>(index, features.FieldError.size() - 1);
  return factor * std::exp(logError) + FieldMargin * features.FieldError[setting];
}

double Predict(int index, const std::vector<Features>& lights)
{
  double worst = 0.0;
  for (const Features& light : lights)
  {
    worst = std::max(worst, Predict(index, light));
  }
  return worst;
}

double PredictApartFromLightLeg(int index, const std::vector<Features>& lights)
{
  double worst = 0.0;
  for (Features light : lights)
  {
    SetLightLegError(light, 0.0);
    worst = std::max(worst, Predict(index, light));
  }
  return worst;
}

void SetLightLegError(Features& features, double error)
{
  // FieldError adds its terms in quadrature.
  const double before = features.LightLegError * features.LightLegError;
  for (double& term : features.FieldError)
  {
    term = std::sqrt(std::max(0.0, term * term - before) + error * error);
  }
  features.LightLegError = error;
}

int Choose(double target, const std::vector<Features>& lights, bool closedForm, double& predicted)
{
  auto usable = [closedForm](int i)
  { return closedForm || GetSetting(i).Method != vtkLightShaftEnums::LIGHT_VOLUME; };
  int best = NumberOfSettings - 1;
  while (best > 0 && !usable(best))
  {
    --best;
  }
  predicted = Predict(best, lights);
  for (int i = 0; i < NumberOfSettings; ++i)
  {
    if (!usable(i))
    {
      continue;
    }
    const double error = Predict(i, lights);
    if (error <= target)
    {
      predicted = error;
      return i;
    }
    if (error < predicted)
    {
      best = i;
      predicted = error;
    }
  }
  return best;
}
}
