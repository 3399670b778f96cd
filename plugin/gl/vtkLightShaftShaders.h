/**
 * @file   vtkLightShaftShaders.h
 * @brief  The pass's shader variants and uniforms (private, not installed): feature variants
 *         as #defines, programs rebuilt only when their variant changes (their text assembled
 *         by vtkLightShaftShaderText), and the uniforms several shaders share set in one place.
 */

#ifndef vtkLightShaftShaders_h
#define vtkLightShaftShaders_h

#include <string> // For sources, keys and descriptions
#include <vector> // For the defines

class vtkLightShaftFieldTableTexture;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
struct vtkLightShaftFrame;

namespace vtkLightShaftGeometry
{
struct CameraFrame;
struct LightFrame;
}
namespace vtkLightShaftModel
{
struct Light;
}

namespace vtkLightShaftShaders
{
/**
 * A feature variant: the #defines a shader is compiled with, and their description as
 * vtkLightShaftFrameReport::GetShaderVariant reports it ("method=slices phase=isotropic shadow
 * cookie ...").
 */
struct Variant
{
  std::vector<std::string> Defines;
  std::string Description;

  /// Add `define` (and ` name` to the description) when `on`.
  void Feature(bool on, const char* define, const char* name);
};

/// The light's kind: its define (LIGHTSHAFT_POINT, LIGHTSHAFT_DIRECTIONAL; none for a spot)
/// and " light=spot|point|directional".
void AddLightKind(Variant& variant, const vtkLightShaftModel::Light& light);

/**
 * The variant of a method's slab shaders for the frame's current light: the method's define
 * (may be nullptr), the phase function, the light's kind, and the light-space features in use
 * (shadow, cookie, noise).
 */
Variant IntegrandVariant(const char* methodName,
  const char* methodDefine,
  const vtkLightShaftFrame& frame,
  bool shadows);

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

/// Where the light is and points (the LightKind chunk's uniforms), in view coordinates.
void SetLightUniforms(vtkShaderProgram* program, const vtkLightShaftGeometry::LightFrame& light);

/// The light and the medium (the integrand's uniforms), in view coordinates.
void SetIntegrandUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/// The samples of each optical depth through the density field (the light leg of each of
/// `viewSteps` steps, the eye's leg): the rule, in one place.
int DensitySteps(int viewSteps);

/// The density field's uniforms (LIGHTSHAFT_FIELD) and its texture, activated.
void SetDensityUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/// The camera leg's translucent layers (LIGHTSHAFT_CAMERA_LAYERS), their texture activated.
void SetCameraLayerUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/// The scene's volume's uniforms (LIGHTSHAFT_VOLUME), its textures activated.
void SetVolumeUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/// A light leg's table (a GLSL LightShaftTable uniform named `name`): its layout's uniforms.
void SetTableUniforms(vtkShaderProgram* program,
  const std::string& name,
  const vtkLightShaftFieldTableTexture& table,
  const vtkLightShaftFrame& frame);

/// The light leg's table through the field (LIGHTSHAFT_FIELD_SHADOW) and its texture, activated.
void SetFieldShadowUniforms(vtkShaderProgram* program, const vtkLightShaftFrame& frame);

/**
 * The LightSpace chunk's uniforms for the frame's current light and a target `width` pixels
 * wide: the light's square and footprints (cookie and noise levels), and with `shadowMap`
 * (activated here) the map's cameras and depth range.
 */
void SetLightSpaceUniforms(vtkShaderProgram* program,
  const vtkLightShaftFrame& frame,
  int width,
  vtkTextureObject* shadowMap);

/// The cookie texture (activated; clamped for a spot, repeating for a directional light) and
/// its size.
void SetCookieUniforms(vtkShaderProgram* program,
  vtkTextureObject* cookie,
  const vtkLightShaftModel::Light& light);
}

#endif
