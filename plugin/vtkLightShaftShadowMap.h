/**
 * @file   vtkLightShaftShadowMap.h
 * @brief  The light's depth map for vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftShadowMap_h
#define vtkLightShaftShadowMap_h

#include "vtkLightShaftResources.h" // For the owned map
#include "vtkNew.h"                 // For the passes and camera held
#include "vtkSmartPointer.h"        // For the framebuffer held

#include <glm/glm.hpp> // For the light camera's matrix

class vtkCamera;
class vtkCameraPass;
class vtkImageData;
class vtkMatrix4x4;
class vtkOpaquePass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftShadowMap
 * @brief   Renders the shadow casters' depth from the light (the producer of the map the shafts
 *          consume), lets observers rewrite it, and reads it back.
 *
 * As vtkShadowMapBakerPass does for surfaces: the opaque step of the casters only (the props
 * whose bounds reach into the light's bounding pyramid), through VTK's own camera and opaque
 * passes, with the light camera vtkLightShaftGeometry::ComputeLightFrame set up. 32-bit float
 * depth, ShadowMapSize texels square (at most the GL's maximum texture size).
 */
class vtkLightShaftShadowMap
{
public:
  vtkLightShaftShadowMap();
  ~vtkLightShaftShadowMap();

  /// The light camera the map is rendered with.
  vtkCamera* GetLightCamera();

  /**
   * Render the map of `frame.Light`'s casters, then invoke `eventId` on `frame.Owner` (its
   * observers may read and rewrite the map: GetEventTexture). Returns false (and renders
   * nothing) when nothing can shadow the light's volume. Records what it did in the frame's
   * statistics.
   */
  bool Render(vtkLightShaftFrame& frame, unsigned long eventId);

  /**
   * Render the opaque step of the frame's casters into the depth texture `depth` (cleared),
   * seen by `camera`: the shadow map's, or another (the radial blur's guard band).
   */
  void RenderCasters(vtkLightShaftFrame& frame,
    vtkCamera* camera,
    vtkSmartPointer<vtkOpenGLFramebufferObject>& target,
    vtkTextureObject* depth);

  /// The map (valid after Render returned true).
  vtkTextureObject* GetTexture();
  /// The map while the event is being handled, nullptr at any other time.
  vtkTextureObject* GetEventTexture();
  /// The lookup's relative depth tolerance for the current map (two texels' worth of depth: a
  /// sample this close behind a caster's front face is inside the caster).
  double GetBias(const vtkLightShaftFrame& frame);

  /// The last map's depths (N x N floats, 1 = nothing) and world-to-light-clip matrix; false
  /// when none was rendered.
  bool ReadBack(vtkOpenGLRenderWindow* window,
    vtkImageData* depths,
    vtkMatrix4x4* worldToLightClip);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftShadowMap(const vtkLightShaftShadowMap&) = delete;
  void operator=(const vtkLightShaftShadowMap&) = delete;

  vtkNew<vtkCameraPass> CameraPass;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkCamera> LightCamera;
  vtkLightShaftResources::OwnedTexture Map;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTextureObject* EventTexture = nullptr;
  bool Valid = false;
  glm::dmat4 WorldToLightClip{ 1.0 };
};

#endif
