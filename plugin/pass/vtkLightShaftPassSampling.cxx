// vtkLightShaftPass's third source file: how a frame's sampling is chosen. The error model
// predicts each setting's error on the frame's lights; a target error takes the cheapest
// setting predicted to meet it, a frame budget the most accurate predicted to fit (the cost
// model, learnt from the frames it measures).
#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"

#include "vtkLightShaftCostModel.h"
#include "vtkLightShaftEnums.h"
#include "vtkLightShaftEpipolarMethod.h"
#include "vtkLightShaftErrorModel.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftGeometryBudget.h"
#include "vtkLightShaftGeometryLights.h"
#include "vtkLightShaftInScatter.h"

#include "vtkRenderer.h"

#include <algorithm>

namespace
{
namespace model = vtkLightShaftErrorModel;

/// The renderer's allocated time at or above which a view is at rest (VTK allocates 1 /
/// StillUpdateRate, 10000 s by default): no budget.
constexpr double RestingAllocation = 10.0;

/// The fewest steps a split still setting marches per estimate: each estimate pays the frame's
/// fixed costs again (the scene, the march's setup, the average; about 95 ms at 1280x720 on
/// llvmpipe), and shorter shares make the still picture dearer in all. Measured on the window
/// scene's Final (docs/known-issues.md): 8 steps, 0.2 s frames, a Final frame's error after
/// 6.2 s; 16 steps, 0.3 s and 4.8 s; 32 steps, 0.5 s and 4.3 s; whole, 3.5 s and 3.5 s.
constexpr int MinimumSplitSteps = 16;

/// The frame's parameters set to the ladder's `chosen` setting at `factor` (AUTOMATIC keeps its
/// exact integral where nothing can shadow).
void ApplySetting(vtkLightShaftFrame& frame,
  const model::Setting& chosen,
  int factor,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights)
{
  vtkLightShaftParameters& p = frame.Parameters;
  const bool exact =
    p.Method == vtkLightShaftPass::AUTOMATIC && p.NoiseAmplitude <= 0.0 &&
    std::none_of(lights.begin(),
      lights.end(),
      [](const vtkLightShaftGeometry::LightFrame& l) { return l.ShadowsPossible; });
  p.MethodNamed = false; // chosen: a method that cannot be used gives way silently
  p.Method = exact ? p.Method : chosen.Method;
  p.AutomaticSliceCount = false;
  p.NumberOfSlices = chosen.Method == vtkLightShaftPass::SLICES ? chosen.Samples : p.NumberOfSlices;
  const bool marched =
    chosen.Method == vtkLightShaftPass::RAY_MARCH || chosen.Method == vtkLightShaftPass::EPIPOLAR;
  p.NumberOfSteps = marched ? chosen.Samples : p.NumberOfSteps;
  if (chosen.Method == vtkLightShaftPass::EPIPOLAR)
  {
    p.EpipolarLines = chosen.EpipolarLines;
    p.EpipolarSamples = chosen.EpipolarSamples;
    p.EpipolarStep = chosen.EpipolarStep;
  }
  p.LightVolumeResolution =
    chosen.Method == vtkLightShaftPass::LIGHT_VOLUME ? chosen.Samples : p.LightVolumeResolution;
  p.Jitter = chosen.Jitter;
  p.InterleaveSize = chosen.InterleaveSize;
  p.BlurRadius = chosen.BlurRadius;
  p.DownsampleFactor = factor;
  p.ShadowMapSize = chosen.ShadowMapSize;
  p.AccumulationPrecision = vtkLightShaftPass::ACCUMULATE_FLOAT32;
  frame.Reduced[0] = (frame.Size[0] + factor - 1) / factor;
  frame.Reduced[1] = (frame.Size[1] + factor - 1) / factor;
}

/// The ladder's setting the parameters set are (-1: none of them).
int SettingOfParameters(const vtkLightShaftParameters& p)
{
  const bool slices = p.Method == vtkLightShaftPass::SLICES && !p.AutomaticSliceCount;
  const bool volume = p.Method == vtkLightShaftPass::LIGHT_VOLUME;
  if (!slices && !volume && p.Method != vtkLightShaftPass::RAY_MARCH &&
      p.Method != vtkLightShaftPass::EPIPOLAR)
  {
    return -1;
  }
  if (p.AccumulationPrecision != vtkLightShaftPass::ACCUMULATE_FLOAT32)
  {
    return -1;
  }
  const model::Setting current{ "",
    p.Method,
    slices ? p.NumberOfSlices : (volume ? p.LightVolumeResolution : p.NumberOfSteps),
    p.Jitter,
    p.BlurRadius,
    p.DownsampleFactor,
    p.ShadowMapSize,
    p.InterleaveSize,
    p.EpipolarLines,
    p.EpipolarSamples,
    p.EpipolarStep };
  return model::FindSetting(current);
}
}

