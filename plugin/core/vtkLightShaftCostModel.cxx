#include "vtkLightShaftCostModel.h"

#include "vtkLightShaftEnums.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace
{
/// Seconds per pixel of a plain frame on the machine the priors were measured on (llvmpipe,
/// 2 cores: 9-11 ms at 1280x720).
constexpr double PlainSecondsPerPixel = 1.1e-8;

/// A setting's prior cost in plain frames: its median time over the plain frame on the 50
/// held-out random scenes (docs/random-scenes.md, seed 0), less the plain frame itself; for a
/// setting not measured there, a guess from its method and samples.
double PriorPlainFrames(const vtkLightShaftErrorModel::Setting& setting)
{
  static const struct
  {
    const char* Name;
    double Ratio;
  } measured[] = { { "E16 l128 s256 k8 m512", 8.7 },
    { "E32 l256 s256 k8 m1024", 12.5 },
    { "V128 m512", 21.0 },
    { "V256 m1024", 29.0 },
    { "V512 m2048", 49.0 },
    { "V1024 m2048", 91.0 },
    { "M128 i1 m2048", 282.0 },
    { "M256 i1 m2048", 532.0 } };
  for (const auto& entry : measured)
  {
    if (std::strcmp(entry.Name, setting.Name) == 0)
    {
      return entry.Ratio - 1.0;
    }
  }
  switch (setting.Method)
  {
    case vtkLightShaftEnums::RAY_MARCH:
      return 2.0 * setting.Samples;
    case vtkLightShaftEnums::EPIPOLAR:
      return 0.5 * setting.Samples;
    case vtkLightShaftEnums::LIGHT_VOLUME:
      return 0.1 * setting.Samples;
    default:
      return 0.5 * setting.Samples;
  }
}

/// How a setting's time follows the in-scatter's resolution: as (pixels / factor^2)^exponent.
/// Measured between full and quarter resolution on the window scene at 1280x720, camera moving
/// (`tools/measure.sh resolution-cost`)
/// (E16 47 -> 39 ms, E32 54 -> 46, V256 425 -> 87, M128 1969 -> 185): EPIPOLAR marches its
/// lines' samples whatever the resolution and only interpolates per pixel; LIGHT_VOLUME
/// rasterises its mesh over the in-scatter's pixels, over a fixed cost of its grid; RAY_MARCH
/// marches every pixel.
double ResolutionExponent(const vtkLightShaftErrorModel::Setting& setting)
{
  switch (setting.Method)
  {
    case vtkLightShaftEnums::EPIPOLAR:
      return 0.06;
    case vtkLightShaftEnums::LIGHT_VOLUME:
      return 0.55;
    default:
      return 0.85;
  }
}
}

//------------------------------------------------------------------------------
vtkLightShaftCostModel::vtkLightShaftCostModel()
  : LogCost(vtkLightShaftErrorModel::GetNumberOfSettings(),
      { std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::quiet_NaN() })
  , LogRestPerPixel(std::log(1.5 * PlainSecondsPerPixel))
{
}

int vtkLightShaftCostModel::FactorIndex(int factor)
{
  return factor >= 4 ? 2 : (factor >= 2 ? 1 : 0);
}

//------------------------------------------------------------------------------
// This machine's log seconds per pixel of one plain frame: what the measured settings cost
// over their priors (the priors' own machine before any measurement).
double vtkLightShaftCostModel::LogScale() const
{
  double sum = 0.0;
  int count = 0;
  for (size_t i = 0; i < this->LogCost.size(); ++i)
  {
    const double prior = std::log(PriorPlainFrames(vtkLightShaftErrorModel::GetSetting(int(i))));
    for (double cost : this->LogCost[i])
    {
      if (!std::isnan(cost))
      {
        sum += cost - prior;
        ++count;
      }
    }
  }
  return count > 0 ? sum / count : std::log(PlainSecondsPerPixel);
}

