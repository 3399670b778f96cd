#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"

#include "vtkLightShaftComposite.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftEnums.h"
#include "vtkLightShaftErrorModel.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftInScatter.h"
#include "vtkLightShaftLightTextures.h"
#include "vtkLightShaftLights.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftResources.h"
#include "vtkLightShaftSceneRenderer.h"
#include "vtkLightShaftSetters.h"
#include "vtkLightShaftShadowMap.h"
#include "vtkLightShaftSurfaceLight.h"

#include "vtkCallbackCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkLight.h"
#include "vtkLightShaftGeometryLights.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderPass.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

namespace
{
constexpr double MaximumExposure = 1.0e6;
using vtkLightShaftSetters::RefuseNonFinite;
using vtkLightShaftSetters::SetClamped;
}

vtkStandardNewMacro(vtkLightShaftPass);
vtkInformationKeyMacro(vtkLightShaftPass, MODELLED_PROP, ObjectBase);

//------------------------------------------------------------------------------
vtkLightShaftPass::vtkLightShaftPass()
  : Impl(new Internals)
{
  this->Impl->Medium = vtkSmartPointer<vtkLightShaftMedium>::New();
}

//------------------------------------------------------------------------------
vtkLightShaftPass::~vtkLightShaftPass()
{
  // Free our GL objects even when nobody called ReleaseGraphicsResources (the window may still
  // be alive while the pass goes away).
  if (vtkOpenGLRenderWindow* window = this->Impl->Window)
  {
    window->MakeCurrent();
    this->Impl->ReleaseOwnResources(window);
  }
  this->Impl->Untrack();
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::ReleaseGraphicsResources(vtkWindow* w)
{
  // VTK's passes require a window (vtkRenderPass asserts one, in a VTK built with assertions).
  if (!w)
  {
    w = this->Impl->Window;
    if (!w)
    {
      return;
    }
    w->MakeCurrent();
  }
  this->Superclass::ReleaseGraphicsResources(w);
  this->Impl->ReleaseOwnResources(w);
}

//------------------------------------------------------------------------------
// Track the window whose context holds our GL objects. When it goes away first, free them
// while its context still exists (at DeleteEvent the window is still whole).
void vtkLightShaftPass::Internals::Track(vtkOpenGLRenderWindow* window)
{
  if (this->Window == window)
  {
    return;
  }
  if (this->Window)
  {
    // Objects made in another window's context cannot be used here.
    this->Window->MakeCurrent();
    this->ReleaseOwnResources(this->Window);
    window->MakeCurrent();
  }
  this->Untrack();
  this->Window = window;
  this->WindowDeleted->SetClientData(this);
  this->WindowDeleted->SetCallback(
    [](vtkObject* caller, unsigned long, void* clientData, void*)
    {
      auto* self = static_cast<Internals*>(clientData);
      auto* dying = static_cast<vtkOpenGLRenderWindow*>(caller);
      dying->MakeCurrent();
      self->ReleaseOwnResources(dying);
      self->Window = nullptr;
      self->WindowDeletedTag = 0;
      self->WindowRenderedTag = 0;
      self->WindowStartedTag = 0;
    });
  this->WindowDeletedTag = window->AddObserver(vtkCommand::DeleteEvent, this->WindowDeleted);
  // The exact finish's workers wait from the window's start of a frame to its end.
  this->WindowRendered->SetClientData(this);
  this->WindowRendered->SetCallback([](vtkObject*, unsigned long event, void* clientData, void*)
    { static_cast<Internals*>(clientData)->Finish.Hold(event == vtkCommand::StartEvent); });
  this->WindowStartedTag = window->AddObserver(vtkCommand::StartEvent, this->WindowRendered);
  this->WindowRenderedTag = window->AddObserver(vtkCommand::EndEvent, this->WindowRendered);
}

void vtkLightShaftPass::Internals::Untrack()
{
  if (this->Window && this->WindowDeletedTag)
  {
    this->Window->RemoveObserver(this->WindowDeletedTag);
    this->Window->RemoveObserver(this->WindowRenderedTag);
    this->Window->RemoveObserver(this->WindowStartedTag);
  }
  this->WindowDeletedTag = 0;
  this->WindowRenderedTag = 0;
  this->WindowStartedTag = 0;
  this->Window = nullptr;
}

void vtkLightShaftPass::Internals::ReleaseOwnResources(vtkWindow* w)
{
  this->Lights.ReleaseGraphicsResources(w);
  this->Scene.ReleaseGraphicsResources(w);
  this->Textures.ReleaseGraphicsResources(w);
  this->DensityTexture.ReleaseGraphicsResources(w);
  this->VolumeTexture.ReleaseGraphicsResources(w);
  this->InScatter.ReleaseGraphicsResources(w);
  this->SurfaceLight.ReleaseGraphicsResources(w);
  this->Composite.ReleaseGraphicsResources(w);
  this->Refinement.ReleaseGraphicsResources(w);
  this->Finish.ReleaseGraphicsResources(w);
  vtkLightShaftResources::ReleaseFramebuffer(this->ReadFramebuffer, w);
  this->FinalInScatter = nullptr;
  this->InScatterValid = false;
}

//------------------------------------------------------------------------------
// Parameters.
void vtkLightShaftPass::SetMedium(vtkLightShaftMedium* medium)
{
  if (!medium)
  {
    this->Impl->Medium = vtkSmartPointer<vtkLightShaftMedium>::New(); // (a fresh one)
  }
  else if (medium != this->Impl->Medium)
  {
    this->Impl->Medium = medium;
  }
  else
  {
    return;
  }
  this->Modified();
}

vtkLightShaftMedium* vtkLightShaftPass::GetMedium()
{
  return this->Impl->Medium;
}

vtkMTimeType vtkLightShaftPass::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Impl->Medium->GetMTime());
}

