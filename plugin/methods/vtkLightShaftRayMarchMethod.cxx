#include "vtkLightShaftRayMarchMethod.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"
#include "vtkLightShaftSlabDrawer.h"

#include "vtkShaderProgram.h"

#include "vtkLightShaftRayMarchFS.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkLightShaftRayMarchMethod::vtkLightShaftRayMarchMethod(vtkLightShaftSlabDrawer& drawer)
  : Drawer(drawer)
{
}

vtkLightShaftRayMarchMethod::~vtkLightShaftRayMarchMethod() = default;

// (Without the gather, each pixel's offset still differs from its neighbours': refinement's
// picture averages them in its own filter.)
bool vtkLightShaftRayMarchMethod::Gathers(const vtkLightShaftFrame& frame)
{
  return frame.Parameters.InterleaveSize > 1 && !frame.Unfiltered;
}

bool vtkLightShaftRayMarchMethod::AddsIntoTarget(const vtkLightShaftFrame& frame) const
{
  return !Gathers(frame); // the gather writes another texture
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftRayMarchMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  vtkTextureObject* shadowMap = nullptr;
  vtkLightShaftShaders::Variant variant;
  if (!this->PrepareMarch(frame, lit, "LIGHTSHAFT_RAY_MARCH", this->Footprints, shadowMap, variant))
  {
    return nullptr;
  }
  vtkShaderProgram* program = this->ReadySlabProgram(frame, vtkLightShaftRayMarchFS, variant);
  if (!program)
  {
    return nullptr;
  }
  const int steps = this->StepsWithinBudget(frame);
  program->SetUniformi("numberOfSteps", steps);
  program->SetUniformi("interleaveSize", p.InterleaveSize);
  program->SetUniformf("samplingRotation", static_cast<float>(frame.SamplingRotation));
  program->SetUniformi("sampleShare", frame.RefinementSplit);
  program->SetUniformi("samplePart", frame.SamplePart);

  target.Bind();
  vtkLightShaftSlabDrawer::Slabs slabs =
    vtkLightShaftSlabDrawer::Slabs::Over(lit, this->Footprints, target.GetDepth());
  slabs.ShadowMap = shadowMap;
  slabs.ShadowBias = shadowMap ? frame.LightStatistics->ShadowBias : 0.0;
  slabs.Rows = frame.ComputeRows;
  if (frame.ComputeRows && Gathers(frame))
  {
    // The gather averages InterleaveSize rows on each side: the piece's rows need them too.
    this->GatherRows =
      vtkLightShaftGeometry::GrowRows(*frame.ComputeRows, p.InterleaveSize, frame.Reduced[1]);
    slabs.Rows = &this->GatherRows;
  }
  this->Drawer.Draw(frame, program, slabs);
  frame.LightStatistics->SlicesDrawn = static_cast<int>(this->Footprints.size());

  vtkTextureObject* marched = target.GetAccumulation(0);
  if (Gathers(frame))
  {
    // The gather: an unweighted, depth-aware mean over InterleaveSize consecutive pixels, in
    // x then in y.
    marched = this->Gather.Apply(frame, marched, target.GetDepth(), 0, p.InterleaveSize);
  }
  return marched;
}

//------------------------------------------------------------------------------
void vtkLightShaftRayMarchMethod::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SlabProgram.Release();
  this->Gather.ReleaseGraphicsResources(window);
}