//------------------------------------------------------------------------------
// The cookie and noise (decided once: a target error or budget leaves out the settings that
// have no closed form with them), the frame's sampling, and progressive refinement's shifts
// of it. Returns the cookie texture (nullptr: none).
vtkTextureObject* vtkLightShaftPass::Internals::ChooseSampling(vtkLightShaftFrame& frame,
  const std::vector<vtkLight*>& lights,
  std::vector<vtkLightShaftGeometry::LightFrame>& lightFrames)
{
  vtkTextureObject* cookie = this->Textures.ReadyCookie(frame.Window, frame.Owner);
  if (this->Textures.GetNoiseImage() != this->Medium->GetNoiseTexture())
  {
    this->Textures.SetNoiseImage(this->Medium->GetNoiseTexture()); // (the medium's, maybe new)
  }
  if (frame.Parameters.NoiseAmplitude > 0.0 && frame.Medium.Scatters())
  {
    frame.Noise = this->Textures.ReadyNoise(frame.Window, frame.Owner);
  }
  frame.Density = this->DensityTexture.Ready(frame.Window, frame.Owner, this->Medium);
  frame.DensityField = frame.Density ? &this->DensityTexture : nullptr;
  // What decides the picture, signed only when refinement, a budget or the budget's last choice
  // (a still view may keep it) asks whether it changed: features that are off cost nothing (a
  // prop's redraw MTime updates its pipeline).
  const bool signs =
    frame.Parameters.ProgressiveRefinement || FrameBudget(frame) > 0.0 || this->HasMovingChoice;
  vtkLightShaftRefinement::Signature signature =
    signs ? vtkLightShaftRefinement::Sign(frame,
              lights,
              std::max(this->Textures.GetImagesTime(), this->DensityTexture.GetUploadTime()))
          : vtkLightShaftRefinement::Signature();
  frame.ViewStill = signs && this->Refinement.IsStill(signature);
  this->ApplyErrorModel(frame,
    lightFrames,
    cookie != nullptr || frame.Noise != nullptr || frame.Density != nullptr,
    frame.ViewStill);
  // The exact finish of a still view: any change stops it (Begin's signature, sampling aside).
  const vtkLightShaftParameters& p = frame.Parameters;
  bool finishes = false;
  if (frame.ViewStill && p.ExactFinish && p.ProgressiveRefinement)
  {
    this->Finish.Check(frame.Renderer);
    finishes = this->Finish.GetState() != vtkLightShaftExactFinish::State::Unsupported;
  }
  else
  {
    frame.Statistics.ExactFinishStopTime = this->Finish.Stop();
  }
  this->KeepMovingSampling(frame, lightFrames, finishes);
  this->SplitStillSetting(frame);
  if (frame.ViewStill && !(finishes && !this->Finish.IsActive()))
  {
    // (Not on the frame that starts the exact finish: it shows the moving picture again.)
    this->RefineTableWhenStill(frame, lightFrames);
  }
  vtkLightShaftRefinement::SetSampling(signature, frame);
  this->Refinement.Begin(frame, std::move(signature));
  if (frame.ShadowMapOffset[0] != 0.0 || frame.ShadowMapOffset[1] != 0.0)
  {
    const double texel = 2.0 / frame.Parameters.ShadowMapSize; // in the map's NDC
    for (vtkLightShaftGeometry::LightFrame& light : lightFrames)
    {
      vtkLightShaftGeometry::OffsetShadowCameras(
        light, texel * frame.ShadowMapOffset[0], texel * frame.ShadowMapOffset[1]);
    }
  }
  return cookie;
}

