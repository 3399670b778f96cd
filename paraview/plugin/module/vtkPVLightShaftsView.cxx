#include "vtkPVLightShaftsView.h"
#include "vtkPVLightShaftsViewInternals.h"

#include "vtkCallbackCommand.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkLight.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkToneMappingPass.h"
#include "vtkVolume.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPVLightShaftsView);

//------------------------------------------------------------------------------
vtkPVLightShaftsView::vtkPVLightShaftsView()
  : Impl(new Internals)
{
  Internals& impl = *this->Impl;
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;

  // vtkPVRenderView keeps its vtkToneMappingPass private and swaps it in and out of the
  // synchronized renderers' one image-processing slot. Borrow it: with the slot empty, turning
  // tone mapping on puts exactly that pass there. The view's tone-mapping properties (Exposure,
  // Contrast, ...) keep going to it, and this view chains it after the shafts.
  if (!sync->GetImageProcessingPass())
  {
    this->Superclass::SetUseToneMapping(true);
    impl.ToneMapping = sync->GetImageProcessingPass();
    this->Superclass::SetUseToneMapping(false);
    if (sync->GetImageProcessingPass())
    {
      sync->SetImageProcessingPass(nullptr);
    }
  }
  if (!vtkToneMappingPass::SafeDownCast(impl.ToneMapping))
  {
    vtkWarningMacro("The render view's tone-mapping pass was not found; tone mapping uses a "
                    "pass of its own (the view's tone-mapping settings do not reach it).");
    impl.ToneMapping = vtkSmartPointer<vtkToneMappingPass>::New();
  }

  // IceT composites depth too, so the shafts stop at the nearest surface of any rank.
  sync->SetUseDepthBuffer(true);
  this->UpdateImageProcessing();

  // Distributed: every process's shadow map gets every process's occluders, and the processes
  // divide the in-scatter's rows (on process 0's composited depth, gathered there).
  vtkNew<vtkCallbackCommand> exchange;
  exchange->SetClientData(this);
  exchange->SetCallback([](vtkObject*, unsigned long event, void* self, void* data)
    { static_cast<vtkPVLightShaftsView*>(self)->Exchange(event, data); });
  for (unsigned long event : { vtkLightShaftPass::FrameTimedEvent,
         vtkLightShaftPass::ShadowMapReuseEvent,
         vtkLightShaftPass::ShadowMapRenderedEvent,
         vtkLightShaftPass::SceneDepthReadyEvent,
         vtkLightShaftPass::InScatterPieceEvent })
  {
    impl.Shafts->AddObserver(event, exchange);
  }

  vtkNew<vtkCallbackCommand> restoreFXAA;
  restoreFXAA->SetClientData(this);
  restoreFXAA->SetCallback(
    [](vtkObject* renderer, unsigned long, void* self, void*)
    {
      bool& restore = static_cast<vtkPVLightShaftsView*>(self)->Impl->RestoreRendererFXAA;
      if (restore)
      {
        static_cast<vtkRenderer*>(renderer)->SetUseFXAA(true);
        restore = false;
      }
    });
  this->GetRenderer()->AddObserver(vtkCommand::EndEvent, restoreFXAA);
}

