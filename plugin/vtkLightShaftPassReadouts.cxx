// What the last frame did: vtkLightShaftPass's read-outs (its parameters and the frame's
// recipe are in vtkLightShaftPass.cxx).
#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"

#include "vtkLightShaftResources.h"
#include "vtkLightShaftShadowMap.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

#include <algorithm>

//------------------------------------------------------------------------------
// The last frame's lights.
const vtkLightShaftLightStatistics* vtkLightShaftPass::Internals::LastLight(int index) const
{
  return index >= 0 && index < static_cast<int>(this->LastLights.size()) ? &this->LastLights[index]
                                                                         : nullptr;
}

int vtkLightShaftPass::GetLastNumberOfUsedLights()
{
  return static_cast<int>(this->Impl->LastLights.size());
}

vtkLight* vtkLightShaftPass::GetLastUsedLight(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->Light.Get() : nullptr;
}

int vtkLightShaftPass::GetLastLightKind(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->Kind : -1;
}

int vtkLightShaftPass::GetLastLightMethod(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->Method : -1;
}

int vtkLightShaftPass::GetLastLightSlicesDrawn(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->SlicesDrawn : 0;
}

bool vtkLightShaftPass::GetLastLightShadowMapRendered(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light && light->ShadowMapRendered;
}

bool vtkLightShaftPass::GetLastLightShadowMapReused(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light && light->ShadowMapReused;
}

int vtkLightShaftPass::GetLastLightShadowCasters(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->ShadowCasters : 0;
}

double vtkLightShaftPass::GetLastLightTime(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->Time : -1.0;
}

double vtkLightShaftPass::GetLastLightFieldShadowBytes(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->FieldShadowBytes : 0.0;
}

double vtkLightShaftPass::GetLastLightFieldShadowBuildTime(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->FieldShadowBuildTime : 0.0;
}

int vtkLightShaftPass::GetLastLightTranslucentLayers(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->TranslucentLayers : 0;
}

double vtkLightShaftPass::GetLastLightTranslucentBytes(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  return light ? light->TranslucentBytes : 0.0;
}

//------------------------------------------------------------------------------
// What the frame did, as the pass's read-outs: per light, and the totals and first light's
// values the older read-outs report.
void vtkLightShaftPass::Internals::Publish(vtkLightShaftPass& self, const vtkLightShaftFrame& frame)
{
  const vtkLightShaftStatistics& stats = frame.Statistics;
  self.NumberOfRenderedProps = stats.RenderedProps;
  self.LastViewportSize[0] = std::max(frame.Size[0], 0);
  self.LastViewportSize[1] = std::max(frame.Size[1], 0);
  self.LastNumberOfSlabBatches = stats.SlabBatches;
  self.LastLatticeResolution = stats.LatticeResolution;
  self.LastNumberOfSteps = stats.NumberOfSteps;
  self.LastNumberOfPostPasses = stats.PostPasses;
  self.LastNumberOfSceneRenders = stats.SceneRenders;
  self.LastMultiSamples = stats.MultiSamples;
  self.LastPlainScene = stats.PlainScene;
  self.LastRendererFXAA = stats.RendererFXAA;
  self.LastSliceDepthRange[0] = stats.SliceDepthRange[0];
  self.LastSliceDepthRange[1] = stats.SliceDepthRange[1];
  self.LastRadialGuardBand = stats.RadialGuardBand;
  self.LastPredictedError = stats.PredictedError;
  self.LastErrorModelSetting = stats.ErrorModelSetting;
  self.LastRefinementEstimates = stats.RefinementEstimates;
  self.LastRefinementConverged = stats.RefinementConverged;
  self.LastInScatterReused = stats.InScatterReused;
  self.LastTimeBudget = stats.TimeBudget;
  self.LastPredictedFrameTime = stats.TimeBudget > 0.0 ? stats.PredictedFrameTime : -1.0;
  self.LastFrameTime = stats.FrameTime;
  self.LastDownsampleFactor = frame.Parameters.DownsampleFactor;
  self.LastDepthRangeInBeamWidths = stats.ErrorFeatures.DepthRangeInBeamWidths;
  self.LastBeamWidthInPixels = stats.ErrorFeatures.BeamWidthInPixels;
  self.LastOpticalDepth = stats.ErrorFeatures.OpticalDepth;
  self.LastShadowTexelInPixels = stats.ErrorFeatures.ShadowTexelInPixels;
  self.LastLightInView = stats.ErrorFeatures.LightInView;
  self.LastMethod = -1;
  self.LastNumberOfSlicesDrawn = 0;
  self.LastShadowMapRendered = false;
  self.LastNumberOfShadowCasters = 0;
  for (const vtkLightShaftLightStatistics& light : stats.Lights)
  {
    if (self.LastMethod < 0)
    {
      self.LastMethod = light.Method;
    }
    self.LastNumberOfSlicesDrawn += light.SlicesDrawn;
    self.LastNumberOfShadowCasters += light.ShadowCasters;
    const bool mapped = light.ShadowMapRendered || light.ShadowMapReused;
    if (mapped && !self.LastShadowMapRendered)
    {
      self.LastLightDepthRange[0] = light.LightDepthRange[0];
      self.LastLightDepthRange[1] = light.LightDepthRange[1];
      self.LastShadowBias = light.ShadowBias;
    }
    self.LastShadowMapRendered = self.LastShadowMapRendered || mapped;
  }
  self.Impl->LastLights = stats.Lights;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::GetInScatteredRadiance(vtkImageData* out)
{
  if (!out)
  {
    vtkErrorMacro("GetInScatteredRadiance: the output image is nullptr.");
    return false;
  }
  out->Initialize();
  Internals& impl = *this->Impl;
  const int w = this->LastViewportSize[0];
  const int h = this->LastViewportSize[1];
  if (!impl.Window || w < 1 || h < 1)
  {
    vtkErrorMacro("GetInScatteredRadiance: nothing has been rendered yet.");
    return false;
  }
  out->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("InScatteredRadiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  radiance->Fill(0.0);
  vtkTextureObject* final = impl.FinalInScatter;
  if (impl.InScatterValid && final && static_cast<int>(final->GetWidth()) == w &&
      static_cast<int>(final->GetHeight()) == h)
  {
    impl.Window->MakeCurrent();
    vtkOpenGLState* ostate = impl.Window->GetState();
    ostate->PushFramebufferBindings();
    vtkLightShaftResources::BindTargets(
      vtkLightShaftResources::EnsureFramebuffer(impl.ReadFramebuffer, impl.Window),
      { final },
      nullptr,
      w,
      h);
    impl.ReadFramebuffer->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, radiance->GetPointer(0));
    ostate->PopFramebufferBindings();
  }
  out->GetPointData()->SetScalars(radiance);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::GetLastShadowMap(vtkImageData* depths,
  vtkMatrix4x4* worldToLightClip,
  int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->LastLight(index);
  if (!depths || !worldToLightClip || !light || !light->Light ||
      !(light->ShadowMapRendered || light->ShadowMapReused))
  {
    return false;
  }
  return this->Impl->Lights.StateOf(light->Light)
    .ShadowMap.ReadBack(this->Impl->Window, depths, worldToLightClip);
}