//------------------------------------------------------------------------------
double vtkLightShaftPass::Internals::FrameBudget(const vtkLightShaftFrame& frame)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  double budget = p.TimeBudget;
  const double allocated = frame.Renderer->GetAllocatedRenderTime();
  if (p.UseAllocatedRenderTime && allocated > 0.0 && allocated < RestingAllocation)
  {
    budget = budget > 0.0 ? std::min(budget, allocated) : allocated;
  }
  return budget;
}

//------------------------------------------------------------------------------
// The frame's sampling: with a frame budget, the most accurate (ladder setting, resolution)
// the cost model predicts will fit, the choice kept while the view is still; else with a
// target error, the cheapest setting predicted to meet it on every lit light; else the
// parameters set, with the model's prediction when they are one of its settings. LIGHT_VOLUME's
// settings are left out where it has no closed form (cookie, noise, a medium from data). A
// medium from data is measured along view rays (vtkLightShaftFieldError) into the features.
void vtkLightShaftPass::Internals::ApplyErrorModel(vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
  bool noLightVolume,
  bool still)
{
  if (this->FrameBudget(frame) <= 0.0)
  {
    this->ResolveTableForTarget(frame, lights);
  }
  // A still view is described as it was (the probe of a field costs milliseconds a frame).
  if (!still || !this->DescribedValid)
  {
    this->DescribeLights(frame, lights);
  }
  this->Features = this->Described;
  const std::vector<model::Features>& features = this->Features;
  int lit = 0;
  for (const model::Features& light : this->Features)
  {
    lit += light.Lit ? 1 : 0;
    if (light.Lit && !frame.Statistics.ErrorFeatures.Lit)
    {
      frame.Statistics.ErrorFeatures = light;
    }
  }
  vtkLightShaftParameters& p = frame.Parameters;
  frame.Statistics.TimeBudget = FrameBudget(frame);
  if (!frame.Medium.Scatters() || lit == 0)
  {
    this->HasBudgetChoice = false;
    return; // no shafts to predict
  }
  int setting = -1;
  double predicted = -1.0;
  if (frame.Statistics.TimeBudget > 0.0)
  {
    const double pixels = double(frame.Size[0]) * frame.Size[1];
    // Kept while the view is still under the same budget (an interactor's new rate is not).
    if (!still || !this->HasBudgetChoice || this->BudgetOfChoice != frame.Statistics.TimeBudget)
    {
      this->BudgetOfChoice = frame.Statistics.TimeBudget;
      this->BudgetChoice = this->Costs.Choose(
        frame.Statistics.TimeBudget, p.TargetError, features, !noLightVolume, pixels, lit);
      this->HasBudgetChoice = true;
    }
    const vtkLightShaftCostModel::Choice& choice = this->BudgetChoice;
    ApplySetting(frame, model::GetSetting(choice.Setting), choice.DownsampleFactor, lights);
    setting = choice.Setting;
    // The error model knows full resolution only.
    predicted = choice.DownsampleFactor == 1 ? choice.Error : -1.0;
    frame.Statistics.PredictedFrameTime = choice.Seconds;
    frame.Statistics.BudgetLights = lit;
  }
  else if (p.TargetError > 0.0)
  {
    this->HasBudgetChoice = false;
    setting = model::Choose(p.TargetError, features, !noLightVolume, predicted);
    const model::Setting& chosen = model::GetSetting(setting);
    ApplySetting(frame, chosen, chosen.DownsampleFactor, lights);
  }
  else
  {
    this->HasBudgetChoice = false;
    setting = SettingOfParameters(p);
    predicted = setting >= 0 ? model::Predict(setting, features) : -1.0;
  }
  frame.Statistics.ErrorModelSetting = setting;
  frame.Statistics.PredictedError = predicted;
}

