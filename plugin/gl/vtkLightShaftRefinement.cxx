#include "vtkLightShaftRefinement.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftModel.h"

#include "vtkLight.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftRefineFS.h"

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftRefinement::vtkLightShaftRefinement() = default;
vtkLightShaftRefinement::~vtkLightShaftRefinement() = default;

//------------------------------------------------------------------------------
namespace
{
// Equal to within rounding: a re-render for a screenshot (vtkWindowToImageFilter) rebuilds the
// projection through the tile scale, a few 1e-8 off the window's own.
bool NearlyEqual(const glm::dmat4& a, const glm::dmat4& b)
{
  for (int column = 0; column < 4; ++column)
  {
    for (int row = 0; row < 4; ++row)
    {
      const double x = a[column][row];
      const double y = b[column][row];
      if (!(std::abs(x - y) <= 1e-6 * std::max({ 1.0, std::abs(x), std::abs(y) })))
      {
        return false;
      }
    }
  }
  return true;
}
}

namespace
{
/// `index` (below `count`, a power of two) with its bits reversed.
int BitReversed(int index, int count)
{
  int reversed = 0;
  for (int bit = 1; bit < count; bit <<= 1)
  {
    reversed = (reversed << 1) | ((index & bit) ? 1 : 0);
  }
  return reversed;
}
}

bool vtkLightShaftRefinement::Signature::SameScene(const Signature& other) const
{
  return NearlyEqual(this->WorldToView, other.WorldToView) &&
         NearlyEqual(this->ViewToClip, other.ViewToClip) && this->Origin[0] == other.Origin[0] &&
         this->Origin[1] == other.Origin[1] && this->Size[0] == other.Size[0] &&
         this->Size[1] == other.Size[1] && this->Objects == other.Objects &&
         this->Lights == other.Lights;
}

bool vtkLightShaftRefinement::Signature::operator==(const Signature& other) const
{
  return this->SameScene(other) && this->Sampling == other.Sampling;
}

void vtkLightShaftRefinement::SetSampling(Signature& signature, const vtkLightShaftFrame& frame)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  signature.Sampling = { double(p.Method),
    double(p.NumberOfSlices),
    double(p.AutomaticSliceCount),
    double(p.NumberOfSteps),
    double(p.InterleaveSize),
    double(p.LightVolumeResolution),
    double(p.EpipolarLines),
    double(p.EpipolarSamples),
    double(p.EpipolarStep),
    double(p.Jitter),
    double(p.BlurRadius),
    double(p.DownsampleFactor),
    double(p.ShadowMapSize),
    double(p.AccumulationPrecision),
    double(p.MediumShadowResolution),
    double(frame.RefinementSplit) };
}

bool vtkLightShaftRefinement::IsStill(const Signature& signature) const
{
  return this->HasLast && signature.SameScene(this->Last);
}

vtkLightShaftRefinement::Signature vtkLightShaftRefinement::Sign(const vtkLightShaftFrame& frame,
  const std::vector<vtkLight*>& lights,
  vtkMTimeType imagesTime)
{
  Signature signature;
  signature.Objects.emplace_back(frame.Owner, frame.Owner->GetMTime());
  signature.Objects.emplace_back(nullptr, imagesTime);
  for (vtkLight* light : lights)
  {
    signature.Objects.emplace_back(light, 0);
    const vtkLightShaftModel::Light model = vtkLightShaftModel::DescribeLight(light);
    signature.Lights.insert(signature.Lights.end(),
      { static_cast<double>(model.Kind),
        model.Position.x,
        model.Position.y,
        model.Position.z,
        model.Axis.x,
        model.Axis.y,
        model.Axis.z,
        model.ConeHalfAngle,
        model.Exponent,
        model.Attenuation[0],
        model.Attenuation[1],
        model.Attenuation[2],
        model.RadiantIntensity[0],
        model.RadiantIntensity[1],
        model.RadiantIntensity[2],
        model.SquareSide });
  }
  vtkPropCollection* props = frame.Renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility())
    {
      signature.Objects.emplace_back(prop, prop->GetRedrawMTime());
    }
  }
  signature.WorldToView = frame.Camera.WorldToView;
  signature.ViewToClip = frame.Camera.ViewToClip;
  for (int i = 0; i < 2; ++i)
  {
    signature.Origin[i] = frame.Origin[i];
    signature.Size[i] = frame.Size[i];
  }
  return signature;
}

