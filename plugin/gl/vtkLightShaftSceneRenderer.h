/**
 * @file   vtkLightShaftSceneRenderer.h
 * @brief  The scene under the shafts, for vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftSceneRenderer_h
#define vtkLightShaftSceneRenderer_h

#include "vtkLightShaftRendererStep.h" // For the default delegate's steps
#include "vtkLightShaftResources.h"    // For the owned targets and passes
#include "vtkNew.h"                    // For the delegates held
#include "vtkSmartPointer.h"           // For the framebuffers held

class vtkLight;
class vtkOpenGLFXAAFilter;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderPass;
class vtkRenderState;
class vtkRenderStepsPass;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftSceneRenderer
 * @brief   Renders the scene the shafts go into: the delegate (or, with none, VTK's default
 *          steps, translucency and volumes as the renderer's own render draws them), into targets
 * multisampled like the pass's own target, with all its lights and, for the surface light of a
 * shadowed or cookie-shaped light, without that light; and the renders that must stay plain
 * (selection, enclosing passes).
 *
 * The 2D overlay step of the delegate's vtkRenderStepsPass is held back while the scene renders,
 * so that the pass can draw it after compositing (on top, unfogged); the renderer's FXAA is
 * applied before it, as VTK's own render does.
 */
class vtkLightShaftSceneRenderer
{
public:
  vtkLightShaftSceneRenderer();
  ~vtkLightShaftSceneRenderer();

  /**
   * Whether the render `s` needs the scene exactly as without the pass: a hardware selector's
   * (VTK's picking and selection draw ids, not colours); one of an enclosing pass that renders
   * the props itself, with its own shaders (a vtkOpenGLRenderPass such as a shadow-map baker or
   * a value pass marks the props while it renders) or by their information keys; one into a
   * target that takes no colour (depth only).
   */
  static bool NeedsPlainScene(const vtkRenderState* s);

  /**
   * The scene exactly as the renderer would draw it without `pass`: for a hardware selector the
   * renderer's own pass-less render (it hands the props, or the pick list, to the selector),
   * else `userDelegate` or VTK's default steps. Returns the number of props rendered.
   */
  int RenderPlain(vtkRenderPass* pass, vtkRenderPass* userDelegate, const vtkRenderState* s);

  /// The pass that renders the scene: `userDelegate`, else VTK's default steps.
  vtkRenderPass* ChooseDelegate(vtkRenderPass* userDelegate);

  /// `delegate` into the current target, unchanged (no shafts this frame).
  void RenderUnchanged(vtkLightShaftFrame& frame, vtkRenderPass* delegate);

  /**
   * Take the overlay step out of the scene's steps until FinishFrame: of `delegate` when it is
   * a vtkRenderStepsPass, else of the first one inside it (through camera, sequence and image
   * processing passes: PyVista's chain, for one). Nothing when there is none.
   */
  void HoldOverlay(vtkRenderPass* delegate);

  /**
   * What VTK's own render does after the geometry, on the picture the pass made: the
   * renderer's FXAA (vtkRenderer::UseFXAA; a multisampled target is antialiased already), then
   * the overlay step held back (on top, unfogged). The overlay is given back to its steps.
   */
  void FinishFrame(vtkLightShaftFrame& frame);

  /**
   * Render the scene into the frame's scene image (frame.Scene: colour, depth and the depth the
   * shafts read), with the samples of the target the pass draws into.
   */
  void Render(vtkLightShaftFrame& frame, vtkRenderPass* delegate);

  /**
   * Render the scene again without `light` (its intensity at zero: with no light on, VTK would
   * add a headlight) into a colour texture like the scene's, returned (valid until the next
   * call).
   */
  vtkTextureObject* RenderWithout(vtkLightShaftFrame& frame,
    vtkRenderPass* delegate,
    vtkLight* light);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftSceneRenderer(const vtkLightShaftSceneRenderer&) = delete;
  void operator=(const vtkLightShaftSceneRenderer&) = delete;

  void RenderInto(vtkLightShaftFrame& frame,
    vtkRenderPass* delegate,
    vtkTextureObject* color,
    vtkTextureObject* depth);
  vtkTextureObject* ResolveDepth(vtkLightShaftFrame& frame, vtkTextureObject* depthSamples);

  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  vtkNew<vtkLightShaftRendererStep> DefaultOpaque;
  vtkNew<vtkLightShaftRendererStep> DefaultTranslucent;
  vtkNew<vtkLightShaftRendererStep> DefaultVolumes;
  vtkRenderStepsPass* OverlayOwner = nullptr;
  vtkSmartPointer<vtkRenderPass> HeldOverlay;
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;

  vtkLightShaftResources::OwnedTexture Color;
  vtkLightShaftResources::OwnedTexture ColorUnlit;
  vtkLightShaftResources::OwnedTexture Depth;
  vtkLightShaftResources::OwnedTexture DepthUnlit;
  vtkLightShaftResources::OwnedTexture ResolvedDepth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResolveFramebuffer;
  vtkLightShaftResources::FullScreenPass DepthResolve;
};

#endif
