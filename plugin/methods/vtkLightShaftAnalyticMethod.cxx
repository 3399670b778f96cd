#include "vtkLightShaftAnalyticMethod.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"
#include "vtkLightShaftSlabDrawer.h"

#include "vtkShaderProgram.h"

#include "vtkLightShaftAnalyticFS.h"

//------------------------------------------------------------------------------
vtkLightShaftAnalyticMethod::vtkLightShaftAnalyticMethod(vtkLightShaftSlabDrawer& drawer)
  : Drawer(drawer)
{
}

vtkLightShaftAnalyticMethod::~vtkLightShaftAnalyticMethod() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftAnalyticMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  return this->RenderUnshadowed(frame, lit, target, this->GetName());
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftAnalyticMethod::RenderUnshadowed(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target,
  const char* methodName)
{
  this->Footprints = vtkLightShaftGeometry::ComputeSlabFootprints(lit, frame.Camera, 1, false);
  if (this->Footprints.empty())
  {
    return nullptr;
  }
  vtkLightShaftShaders::Variant variant =
    vtkLightShaftShaders::IntegrandVariant(methodName, "LIGHTSHAFT_ANALYTIC", frame, false);
  variant.Description += FloatAccumulation(frame.Parameters);
  vtkShaderProgram* program = this->ReadySlabProgram(frame, vtkLightShaftAnalyticFS, variant);
  if (!program)
  {
    return nullptr;
  }
  // Cookie and noise vary across the light's square: 16 pieces at least sample them.
  program->SetUniformi("analyticPieces", (frame.Cookie || frame.Noise) ? 16 : 4);
  program->SetUniformf("maximumSigmaT", static_cast<float>(frame.Medium.MaximumSigmaT()));

  target.Bind();
  vtkLightShaftSlabDrawer::Slabs slabs =
    vtkLightShaftSlabDrawer::Slabs::Over(lit, this->Footprints, target.GetDepth());
  slabs.Rows = frame.ComputeRows; // (nullptr inside RADIAL_BLUR: it needs the whole image)
  this->Drawer.Draw(frame, program, slabs);
  frame.LightStatistics->SlicesDrawn = static_cast<int>(this->Footprints.size());
  return target.GetAccumulation(0);
}

//------------------------------------------------------------------------------
void vtkLightShaftAnalyticMethod::ReleaseGraphicsResources(vtkWindow*)
{
  this->SlabProgram.Release();
}