//------------------------------------------------------------------------------
// Never worse when the camera stops: a still view after frames under a budget keeps their
// setting where the error model predicts it better than the still setting (where the model
// cannot tell, the setting asked for is used). With the exact finish, also until the finish has
// started: that first still frame shows the moving picture again, so that it costs no more than
// a moving frame.
void vtkLightShaftPass::Internals::KeepMovingSampling(vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
  bool finishes)
{
  if (frame.Statistics.TimeBudget > 0.0)
  {
    this->HasMovingChoice = this->HasBudgetChoice;
    this->MovingChoice = this->BudgetChoice;
    return;
  }
  if (!frame.ViewStill || !this->HasMovingChoice)
  {
    this->HasMovingChoice = false;
    return;
  }
  const vtkLightShaftCostModel::Choice& moving = this->MovingChoice;
  const double movingError = moving.DownsampleFactor == 1 ? moving.Error : -1.0;
  const double stillError = frame.Statistics.PredictedError;
  const bool known = movingError >= 0.0 && stillError >= 0.0;
  if ((finishes && !this->Finish.IsActive()) || (known && movingError < stillError))
  {
    ApplySetting(frame, model::GetSetting(moving.Setting), moving.DownsampleFactor, lights);
    frame.Statistics.ErrorModelSetting = moving.Setting;
    frame.Statistics.PredictedError = movingError;
  }
}

//------------------------------------------------------------------------------
// Final without blocking: a still view after frames under a budget whose setting is a ray march
// the cost model predicts longer than the budget's frame marches a power-of-two share of its
// steps per estimate, the fewest shares whose frame fits (MinimumSplitSteps steps a share at
// least). Each group of that many estimates adds up to one frame of the setting, piece for
// piece (each integrates its own part of the steps: vtkLightShaftRefinement::Begin); refinement
// shows the moving picture until a group is complete, and goes on to RefinementFrames groups. Not
// through a medium from data or a volume, whose extinction a share counts at its own pieces'
// density only, nor behind translucent surfaces in view (when shares marched longer pieces, the
// sphere scene's Final behind a half-transparent pane was 0.24% from the reference split, 0.09%
// whole; not measured since they integrate the setting's own).
void vtkLightShaftPass::Internals::SplitStillSetting(vtkLightShaftFrame& frame)
{
  vtkLightShaftParameters& p = frame.Parameters;
  const int setting = frame.Statistics.ErrorModelSetting;
  const double budget = this->BudgetOfChoice;
  frame.RefinementSplit = 1;
  if (!p.ProgressiveRefinement)
  {
    return;
  }
  if (!frame.ViewStill || !this->HasMovingChoice || frame.Statistics.TimeBudget > 0.0 ||
      setting < 0 || !(budget > 0.0) || p.Method != vtkLightShaftPass::RAY_MARCH ||
      p.DownsampleFactor != 1 || frame.Density || this->Medium->GetDensityVolume() ||
      (p.CameraLayers > 0 && !vtkLightShaftInScatter::TranslucentProps(frame).empty()))
  {
    this->SplitLongFrame(frame);
    return;
  }
  const int lit = static_cast<int>(std::count_if(this->Features.begin(),
    this->Features.end(),
    [](const model::Features& light) { return light.Lit; }));
  const double pixels = double(frame.Size[0]) * frame.Size[1];
  double trust = 1.0;
  const double shafts = this->Costs.PredictShafts(setting, 1, pixels, lit, &trust);
  const double rest = this->Costs.PredictRest(pixels);
  int split = 1;
  while (
    shafts / split + rest > trust * budget && p.NumberOfSteps / (2 * split) >= MinimumSplitSteps)
  {
    split *= 2;
  }
  frame.RefinementSplit = split;
}

