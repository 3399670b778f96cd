/**
 * @file   vtkLightShaftRadialBlurMethod.h
 * @brief  RADIAL_BLUR: screen-space radial blur of an occlusion buffer (private, not
 *         installed).
 */

#ifndef vtkLightShaftRadialBlurMethod_h
#define vtkLightShaftRadialBlurMethod_h

#include "vtkLightShaftMethod.h"    // For the base class
#include "vtkLightShaftResources.h" // For the owned textures and passes
#include "vtkNew.h"                 // For the guard band's camera
#include "vtkSmartPointer.h"        // For the framebuffers held

class vtkCamera;
class vtkLightShaftAnalyticMethod;
class vtkOpenGLFramebufferObject;

/**
 * @class   vtkLightShaftRadialBlurMethod
 * @brief   RADIAL_BLUR (GPU Gems 3, ch. 13): the unshadowed integral (ANALYTIC's) darkened by a
 *          radial walk of an occlusion buffer towards the light's screen position.
 *
 * The occlusion pre-pass runs at half the in-scatter resolution and marks surfaces inside the
 * cone nearer the light than the pixel's shaft; with RadialGuardBand > 1 the casters' depth is
 * rendered once more with the scene camera's frustum widened about its axis, so that occluders
 * off the screen still cut the shafts on it. The blur fades out as the light nears the camera
 * plane and is off behind it; it is skipped when nothing can occlude or Weight is 0.
 */
class vtkLightShaftRadialBlurMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftRadialBlurMethod(vtkLightShaftAnalyticMethod& unshadowed);
  ~vtkLightShaftRadialBlurMethod() override;

  const char* GetName() const override { return "radial-blur"; }
  bool AddsIntoTarget(const vtkLightShaftFrame&) const override { return false; }
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  static bool LightOnScreen(const vtkLightShaftFrame& frame, float lightUV[2], double& fade);
  static double DecayTotal(double decay, int samples);
  double GuardBand(const vtkLightShaftFrame& frame);
  vtkTextureObject* RenderOcclusion(vtkLightShaftFrame& frame,
    vtkTextureObject* depth,
    double guard);
  vtkTextureObject* Blur(vtkLightShaftFrame& frame,
    vtkTextureObject* unshadowed,
    vtkTextureObject* occlusion,
    const float lightUV[2],
    double fade,
    double guard);

  vtkLightShaftAnalyticMethod& Unshadowed;
  vtkNew<vtkCamera> GuardCamera;
  vtkLightShaftResources::OwnedTexture GuardDepth;
  vtkLightShaftResources::OwnedTexture OcclusionMask;
  vtkLightShaftResources::OwnedTexture Output;
  vtkLightShaftResources::FullScreenPass Occlusion;
  vtkLightShaftResources::FullScreenPass RadialBlur;
  vtkSmartPointer<vtkOpenGLFramebufferObject> GuardFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};

#endif
