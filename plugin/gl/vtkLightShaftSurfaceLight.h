/**
 * @file   vtkLightShaftSurfaceLight.h
 * @brief  The lights' shadows and cookie on the scene's surfaces, for vtkLightShaftPass
 *         (private, not installed).
 */

#ifndef vtkLightShaftSurfaceLight_h
#define vtkLightShaftSurfaceLight_h

#include "vtkLightShaftResources.h" // For the owned texture and passes
#include "vtkSmartPointer.h"        // For the framebuffer held

class vtkLight;
class vtkLightShaftSceneRenderer;
class vtkOpenGLFramebufferObject;
class vtkRenderPass;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftSurfaceLight
 * @brief   Takes away, from the scene's surfaces, the light their lights' shadow maps shadow and
 *          the cookie darkens: with any delegate, for every light kind.
 *
 * VTK's lighting has no shadows. For each light whose surface light must change (ShadowSurfaces,
 * where the light has a shadow map or the medium dims its way to the surfaces; or a cookie
 * shapes it), the scene is rendered again without that light, and a full-screen pass adds
 * (1 - visibility * cookie * transmittance) * (lit - unlit) into a float correction buffer
 * (multisampled like the scene, per sample), which the composite subtracts. The visibility is
 * the shafts' own shadow map, and the transmittance their light leg's (exp(-sigma_t times its
 * optical depth), from the field's table where they use it), so surfaces and shafts agree.
 * Costs one scene render and one full-screen pass per such light; nothing for the others.
 */
class vtkLightShaftSurfaceLight
{
public:
  vtkLightShaftSurfaceLight();
  ~vtkLightShaftSurfaceLight();

  /// Forget the last frame's correction (none until Add adds one).
  void Begin();

  /**
   * Add the frame's current light's correction (`light`, its shadow map `shadowMap` or nullptr,
   * the frame's cookie for it or none, and with `lightLeg` the medium's transmittance from the
   * light): renders the scene without the light through `scene`. Does nothing when there is
   * none of the three.
   */
  void Add(vtkLightShaftFrame& frame,
    vtkLightShaftSceneRenderer& scene,
    vtkRenderPass* delegate,
    vtkLight* light,
    vtkTextureObject* shadowMap,
    bool lightLeg);

  /// The correction this frame added up, nullptr when none.
  vtkTextureObject* GetCorrection();

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftSurfaceLight(const vtkLightShaftSurfaceLight&) = delete;
  void operator=(const vtkLightShaftSurfaceLight&) = delete;

  vtkLightShaftResources::OwnedTexture Correction;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  /// One pass per light kind, so that lights of several kinds do not rebuild it every frame.
  vtkLightShaftResources::FullScreenPass Pass[3];
  bool Added = false;
};

#endif
