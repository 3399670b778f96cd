/**
 * @file   vtkLightShaftShaders.h
 * @brief  Shader assembly for vtkLightShaftPass (private, not installed): feature variants as
 *         #defines, the shared GLSL chunks substituted, programs rebuilt only when their
 *         variant changes, and the uniforms several shaders share set in one place.
 */

#ifndef vtkLightShaftShaders_h
#define vtkLightShaftShaders_h

#include <string> // For sources, keys and descriptions
#include <vector> // For the defines

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
struct vtkLightShaftFrame;

namespace vtkLightShaftGeometry
{
struct CameraFrame;
}

namespace vtkLightShaftShaders
{
/// The defines as "#define NAME" lines.
std::string JoinDefines(const std::vector<std::string>& defines);

/**
 * `source` with its features (//VTK::LightShaft::Features: the defines) and the shared chunks
 * substituted: //VTK::LightShaft::Common (the view ray), ::Integrand (light, medium, cone, smooth
 * factors), ::Segment (light-space lookups, one segment's integral, the lit interval).
 */
std::string WithFeatures(const char* source, const std::vector<std::string>& defines);

/**
 * A feature variant: the #defines a shader is compiled with, and their description as
 * GetLastShaderVariant reports it ("method=slices phase=isotropic shadow cookie ...").
 */
struct Variant
{
  std::vector<std::string> Defines;
  std::string Description;

  /// Add `define` (and ` name` to the description) when `on`.
  void Feature(bool on, const char* define, const char* name);
};

/**
 * The variant of a method's slab shaders: the method's define (may be nullptr), the phase
 * function, and the light-space features in use this frame (shadow, cookie, noise).
 */
Variant IntegrandVariant(const char* methodName,
  const char* methodDefine,
  int phase,
  bool shadows,
  bool cookie,
  bool noise);

/**
 * A vertex + fragment program from the window's shader cache, rebuilt only when its variant
 * changes.
 */
class Program
{
public:
  /// The compiled program of `vertex` and `fragment` with `variant`, bound; nullptr when it
  /// does not compile.
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window,
    const char* vertex,
    const char* fragment,
    const Variant& variant);
  const std::string& GetFragmentSource() const { return this->FragmentSource; }
  /// Forget the program (the shader cache owns and frees it).
  void Release();

private:
  vtkShaderProgram* Shader = nullptr;
  std::string Key;
  std::string FragmentSource;
};

/// The view ray's uniforms: invProjectionDCVC and targetSize (a `width` x `height` target).
void SetViewUniforms(vtkShaderProgram* program,
  const vtkLightShaftGeometry::CameraFrame& camera,
  int width,
  int height);

/// The light and the medium (the integrand's uniforms), in view coordinates.
void SetIntegrandUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/// The light camera's clip coordinates and the footprints that pick cookie and noise levels,
/// for a target `width` pixels wide.
void SetLightSpaceUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame, int width);

/// The cookie texture (activated) and its size.
void SetCookieUniforms(vtkShaderProgram* program, vtkTextureObject* cookie);
}

#endif