vtkLightShaftFrameReport* vtkLightShaftPass::GetLastFrame()
{
  return this->Impl->LastFrame;
}

void vtkLightShaftPass::SetExposure(double exposure)
{
  this->Impl->ExposureSet.Modified();
  SetClamped(this, "Exposure", &this->Exposure, { exposure }, 0.0, MaximumExposure);
}

void vtkLightShaftPass::SetFitMediumToScene(bool fit)
{
  this->Impl->FitPending = fit;
  if (fit)
  {
    this->Impl->FitRequested.Modified();
  }
  if (fit != this->FitMediumToScene)
  {
    this->FitMediumToScene = fit;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
// The medium and exposure from the scene's box and its first light (vtkLightShaftModel's
// rule), leaving what the user set since the request; once, when there is a scene and a light.
bool vtkLightShaftPass::FitMedium(vtkRenderer* renderer)
{
  Internals& impl = *this->Impl;
  vtkLightShaftMedium* medium = impl.Medium;
  double bounds[6];
  double given[6];
  const bool distributed = this->GetShadowCasterBounds(given);
  if (!vtkLightShaftModel::SceneBounds(
        renderer, distributed ? given : nullptr, medium->GetDensityField(), bounds))
  {
    return false;
  }
  std::vector<vtkLight*> requested;
  for (int i = 0; i < this->GetNumberOfLights(); ++i)
  {
    requested.push_back(this->GetLight(i));
  }
  for (vtkLight* light : vtkLightShaftModel::FindLights(requested, renderer))
  {
    const vtkLightShaftModel::Light model = vtkLightShaftModel::DescribeLight(light);
    if (!vtkLightShaftModel::UnusableLightValue(light).empty() || !model.Radiates())
    {
      continue;
    }
    const vtkMTimeType requestedAt = impl.FitRequested.GetMTime();
    impl.FitPending = false;
    if (medium->GetCoefficientsSetTime() < requestedAt)
    {
      const double sigma = vtkLightShaftModel::FittedScattering(bounds, model);
      medium->SetScatteringCoefficient(sigma);
      medium->SetAbsorptionCoefficient(0.0);
    }
    if (impl.ExposureSet.GetMTime() < requestedAt)
    {
      const double* sigmaS = medium->GetScatteringCoefficient();
      this->SetExposure(vtkLightShaftModel::FittedExposure(
        bounds, model, std::max(sigmaS[0], std::max(sigmaS[1], sigmaS[2]))));
    }
    return true;
  }
  return false;
}

void vtkLightShaftPass::SetRadialGuardBand(double extent)
{
  SetClamped(this, "RadialGuardBand", &this->RadialGuardBand, { extent }, 1.0, 4.0);
}

void vtkLightShaftPass::SetTimeBudget(double seconds)
{
  SetClamped(this, "TimeBudget", &this->TimeBudget, { seconds }, 0.0, 3600.0);
}

void vtkLightShaftPass::SetTargetError(double error)
{
  SetClamped(this, "TargetError", &this->TargetError, { error }, 0.0, 1.0);
}

const char* vtkLightShaftPass::GetErrorModelSettingName(int setting)
{
  return vtkLightShaftErrorModel::GetSettingName(setting);
}

void vtkLightShaftPass::SetDecay(double decay)
{
  SetClamped(this, "Decay", &this->Decay, { decay }, 0.0, 1.0);
}

void vtkLightShaftPass::SetDensity(double density)
{
  SetClamped(this, "Density", &this->Density, { density }, 0.0, 1.0);
}

void vtkLightShaftPass::SetWeight(double weight)
{
  SetClamped(this, "Weight", &this->Weight, { weight }, 0.0, 1.0);
}

const char* vtkLightShaftPass::GetMethodName(int method)
{
  return vtkLightShaftEnums::MethodName(method);
}

// The public enums are the layers' (vtkLightShaftEnums.h), for the wrappers to read.
namespace
{
constexpr bool Same(int a, int b)
{
  return a == b;
}
}
static_assert(Same(vtkLightShaftPass::SLICES, vtkLightShaftEnums::SLICES) &&
                Same(vtkLightShaftPass::RAY_MARCH, vtkLightShaftEnums::RAY_MARCH) &&
                Same(vtkLightShaftPass::RADIAL_BLUR, vtkLightShaftEnums::RADIAL_BLUR) &&
                Same(vtkLightShaftPass::ANALYTIC, vtkLightShaftEnums::ANALYTIC) &&
                Same(vtkLightShaftPass::AUTOMATIC, vtkLightShaftEnums::AUTOMATIC) &&
                Same(vtkLightShaftPass::EPIPOLAR, vtkLightShaftEnums::EPIPOLAR) &&
                Same(vtkLightShaftPass::LIGHT_VOLUME, vtkLightShaftEnums::LIGHT_VOLUME),
  "the methods' values");
static_assert(
  Same(vtkLightShaftPass::ACCUMULATE_FLOAT32, vtkLightShaftEnums::ACCUMULATE_FLOAT32) &&
    Same(vtkLightShaftPass::ACCUMULATE_FLOAT16, vtkLightShaftEnums::ACCUMULATE_FLOAT16) &&
    Same(vtkLightShaftPass::ACCUMULATE_8BIT, vtkLightShaftEnums::ACCUMULATE_8BIT),
  "the precisions' values");
static_assert(
  Same(vtkLightShaftPass::ShadowMapRenderedEvent, vtkLightShaftEnums::ShadowMapRenderedEvent) &&
    Same(vtkLightShaftPass::RefinementNeededEvent, vtkLightShaftEnums::RefinementNeededEvent) &&
    Same(vtkLightShaftPass::SceneDepthReadyEvent, vtkLightShaftEnums::SceneDepthReadyEvent) &&
    Same(vtkLightShaftPass::InScatterPieceEvent, vtkLightShaftEnums::InScatterPieceEvent) &&
    Same(vtkLightShaftPass::ShadowMapReuseEvent, vtkLightShaftEnums::ShadowMapReuseEvent) &&
    Same(vtkLightShaftPass::FrameTimedEvent, vtkLightShaftEnums::FrameTimedEvent),
  "the events' ids");

namespace
{
// A preset is a setting of the error model's ladder, the one its training percentiles chose
// (tests/benchmarks/fit_error_model.py).
void ApplyQuality(vtkLightShaftPass* pass, vtkLightShaftErrorModel::Preset preset)
{
  const vtkLightShaftErrorModel::Setting& s = vtkLightShaftErrorModel::GetPreset(preset);
  pass->SetMethod(s.Method);
  pass->SetAutomaticSliceCount(false);
  if (s.Method == vtkLightShaftPass::SLICES)
  {
    pass->SetNumberOfSlices(s.Samples);
    pass->SetJitter(s.Jitter);
  }
  else if (s.Method == vtkLightShaftPass::LIGHT_VOLUME)
  {
    pass->SetLightVolumeResolution(s.Samples);
  }
  else
  {
    pass->SetNumberOfSteps(s.Samples);
    pass->SetInterleaveSize(s.InterleaveSize);
  }
  if (s.Method == vtkLightShaftPass::EPIPOLAR)
  {
    pass->SetEpipolarLines(s.EpipolarLines);
    pass->SetEpipolarSamples(s.EpipolarSamples);
    pass->SetEpipolarStep(s.EpipolarStep);
  }
  pass->SetShadowMapSize(s.ShadowMapSize);
  pass->SetBlurRadius(s.BlurRadius);
  pass->SetDownsampleFactor(s.DownsampleFactor);
  pass->SetAccumulationPrecision(vtkLightShaftPass::ACCUMULATE_FLOAT32);
}
}

void vtkLightShaftPass::SetQualityToDraft()
{
  ApplyQuality(this, vtkLightShaftErrorModel::Preset::Draft);
  this->MethodNamed = false;
}

void vtkLightShaftPass::SetQualityToInteractive()
{
  ApplyQuality(this, vtkLightShaftErrorModel::Preset::Interactive);
  this->MethodNamed = false;
}

void vtkLightShaftPass::SetQualityToFinal()
{
  ApplyQuality(this, vtkLightShaftErrorModel::Preset::Final);
  this->MethodNamed = false;
}

void vtkLightShaftPass::SetMethod(int method)
{
  method = std::min(std::max(method, static_cast<int>(SLICES)), static_cast<int>(LIGHT_VOLUME));
  if (method != this->Method || !this->MethodNamed)
  {
    this->Method = method;
    this->MethodNamed = true;
    this->Modified();
  }
}

void vtkLightShaftPass::SetDownsampleFactor(int factor)
{
  factor = factor >= 4 ? 4 : (factor >= 2 ? 2 : 1);
  if (factor != this->DownsampleFactor)
  {
    this->DownsampleFactor = factor;
    this->Modified();
  }
}

void vtkLightShaftPass::SetLight(vtkLight* light)
{
  if (this->Impl->Lights.Set(light))
  {
    this->Modified();
  }
}

void vtkLightShaftPass::AddLight(vtkLight* light)
{
  if (this->Impl->Lights.Add(light))
  {
    this->Modified();
  }
}

void vtkLightShaftPass::RemoveLight(vtkLight* light)
{
  if (this->Impl->Lights.Remove(light))
  {
    this->Modified();
  }
}

void vtkLightShaftPass::RemoveAllLights()
{
  if (this->Impl->Lights.RemoveAll())
  {
    this->Modified();
  }
}

int vtkLightShaftPass::GetNumberOfLights()
{
  return this->Impl->Lights.GetNumberOfGiven();
}

vtkLight* vtkLightShaftPass::GetLight()
{
  return this->Impl->Lights.GetGiven(0);
}

vtkLight* vtkLightShaftPass::GetLight(int index)
{
  return this->Impl->Lights.GetGiven(index);
}

void vtkLightShaftPass::SetCookie(vtkTexture* cookie)
{
  if (this->Impl->Textures.GetCookie() != cookie)
  {
    this->Impl->Textures.SetCookie(cookie);
    this->Modified();
  }
}

vtkTexture* vtkLightShaftPass::GetCookie()
{
  return this->Impl->Textures.GetCookie();
}

vtkTextureObject* vtkLightShaftPass::GetShadowMapTexture()
{
  vtkLightShaftLightState* state = this->Impl->Lights.GetEventState();
  return state ? state->ShadowMap.GetEventTexture() : nullptr;
}

void vtkLightShaftPass::SetShadowCasterBounds(const double bounds[6])
{
  if (RefuseNonFinite(this,
        "ShadowCasterBounds",
        { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] }))
  {
    return;
  }
  if (!this->UseShadowCasterBounds || !std::equal(bounds, bounds + 6, this->ShadowCasterBounds))
  {
    std::copy(bounds, bounds + 6, this->ShadowCasterBounds);
    this->UseShadowCasterBounds = true;
    this->Modified();
  }
}

void vtkLightShaftPass::SetPaintedBackground(double r, double g, double b)
{
  SetClamped(this, "PaintedBackground", this->PaintedBackground, { r, g, b }, 0.0, 1.0);
}

void vtkLightShaftPass::SetImagePiece(int piece, int numberOfPieces)
{
  const int pieces = std::max(numberOfPieces, 1);
  piece = std::min(std::max(piece, 0), pieces - 1);
  if (piece != this->ImagePiece || pieces != this->NumberOfImagePieces)
  {
    this->ImagePiece = piece;
    this->NumberOfImagePieces = pieces;
    this->Modified();
  }
}

void vtkLightShaftPass::UnsetShadowCasterBounds()
{
  if (this->UseShadowCasterBounds)
  {
    this->UseShadowCasterBounds = false;
    this->Modified();
  }
}

bool vtkLightShaftPass::GetShadowCasterBounds(double bounds[6])
{
  std::copy(this->ShadowCasterBounds, this->ShadowCasterBounds + 6, bounds);
  return this->UseShadowCasterBounds;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Render(const vtkRenderState* s)
{
  // Errors left by others are not ours: drain them, then count what this frame raises.
  for (int guard = 0; guard < 64 && glGetError() != GL_NO_ERROR; ++guard)
  {
  }
  this->RenderFrame(s);
  int count = 0;
  std::string names;
  for (GLenum error = glGetError(); error != GL_NO_ERROR && count < 64; error = glGetError())
  {
    ++count;
    names += std::string(names.empty() ? "" : ", ") + vtkOpenGLStrError(error);
  }
  this->Impl->LastFrame->SetGLErrorCount(count);
  if (count > 0)
  {
    vtkErrorMacro("OpenGL errors during the frame: " << names);
  }
}

//------------------------------------------------------------------------------
// The frame's recipe: the plain scene where one is needed, the scene unchanged when nothing
// scatters and no surface is shadowed, else the scene, each light's shafts and surface light,
// and their composite.
void vtkLightShaftPass::RenderFrame(const vtkRenderState* s)
{
  Internals& impl = *this->Impl;
  impl.InScatterValid = false;
  impl.FinalInScatter = nullptr;
  vtkLightShaftFrame frame;
  frame.Number = ++impl.FrameCounter;
  frame.MediumFitted = impl.FitPending && this->FitMedium(s->GetRenderer());
  // The frame's read-outs, with the shader variants it compiled.
  auto publish = [this, &impl](const vtkLightShaftFrame& done)
  {
    this->NumberOfRenderedProps = done.Statistics.RenderedProps;
    impl.LastFrame->Publish(done, impl.ShaderVariants(done).c_str(), impl.ShaderSource());
  };
  if (!impl.BeginFrame(*this, s, frame))
  {
    publish(frame);
    return;
  }
  if (vtkLightShaftSceneRenderer::NeedsPlainScene(s))
  {
    frame.Statistics.RenderedProps = impl.Scene.RenderPlain(this, this->DelegatePass, s);
    frame.Statistics.SceneRenders = 1;
    frame.Statistics.PlainScene = true;
    publish(frame);
    return;
  }
  if (frame.Size[0] < 1 || frame.Size[1] < 1)
  {
    // A viewport with no pixel shows nothing (and VTK's volume mappers raise GL errors when
    // asked to draw into one).
    publish(frame);
    return;
  }
  impl.Track(frame.Window);
  vtkRenderPass* delegate = impl.Scene.ChooseDelegate(this->DelegatePass);
  const std::vector<vtkLight*> lights = impl.Lights.Choose(this, frame.Renderer);
  impl.Lights.KeepOnly(lights, frame.Window);
  const bool medium = frame.Medium.Scatters() || frame.Medium.Extinguishes();
  const bool cameraUsable = impl.Check.CheckCamera(this, frame);
  impl.Check.CheckProps(this, frame);
  impl.Scene.HoldOverlay(delegate);
  if (lights.empty() || !(medium || this->ShadowSurfaces) || !cameraUsable || !frame.SceneInView)
  {
    impl.Scene.RenderUnchanged(frame, delegate); // nothing to add: the delegate's image
  }
  else
  {
    // The exact finish's workers wait while the frame renders, until the window's EndEvent.
    impl.Finish.Hold(true);
    impl.RenderShafts(frame, delegate, lights, this->ShadowSurfaces);
  }
  impl.Scene.FinishFrame(frame);
  publish(frame);
  if (frame.Statistics.RefinementEstimates > 0 && !frame.Statistics.RefinementConverged)
  {
    this->InvokeEvent(RefinementNeededEvent);
  }
}

//------------------------------------------------------------------------------
// The frame's context: the window, the viewport, the parameters and the camera.
bool vtkLightShaftPass::Internals::BeginFrame(vtkLightShaftPass& self,
  const vtkRenderState* s,
  vtkLightShaftFrame& frame)
{
  frame.Renderer = s->GetRenderer();
  frame.State = s;
  frame.Owner = &self;
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(frame.Renderer->GetRenderWindow());
  if (!frame.Window)
  {
    vtkErrorWithObjectMacro(&self, "vtkLightShaftPass needs an OpenGL render window.");
    return false;
  }
  if (vtkFrameBufferObjectBase* target = s->GetFrameBuffer())
  {
    target->GetLastSize(frame.Size[0], frame.Size[1]);
  }
  else
  {
    frame.Renderer->GetTiledSizeAndOrigin(
      &frame.Size[0], &frame.Size[1], &frame.Origin[0], &frame.Origin[1]);
  }
  frame.Parameters = Snapshot(self, *this->Medium);
  const int factor = frame.Parameters.DownsampleFactor;
  frame.Reduced[0] = (frame.Size[0] + factor - 1) / factor;
  frame.Reduced[1] = (frame.Size[1] + factor - 1) / factor;
  vtkLightShaftMedium* medium = this->Medium;
  frame.Medium = vtkLightShaftModel::DescribeMedium(medium->GetScatteringCoefficient(),
    medium->GetAbsorptionCoefficient(),
    medium->GetPhaseFunction(),
    medium->GetAnisotropy());
  frame.DensityScale = medium->GetDensityScale();
  frame.DensityBackground = medium->GetBackgroundDensity();

  // The scene camera, exactly as the mappers see it.
  auto* camera = vtkOpenGLCamera::SafeDownCast(frame.Renderer->GetActiveCamera());
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  vtkMatrix3x3* normals = nullptr;
  camera->GetKeyMatrices(frame.Renderer, wcvc, normals, vcdc, wcdc);
  frame.Camera = vtkLightShaftGeometry::CameraFrame::FromMatrices(
    vtkLightShaftGeometry::FromKeyMatrix(wcvc), vtkLightShaftGeometry::FromKeyMatrix(vcdc));
  // Rays that hit nothing end at the scene's backdrop, not at the far clipping plane.
  double bounds[6];
  if (vtkLightShaftModel::SceneBounds(
        frame.Renderer, frame.Parameters.ShadowCasterBounds, medium->GetDensityField(), bounds))
  {
    frame.Camera.FarDepth = vtkLightShaftModel::BackdropDepth(frame.Camera.WorldToView, bounds);
    frame.SceneInView = frame.Camera.FarDepth > 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkLightShaftParameters vtkLightShaftPass::Internals::Snapshot(vtkLightShaftPass& self,
  vtkLightShaftMedium& medium)
{
  vtkLightShaftParameters p;
  p.Method = self.Method;
  p.MethodNamed = self.MethodNamed;
  p.Exposure = self.Exposure;
  p.AttenuateScene = self.AttenuateScene;
  p.AttenuateSurfaceLight = self.AttenuateSurfaceLight;
  p.NumberOfSlices = self.NumberOfSlices;
  p.AutomaticSliceCount = self.AutomaticSliceCount;
  p.MaximumNumberOfSlices = self.MaximumNumberOfSlices;
  p.Jitter = self.Jitter;
  p.LatticeResolution = self.LatticeResolution;
  p.ShadowMapSize = self.ShadowMapSize;
  p.BlurRadius = self.BlurRadius;
  p.DownsampleFactor = self.DownsampleFactor;
  p.AccumulationPrecision = self.AccumulationPrecision;
  p.NoiseAmplitude = medium.GetNoiseAmplitude();
  p.NoiseScale = medium.GetNoiseScale();
  vtkLightShaftModel::NoiseShifts(
    medium.GetNoiseVelocity1(), medium.GetNoiseVelocity2(), medium.GetTime(), p.NoiseShift);
  p.NumberOfSteps = self.NumberOfSteps;
  p.InterleaveSize = self.InterleaveSize;
  p.RadialSamples = self.RadialSamples;
  p.EpipolarLines = self.EpipolarLines;
  p.EpipolarSamples = self.EpipolarSamples;
  p.EpipolarStep = self.EpipolarStep;
  p.LightVolumeResolution = self.LightVolumeResolution;
  p.MediumShadowResolution = medium.GetFieldShadowResolution();
  p.TranslucentLayers = self.TranslucentShadows ? self.TranslucentShadowLayers : 0;
  p.CameraLayers = self.TranslucentShadowLayers;
  p.Decay = self.Decay;
  p.Density = self.Density;
  p.Weight = self.Weight;
  p.RadialJitter = self.RadialJitter;
  p.RadialGuardBand = self.RadialGuardBand;
  p.ShadowCasterBounds = self.UseShadowCasterBounds ? self.ShadowCasterBounds : nullptr;
  p.PaintBackground = self.PaintBackground;
  p.PaintedBackground = self.PaintedBackground;
  p.ImagePiece = self.ImagePiece;
  p.ImagePieces = self.NumberOfImagePieces;
  p.TargetError = self.TargetError;
  p.ProgressiveRefinement = self.ProgressiveRefinement;
  p.RefinementFrames = self.RefinementFrames;
  p.ExactFinish = self.ExactFinish;
  p.SplitLongFrames = self.SplitLongFrames;
  p.TimeBudget = self.TimeBudget;
  p.UseAllocatedRenderTime = self.UseAllocatedRenderTime;
  return p;
}

//------------------------------------------------------------------------------
// The scene, each light's shafts and surface light, and the composite, in the target the pass
// draws into, with the GL state it changes restored.
void vtkLightShaftPass::Internals::RenderShafts(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  const std::vector<vtkLight*>& lights,
  bool shadowSurfaces)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable multisampleSaver(ostate, GL_MULTISAMPLE);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);

  // Each light's geometry first: with a target error it decides the frame's sampling.
  std::vector<vtkLightShaftGeometry::LightFrame> lightFrames;
  frame.RadiatingLights = 0;
  vtkPropCollection* modelled = this->ResolveModelledProps(frame);
  for (vtkLight* light : lights)
  {
    lightFrames.push_back(
      vtkLightShaftGeometry::ComputeLightFrame(vtkLightShaftModel::DescribeLight(light),
        frame.Camera,
        modelled,
        frame.Parameters.ShadowCasterBounds));
    frame.RadiatingLights += lightFrames.back().Model.Radiates() ? 1 : 0;
  }
  vtkTextureObject* cookie = this->ChooseSampling(frame, lights, lightFrames);
  // Under a frame budget the frame is measured (each part finished) for the cost model.
  const bool timed = frame.Statistics.TimeBudget > 0.0;
  using Clock = std::chrono::steady_clock;
  if (timed)
  {
    glFinish();
  }
  const Clock::time_point start = Clock::now();

  // The scene, with the samples of the target it is composited into.
  frame.Scene.Samples = vtkLightShaftResources::TargetSamples();
  frame.Statistics.MultiSamples = frame.Scene.Samples;
  frame.Scene.HighRange = shadowSurfaces || cookie;
  ostate->PushFramebufferBindings();
  this->Scene.Render(frame, delegate);

  // The converged picture needs no shafts computed, unless the surfaces need their light.
  this->SurfaceLight.Begin();
  bool computed = false;
  vtkTextureObject* inScatter = nullptr;
  double shafts = 0.0;
  // A still view's exact finish starts from the picture it has, which that frame shows again
  // (no long frame when the camera stops); then refinement goes on, the finished tiles replacing
  // its estimates, until the finish completes and supersedes them.
  const vtkLightShaftParameters& p = frame.Parameters;
  bool finishStarts = false;
  if (frame.ViewStill && p.ExactFinish && p.ProgressiveRefinement &&
      this->Refinement.GetEstimates() > 0)
  {
    finishStarts = !this->Finish.IsActive();
    this->Finish.Start(frame,
      vtkLightShaftPassReferenceInput(static_cast<vtkLightShaftPass*>(frame.Owner)),
      this->Refinement.GetHistory());
    finishStarts = finishStarts && this->Finish.IsActive();
  }
  using FinishState = vtkLightShaftExactFinish::State;
  if ((this->Refinement.IsConverged() || this->Finish.GetState() == FinishState::Complete ||
        finishStarts) &&
      !shadowSurfaces && !cookie)
  {
    inScatter = this->Refinement.GetHistory();
    computed = true;
    frame.Statistics.Lights = this->ComputedLights;
    frame.Statistics.InScatterReused = true;
  }
  else
  {
    if (timed)
    {
      glFinish();
    }
    const Clock::time_point shaftsStart = Clock::now();
    inScatter = this->ComputeInScatter(
      frame, delegate, lights, lightFrames, cookie, shadowSurfaces, computed);
    if (timed)
    {
      glFinish();
    }
    shafts = std::chrono::duration<double>(Clock::now() - shaftsStart).count();
  }
  inScatter = this->Finish.Apply(frame, inScatter, !frame.Statistics.InScatterReused);
  this->PublishRefinement(frame);
  this->FinalInScatter = inScatter;
  this->InScatterValid = computed;
  frame.Scene.SurfaceCorrection = this->SurfaceLight.GetCorrection();
  ostate->PopFramebufferBindings();

  const int* origin = frame.Origin;
  ostate->vtkglViewport(origin[0], origin[1], frame.Size[0], frame.Size[1]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(origin[0], origin[1], frame.Size[0], frame.Size[1]);
  this->Composite.Render(frame, inScatter);
  if (timed)
  {
    glFinish();
    this->ObserveFrameTime(
      frame, shafts, std::chrono::duration<double>(Clock::now() - start).count());
  }
}

//------------------------------------------------------------------------------
// The still view's state: converged once nothing more will change it (the exact finish done,
// or the estimates done with no finish running).
void vtkLightShaftPass::Internals::PublishRefinement(vtkLightShaftFrame& frame)
{
  using State = vtkLightShaftExactFinish::State;
  const State finish = this->Finish.GetState();
  frame.Statistics.RefinementEstimates = this->Refinement.GetEstimates();
  frame.Statistics.RefinementFilterWidth = this->Refinement.GetPictureSigma();
  frame.Statistics.RefinementSplit = this->Refinement.GetSplit();
  frame.Statistics.RefinementHeld = this->Refinement.IsHolding();
  if (this->Refinement.IsHoldingEarlierPicture())
  {
    // The picture shown is the moving frames' (the error model knows full resolution only).
    const vtkLightShaftCostModel::Choice& moving = this->MovingChoice;
    frame.Statistics.PredictedError = moving.DownsampleFactor == 1 ? moving.Error : -1.0;
  }
  // With the finish asked for, the picture is final only once it completes (or the scene turns
  // out to be one it cannot model): a view converged at its first frame is not yet still.
  const vtkLightShaftParameters& p = frame.Parameters;
  const bool awaited =
    p.ExactFinish && p.ProgressiveRefinement && (finish == State::Off || finish == State::Running);
  frame.Statistics.RefinementConverged =
    finish == State::Complete || (this->Refinement.IsConverged() && !awaited);
  frame.Statistics.ExactFinishState = static_cast<int>(finish);
  frame.Statistics.ExactFinishFraction = this->Finish.GetFinishedFraction();
  frame.Statistics.ExactFinishProblem = this->Finish.GetProblem();
  frame.Statistics.ExactFinishExhaustedPixels = this->Finish.GetExhaustedPixels();
  if (finish == State::Complete)
  {
    frame.Statistics.PredictedError = 0.0; // the reference's, to float rounding
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPass::Internals::ComputeInScatter(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  const std::vector<vtkLight*>& lights,
  std::vector<vtkLightShaftGeometry::LightFrame>& lightFrames,
  vtkTextureObject* cookie,
  bool shadowSurfaces,
  bool& computed)
{
  // The scene's volume dims the shafts behind it and the light through it.
  frame.Volume = this->VolumeTexture.Ready(frame, this->Medium->GetDensityVolume());
  frame.VolumeField = frame.Volume ? &this->VolumeTexture.GetField() : nullptr;
  frame.Statistics.Volume = frame.Volume ? this->VolumeTexture.GetVolume() : nullptr;
  this->BeginImagePiece(frame);
  // Each light: its in-scatter added to the others', its surface light corrected.
  this->InScatter.Begin(frame);
  frame.Statistics.Lights.resize(lights.size());
  bool rotates = false; // whether anything of this estimate moves with the next one's shifts
  for (size_t i = 0; i < lights.size(); ++i)
  {
    frame.LightStatistics = &frame.Statistics.Lights[i];
    this->RenderLight(
      frame, delegate, lights[i], std::move(lightFrames[i]), cookie, shadowSurfaces);
    // Samples that shift. (The shadow map's texel grid shifts too, but alone, for
    // LIGHT_VOLUME, it gains little: 0.39% -> 0.36% in 32 estimates on the sphere scene.)
    const int method = frame.Statistics.Lights[i].Method;
    rotates = rotates || method == RAY_MARCH || method == EPIPOLAR ||
              (method == SLICES && frame.Parameters.Jitter);
  }
  frame.LightStatistics = nullptr;
  this->ComputedLights = frame.Statistics.Lights;
  vtkTextureObject* inScatter = this->InScatter.Sum(frame, computed);
  if (computed)
  {
    if (frame.Parameters.ImagePieces > 1)
    {
      // The observers gather the pieces' rows (the lights summed, before the filters, which
      // read neighbouring rows).
      this->InScatterForEvent = inScatter;
      frame.Owner->InvokeEvent(vtkLightShaftEnums::InScatterPieceEvent);
      this->InScatterForEvent = nullptr;
    }
    inScatter = this->InScatter.PostProcess(frame, inScatter);
  }
  return this->Refinement.Accumulate(frame, inScatter, rotates);
}

//------------------------------------------------------------------------------
// One light: its frame (geometry, casters, shadow cameras), its in-scatter and its surface
// light, timed.
void vtkLightShaftPass::Internals::RenderLight(vtkLightShaftFrame& frame,
  vtkRenderPass* delegate,
  vtkLight* light,
  vtkLightShaftGeometry::LightFrame&& lightFrame,
  vtkTextureObject* cookie,
  bool shadowSurfaces)
{
  vtkLightShaftLightState& state = this->Lights.StateOf(light);
  vtkLightShaftLightStatistics& stats = *frame.LightStatistics;
  frame.Light = std::move(lightFrame);
  frame.ShadowMap = &state.ShadowMap;
  stats.Light = light;
  stats.Kind = static_cast<int>(frame.Light.Model.Kind);
  stats.ShadowCasters = static_cast<int>(frame.Light.Casters.size());
  // The cookie shapes spot and directional lights (a point light would need a cube of them).
  const bool point = frame.Light.Model.Kind == vtkLightShaftModel::LightKind::Point;
  frame.Cookie = point ? nullptr : cookie;
  if (point && cookie && !this->WarnedPointCookie)
  {
    vtkWarningWithObjectMacro(frame.Owner,
      "The cookie shapes spot and directional lights only: point light " << light << " gets none.");
    this->WarnedPointCookie = true;
  }

  const bool timed = vtkOpenGLRenderTimer::IsSupported();
  if (timed)
  {
    state.Timer.ReusableStart();
  }
  this->ReadyVolumeShadow(frame, state.VolumeShadow); // (the shafts' and the surfaces')
  // The surfaces' light leg through the medium (its field's table, as the shafts').
  const bool lightLeg =
    shadowSurfaces && frame.Parameters.AttenuateSurfaceLight && frame.Medium.Extinguishes();
  if (frame.Medium.Scatters() || lightLeg)
  {
    this->ReadyFieldShadow(frame, state.FieldShadow, state.RefinedFieldShadow);
  }
  if (frame.Medium.Scatters())
  {
    this->InScatter.Add(frame, this->InScatter.ChooseMethod(frame));
  }
  if (shadowSurfaces || frame.Cookie)
  {
    vtkTextureObject* map = shadowSurfaces ? frame.ShadowMap->Ready(frame) : nullptr;
    this->SurfaceLight.Add(frame, this->Scene, delegate, light, map, lightLeg);
  }
  if (timed)
  {
    state.Timer.ReusableStop();
    const double seconds = state.Timer.GetReusableElapsedSeconds();
    stats.Time = seconds > 0.0 ? 1e3 * seconds : -1.0;
  }
  frame.ShadowMap = nullptr;
  frame.Translucency = nullptr;
  frame.TranslucentLayers = 0;
  frame.FieldShadow = nullptr;
  frame.VolumeShadow = nullptr;
  frame.FieldShadowLayout = nullptr;
}