//------------------------------------------------------------------------------
// No setting stalls a frame: where one frame of the setting would integrate more than
// FrameSegmentAllowance segments (after the segment budget), RAY_MARCH, SLICES and EPIPOLAR
// integrate a power-of-two share of its pieces (steps, slabs) every frame, moving or still (and
// RADIAL_BLUR, past FrameRadialSampleAllowance, a share of its samples), the
// fewest shares that fit (down to one piece a share: here the frame's time, not the still
// picture's, is what matters); a group of shares adds up to one frame of it, piece for piece, as
// a budget's split does (frame.SamplePart: vtkLightShaftRefinement::Begin). (Through a medium
// from data, a march's share counts the extinction of the pieces it leaves at the density of
// the one it integrates: there a group is close to one frame of the setting, not equal.)
void vtkLightShaftPass::Internals::SplitLongFrame(vtkLightShaftFrame& frame)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int lights = frame.RadiatingLights;
  if (!p.SplitLongFrames || lights == 0)
  {
    return;
  }
  const long long pixels = static_cast<long long>(frame.Reduced[0]) * frame.Reduced[1];
  long long whole = 0;
  long long rays = pixels;
  long long allowance = vtkLightShaftGeometry::FrameSegmentAllowance / lights;
  switch (p.Method)
  {
    case vtkLightShaftPass::RAY_MARCH:
      whole = vtkLightShaftGeometry::AffordableSamples(p.NumberOfSteps, rays, lights);
      break;
    case vtkLightShaftPass::SLICES:
      // (An automatic count is at most its maximum.)
      whole = vtkLightShaftGeometry::AffordableSamples(
        p.AutomaticSliceCount ? p.MaximumNumberOfSlices : p.NumberOfSlices, rays, lights);
      break;
    case vtkLightShaftPass::EPIPOLAR:
      rays = vtkLightShaftEpipolarMethod::MarchedRays(frame);
      whole = vtkLightShaftGeometry::AffordableSamples(p.NumberOfSteps, rays, lights);
      break;
    case vtkLightShaftPass::RADIAL_BLUR:
      whole = p.RadialSamples;
      allowance = vtkLightShaftGeometry::FrameRadialSampleAllowance / lights;
      break;
    default:
      return;
  }
  int split = 1;
  while ((whole / split) * rays > allowance && whole / (2 * split) >= 1)
  {
    split *= 2;
  }
  frame.RefinementSplit = split;
}

