#include "vtkLightShaftFrameReport.h"

#include "vtkLight.h"
#include "vtkLightShaftEnums.h"
#include "vtkLightShaftErrorModel.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftLights.h"
#include "vtkObjectFactory.h"
#include "vtkVolume.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <string>
#include <vector>

class vtkLightShaftFrameReport::Internals
{
public:
  std::vector<vtkLightShaftLightStatistics> Lights;
  std::string Variant;
  std::string Source;
  std::string ExactFinishProblem;
  vtkWeakPointer<vtkVolume> Volume;

  const vtkLightShaftLightStatistics* Light(int index) const
  {
    return index >= 0 && index < static_cast<int>(this->Lights.size()) ? &this->Lights[index]
                                                                       : nullptr;
  }
};

vtkStandardNewMacro(vtkLightShaftFrameReport);

vtkLightShaftFrameReport::vtkLightShaftFrameReport()
  : Impl(new Internals)
{
}

vtkLightShaftFrameReport::~vtkLightShaftFrameReport() = default;

//------------------------------------------------------------------------------
// The frame's values: per light, and the totals and first light's values the frame-wide
// read-outs report.
void vtkLightShaftFrameReport::Publish(const vtkLightShaftFrame& frame,
  const char* variant,
  const char* source)
{
  const vtkLightShaftStatistics& stats = frame.Statistics;
  this->ViewportSize[0] = std::max(frame.Size[0], 0);
  this->ViewportSize[1] = std::max(frame.Size[1], 0);
  this->NumberOfSlabBatches = stats.SlabBatches;
  this->LatticeResolution = stats.LatticeResolution;
  this->NumberOfSteps = stats.NumberOfSteps;
  this->LightVolumeResolution = stats.LightVolumeResolution;
  this->NumberOfPostPasses = stats.PostPasses;
  this->NumberOfSceneRenders = stats.SceneRenders;
  this->MultiSamples = stats.MultiSamples;
  this->PlainScene = stats.PlainScene;
  this->RendererFXAA = stats.RendererFXAA;
  this->SliceDepthRange[0] = stats.SliceDepthRange[0];
  this->SliceDepthRange[1] = stats.SliceDepthRange[1];
  this->BackdropDepth = frame.SceneInView ? frame.Camera.FarDepth : 0.0;
  this->MediumFitted = frame.MediumFitted;
  this->RadialGuardBand = stats.RadialGuardBand;
  this->ImagePieceRows = stats.ImagePieceRows;
  this->InScatterFragments = stats.InScatterFragments;
  this->PredictedError = stats.PredictedError;
  this->ErrorModelSetting = stats.ErrorModelSetting;
  this->RefinementEstimates = stats.RefinementEstimates;
  this->RefinementConverged = stats.RefinementConverged;
  this->RefinementFilterWidth = stats.RefinementFilterWidth;
  this->RefinementSplit = stats.RefinementSplit;
  this->RefinementHeld = stats.RefinementHeld;
  this->InScatterReused = stats.InScatterReused;
  this->ExactFinishState = stats.ExactFinishState;
  this->ExactFinishFraction = stats.ExactFinishFraction;
  this->Impl->ExactFinishProblem = stats.ExactFinishProblem;
  this->ExactFinishStopTime = stats.ExactFinishStopTime;
  this->ExactFinishExhaustedPixels = static_cast<vtkIdType>(stats.ExactFinishExhaustedPixels);
  this->CameraTranslucentLayers = stats.CameraLayers;
  this->CameraTranslucentBytes = stats.CameraLayerBytes;
  this->Impl->Volume = stats.Volume;
  this->TimeBudget = stats.TimeBudget;
  this->PredictedFrameTime = stats.TimeBudget > 0.0 ? stats.PredictedFrameTime : -1.0;
  this->FrameTime = stats.FrameTime;
  this->DownsampleFactor = frame.Parameters.DownsampleFactor;
  this->DepthRangeInBeamWidths = stats.ErrorFeatures.DepthRangeInBeamWidths;
  this->BeamWidthInPixels = stats.ErrorFeatures.BeamWidthInPixels;
  this->OpticalDepth = stats.ErrorFeatures.OpticalDepth;
  this->ShadowTexelInPixels = stats.ErrorFeatures.ShadowTexelInPixels;
  this->LightInView = stats.ErrorFeatures.LightInView;
  const std::vector<double>& field = stats.ErrorFeatures.FieldError;
  const int setting = stats.ErrorModelSetting;
  this->FieldError =
    setting >= 0 && setting < static_cast<int>(field.size()) ? field[setting] : -1.0;
  this->Method = -1;
  this->NumberOfSlicesDrawn = 0;
  this->ShadowMapRendered = false;
  this->NumberOfShadowCasters = 0;
  for (const vtkLightShaftLightStatistics& light : stats.Lights)
  {
    if (this->Method < 0)
    {
      this->Method = light.Method;
    }
    this->NumberOfSlicesDrawn += light.SlicesDrawn;
    this->NumberOfShadowCasters += light.ShadowCasters;
    const bool mapped = light.ShadowMapRendered || light.ShadowMapReused;
    if (mapped && !this->ShadowMapRendered)
    {
      this->LightDepthRange[0] = light.LightDepthRange[0];
      this->LightDepthRange[1] = light.LightDepthRange[1];
      this->ShadowBias = light.ShadowBias;
    }
    this->ShadowMapRendered = this->ShadowMapRendered || mapped;
  }
  this->Impl->Lights = stats.Lights;
  this->Impl->Variant = variant ? variant : "";
  this->Impl->Source = source ? source : "";
  this->Modified();
}

