#include "vtkLightShaftShaderText.h"

#include "vtkShaderProgram.h"

#include "vtkLightShaftCameraLayers.h"
#include "vtkLightShaftCommon.h"
#include "vtkLightShaftField.h"
#include "vtkLightShaftIntegrand.h"
#include "vtkLightShaftLightKind.h"
#include "vtkLightShaftLightSpace.h"
#include "vtkLightShaftSegment.h"
#include "vtkLightShaftVolume.h"

namespace vtkLightShaftShaderText
{
//------------------------------------------------------------------------------
std::string JoinDefines(const std::vector<std::string>& defines)
{
  std::string features;
  for (const auto& define : defines)
  {
    features += "#define " + define + "\n";
  }
  return features;
}

std::string WithFeatures(const char* source, const std::vector<std::string>& defines)
{
  std::string out = source;
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Features", JoinDefines(defines));
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Common", vtkLightShaftCommon);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Integrand", vtkLightShaftIntegrand);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Segment", vtkLightShaftSegment);
  // Chunks the ones above use (each guarded against being included twice).
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::LightSpace", vtkLightShaftLightSpace);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::LightKind", vtkLightShaftLightKind);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Field", vtkLightShaftField);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Volume", vtkLightShaftVolume);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::CameraLayers", vtkLightShaftCameraLayers);
  return out;
}
}
