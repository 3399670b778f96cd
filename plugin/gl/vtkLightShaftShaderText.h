/**
 * @file   vtkLightShaftShaderText.h
 * @brief  The pass's GLSL assembled (private, not installed): a variant's #defines and the
 *         shared chunks substituted into a shader's source. No uniforms, no GL objects: the
 *         programs (vtkLightShaftResources, vtkLightShaftShaders) build on it.
 */
#ifndef vtkLightShaftShaderText_h
#define vtkLightShaftShaderText_h

#include <string> // For the sources
#include <vector> // For the defines

namespace vtkLightShaftShaderText
{
/// The defines as "#define NAME" lines.
std::string JoinDefines(const std::vector<std::string>& defines);

/**
 * `source` with its features (//VTK::LightShaft::Features: the defines) and the shared chunks
 * substituted: //VTK::LightShaft::Common (the view ray), ::Integrand (medium, smooth factors),
 * ::Segment (one segment's integral, the lit interval), ::LightSpace (shadow map, cookie and
 * noise lookups), ::LightKind (where a light of the variant's kind shines, its distance r).
 */
std::string WithFeatures(const char* source, const std::vector<std::string>& defines);
}

#endif