//------------------------------------------------------------------------------
// The error model's features of each light that radiates, a medium from data measured along
// view rays (vtkLightShaftFieldError) with its light leg's table's error.
void vtkLightShaftPass::Internals::DescribeLights(const vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights)
{
  this->Described.clear();
  vtkLightShaftFieldError::Density density;
  density.Field = frame.Density ? &this->DensityTexture.GetField() : nullptr;
  density.Scale = frame.DensityScale;
  density.Background = frame.DensityBackground;
  if (frame.Density)
  {
    frame.Renderer->ComputeVisiblePropBounds(density.SceneBounds);
  }
  for (const vtkLightShaftGeometry::LightFrame& light : lights)
  {
    if (light.Model.Radiates())
    {
      if (frame.Density)
      {
        density.TableError = this->TableError(this->Described.size(),
          light.Model,
          frame.Parameters.MediumShadowResolution,
          frame.Medium.MaximumSigmaT() * frame.DensityScale);
      }
      this->Described.push_back(
        model::Describe(light, frame.Camera, frame.Medium, frame.Size[0], &density));
    }
  }
  this->DescribedValid = true;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::ObserveFrameTime(vtkLightShaftFrame& frame,
  double shafts,
  double total)
{
  // Observers may rewrite the times (distributed processes take the slowest one's, so that
  // every process's cost model learns the same and chooses the same next frame).
  double seconds[2] = { shafts, total };
  frame.Owner->InvokeEvent(vtkLightShaftEnums::FrameTimedEvent, seconds);
  frame.Statistics.FrameTime = seconds[1];
  if (frame.Statistics.TimeBudget > 0.0 && frame.Statistics.ErrorModelSetting >= 0)
  {
    this->Costs.Observe(frame.Statistics.ErrorModelSetting,
      frame.Parameters.DownsampleFactor,
      double(frame.Size[0]) * frame.Size[1],
      frame.Statistics.BudgetLights,
      seconds[0],
      seconds[1]);
  }
}

//------------------------------------------------------------------------------
double vtkLightShaftPass::Internals::TableError(std::size_t index,
  const vtkLightShaftModel::Light& light,
  int resolution,
  double extinction)
{
  const vtkMTimeType version = this->DensityTexture.GetVersion();
  // Entries of another field are stale; one per light and resolution tried.
  auto stale = [&](const TableErrorEntry& e) { return e.FieldVersion != version; };
  this->TableErrors.erase(std::remove_if(this->TableErrors.begin(), this->TableErrors.end(), stale),
    this->TableErrors.end());
  auto entry = std::find_if(this->TableErrors.begin(),
    this->TableErrors.end(),
    [&](const TableErrorEntry& e) { return e.Index == index && e.Resolution == resolution; });
  if (entry == this->TableErrors.end())
  {
    this->TableErrors.emplace_back();
    entry = this->TableErrors.end() - 1;
    entry->Index = index;
    entry->Resolution = resolution;
    entry->FieldVersion = version;
  }
  else if (entry->Extinction == extinction && entry->Light.Kind == light.Kind &&
           entry->Light.Position == light.Position && entry->Light.Axis == light.Axis &&
           entry->Light.ConeHalfAngle == light.ConeHalfAngle)
  {
    return entry->Error;
  }
  entry->Error = vtkLightShaftFieldError::TableError(
    this->DensityTexture.GetField(), light, resolution, extinction);
  entry->Extinction = extinction;
  entry->Light = light;
  return entry->Error;
}

//------------------------------------------------------------------------------
// Doubling the resolution quarters a smooth table's error (trilinear interpolation); a sharp
// field's falls slower, and past 256 (the table's memory bound) only marching the leg helps.
void vtkLightShaftPass::Internals::ResolveTable(vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
  double aim)
{
  int& resolution = frame.Parameters.MediumShadowResolution;
  if (!frame.Density || resolution <= 0)
  {
    return;
  }
  const double extinction = frame.Medium.MaximumSigmaT() * frame.DensityScale;
  for (int r = resolution;; r = std::min(2 * r, 256))
  {
    double worst = 0.0;
    std::size_t index = 0;
    for (const vtkLightShaftGeometry::LightFrame& light : lights)
    {
      if (light.Model.Radiates())
      {
        worst = std::max(
          worst, model::FieldMargin * this->TableError(index++, light.Model, r, extinction));
      }
    }
    if (worst <= aim)
    {
      resolution = r;
      return;
    }
    if (r >= 256)
    {
      break;
    }
  }
  resolution = 0;
}

//------------------------------------------------------------------------------
// With a target error and a medium from data, the light leg's table at a resolution whose
// error stays within half the target, else the leg is marched: no setting of the ladder reduces
// the table's error, and the target would otherwise go unmet whatever the steps.
void vtkLightShaftPass::Internals::ResolveTableForTarget(vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights)
{
  if (frame.Parameters.TargetError > 0.0)
  {
    this->ResolveTable(frame, lights, 0.5 * frame.Parameters.TargetError);
  }
}

//------------------------------------------------------------------------------
// A still view's refinement averages estimates: it removes what the shifted samples scatter,
// not the table's interpolation, which is the same in every estimate. So while the view is
// still the table is refined where its term is more than half of what the setting's samples
// are predicted to make, or the leg is marched; the new resolution starts a new history (the
// sampling signs it). From the frame where the camera stops: its history holds one estimate
// then (the moving frame's), so that the new one is never worse than the picture before. Left to
// the target's rule with a TargetError; nothing under a frame budget (a table to build, or a
// marched leg, would overrun it) or where the setting has no prediction (parameters off the
// ladder).
void vtkLightShaftPass::Internals::RefineTableWhenStill(vtkLightShaftFrame& frame,
  const std::vector<vtkLightShaftGeometry::LightFrame>& lights)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int setting = frame.Statistics.ErrorModelSetting;
  if (!p.ProgressiveRefinement || !frame.Density || p.TargetError > 0.0 || setting < 0 ||
      p.DownsampleFactor != 1 || frame.Statistics.TimeBudget > 0.0 || this->Features.empty())
  {
    return;
  }
  const double samples = model::PredictApartFromLightLeg(setting, this->Features);
  const int before = p.MediumShadowResolution;
  if (!(samples > 0.0) || before <= 0)
  {
    return;
  }
  this->ResolveTable(frame, lights, 0.5 * samples);
  const int after = p.MediumShadowResolution;
  if (after == before)
  {
    return;
  }
  // The prediction and its read-outs with the new table.
  const double extinction = frame.Medium.MaximumSigmaT() * frame.DensityScale;
  std::size_t index = 0;
  for (const vtkLightShaftGeometry::LightFrame& light : lights)
  {
    if (light.Model.Radiates() && index < this->Features.size())
    {
      const double leg = after > 0 ? this->TableError(index, light.Model, after, extinction) : 0.0;
      model::SetLightLegError(this->Features[index++], leg);
    }
  }
  const auto firstLit = std::find_if(
    this->Features.begin(), this->Features.end(), [](const model::Features& f) { return f.Lit; });
  if (firstLit != this->Features.end())
  {
    frame.Statistics.ErrorFeatures = *firstLit;
  }
  frame.Statistics.PredictedError = model::Predict(setting, this->Features);
}

