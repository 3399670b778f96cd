/**
 * @file   vtkLightShaftSeparableFilter.h
 * @brief  The depth-aware separable filter of vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftSeparableFilter_h
#define vtkLightShaftSeparableFilter_h

#include "vtkLightShaftResources.h" // For the owned textures and pass
#include "vtkSmartPointer.h"        // For the framebuffer held

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftSeparableFilter
 * @brief   Two passes of the blur shader over the in-scatter (x, then y), leaving out samples
 *          whose surface is not the centre pixel's: a Gaussian of a radius (the blur), or a box
 *          (the interleaved-sampling gather of RAY_MARCH).
 */
class vtkLightShaftSeparableFilter
{
public:
  /// Relative view-depth difference under which two pixels see "the same surface" (the
  /// depth-aware blur, gather and upsampling).
  static constexpr float SameSurfaceTolerance = 0.05f;

  vtkLightShaftSeparableFilter();
  ~vtkLightShaftSeparableFilter();

  /**
   * Filter `source` (the frame's reduced resolution, with the depth `depth`): a Gaussian of
   * `radius` pixels, or with boxWidth > 0 a box of that width (even widths: boxWidth + 1 pixels
   * with half-weight ends). Returns the filtered texture; counts two post passes.
   */
  vtkTextureObject* Apply(vtkLightShaftFrame& frame,
    vtkTextureObject* source,
    vtkTextureObject* depth,
    int radius,
    int boxWidth);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftSeparableFilter(const vtkLightShaftSeparableFilter&) = delete;
  void operator=(const vtkLightShaftSeparableFilter&) = delete;

  vtkLightShaftResources::FullScreenPass Pass;
  vtkLightShaftResources::OwnedTexture Temporary;
  vtkLightShaftResources::OwnedTexture Output;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};

#endif
