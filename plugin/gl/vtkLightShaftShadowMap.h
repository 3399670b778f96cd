/**
 * @file   vtkLightShaftShadowMap.h
 * @brief  One light's depth map for vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftShadowMap_h
#define vtkLightShaftShadowMap_h

#include "vtkLightShaftResources.h"         // For the owned maps
#include "vtkLightShaftTranslucentLayers.h" // For the translucent casters' layers
#include "vtkNew.h"                         // For the passes and camera held
#include "vtkSmartPointer.h"                // For the framebuffers held
#include "vtkType.h"                        // For vtkMTimeType

#include <glm/glm.hpp> // For the light cameras' matrices

#include <utility> // For the casters' signature
#include <vector>  // For the casters' signature

class vtkCamera;
class vtkCameraPass;
class vtkImageData;
class vtkMatrix4x4;
class vtkOpaquePass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

namespace vtkLightShaftGeometry
{
struct LightView;
}

/**
 * @class   vtkLightShaftShadowMap
 * @brief   Renders one light's shadow casters' depth (the producer of the map the shafts and the
 *          surfaces consume), lets observers rewrite it, keeps it while nothing that decides it
 *          changes, and reads it back.
 *
 * As vtkShadowMapBakerPass does for surfaces: the opaque step of the casters only, through
 * VTK's own camera and opaque passes, with the cameras vtkLightShaftGeometry::ComputeLightFrame
 * set up. 32-bit float depth, ShadowMapSize texels square (at most the GL's maximum texture
 * size); a point light's six cube faces side by side in a 3 x 2 atlas (faces of at most a
 * third of the maximum size).
 *
 * The map is kept from frame to frame while its signature stays the same: the cameras'
 * matrices and depth range, the map's size, and each caster with its redraw time (the prop,
 * its mapper and the mapper's input). Translucent casters are peeled into layers of
 * transmittance next to it (vtkLightShaftTranslucentLayers), rendered and kept with it; the
 * frame's Translucency points to them while the light is worked on. It is rendered every frame when
 * someone observes vtkLightShaftPass::ShadowMapRenderedEvent (distributed processes combine their
 * maps: what the others hold may change without this process seeing it).
 */
class vtkLightShaftShadowMap
{
public:
  vtkLightShaftShadowMap();
  ~vtkLightShaftShadowMap();

  /**
   * The map of `frame.Light`'s casters for this frame, nullptr when nothing can shadow the
   * light's volume: rendered (then vtkLightShaftPass::ShadowMapRenderedEvent is invoked on
   * `frame.Owner`, its observers may read and rewrite the map: GetEventTexture), or kept from
   * an earlier render. Records what it did in the frame's statistics of the light.
   */
  vtkTextureObject* Ready(vtkLightShaftFrame& frame);

  /**
   * Render the opaque step of `casters` into the depth texture `depth` (cleared), seen by
   * `camera`: a shadow map's, or another (the radial blur's guard band).
   */
  void RenderCasters(vtkLightShaftFrame& frame,
    std::vector<vtkProp*>& casters,
    vtkCamera* camera,
    vtkSmartPointer<vtkOpenGLFramebufferObject>& target,
    vtkTextureObject* depth);

  /// The map (valid after Ready returned it).
  vtkTextureObject* GetTexture();
  /// The map while the event is being handled, nullptr at any other time.
  vtkTextureObject* GetEventTexture();
  /// The lookup's depth tolerance for the current map: relative (spot, point: two texels'
  /// worth of depth at a 45-degree slope, a sample this close behind a caster's front face is
  /// inside the caster) or absolute in world units (directional: two texels' width).
  double GetBias(const vtkLightShaftFrame& frame);

  /// The last map's depths (N x N floats, 1 = nothing) and world-to-light-clip matrix; false
  /// when none was rendered or the map is a point light's cube.
  bool ReadBack(vtkOpenGLRenderWindow* window,
    vtkImageData* depths,
    vtkMatrix4x4* worldToLightClip);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftShadowMap(const vtkLightShaftShadowMap&) = delete;
  void operator=(const vtkLightShaftShadowMap&) = delete;

  /// What decides the map's content.
  struct Signature
  {
    std::vector<glm::dmat4> Cameras;
    std::vector<std::pair<vtkProp*, vtkMTimeType>> Casters;
    double Range[2] = { 0.0, 0.0 };
    int Size = 0;
    int TranslucentLayers = 0; ///< the most layers asked (0: translucent casters cast nothing)
    bool operator==(const Signature& other) const;
  };
  Signature Sign(vtkLightShaftFrame& frame, int size) const;
  void RenderCube(vtkLightShaftFrame& frame, int size);
  void SetCamera(const vtkLightShaftGeometry::LightView& view);
  /// The translucent layers (and their statistics) into the frame.
  void PublishTranslucency(vtkLightShaftFrame& frame);

  vtkNew<vtkCameraPass> CameraPass;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkCamera> LightCamera;
  vtkLightShaftResources::OwnedTexture Map;
  vtkLightShaftResources::OwnedTexture Face;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FaceFramebuffer;
  vtkLightShaftTranslucentLayers Translucent;
  int TranslucentLayerCount = 0; ///< the layers of the map (0: none)
  vtkTextureObject* EventTexture = nullptr;
  bool Valid = false;
  bool Cube = false;
  int RenderedFrame = -1;
  Signature Rendered;
  glm::dmat4 WorldToLightClip{ 1.0 };
};

#endif