//------------------------------------------------------------------------------
// Log seconds per (in-scatter pixel x lit light) of `setting` at `factor`: measured; else from
// the same setting measured at the nearest other factor, scaled by its method's resolution
// exponent; else its prior times this machine's scale, per in-scatter pixel at any factor (so
// an unmeasured setting looks cheap at reduced resolution, is tried there first, and once
// measured predicts its other resolutions).
double vtkLightShaftCostModel::LogCostOf(int setting, int factor, double* trust) const
{
  const std::array<double, 3>& costs = this->LogCost[setting];
  const double measured = costs[FactorIndex(factor)];
  double ignored = 0.0;
  double& confidence = trust ? *trust : ignored;
  confidence = MeasuredTrust;
  if (!std::isnan(measured))
  {
    return measured;
  }
  const vtkLightShaftErrorModel::Setting& s = vtkLightShaftErrorModel::GetSetting(setting);
  int nearest = 0;
  for (int other : Factors)
  {
    if (!std::isnan(costs[FactorIndex(other)]) &&
        (nearest == 0 || std::abs(std::log(double(other) / factor)) <
                           std::abs(std::log(double(nearest) / factor))))
    {
      nearest = other;
    }
  }
  if (nearest == 0)
  {
    confidence = PriorTrust;
    return this->LogScale() + std::log(PriorPlainFrames(s));
  }
  confidence = ExtrapolatedTrust;
  // A frame's time of pixels^e is, per in-scatter pixel, factor^(2 (1 - e)).
  const double exponent = ResolutionExponent(s);
  return costs[FactorIndex(nearest)] +
         (1.0 - exponent) * std::log(double(factor * factor) / double(nearest * nearest));
}

//------------------------------------------------------------------------------
double vtkLightShaftCostModel::PredictShafts(int setting,
  int factor,
  double pixels,
  int lights,
  double* trust) const
{
  return std::exp(this->LogCostOf(setting, factor, trust)) * pixels / (factor * factor) *
         std::max(lights, 1);
}

double vtkLightShaftCostModel::PredictRest(double pixels) const
{
  return std::exp(this->LogRestPerPixel) * pixels;
}

//------------------------------------------------------------------------------
vtkLightShaftCostModel::Choice vtkLightShaftCostModel::Choose(double budget,
  double target,
  const std::vector<vtkLightShaftErrorModel::Features>& features,
  bool closedForm,
  double pixels,
  int lights) const
{
  const double rest = this->PredictRest(pixels);
  Choice best;        // the most accurate that fits (or the cheapest meeting the target)
  Choice cheapest;    // the cheapest of all, when nothing fits
  bool meets = false; // best meets the target
  for (int factor : Factors)
  {
    for (int i = 0; i < vtkLightShaftErrorModel::GetNumberOfSettings(); ++i)
    {
      if (!closedForm &&
          vtkLightShaftErrorModel::GetSetting(i).Method == vtkLightShaftEnums::LIGHT_VOLUME)
      {
        continue;
      }
      double trust = MeasuredTrust;
      Choice candidate{ i,
        factor,
        rest + this->PredictShafts(i, factor, pixels, lights, &trust),
        vtkLightShaftErrorModel::Predict(i, features) };
      if (cheapest.Setting < 0 || candidate.Seconds < cheapest.Seconds)
      {
        cheapest = candidate;
      }
      // A prediction not measured must fit with room to spare: a wrong guess costs a frame
      // over the budget, and the next one too (the first of a setting is not learnt).
      if (candidate.Seconds > budget * trust)
      {
        continue;
      }
      // The error model knows full resolution only: a reduced one meets no target.
      const bool candidateMeets = target > 0.0 && factor == 1 && candidate.Error <= target;
      bool better = best.Setting < 0;
      if (!better && target > 0.0 && (candidateMeets || meets))
      {
        better = candidateMeets && (!meets || candidate.Seconds < best.Seconds);
      }
      else if (!better)
      {
        // Full resolution first (the outer loop), then the lowest predicted error.
        better =
          candidate.DownsampleFactor == best.DownsampleFactor && candidate.Error < best.Error;
      }
      if (better)
      {
        best = candidate;
        meets = candidateMeets;
      }
    }
  }
  return best.Setting >= 0 ? best : cheapest;
}

//------------------------------------------------------------------------------
void vtkLightShaftCostModel::Observe(int setting,
  int factor,
  double pixels,
  int lights,
  double shafts,
  double total)
{
  if (setting < 0 || setting >= static_cast<int>(this->LogCost.size()) || pixels <= 0.0 ||
      !(shafts > 0.0) || !(total > 0.0))
  {
    return;
  }
  // The first frame after a change of setting pays its one-off costs (programs compiled,
  // textures and shadow maps made): it says nothing of the next frames.
  const bool repeated = setting == this->LastSetting && factor == this->LastFactor;
  this->LastSetting = setting;
  this->LastFactor = factor;
  if (!repeated)
  {
    return;
  }
  auto follow = [](double& value, double measured)
  { value = std::isnan(value) ? measured : 0.5 * (value + measured); };
  const double reducedPixels = pixels / (factor * factor) * std::max(lights, 1);
  follow(this->LogCost[setting][FactorIndex(factor)], std::log(shafts / reducedPixels));
  follow(this->LogRestPerPixel, std::log(std::max(total - shafts, 1e-6) / pixels));
  ++this->Measurements;
}
