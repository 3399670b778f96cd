/**
 * @file   vtkLightShaftTranslucentPeel.h
 * @brief  Renders one layer of the translucent casters' transmittance as the light sees them,
 *         for vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftTranslucentPeel_h
#define vtkLightShaftTranslucentPeel_h

#include "vtkNew.h"              // For the translucent step held
#include "vtkOpenGLRenderPass.h" // For the base class (the props' shader replacements)

class vtkTextureObject;
class vtkTranslucentPass;

/**
 * @class   vtkLightShaftTranslucentPeel
 * @brief   The translucent step of the casters (VTK's own, through their mappers), with the
 *          fragment's colour replaced by the surface's transmittance and the nearest surface
 *          behind the previous layer and in front of the opaque casters kept.
 *
 * The rule (docs/translucent-and-volumes.md): a surface of opacity a (the fragment's, with its
 * scalars' and texture's alpha) and diffuse colour c (the mapper's: Diffuse times the colour
 * or the mapped scalars, clamped to [0, 1]) passes 1 - a (1 - c) of the light per channel:
 * a - the covered fraction - filters it through c, the rest passes. Opacity 0 passes all (VTK
 * discards such fragments: no layer), opacity 1 is an opaque prop (VTK renders it with the
 * opaque casters).
 *
 * (With the CAMERA rule it writes 1 - a instead: see SetRule.)
 *
 * Each fragment writes (transmittance, gl_FragCoord.z) into an RGBA32F target whose depth
 * buffer keeps the nearest; fragments at or behind the opaque casters' depth (OpaqueDepth), and
 * for a layer after the first at or in front of the previous layer's depth (PreviousLayer's
 * alpha), are discarded: front-to-back depth peeling in the light's view. The textures are
 * looked up at the fragment's position across the target, mapped into their rectangles
 * (origin and size in texture coordinates: a cube face's cell of an atlas).
 *
 * Its props' depth writes are switched on while it renders (vtkOpenGLActor's
 * GLDepthMaskOverride, as depth peeling does), and their keys restored after.
 */
class vtkLightShaftTranslucentPeel : public vtkOpenGLRenderPass
{
public:
  static vtkLightShaftTranslucentPeel* New();
  vtkTypeMacro(vtkLightShaftTranslucentPeel, vtkOpenGLRenderPass);

  /// The opaque casters' depth map and the rectangle of it the target covers.
  void SetOpaqueDepth(vtkTextureObject* depth, const float rect[4]);
  /// The previous layer (nullptr: this is the first) and the rectangle of it the target covers.
  void SetPreviousLayer(vtkTextureObject* layer, const float rect[4]);

  /**
   * What a fragment writes in rgb. LIGHT (the default): the light it passes, 1 - a (1 - c)
   * (the casters' rule). CAMERA: what VTK's blending keeps of what lies behind it, 1 - a (the
   * camera leg of the shafts behind it, as of the scene behind it).
   */
  enum Rule
  {
    LIGHT,
    CAMERA
  };
  void SetRule(Rule rule) { this->Kept = rule; }

  /// Render the translucent step of the state's props into its framebuffer (bound, cleared).
  void Render(const vtkRenderState* s) override;

  bool PostReplaceShaderValues(std::string& vertexShader,
    std::string& geometryShader,
    std::string& fragmentShader,
    vtkAbstractMapper* mapper,
    vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program,
    vtkAbstractMapper* mapper,
    vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkLightShaftTranslucentPeel();
  ~vtkLightShaftTranslucentPeel() override;

private:
  vtkLightShaftTranslucentPeel(const vtkLightShaftTranslucentPeel&) = delete;
  void operator=(const vtkLightShaftTranslucentPeel&) = delete;

  vtkNew<vtkTranslucentPass> TranslucentPass;
  vtkTextureObject* OpaqueDepth = nullptr;
  vtkTextureObject* PreviousLayer = nullptr;
  float OpaqueRect[4] = { 0.0f, 0.0f, 1.0f, 1.0f };
  float PreviousRect[4] = { 0.0f, 0.0f, 1.0f, 1.0f };
  float TargetSize[2] = { 1.0f, 1.0f };
  Rule Kept = LIGHT;
};

#endif
