// What the pass reads out: its parameters (PrintSelf), what the last frame left to read back
// (the in-scatter and shadow maps, the shader variants its report names), and the textures an
// image piece's observers exchange (its parameters' setters and the frame's recipe are in
// vtkLightShaftPass.cxx; the report itself is vtkLightShaftFrameReport).
#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftMethod.h"
#include "vtkLightShaftResources.h"
#include "vtkLightShaftShadowMap.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkLight.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <algorithm>

//------------------------------------------------------------------------------
// The frame's shader variants: each light's, joined by "; " (the last readied program's while
// no light computed any).
std::string vtkLightShaftPass::Internals::ShaderVariants(const vtkLightShaftFrame& frame) const
{
  std::string variants;
  for (const vtkLightShaftLightStatistics& light : frame.Statistics.Lights)
  {
    if (!light.ShaderVariant.empty())
    {
      variants += (variants.empty() ? "" : "; ") + light.ShaderVariant;
    }
  }
  const vtkLightShaftMethod* method = this->InScatter.GetShaderMethod();
  if (variants.empty() && method)
  {
    variants = method->GetShaderVariant();
  }
  return variants;
}

const char* vtkLightShaftPass::Internals::ShaderSource() const
{
  const vtkLightShaftMethod* method = this->InScatter.GetShaderMethod();
  return method ? method->GetShaderSource().c_str() : "";
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
  const int w = impl.LastFrame->GetViewportSize()[0];
  const int h = impl.LastFrame->GetViewportSize()[1];
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
  vtkLightShaftFrameReport* report = this->Impl->LastFrame;
  vtkLight* light = report->GetUsedLight(index);
  if (!depths || !worldToLightClip || !light ||
      !(report->GetLightShadowMapRendered(index) || report->GetLightShadowMapReused(index)))
  {
    return false;
  }
  return this->Impl->Lights.StateOf(light).ShadowMap.ReadBack(
    this->Impl->Window, depths, worldToLightClip);
}