//------------------------------------------------------------------------------
void vtkLightShaftRefinement::Begin(vtkLightShaftFrame& frame, Signature&& signature)
{
  const bool on = frame.Parameters.ProgressiveRefinement;
  if (!on || !this->HasLast || !(signature == this->Last))
  {
    // A split setting starts from the picture it replaces, where that shows the same scene.
    const bool hasPicture = this->HasLast && this->Estimates > 0 && this->IsStill(signature);
    this->HoldSource =
      (on && hasPicture && frame.RefinementSplit > 1) ? this->GetHistory() : nullptr;
    this->Holding = false;
    this->Split = on ? std::max(frame.RefinementSplit, 1) : 1;
    this->Estimates = 0;
    this->Converged = false;
    this->Picture = nullptr;
    this->Sigma = 0.0;
  }
  this->Last = std::move(signature);
  this->HasLast = true; // also off: IsStill tells a frame budget the view is still
  // The R4 sequence (Roberts 2018): the n-th estimate's shifts fall where the earlier ones left
  // the largest gaps, so n estimates sample their (step offset, lookup, map offset) space about
  // as evenly as a grid would. Estimate 0 has no shift.
  // A split setting (Split estimates of a Split-th of the pieces each) shifts as the setting's
  // n-th estimate would for each group of Split, its estimates integrating the Split parts of
  // the setting's pieces (in bit-reversed order: a group's first estimates spread over them):
  // together, a group is one frame of the setting, piece for piece.
  const int split = on ? this->Split : 1;
  const int n = on ? this->Estimates / split : 0;
  const int part = on ? this->Estimates % split : 0;
  const double alpha[4] = {
    0.8566748838545029, 0.7338918566271260, 0.6287067210378087, 0.5385972572236101
  }; // 1 / g^i, g^5 = g + 1
  double whole = 0.0;
  frame.SamplingRotation = std::modf(n * alpha[0], &whole);
  frame.LookupFraction = std::modf(0.5 + n * alpha[1], &whole);
  // (The group's first estimate integrates the middle part: shown alone, as a long frame's
  // moving frame is, each of its pieces stands for the span around it.)
  frame.RefinementSplit = split;
  frame.SamplePart = (BitReversed(part, split) + split / 2) % split;
  frame.ShadowMapOffset[0] = std::modf(0.5 + n * alpha[2], &whole) - 0.5;
  frame.ShadowMapOffset[1] = std::modf(0.5 + n * alpha[3], &whole) - 0.5;
  // The first group is filtered as the parameters say (each estimate: the filters are linear,
  // so the group's mean is one frame of the setting filtered), the later ones are not.
  frame.Unfiltered = on && this->Estimates >= split;
}

//------------------------------------------------------------------------------
// The width that makes a filter's error least over a sharp edge (a shadow's: the blur's bias
// grows as its width, the noise it leaves as 1 / (n width^2) for n estimates) falls as
// n^(-1/4); taking the first picture's filters as right for one estimate, the picture's
// Gaussian averages firstSamples n^(-1/4) samples along an axis. (Measured on the sphere and
// window scenes, 640x360: n^(-1/2) left the window's noise, 1.03% after 16 estimates of 16
// interleaved steps where filtering each estimate gave 0.81%; n^(-1/4) 0.81%, and halved the
// sphere's floor.) A Gaussian's samples grow with its width: bisected, to a tenth of a percent.
double vtkLightShaftRefinement::PictureSigma(double firstSamples, int estimates)
{
  using Filter = vtkLightShaftSeparableFilter;
  const double needed = firstSamples / std::pow(static_cast<double>(std::max(estimates, 1)), 0.25);
  if (!(needed > 1.01))
  {
    return 0.0; // (a Gaussian that averages 1% more is a quarter of a pixel wide)
  }
  auto samples = [](double sigma)
  { return Filter::EffectiveSamples(Filter::Kernel::Gaussian(sigma).Weights()); };
  double low = 0.25;
  double high = 64.0;
  if (samples(high) <= needed)
  {
    return high;
  }
  while (high - low > 1e-3 * high)
  {
    const double mid = 0.5 * (low + high);
    (samples(mid) < needed ? low : high) = mid;
  }
  return high;
}