//------------------------------------------------------------------------------
// The light's leg through a medium from data, tabulated (MediumShadowResolution > 0; rebuilt
// when the field or the light moved), or nothing: the shaders march it.
void vtkLightShaftPass::Internals::ReadyFieldShadow(vtkLightShaftFrame& frame,
  vtkLightShaftFieldTableTexture& asSet,
  vtkLightShaftFieldTableTexture& refined)
{
  frame.FieldShadow = nullptr;
  frame.FieldShadowLayout = nullptr;
  const int resolution = frame.Parameters.MediumShadowResolution;
  if (!frame.Density || this->Medium->GetFieldShadowResolution() == 0)
  {
    asSet.ReleaseGraphicsResources(frame.Window);
  }
  if (!frame.Density)
  {
    refined.ReleaseGraphicsResources(frame.Window);
  }
  if (!frame.Density || resolution == 0)
  {
    return;
  }
  vtkLightShaftFieldTableTexture& shadow =
    resolution == this->Medium->GetFieldShadowResolution() ? asSet : refined;
  frame.FieldShadow = shadow.Ready(frame.Window,
    this->DensityTexture.GetField(),
    this->DensityTexture.GetVersion(),
    frame.Light.Model,
    frame.Parameters.MediumShadowResolution);
  frame.FieldShadowLayout = &shadow;
  frame.LightStatistics->FieldShadowBytes = static_cast<double>(shadow.GetBytes());
  frame.LightStatistics->FieldShadowBuildTime = shadow.GetBuildTime();
}

//------------------------------------------------------------------------------
// The light's leg through the scene's volume, tabulated as the field's is (at the medium's
// FieldShadowResolution; 64 where that is 0: a volume's leg is not marched).
void vtkLightShaftPass::Internals::ReadyVolumeShadow(vtkLightShaftFrame& frame,
  vtkLightShaftFieldTableTexture& shadow)
{
  frame.VolumeShadow = nullptr;
  frame.VolumeShadowLayout = nullptr;
  if (!frame.Volume)
  {
    shadow.ReleaseGraphicsResources(frame.Window);
    return;
  }
  // (The resolution set, not the one a target or a still view chose for the field's table:
  // their rules measured the field's, and the volume's would be rebuilt at each change.)
  const int set = this->Medium->GetFieldShadowResolution();
  const int resolution = set > 0 ? set : 64;
  frame.VolumeShadow = shadow.Ready(frame.Window,
    this->VolumeTexture.GetField(),
    this->VolumeTexture.GetVersion(),
    frame.Light.Model,
    resolution);
  frame.VolumeShadowLayout = &shadow;
  frame.LightStatistics->VolumeShadowBytes = static_cast<double>(shadow.GetBytes());
  frame.LightStatistics->VolumeShadowBuildTime = shadow.GetBuildTime();
}
