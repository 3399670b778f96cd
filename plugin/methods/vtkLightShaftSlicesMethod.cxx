#include "vtkLightShaftSlicesMethod.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"
#include "vtkLightShaftShadowMap.h"
#include "vtkLightShaftSlabDrawer.h"

#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftGeometryBudget.h"
#include "vtkLightShaftResolveFS.h"
#include "vtkLightShaftSliceFS.h"

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftSlicesMethod::vtkLightShaftSlicesMethod(vtkLightShaftSlabDrawer& drawer)
  : Drawer(drawer)
{
}

vtkLightShaftSlicesMethod::~vtkLightShaftSlicesMethod() = default;

//------------------------------------------------------------------------------
TextureKind vtkLightShaftSlicesMethod::AccumulationKind(const vtkLightShaftParameters& parameters,
  int& buffers) const
{
  if (parameters.AccumulationPrecision == vtkLightShaftEnums::ACCUMULATE_8BIT)
  {
    buffers = 3; // one RGBA8 buffer per colour, every fourth slab in each channel
    return TextureKind::RGBA8;
  }
  return this->vtkLightShaftMethod::AccumulationKind(parameters, buffers);
}

bool vtkLightShaftSlicesMethod::AddsIntoTarget(const vtkLightShaftFrame& frame) const
{
  return frame.Parameters.AccumulationPrecision != vtkLightShaftEnums::ACCUMULATE_8BIT;
}

//------------------------------------------------------------------------------
// How many slabs: fixed, or (automatic) as many slabs of thickness far / maximum as the lit
// depth range needs.
int vtkLightShaftSlicesMethod::CountSlices(const vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  if (!p.AutomaticSliceCount)
  {
    return p.NumberOfSlices;
  }
  const double spacing = frame.Camera.FarDepth / p.MaximumNumberOfSlices;
  const int slices = static_cast<int>(std::ceil((lit.Deepest - lit.Nearest) / spacing - 1e-9));
  return std::max(1, std::min(slices, p.MaximumNumberOfSlices));
}

//------------------------------------------------------------------------------
int vtkLightShaftSlicesMethod::LatticeWithinBudget(vtkLightShaftFrame& frame, int slabs)
{
  const int requested = frame.Parameters.LatticeResolution;
  const int affordable =
    vtkLightShaftGeometry::AffordableLattice(requested, slabs, frame.RadiatingLights);
  if (SayReduction(affordable != requested, this->WarnedLatticeBudget))
  {
    vtkWarningWithObjectMacro(frame.Owner,
      "LatticeResolution " << requested << " over " << slabs << " slabs would be "
                           << static_cast<long long>(requested) * requested * slabs
                           << " lattice cells in a frame, more than the "
                           << vtkLightShaftGeometry::LatticeCellBudget << " allowed"
                           << SharedBy(frame) << ": using a lattice of " << affordable
                           << " (vtkLightShaftFrameReport::GetLatticeResolution).");
  }
  return affordable;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftSlicesMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int slices = this->SamplesWithinBudget(frame,
    p.AutomaticSliceCount ? "The automatic slice count" : "NumberOfSlices",
    this->CountSlices(frame, lit));
  // (A split setting's share draws every RefinementSplit-th of the setting's slabs.)
  const bool jitter = p.Jitter;
  this->Footprints = vtkLightShaftGeometry::ComputeSlabFootprints(
    lit, frame.Camera, slices, jitter, frame.RefinementSplit, frame.SamplePart);
  if (this->Footprints.empty())
  {
    return nullptr;
  }
  // The lattice of the whole setting's slabs (a share's keeps it).
  const int lattice = this->LatticeWithinBudget(frame, jitter ? slices + 1 : slices);
  frame.Statistics.LatticeResolution = lattice;

  // Shadow map of the casters (none when nothing can shadow).
  vtkTextureObject* shadowMap = frame.ShadowMap->Ready(frame);
  const bool shadows = shadowMap != nullptr;
  const bool eightBit = p.AccumulationPrecision == vtkLightShaftEnums::ACCUMULATE_8BIT;
  vtkLightShaftShaders::Variant variant =
    vtkLightShaftShaders::IntegrandVariant(this->GetName(), nullptr, frame, shadows);
  variant.Feature(jitter, "LIGHTSHAFT_JITTER", "jitter");
  variant.Feature(p.LatticeResolution > 0, "LIGHTSHAFT_LATTICE", "lattice");
  if (eightBit)
  {
    variant.Defines.emplace_back("LIGHTSHAFT_ACCUMULATE_8BIT");
  }
  variant.Description += eightBit ? " accumulate=8bit" : FloatAccumulation(p);
  vtkShaderProgram* program = this->ReadySlabProgram(frame, vtkLightShaftSliceFS, variant);
  if (!program)
  {
    return nullptr;
  }
  program->SetUniformf("samplingRotation", static_cast<float>(frame.SamplingRotation));
  program->SetUniformf("sampleWeight", static_cast<float>(frame.RefinementSplit));
  if (eightBit)
  {
    program->SetUniformf(
      "accumulationScale", static_cast<float>(p.Exposure > 0.0 ? p.Exposure : 1.0));
  }

  target.Bind();
  vtkLightShaftSlabDrawer::Slabs slabs =
    vtkLightShaftSlabDrawer::Slabs::Over(lit, this->Footprints, target.GetDepth(), slices);
  slabs.Lattice = lattice;
  slabs.LastSlab = jitter ? slices : slices - 1; // with jitter, one more slab
  slabs.LatticeShift = jitter ? -0.5 : 0.0;
  slabs.ShadowMap = shadowMap;
  slabs.ShadowBias = shadows ? frame.LightStatistics->ShadowBias : 0.0;
  slabs.Rows = frame.ComputeRows;
  this->Drawer.Draw(frame, program, slabs);
  frame.LightStatistics->SlicesDrawn = static_cast<int>(this->Footprints.size());
  return eightBit ? this->ResolveEightBit(frame, target) : target.GetAccumulation(0);
}

//------------------------------------------------------------------------------
// The 8-bit accumulation (the GDC 2004 trick): the four channels of each colour's RGBA8 buffer
// hold the partial sums of every fourth slab; add them and undo the display scale.
vtkTextureObject* vtkLightShaftSlicesMethod::ResolveEightBit(vtkLightShaftFrame& frame,
  vtkLightShaftInScatterTarget& target)
{
  const int lw = frame.Reduced[0];
  const int lh = frame.Reduced[1];
  vtkTextureObject* resolved = this->Resolved.Ensure(frame.Window, TextureKind::RGBA32F, lw, lh);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { resolved },
    nullptr,
    lw,
    lh);
  if (vtkShaderProgram* program = this->Resolve.Ready(frame.Window, vtkLightShaftResolveFS))
  {
    const char* names[3] = { "accumulatedRed", "accumulatedGreen", "accumulatedBlue" };
    for (int c = 0; c < 3; ++c)
    {
      target.GetAccumulation(c)->Activate();
      program->SetUniformi(names[c], target.GetAccumulation(c)->GetTextureUnit());
    }
    const double exposure = frame.Parameters.Exposure;
    program->SetUniformf(
      "inverseScale", static_cast<float>(1.0 / (exposure > 0.0 ? exposure : 1.0)));
    this->Resolve.Render();
    for (int c = 0; c < 3; ++c)
    {
      target.GetAccumulation(c)->Deactivate();
    }
  }
  return resolved;
}

//------------------------------------------------------------------------------
void vtkLightShaftSlicesMethod::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SlabProgram.Release();
  this->Resolve.Release(window);
  this->Resolved.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
