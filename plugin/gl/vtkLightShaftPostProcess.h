/**
 * @file   vtkLightShaftPostProcess.h
 * @brief  The in-scatter's post chain in vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftPostProcess_h
#define vtkLightShaftPostProcess_h

#include "vtkLightShaftResources.h"       // For the owned texture and pass
#include "vtkLightShaftSeparableFilter.h" // For the blur
#include "vtkSmartPointer.h"              // For the framebuffer held

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftPostProcess
 * @brief   After a method: the depth-aware blur (BlurRadius), and the depth-aware upsampling
 *          back to full resolution (DownsampleFactor > 1: each full-resolution pixel takes the
 *          reduced sample whose depth matches its own, so no halo appears around foreground
 *          edges).
 */
class vtkLightShaftPostProcess
{
public:
  vtkLightShaftPostProcess();
  ~vtkLightShaftPostProcess();

  /**
   * The full-resolution in-scatter from `inScatter` (reduced resolution, with the depth
   * `reducedDepth`; `fullDepth` is the scene's single-sample depth).
   */
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    vtkTextureObject* inScatter,
    vtkTextureObject* reducedDepth,
    vtkTextureObject* fullDepth);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftPostProcess(const vtkLightShaftPostProcess&) = delete;
  void operator=(const vtkLightShaftPostProcess&) = delete;

  vtkLightShaftSeparableFilter Blur;
  vtkLightShaftResources::FullScreenPass Upsample;
  vtkLightShaftResources::OwnedTexture Upsampled;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};

#endif