//------------------------------------------------------------------------------
vtkLightShaftReferenceInput vtkLightShaftPassReferenceInput(vtkLightShaftPass* pass)
{
  vtkLightShaftReferenceInput input;
  for (int i = 0; i < pass->GetNumberOfLights(); ++i)
  {
    input.Lights.push_back(pass->GetLight(i));
  }
  input.Medium = pass->GetMedium();
  input.Cookie = pass->GetCookie();
  input.CasterBoundsGiven = pass->GetShadowCasterBounds(input.CasterBounds);
  // (The report's depth range and bias are its first mapped light's: one light only.)
  input.LastShadowMap = [pass](vtkLight* light,
                          vtkImageData* depths,
                          vtkMatrix4x4* worldToLightClip,
                          double depthRange[2],
                          double& bias)
  {
    vtkLightShaftFrameReport* last = pass->GetLastFrame();
    for (int i = 0; i < last->GetNumberOfUsedLights(); ++i)
    {
      if (last->GetUsedLight(i) == light)
      {
        if (!pass->GetLastShadowMap(depths, worldToLightClip, i))
        {
          return false;
        }
        depthRange[0] = last->GetLightDepthRange()[0];
        depthRange[1] = last->GetLightDepthRange()[1];
        bias = last->GetShadowBias();
        return true;
      }
    }
    return false;
  };
  return input;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights: " << this->GetNumberOfLights() << " given\n";
  os << indent << "Medium: " << this->Impl->Medium.Get() << "\n";
  this->Impl->Medium->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "FitMediumToScene: " << this->FitMediumToScene << "\n";
  os << indent << "AttenuateScene: " << this->AttenuateScene << "\n";
  os << indent << "ShadowSurfaces: " << this->ShadowSurfaces << "\n";
  os << indent << "AttenuateSurfaceLight: " << this->AttenuateSurfaceLight << "\n";
  os << indent << "NumberOfSlices: " << this->NumberOfSlices << "\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "Cookie: " << this->Impl->Textures.GetCookie() << "\n";
  os << indent << "AutomaticSliceCount: " << this->AutomaticSliceCount << "\n";
  os << indent << "MaximumNumberOfSlices: " << this->MaximumNumberOfSlices << "\n";
  os << indent << "Jitter: " << this->Jitter << "\n";
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "LatticeResolution: " << this->LatticeResolution << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "InterleaveSize: " << this->InterleaveSize << "\n";
  os << indent << "RadialSamples: " << this->RadialSamples << "\n";
  os << indent << "EpipolarLines: " << this->EpipolarLines << "\n";
  os << indent << "EpipolarSamples: " << this->EpipolarSamples << "\n";
  os << indent << "EpipolarStep: " << this->EpipolarStep << "\n";
  os << indent << "LightVolumeResolution: " << this->LightVolumeResolution << "\n";
  os << indent << "TranslucentShadows: " << this->TranslucentShadows << "\n";
  os << indent << "TranslucentShadowLayers: " << this->TranslucentShadowLayers << "\n";
  os << indent << "Decay: " << this->Decay << "\n";
  os << indent << "Density: " << this->Density << "\n";
  os << indent << "Weight: " << this->Weight << "\n";
  os << indent << "RadialJitter: " << this->RadialJitter << "\n";
  os << indent << "RadialGuardBand: " << this->RadialGuardBand << "\n";
  os << indent << "TargetError: " << this->TargetError << "\n";
  os << indent << "ProgressiveRefinement: " << this->ProgressiveRefinement << "\n";
  os << indent << "RefinementFrames: " << this->RefinementFrames << "\n";
  os << indent << "ExactFinish: " << this->ExactFinish << "\n";
  os << indent << "SplitLongFrames: " << this->SplitLongFrames << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
  os << indent << "UseAllocatedRenderTime: " << this->UseAllocatedRenderTime << "\n";
  os << indent << "PaintBackground: " << this->PaintBackground << "\n";
  os << indent << "PaintedBackground: " << this->PaintedBackground[0] << ", "
     << this->PaintedBackground[1] << ", " << this->PaintedBackground[2] << "\n";
  os << indent << "ImagePiece: " << this->ImagePiece << " of " << this->NumberOfImagePieces << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "DownsampleFactor: " << this->DownsampleFactor << "\n";
  os << indent << "AccumulationPrecision: " << this->AccumulationPrecision << "\n";
  os << indent << "LastFrame:\n";
  this->Impl->LastFrame->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
// The frame's props as the shafts model them: each visible prop of the render state, or the one
// its MODELLED_PROP key names (a distributed view's whole data); the view's props likewise, as
// a collection for the lights' casters.
vtkPropCollection* vtkLightShaftPass::Internals::ResolveModelledProps(vtkLightShaftFrame& frame)
{
  auto modelled = [](vtkProp* prop)
  {
    vtkInformation* keys = prop->GetPropertyKeys();
    return (keys && keys->Has(vtkLightShaftPass::MODELLED_PROP()))
             ? vtkProp::SafeDownCast(keys->Get(vtkLightShaftPass::MODELLED_PROP()))
             : prop;
  };
  frame.Props.clear();
  for (int i = 0; i < frame.State->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = modelled(frame.State->GetPropArray()[i]);
    if (prop && prop->GetVisibility())
    {
      frame.Props.push_back(prop);
    }
  }
  this->ModelledProps->RemoveAllItems();
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = frame.Renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (vtkProp* resolved = modelled(prop))
    {
      this->ModelledProps->AddItem(resolved);
    }
  }
  return this->ModelledProps;
}

//------------------------------------------------------------------------------
// The scene depth, which a distributed view composites, before the in-scatter; with image
// pieces, this process's rows.
void vtkLightShaftPass::Internals::BeginImagePiece(vtkLightShaftFrame& frame)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  frame.PieceRows.clear();
  if (p.ImagePieces > 1)
  {
    frame.PieceRows =
      vtkLightShaftGeometry::ImagePieceRows(p.ImagePiece, p.ImagePieces, frame.Reduced[1]);
    for (const vtkLightShaftGeometry::RowBlock& block : frame.PieceRows)
    {
      frame.Statistics.ImagePieceRows += block.End - block.First;
    }
    frame.Statistics.InScatterFragments = 0;
  }
  this->SceneDepthForEvent = frame.Scene.ShaftDepth;
  frame.Owner->InvokeEvent(vtkLightShaftEnums::SceneDepthReadyEvent);
  this->SceneDepthForEvent = nullptr;
}

vtkTextureObject* vtkLightShaftPass::GetSceneDepthTexture()
{
  return this->Impl->SceneDepthForEvent;
}

vtkTextureObject* vtkLightShaftPass::GetInScatterPieceTexture()
{
  return this->Impl->InScatterForEvent;
}
