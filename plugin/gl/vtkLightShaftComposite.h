/**
 * @file   vtkLightShaftComposite.h
 * @brief  The final composite of vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftComposite_h
#define vtkLightShaftComposite_h

#include "vtkLightShaftResources.h" // For the full-screen pass

class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftComposite
 * @brief   Writes the picture into the target the pass draws into:
 *          (scene - correction) * exp(-sigma_t t_surface) + Exposure * L_in, per sample when
 *          the scene is multisampled (the correction: the surface light the lights' shadow maps
 *          and cookie take away, vtkLightShaftSurfaceLight), an alpha that makes the shafts
 *          part of the picture for passes that blend by it, and the scene's depth unchanged (copied
 * bit for bit when the target's depth has the scene's format, else written by the shader).
 */
class vtkLightShaftComposite
{
public:
  vtkLightShaftComposite();
  ~vtkLightShaftComposite();

  /// Composite `inScatter` (full resolution) over the frame's scene into the bound target, at
  /// the frame's viewport.
  void Render(vtkLightShaftFrame& frame, vtkTextureObject* inScatter);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftComposite(const vtkLightShaftComposite&) = delete;
  void operator=(const vtkLightShaftComposite&) = delete;

  vtkLightShaftResources::FullScreenPass Pass;
};

#endif