const char* vtkLightShaftFrameReport::GetExactFinishProblem()
{
  return this->Impl->ExactFinishProblem.c_str();
}

const char* vtkLightShaftFrameReport::GetShaderVariant()
{
  return this->Impl->Variant.c_str();
}

const char* vtkLightShaftFrameReport::GetSliceShaderSource()
{
  return this->Impl->Source.c_str();
}

//------------------------------------------------------------------------------
// Per used light.
int vtkLightShaftFrameReport::GetNumberOfUsedLights()
{
  return static_cast<int>(this->Impl->Lights.size());
}

vtkLight* vtkLightShaftFrameReport::GetUsedLight(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->Light.Get() : nullptr;
}

int vtkLightShaftFrameReport::GetLightKind(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->Kind : -1;
}

int vtkLightShaftFrameReport::GetLightMethod(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->Method : -1;
}

const char* vtkLightShaftFrameReport::GetLightMethodFallback(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->MethodFallback.c_str() : "";
}

int vtkLightShaftFrameReport::GetLightSlicesDrawn(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->SlicesDrawn : 0;
}

bool vtkLightShaftFrameReport::GetLightShadowMapRendered(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light && light->ShadowMapRendered;
}

bool vtkLightShaftFrameReport::GetLightShadowMapReused(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light && light->ShadowMapReused;
}

int vtkLightShaftFrameReport::GetLightShadowCasters(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->ShadowCasters : 0;
}

double vtkLightShaftFrameReport::GetLightTime(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->Time : -1.0;
}

double vtkLightShaftFrameReport::GetLightFieldShadowBytes(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->FieldShadowBytes : 0.0;
}

double vtkLightShaftFrameReport::GetLightFieldShadowBuildTime(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->FieldShadowBuildTime : 0.0;
}

double vtkLightShaftFrameReport::GetLightVolumeShadowBytes(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->VolumeShadowBytes : 0.0;
}

double vtkLightShaftFrameReport::GetLightVolumeShadowBuildTime(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->VolumeShadowBuildTime : 0.0;
}

vtkVolume* vtkLightShaftFrameReport::GetVolume()
{
  return this->Impl->Volume;
}

int vtkLightShaftFrameReport::GetLightTranslucentLayers(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->TranslucentLayers : 0;
}

double vtkLightShaftFrameReport::GetLightTranslucentBytes(int index)
{
  const vtkLightShaftLightStatistics* light = this->Impl->Light(index);
  return light ? light->TranslucentBytes : 0.0;
}

//------------------------------------------------------------------------------
void vtkLightShaftFrameReport::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << vtkLightShaftEnums::MethodName(this->Method) << "\n";
  os << indent << "ViewportSize: (" << this->ViewportSize[0] << ", " << this->ViewportSize[1]
     << ")\n";
  os << indent << "PlainScene: " << this->PlainScene << "\n";
  os << indent << "GLErrorCount: " << this->GLErrorCount << "\n";
  os << indent << "ImagePieceRows: " << this->ImagePieceRows << "\n";
  os << indent << "InScatterFragments: " << this->InScatterFragments << "\n";
  os << indent << "NumberOfSlicesDrawn: " << this->NumberOfSlicesDrawn << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "LightVolumeResolution: " << this->LightVolumeResolution << "\n";
  os << indent << "DownsampleFactor: " << this->DownsampleFactor << "\n";
  os << indent << "BackdropDepth: " << this->BackdropDepth << "\n";
  os << indent << "MediumFitted: " << this->MediumFitted << "\n";
  os << indent << "ShadowMapRendered: " << this->ShadowMapRendered << "\n";
  os << indent << "PredictedError: " << this->PredictedError << "\n";
  os << indent
     << "ErrorModelSetting: " << vtkLightShaftErrorModel::GetSettingName(this->ErrorModelSetting)
     << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
  os << indent << "FrameTime: " << this->FrameTime << "\n";
  os << indent << "RefinementEstimates: " << this->RefinementEstimates << "\n";
  os << indent << "RefinementConverged: " << this->RefinementConverged << "\n";
  os << indent << "RefinementFilterWidth: " << this->RefinementFilterWidth << "\n";
  os << indent << "RefinementSplit: " << this->RefinementSplit << "\n";
  os << indent << "RefinementHeld: " << this->RefinementHeld << "\n";
  os << indent << "ExactFinishState: " << this->ExactFinishState << "\n";
  os << indent << "ExactFinishFraction: " << this->ExactFinishFraction << "\n";
  os << indent << "ExactFinishProblem: " << this->Impl->ExactFinishProblem << "\n";
  os << indent << "ExactFinishStopTime: " << this->ExactFinishStopTime << "\n";
  os << indent << "ExactFinishExhaustedPixels: " << this->ExactFinishExhaustedPixels << "\n";
  os << indent << "UsedLights: " << this->Impl->Lights.size() << "\n";
  os << indent << "ShaderVariant: " << this->Impl->Variant << "\n";
}