//------------------------------------------------------------------------------
// What the first estimate's filters averaged along an axis: the gather of interleaved samples
// where a light was marched with it, then the blur.
namespace
{
double FirstFilterSamples(const vtkLightShaftFrame& frame)
{
  using Filter = vtkLightShaftSeparableFilter;
  const vtkLightShaftParameters& p = frame.Parameters;
  std::vector<double> weights{ 1.0 };
  const bool gathered =
    p.InterleaveSize > 1 && std::any_of(frame.Statistics.Lights.begin(),
                              frame.Statistics.Lights.end(),
                              [](const vtkLightShaftLightStatistics& light)
                              { return light.Method == vtkLightShaftEnums::RAY_MARCH; });
  if (gathered)
  {
    weights = Filter::Kernel::Gather(p.InterleaveSize).Weights();
  }
  if (p.BlurRadius > 0)
  {
    weights = Filter::Convolve(weights, Filter::Kernel::Blur(p.BlurRadius).Weights());
  }
  return Filter::EffectiveSamples(weights);
}
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftRefinement::Accumulate(vtkLightShaftFrame& frame,
  vtkTextureObject* estimate,
  bool rotates)
{
  if (!frame.Parameters.ProgressiveRefinement)
  {
    this->Estimates = 0;
    return estimate;
  }
  if (this->Converged)
  {
    return this->GetHistory();
  }
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const int next = this->Estimates == 0 ? this->Current : 1 - this->Current;
  vtkTextureObject* previous = this->History[this->Current].Object;
  vtkTextureObject* target = this->History[next].Ensure(frame.Window, TextureKind::RGBA32F, w, h);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { target },
    nullptr,
    w,
    h);
  vtkShaderProgram* program = this->Average.Ready(frame.Window, vtkLightShaftRefineFS);
  if (!program)
  {
    return estimate;
  }
  if (this->Estimates == 0 && this->HoldSource)
  {
    this->HoldPicture(frame, this->HoldSource); // before the estimate overwrites it
    program = this->Average.Ready(frame.Window, vtkLightShaftRefineFS);
    this->HoldSource = nullptr;
    vtkLightShaftResources::BindTargets(this->Framebuffer, { target }, nullptr, w, h);
  }
  // The first estimate reads no history (its weight is 1): the estimate stands in for it.
  vtkTextureObject* mean = (this->Estimates == 0 || !previous) ? nullptr : previous;
  estimate->Activate();
  program->SetUniformi("estimate", estimate->GetTextureUnit());
  if (mean)
  {
    mean->Activate();
  }
  program->SetUniformi("history", (mean ? mean : estimate)->GetTextureUnit());
  program->SetUniformf(
    "estimateWeight", mean ? 1.0f / static_cast<float>(this->Estimates + 1) : 1.0f);
  this->Average.Render();
  ++frame.Statistics.PostPasses;
  if (mean)
  {
    mean->Deactivate();
  }
  estimate->Deactivate();
  this->Current = next;
  ++this->Estimates;
  // (Samples that do not move converge with the first group: one frame of the setting.)
  this->Converged = (!rotates && this->Estimates >= this->Split) ||
                    this->Estimates >= frame.Parameters.RefinementFrames * this->Split;
  vtkTextureObject* picture = this->ChoosePicture(frame, previous, target);
  // (As a whole setting's second estimate, the second group is not shown until the third is
  // complete: ChoosePicture.)
  if (this->Split > 1 && this->Estimates % this->Split == 0 && !this->Converged &&
      this->Estimates != 2 * this->Split)
  {
    this->HoldPicture(frame, picture); // shown until the next group is complete
  }
  return this->IsHolding() ? this->Held.Object.Get() : picture;
}

