/**
 * @file   vtkLightShaftInScatterTarget.h
 * @brief  Where vtkLightShaftPass's methods add up the in-scattered radiance (private, not
 *         installed).
 */

#ifndef vtkLightShaftInScatterTarget_h
#define vtkLightShaftInScatterTarget_h

#include "vtkLightShaftResources.h" // For the owned textures and passes
#include "vtkSmartPointer.h"        // For the framebuffers held

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftInScatterTarget
 * @brief   The in-scatter buffers at the frame's reduced resolution (DownsampleFactor): the
 *          accumulation buffer(s), the depth the shafts read (the scene's, or the nearest of
 *          each block), and its copy for the slabs' depth test (the slabs sample the depth, so
 *          it cannot be their depth target too).
 */
class vtkLightShaftInScatterTarget
{
public:
  vtkLightShaftInScatterTarget();
  ~vtkLightShaftInScatterTarget();

  /// Make the depth the shafts read (the scene's, or the nearest of each reduced block).
  void PrepareDepth(vtkLightShaftFrame& frame);

  /**
   * Make `buffers` accumulation buffers (1, or 3 for the 8-bit mode) of `kind`, cleared to
   * zero, with the depth-test copy; leaves them bound (Bind).
   */
  void Clear(vtkLightShaftFrame& frame, int buffers, vtkLightShaftResources::TextureKind kind);

  /// Add `inScatter` (reduced size, RGB) into the sum of several lights' in-scatter (cleared
  /// by the first addition of a frame: Clear(frame, ...) starts a new sum).
  void AddToSum(vtkLightShaftFrame& frame, vtkTextureObject* inScatter);
  /// The sum, nullptr when nothing was added since PrepareDepth.
  vtkTextureObject* GetSum();

  /// Bind the accumulation buffers and the depth-test copy for drawing.
  void Bind();
  /// Bind the (single) accumulation buffer and the depth-test copy with `extra` (same size) as
  /// a second colour attachment: a method's own output of the same draw.
  void BindWith(vtkTextureObject* extra);

  /// The depth the shafts read (reduced resolution).
  vtkTextureObject* GetDepth();
  vtkTextureObject* GetAccumulation(int index);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftInScatterTarget(const vtkLightShaftInScatterTarget&) = delete;
  void operator=(const vtkLightShaftInScatterTarget&) = delete;

  vtkLightShaftResources::OwnedTexture ReducedDepth;
  vtkLightShaftResources::OwnedTexture DepthTest;
  vtkLightShaftResources::OwnedTexture Accumulation[3];
  vtkSmartPointer<vtkOpenGLFramebufferObject> AccumulationFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFramebuffer;
  vtkLightShaftResources::FullScreenPass DepthDownsample;
  vtkLightShaftResources::OwnedTexture Sum;
  vtkSmartPointer<vtkOpenGLFramebufferObject> SumFramebuffer;
  vtkLightShaftResources::FullScreenPass Add;
  bool Summed = false;
  vtkTextureObject* Depth = nullptr;
  int Buffers = 1;
  int Size[2] = { 0, 0 };
};

#endif
