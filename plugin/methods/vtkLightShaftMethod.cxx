#include "vtkLightShaftMethod.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShadowMap.h"

#include "vtkObject.h"

#include "vtkLightShaftGeometryBudget.h"
#include "vtkLightShaftSlabVS.h"

#include <algorithm>
#include <string>

//------------------------------------------------------------------------------
vtkLightShaftResources::TextureKind vtkLightShaftMethod::AccumulationKind(
  const vtkLightShaftParameters& parameters,
  int& buffers) const
{
  buffers = 1;
  return parameters.AccumulationPrecision == vtkLightShaftEnums::ACCUMULATE_FLOAT16
           ? vtkLightShaftResources::TextureKind::RGBA16F
           : vtkLightShaftResources::TextureKind::RGBA32F;
}

//------------------------------------------------------------------------------
const char* vtkLightShaftMethod::FloatAccumulation(const vtkLightShaftParameters& parameters)
{
  return parameters.AccumulationPrecision == vtkLightShaftEnums::ACCUMULATE_FLOAT16
           ? " accumulate=float16"
           : " accumulate=float32";
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLightShaftMethod::ReadySlabProgram(vtkLightShaftFrame& frame,
  const char* fragment,
  const vtkLightShaftShaders::Variant& variant)
{
  this->Variant = variant.Description;
  frame.ShaderMethod = this;
  return ReadySlabProgram(frame, this->SlabProgram, fragment, variant);
}

vtkShaderProgram* vtkLightShaftMethod::ReadySlabProgram(vtkLightShaftFrame& frame,
  vtkLightShaftShaders::Program& slabProgram,
  const char* fragment,
  const vtkLightShaftShaders::Variant& variant)
{
  vtkShaderProgram* program =
    slabProgram.Ready(frame.Window, vtkLightShaftSlabVS, fragment, variant);
  if (!program)
  {
    vtkErrorWithObjectMacro(frame.Owner, "Could not build the light-shaft slice shader.");
  }
  return program;
}

//------------------------------------------------------------------------------
bool vtkLightShaftMethod::PrepareMarch(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  const char* define,
  std::vector<vtkLightShaftGeometry::SlabFootprint>& footprints,
  vtkTextureObject*& shadowMap,
  vtkLightShaftShaders::Variant& variant) const
{
  footprints = vtkLightShaftGeometry::ComputeSlabFootprints(lit, frame.Camera, 1, false);
  if (footprints.empty())
  {
    return false;
  }
  shadowMap = frame.ShadowMap->Ready(frame);
  variant =
    vtkLightShaftShaders::IntegrandVariant(this->GetName(), define, frame, shadowMap != nullptr);
  variant.Description += FloatAccumulation(frame.Parameters);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftMethod::SayReduction(bool reduced, bool& warned)
{
  const bool say = reduced && !warned;
  warned = reduced;
  return say;
}

//------------------------------------------------------------------------------
std::string vtkLightShaftMethod::SharedBy(const vtkLightShaftFrame& frame)
{
  return frame.RadiatingLights > 1
           ? " (shared by " + std::to_string(frame.RadiatingLights) + " lights)"
           : std::string();
}

//------------------------------------------------------------------------------
int vtkLightShaftMethod::StepsWithinBudget(vtkLightShaftFrame& frame, long long rays)
{
  // (A split setting's share integrates a RefinementSplit-th of them: lightShaftMarch.)
  const int steps =
    this->SamplesWithinBudget(frame, "NumberOfSteps", frame.Parameters.NumberOfSteps, rays);
  int& recorded = frame.Statistics.NumberOfSteps;
  recorded = recorded > 0 ? std::min(recorded, steps) : steps;
  return steps;
}

//------------------------------------------------------------------------------
int vtkLightShaftMethod::SamplesWithinBudget(vtkLightShaftFrame& frame,
  const char* name,
  int requested,
  long long rays)
{
  const long long pixels =
    rays >= 0 ? rays : static_cast<long long>(frame.Reduced[0]) * frame.Reduced[1];
  const int affordable =
    vtkLightShaftGeometry::AffordableSamples(requested, pixels, frame.RadiatingLights);
  if (SayReduction(affordable != requested, this->WarnedSegmentBudget))
  {
    vtkWarningWithObjectMacro(frame.Owner,
      "" << name << " " << requested << " over " << pixels
         << (rays >= 0 ? " rays" : " in-scatter pixels") << " would be " << requested * pixels
         << " segments in a frame, more than the " << vtkLightShaftGeometry::SegmentBudget
         << " allowed" << SharedBy(frame) << ": using " << affordable << ".");
  }
  return affordable;
}