//------------------------------------------------------------------------------
void vtkLightShaftRefinement::HoldPicture(vtkLightShaftFrame& frame, vtkTextureObject* source)
{
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  if (source == this->Held.Object)
  {
    this->Holding = true; // (already held)
    return;
  }
  if (static_cast<int>(source->GetWidth()) != w || static_cast<int>(source->GetHeight()) != h)
  {
    return; // (the same scene: the same viewport)
  }
  vtkTextureObject* held = this->Held.Ensure(frame.Window, TextureKind::RGBA32F, w, h);
  vtkLightShaftResources::BindTargets(this->Framebuffer, { held }, nullptr, w, h);
  vtkShaderProgram* copy = this->Average.Ready(frame.Window, vtkLightShaftRefineFS);
  if (!copy)
  {
    return;
  }
  source->Activate();
  copy->SetUniformi("estimate", source->GetTextureUnit());
  copy->SetUniformi("history", source->GetTextureUnit());
  copy->SetUniformf("estimateWeight", 1.0f);
  this->Average.Render();
  ++frame.Statistics.PostPasses;
  source->Deactivate();
  this->Holding = true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftRefinement::ChoosePicture(vtkLightShaftFrame& frame,
  vtkTextureObject* previous,
  vtkTextureObject* average)
{
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  // The picture: the first estimate as it was filtered, then the average filtered by what the
  // estimates do not yet average (at full resolution: a reduced pixel is DownsampleFactor wide).
  // Two estimates are not shown unless they are all (the first stays): the unshifted first
  // (lookups at the pieces' midpoints) averaged with one shifted estimate, whose first-order
  // errors no other yet cancels, was worse than the first alone on six of nine scenes and
  // settings, by up to 35% (five, up to 30%, with every estimate filtered:
  // docs/refinement-filters.md).
  // (A split setting's group of estimates is one frame of the setting: it counts as one.)
  const int frames = this->Estimates / this->Split;
  if (this->Estimates == 1)
  {
    this->FirstSamples = FirstFilterSamples(frame);
  }
  this->Sigma = frames > 1 ? PictureSigma(this->FirstSamples, frames) : 0.0;
  this->Sigma *= static_cast<double>(w) / frame.Reduced[0];
  this->Picture = average;
  if (this->Estimates == 2 && !this->Converged && this->Split == 1)
  {
    this->Picture = previous;
    this->Sigma = 0.0;
  }
  else if (this->Sigma > 0.0)
  {
    this->Picture = this->PictureFilter.Apply(frame,
      average,
      frame.Scene.ShaftDepth,
      vtkLightShaftSeparableFilter::Kernel::Gaussian(this->Sigma),
      w,
      h);
  }
  return this->Picture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftRefinement::GetHistory() const
{
  if (this->IsHolding())
  {
    return this->Held.Object.Get();
  }
  return this->Picture ? this->Picture : this->History[this->Current].Object.Get();
}

//------------------------------------------------------------------------------
void vtkLightShaftRefinement::Reset()
{
  this->HasLast = false;
  this->Estimates = 0;
  this->Converged = false;
  this->Picture = nullptr;
  this->Sigma = 0.0;
  this->HoldSource = nullptr;
  this->Holding = false;
  this->Split = 1;
}

void vtkLightShaftRefinement::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Reset();
  this->Held.Release(window);
  this->History[0].Release(window);
  this->History[1].Release(window);
  this->Average.Release(window);
  this->PictureFilter.ReleaseGraphicsResources(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
