/**
 * @file   vtkLightShaftTranslucentLayers.h
 * @brief  One light's translucent casters as layers of transmittance, next to its depth map,
 *         for vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftTranslucentLayers_h
#define vtkLightShaftTranslucentLayers_h

#include "vtkLightShaftResources.h" // For the owned textures
#include "vtkNew.h"                 // For the passes held
#include "vtkSmartPointer.h"        // For the framebuffers held

#include <functional> // For the light cameras' callback
#include <vector>     // For the layers

class vtkCamera;
class vtkCameraPass;
class vtkLightShaftTranslucentPeel;
class vtkOpenGLFramebufferObject;
class vtkProp;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftTranslucentLayers
 * @brief   Peels the translucent surfaces the light meets in front of its opaque casters, front
 *          to back, into layers laid out as its depth map (one view, or a point light's 3 x 2
 *          atlas of cube faces), side by side in one RGBA32F texture: per texel and layer the
 *          surface's transmittance (rgb, vtkLightShaftTranslucentPeel's rule) and its depth
 *          (alpha; 1 where the layer is empty). A point lies behind the first n layers that are
 *          in front of it, and gets the product of their transmittance.
 *
 * Layers are peeled while one has a surface (an occlusion query per layer), up to the
 * maximum asked and as many as fit side by side in the GL's largest texture, at the map's
 * resolution or, where they would hold more than BudgetBytes, a lower one (LayerSize). The
 * light camera of each view is set by the caller (its depth map's).
 */
class vtkLightShaftTranslucentLayers
{
public:
  vtkLightShaftTranslucentLayers();
  ~vtkLightShaftTranslucentLayers();

  /// The most GL memory one light's layers hold (twice that for a moment while they are
  /// assembled side by side; the peel's own targets, one layer's face, are freed after it).
  static constexpr double BudgetBytes = 512.0 * 1024.0 * 1024.0;
  /// A layer texel's bytes: RGBA32F (rgb transmittance, a depth).
  static constexpr double TexelBytes = 16.0;

  /**
   * The layers' rule for a map of `width` x `height` texels (`cube`: 3 x 2 faces): how many
   * may be peeled (at most `maximumLayers`, and as many as fit side by side within
   * `maximumTexture` texels), returned, and each layer's `size`: the map's, or scaled down
   * (whole faces) so that that many hold at most BudgetBytes.
   */
  static int LayerSize(int width,
    int height,
    bool cube,
    int maximumLayers,
    int maximumTexture,
    int size[2]);

  /// Sets the light camera of view `v` and returns it.
  using CameraSetter = std::function<vtkCamera*(int v)>;

  /**
   * Peel the layers of the frame's light: its views' translucent casters in front of the
   * opaque depth map `opaque` (`cube`: a 3 x 2 atlas of faces), at most `maximumLayers`.
   * Returns the number of layers that have a surface (0: none; the texture is then not kept).
   */
  int Render(vtkLightShaftFrame& frame,
    vtkTextureObject* opaque,
    bool cube,
    int maximumLayers,
    const CameraSetter& setCamera);

  /**
   * Peel the translucent surfaces of `props` that the scene's `camera` sees in front of the
   * opaque depth `opaque` (the scene's, single-sample), with the camera's rule
   * (vtkLightShaftTranslucentPeel::CAMERA: per texel 1 - a and the depth), at most
   * `maximumLayers`. Returns the number of layers that have a surface.
   */
  int RenderCamera(vtkLightShaftFrame& frame,
    std::vector<vtkProp*> props,
    vtkTextureObject* opaque,
    int maximumLayers,
    vtkCamera* camera);

  /// The layers side by side (valid after Render returned more than 0): the one layer's own
  /// texture, or an atlas of them (the layers' own textures then freed).
  vtkTextureObject* GetTexture() const { return this->Result; }
  /// The bytes of GL memory the layers hold.
  double GetBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftTranslucentLayers(const vtkLightShaftTranslucentLayers&) = delete;
  void operator=(const vtkLightShaftTranslucentLayers&) = delete;

  int PeelViews(vtkLightShaftFrame& frame,
    std::vector<std::vector<vtkProp*>>& casters,
    vtkTextureObject* opaque,
    bool cube,
    int maximumLayers,
    const CameraSetter& setCamera);
  bool PeelFace(vtkLightShaftFrame& frame,
    std::vector<vtkProp*>& casters,
    vtkCamera* camera,
    int layer,
    const float rect[4]);
  void Assemble(vtkLightShaftFrame& frame, int layers);

  vtkNew<vtkLightShaftTranslucentPeel> Peel;
  vtkNew<vtkCameraPass> CameraPass;
  std::vector<vtkLightShaftResources::OwnedTexture> Layers;
  vtkLightShaftResources::OwnedTexture Atlas;
  vtkLightShaftResources::OwnedTexture FaceColor;
  vtkLightShaftResources::OwnedTexture FaceDepth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FaceFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> LayerFramebuffer;
  vtkTextureObject* Opaque = nullptr;
  vtkTextureObject* Result = nullptr;
  int UsedLayers = 0;
  unsigned int Query = 0; ///< the occlusion query (GL name; 0: none yet)
};

#endif