//------------------------------------------------------------------------------
vtkPVLightShaftsView::~vtkPVLightShaftsView()
{
  this->Impl->Chain->RemoveAllPasses();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightShafts: " << this->LightShafts << "\n";
  os << indent << "ShaftLights:";
  for (int index : this->Impl->ShaftLights)
  {
    os << " " << index;
  }
  os << (this->Impl->ShaftLights.empty() ? " (automatic)\n" : "\n");
  os << indent << "ShaftQuality: " << this->ShaftQuality << "\n";
  os << indent << "LinkShaftTimeToAnimation: " << this->LinkShaftTimeToAnimation << "\n";
  os << indent << "ShaftTime: " << this->ShaftTime << "\n";
  os << indent << "DistributedShadowMap: " << this->DistributedShadowMap << "\n";
  os << indent << "CookieFileName: " << this->Impl->CookieFileName << "\n";
  os << indent << "LightShaftPass:\n";
  this->Impl->Shafts->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
vtkLightShaftPass* vtkPVLightShaftsView::GetLightShaftPass()
{
  return this->Impl->Shafts;
}

bool vtkPVLightShaftsView::GetRefinementConverged()
{
  return this->Impl->Shafts->GetLastFrame()->GetRefinementConverged();
}

int vtkPVLightShaftsView::GetRefinementEstimates()
{
  return this->Impl->Shafts->GetLastFrame()->GetRefinementEstimates();
}

double vtkPVLightShaftsView::GetLastTimeBudget()
{
  return this->Impl->Shafts->GetLastFrame()->GetTimeBudget();
}

double vtkPVLightShaftsView::GetLastPredictedError()
{
  return this->Impl->Shafts->GetLastFrame()->GetPredictedError();
}

int vtkPVLightShaftsView::GetExactFinishState()
{
  return this->Impl->Shafts->GetLastFrame()->GetExactFinishState();
}

double vtkPVLightShaftsView::GetExactFinishFraction()
{
  return this->Impl->Shafts->GetLastFrame()->GetExactFinishFraction();
}

const char* vtkPVLightShaftsView::GetExactFinishProblem()
{
  return this->Impl->Shafts->GetLastFrame()->GetExactFinishProblem();
}

const char* vtkPVLightShaftsView::GetLastShaderVariant()
{
  return this->Impl->Shafts->GetLastFrame()->GetShaderVariant();
}

double vtkPVLightShaftsView::GetLastMediumShadowBuildTime()
{
  return this->Impl->Shafts->GetLastFrame()->GetLightFieldShadowBuildTime(0);
}

double* vtkPVLightShaftsView::GetScatteringCoefficientInUse()
{
  return this->Impl->Shafts->GetMedium()->GetScatteringCoefficient();
}

double vtkPVLightShaftsView::GetShaftExposureInUse()
{
  return this->Impl->Shafts->GetExposure();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::UpdateImageProcessing()
{
  Internals& impl = *this->Impl;
  vtkImageProcessingPass* slot = nullptr;
  impl.Chain->RemoveAllPasses();
  if (this->LightShafts)
  {
    impl.Chain->AddPass(impl.Shafts);
    if (impl.UseToneMapping)
    {
      impl.Chain->AddPass(impl.ToneMapping);
    }
    slot = impl.Chain;
  }
  else if (impl.UseToneMapping)
  {
    slot = impl.ToneMapping;
  }
  if (this->SynchronizedRenderers->GetImageProcessingPass() == slot)
  {
    // Same slot, new chain: have the synchronized renderers link it again.
    this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
  }
  this->SynchronizedRenderers->SetImageProcessingPass(slot);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetLightShafts(bool enabled)
{
  if (this->LightShafts != enabled)
  {
    this->LightShafts = enabled;
    this->UpdateImageProcessing();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetUseToneMapping(bool use)
{
  this->UseToneMapping = use;
  if (this->Impl->UseToneMapping != use)
  {
    this->Impl->UseToneMapping = use;
    this->UpdateImageProcessing();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::UpdateLight()
{
  Internals& impl = *this->Impl;
  // Forget lights that went away.
  impl.Lights.erase(std::remove_if(impl.Lights.begin(),
                      impl.Lights.end(),
                      [](const vtkWeakPointer<vtkLight>& l) { return l == nullptr; }),
    impl.Lights.end());
  vtkLightShaftPass* shafts = impl.Shafts;
  shafts->RemoveAllLights(); // automatic unless a listed light exists
  for (int index : impl.ShaftLights)
  {
    if (index >= 1 && index <= static_cast<int>(impl.Lights.size()))
    {
      shafts->AddLight(impl.Lights[index - 1]);
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::AddShaftLight(int index)
{
  this->Impl->ShaftLights.push_back(index);
  this->UpdateLight();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::RemoveAllShaftLights()
{
  if (!this->Impl->ShaftLights.empty())
  {
    this->Impl->ShaftLights.clear();
    this->UpdateLight();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkPVLightShaftsView::GetNumberOfShaftLights() const
{
  return static_cast<int>(this->Impl->ShaftLights.size());
}

//------------------------------------------------------------------------------
int vtkPVLightShaftsView::GetShaftLight(int i) const
{
  const std::vector<int>& lights = this->Impl->ShaftLights;
  return (i >= 0 && i < static_cast<int>(lights.size())) ? lights[i] : 0;
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::AddLight(vtkLight* light)
{
  this->Superclass::AddLight(light);
  if (light)
  {
    this->Impl->Lights.emplace_back(light);
  }
  this->UpdateLight();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::RemoveLight(vtkLight* light)
{
  this->Superclass::RemoveLight(light);
  auto& lights = this->Impl->Lights;
  lights.erase(std::remove_if(lights.begin(),
                 lights.end(),
                 [light](const vtkWeakPointer<vtkLight>& l) { return l == light; }),
    lights.end());
  this->UpdateLight();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShadowSurfaces(bool shadow)
{
  this->Impl->Shafts->SetShadowSurfaces(shadow);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAttenuateSurfaceLight(bool attenuate)
{
  this->Impl->Shafts->SetAttenuateSurfaceLight(attenuate);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetTranslucentShadows(bool translucent)
{
  this->Impl->Shafts->SetTranslucentShadows(translucent);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetScatteringCoefficient(double r, double g, double b)
{
  this->Impl->Scattering[0] = r;
  this->Impl->Scattering[1] = g;
  this->Impl->Scattering[2] = b;
  this->Impl->Shafts->GetMedium()->SetScatteringCoefficient(r, g, b);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAbsorptionCoefficient(double r, double g, double b)
{
  this->Impl->Absorption[0] = r;
  this->Impl->Absorption[1] = g;
  this->Impl->Absorption[2] = b;
  this->Impl->Shafts->GetMedium()->SetAbsorptionCoefficient(r, g, b);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetFitMediumToScene(bool fit)
{
  Internals& impl = *this->Impl;
  if (fit != impl.FitMedium)
  {
    impl.FitMedium = fit;
    impl.FitAsked = false;
    if (!fit)
    {
      impl.Shafts->FitMediumToSceneOff();
      impl.GiveMedium(false);
    }
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetPhaseFunction(int phase)
{
  this->Impl->Shafts->GetMedium()->SetPhaseFunction(phase);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAnisotropy(double g)
{
  this->Impl->Shafts->GetMedium()->SetAnisotropy(g);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftExposure(double exposure)
{
  this->Impl->Exposure = exposure;
  this->Impl->Shafts->SetExposure(exposure);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftMethod(int method)
{
  this->Impl->Method = method;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetLatticeResolution(int resolution)
{
  this->Impl->Shafts->SetLatticeResolution(resolution);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNumberOfSteps(int steps)
{
  this->Impl->NumberOfSteps = steps;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetInterleaveSize(int size)
{
  this->Impl->InterleaveSize = size;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetRadialSamples(int samples)
{
  this->Impl->Shafts->SetRadialSamples(samples);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetEpipolarLines(int lines)
{
  this->Impl->Shafts->SetEpipolarLines(lines);
}

void vtkPVLightShaftsView::SetEpipolarSamples(int samples)
{
  this->Impl->Shafts->SetEpipolarSamples(samples);
}

void vtkPVLightShaftsView::SetEpipolarStep(int step)
{
  this->Impl->Shafts->SetEpipolarStep(step);
}

void vtkPVLightShaftsView::SetLightVolumeResolution(int cells)
{
  this->Impl->Shafts->SetLightVolumeResolution(cells);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetDecay(double decay)
{
  this->Impl->Shafts->SetDecay(decay);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetDensity(double density)
{
  this->Impl->Shafts->SetDensity(density);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetWeight(double weight)
{
  this->Impl->Shafts->SetWeight(weight);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetRadialJitter(bool jitter)
{
  this->Impl->Shafts->SetRadialJitter(jitter);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetRadialGuardBand(double extent)
{
  this->Impl->Shafts->SetRadialGuardBand(extent);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftTargetError(double error)
{
  this->Impl->Shafts->SetTargetError(error);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetTimeBudget(double seconds)
{
  this->Impl->Shafts->SetTimeBudget(seconds);
}

void vtkPVLightShaftsView::SetUseAllocatedRenderTime(bool use)
{
  this->Impl->Shafts->SetUseAllocatedRenderTime(use);
}

void vtkPVLightShaftsView::SetProgressiveRefinement(bool refine)
{
  this->Impl->Shafts->SetProgressiveRefinement(refine);
}

void vtkPVLightShaftsView::SetRefinementFrames(int frames)
{
  this->Impl->Shafts->SetRefinementFrames(frames);
}

void vtkPVLightShaftsView::SetExactFinish(bool finish)
{
  this->Impl->ExactFinish = finish; // (given to the pass before each render: not under MPI)
}

void vtkPVLightShaftsView::SetSplitLongFrames(bool split)
{
  this->Impl->Shafts->SetSplitLongFrames(split);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAttenuateScene(bool attenuate)
{
  this->Impl->Shafts->SetAttenuateScene(attenuate);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::UpdateQuality()
{
  Internals& impl = *this->Impl;
  vtkLightShaftPass* shafts = impl.Shafts;
  shafts->SetNumberOfSlices(impl.NumberOfSlices);
  shafts->SetShadowMapSize(impl.ShadowMapSize);
  shafts->SetAutomaticSliceCount(impl.AutomaticSliceCount);
  shafts->SetMaximumNumberOfSlices(impl.MaximumNumberOfSlices);
  shafts->SetJitter(impl.Jitter);
  shafts->SetBlurRadius(impl.BlurRadius);
  shafts->SetDownsampleFactor(impl.DownsampleFactor);
  shafts->SetAccumulationPrecision(impl.AccumulationPrecision);
  shafts->SetMethod(impl.Method);
  shafts->SetNumberOfSteps(impl.NumberOfSteps);
  shafts->SetInterleaveSize(impl.InterleaveSize);
  switch (this->ShaftQuality)
  {
    case DRAFT:
      shafts->SetQualityToDraft();
      break;
    case INTERACTIVE:
      shafts->SetQualityToInteractive();
      break;
    case FINAL:
      shafts->SetQualityToFinal();
      break;
    default:
      break;
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftQuality(int quality)
{
  quality = std::min(std::max(quality, static_cast<int>(CUSTOM)), static_cast<int>(FINAL));
  if (this->ShaftQuality != quality)
  {
    this->ShaftQuality = quality;
    this->UpdateQuality();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNumberOfSlices(int slices)
{
  this->Impl->NumberOfSlices = slices;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShadowMapSize(int size)
{
  this->Impl->ShadowMapSize = size;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAutomaticSliceCount(bool automatic)
{
  this->Impl->AutomaticSliceCount = automatic;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMaximumNumberOfSlices(int slices)
{
  this->Impl->MaximumNumberOfSlices = slices;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftJitter(bool jitter)
{
  this->Impl->Jitter = jitter;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftBlurRadius(int radius)
{
  this->Impl->BlurRadius = radius;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftDownsampleFactor(int factor)
{
  this->Impl->DownsampleFactor = factor;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetAccumulationPrecision(int precision)
{
  this->Impl->AccumulationPrecision = precision;
  this->UpdateQuality();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetCookieFileName(const char* fileName)
{
  Internals& impl = *this->Impl;
  const std::string name = fileName ? fileName : "";
  if (name == impl.CookieFileName)
  {
    return;
  }
  impl.CookieFileName = name;
  this->Modified();
  if (name.empty())
  {
    impl.Shafts->SetCookie(nullptr);
    return;
  }
  vtkSmartPointer<vtkImageReader2> reader;
  reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(name.c_str()));
  if (!reader)
  {
    vtkErrorMacro("Cannot read the cookie image '" << name << "': no reader for that file.");
    impl.Shafts->SetCookie(nullptr);
    return;
  }
  reader->SetFileName(name.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (!image || image->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("Cannot read the cookie image '" << name << "'.");
    impl.Shafts->SetCookie(nullptr);
    return;
  }
  vtkNew<vtkImageData> copy;
  copy->DeepCopy(image);
  vtkNew<vtkTexture> cookie;
  cookie->SetInputData(copy);
  impl.Shafts->SetCookie(cookie);
}

//------------------------------------------------------------------------------
const char* vtkPVLightShaftsView::GetCookieFileName()
{
  return this->Impl->CookieFileName.c_str();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNoiseAmplitude(double amplitude)
{
  this->Impl->Shafts->GetMedium()->SetNoiseAmplitude(amplitude);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNoiseScale(double scale)
{
  this->Impl->Shafts->GetMedium()->SetNoiseScale(scale);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNoiseVelocity1(double u, double v)
{
  this->Impl->Shafts->GetMedium()->SetNoiseVelocity1(u, v);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetNoiseVelocity2(double u, double v)
{
  this->Impl->Shafts->GetMedium()->SetNoiseVelocity2(u, v);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumFromVolume(bool on)
{
  if (on == this->MediumFromVolume)
  {
    return;
  }
  this->MediumFromVolume = on;
  if (!on)
  {
    this->Impl->Shafts->GetMedium()->SetDensityFieldConnection(this->Impl->DensityConnection);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumDensityArray(const char* name)
{
  this->Impl->FieldGather->SetArrayName(name);
  this->Impl->Shafts->GetMedium()->SetDensityArrayName(name);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumDensityScale(double scale)
{
  this->Impl->Shafts->GetMedium()->SetDensityScale(scale);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumBackgroundDensity(double density)
{
  this->Impl->Shafts->GetMedium()->SetBackgroundDensity(density);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumShadowResolution(int resolution)
{
  this->Impl->Shafts->GetMedium()->SetFieldShadowResolution(resolution);
}

void vtkPVLightShaftsView::SetMediumFieldResolution(int resolution)
{
  vtkLightShaftMedium* medium = this->Impl->Shafts->GetMedium();
  medium->SetFieldResolution(resolution);
  // Under MPI the pieces are resampled to the medium's grid as they are gathered.
  this->Impl->FieldGather->SetResolution(medium->GetFieldResolution());
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::UpdateTime()
{
  this->Impl->Shafts->GetMedium()->SetTime(
    this->LinkShaftTimeToAnimation ? this->Impl->ViewTime : this->ShaftTime);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetLinkShaftTimeToAnimation(bool link)
{
  if (this->LinkShaftTimeToAnimation != link)
  {
    this->LinkShaftTimeToAnimation = link;
    this->UpdateTime();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetShaftTime(double time)
{
  if (this->ShaftTime != time)
  {
    this->ShaftTime = time;
    this->UpdateTime();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetViewTime(double value)
{
  this->Superclass::SetViewTime(value);
  this->Impl->ViewTime = value;
  this->UpdateTime();
}
