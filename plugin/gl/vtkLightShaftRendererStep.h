/**
 * @file   vtkLightShaftRendererStep.h
 * @brief  The translucent and volumetric steps of the scene as VTK's own render draws them, for
 *         the pass's default delegate (private, not installed).
 */

#ifndef vtkLightShaftRendererStep_h
#define vtkLightShaftRendererStep_h

#include "vtkNew.h"          // For the plain steps held
#include "vtkRenderPass.h"   // For the base class
#include "vtkSmartPointer.h" // For the shadow passes, made when used

class vtkOpaquePass;
class vtkShadowMapPass;
class vtkTranslucentPass;
class vtkVolumetricPass;

/**
 * @class   vtkLightShaftRendererStep
 * @brief   A step of vtkRenderStepsPass drawn the way the renderer draws it without a pass.
 *
 * The OPAQUE step is the renderer's (vtkRenderer::DeviceRenderOpaqueGeometry: hidden line
 * removal where the renderer asks for it and wireframe props exist), or, with the renderer's
 * UseShadows on, VTK's shadow map baker and shadow map pass, as the renderer runs them (it then
 * draws no translucent geometry, and neither does the TRANSLUCENT step).
 * vtkRenderStepsPass draws translucent geometry by plain alpha blending (vtkTranslucentPass),
 * while VTK's own render chooses: order-independent translucency, or depth peeling where the
 * renderer asks for it (dual depth peeling taking the volumes along when
 * UseDepthPeelingForVolumes is on). The TRANSLUCENT step hands the translucent geometry to the
 * renderer's own choice (vtkRenderer::DeviceRenderTranslucentPolygonalGeometry, into the
 * render state's framebuffer), when some prop has any; the VOLUMETRIC step draws the volumes
 * unless its translucent step's depth peeling drew them already. A render with required keys
 * (an enclosing pass choosing its props) gets the plain steps.
 */
class vtkLightShaftRendererStep : public vtkRenderPass
{
public:
  static vtkLightShaftRendererStep* New();
  vtkTypeMacro(vtkLightShaftRendererStep, vtkRenderPass);

  enum Stage
  {
    OPAQUE,
    TRANSLUCENT,
    VOLUMETRIC
  };

  /**
   * Which step this is; a VOLUMETRIC step is told of the TRANSLUCENT one before it (not held:
   * both belong to the same owner).
   */
  void SetStage(Stage stage, vtkLightShaftRendererStep* translucent = nullptr);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// Whether the last TRANSLUCENT render's depth peeling drew the volumes too.
  bool GetPeeledVolumes() const { return this->PeeledVolumes; }

protected:
  vtkLightShaftRendererStep();
  ~vtkLightShaftRendererStep() override;

private:
  vtkLightShaftRendererStep(const vtkLightShaftRendererStep&) = delete;
  void operator=(const vtkLightShaftRendererStep&) = delete;

  void RenderOpaque(const vtkRenderState* s);
  void RenderTranslucent(const vtkRenderState* s);

  Stage Step = TRANSLUCENT;
  vtkLightShaftRendererStep* Translucent = nullptr;
  bool PeeledVolumes = false;
  vtkNew<vtkOpaquePass> PlainOpaque;
  vtkNew<vtkTranslucentPass> PlainTranslucent;
  vtkNew<vtkVolumetricPass> PlainVolumes;
  vtkSmartPointer<vtkShadowMapPass> Shadows;
};

#endif
