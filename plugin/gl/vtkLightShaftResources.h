/**
 * @file   vtkLightShaftResources.h
 * @brief  The GL objects of vtkLightShaftPass's components (private, not installed): owned
 *         textures re-created when their kind, size or samples change, full-screen passes
 *         rebuilt when their feature variant changes, framebuffers bound with exactly the
 *         attachments asked for, and what the target the pass draws into is like.
 *
 * Every object is held by a smart pointer and freed by Release(window), which may be called
 * any number of times.
 */

#ifndef vtkLightShaftResources_h
#define vtkLightShaftResources_h

#include "vtkSmartPointer.h"  // For the owned objects
#include "vtkTextureObject.h" // For vtkTextureObject (owned)

#include <initializer_list> // For BindTargets' colour list
#include <memory>           // For the quad helper
#include <string>           // For the variant key
#include <vector>           // For defines and texels

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

namespace vtkLightShaftResources
{
enum class TextureKind
{
  RGBA8,
  RGBA16F,
  RGBA32F,
  /// The depth format VTK 9.1's render windows (and GPU volume mapper) allocate: depth-stencil
  /// when the window is stencil capable, else 32-bit fixed point. Matching it keeps depth blits
  /// from and to the window's targets legal and exact.
  Depth,
  /// 32-bit float depth: the best precision for a perspective depth (the shadow map).
  Depth32F
};

/**
 * A texture the pass owns, re-allocated only when its kind, size or sample count changes.
 */
struct OwnedTexture
{
  vtkSmartPointer<vtkTextureObject> Object;
  TextureKind Kind = TextureKind::RGBA8;

  /// The texture, w x h, of `kind`; `samples` > 0 makes it multisampled.
  vtkTextureObject* Ensure(vtkOpenGLRenderWindow* window,
    TextureKind kind,
    int w,
    int h,
    int samples = 0);
  void Release(vtkWindow* window);
};

/**
 * A full-screen pass, rebuilt only when its feature variant (its #defines) changes; the source
 * is assembled only then.
 */
struct FullScreenPass
{
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Key;

  FullScreenPass();
  ~FullScreenPass();

  /// The compiled program (nullptr when it does not compile), bound.
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window,
    const char* source,
    const std::vector<std::string>& defines = {});
  void Render();
  void Release(vtkWindow* window);
};

/// A framebuffer of the window's context, created on first use.
vtkOpenGLFramebufferObject* EnsureFramebuffer(
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  vtkOpenGLRenderWindow* window);
void ReleaseFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkWindow* w);

/**
 * Bind `fbo` with exactly these attachments (any others removed: a target of another size left
 * attached would make it incomplete), all of size w x h, drawing into all colour attachments,
 * viewport and scissor set to the whole target.
 */
void BindTargets(vtkOpenGLFramebufferObject* fbo,
  std::initializer_list<vtkTextureObject*> colors,
  vtkTextureObject* depth,
  int w,
  int h);

/// A mipmapped, linearly filtered texture from float texels (1 or 3 components).
void UploadMipmapped(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window,
  const std::vector<float>& texels,
  int width,
  int height,
  int components,
  bool repeat);

/// A linearly filtered, edge-clamped single-channel float32 3D texture of `values` (x fastest),
/// replacing `texture`'s (its size may change).
void UploadFloatVolume(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window,
  const float* values,
  int width,
  int height,
  int depth);

/**
 * Samples per pixel of the bound draw framebuffer (the window's multisampled render
 * framebuffer, or an outer pass's target), 0 when it is not multisampled or when multisampled
 * textures cannot have that many samples.
 */
int TargetSamples();

/// Whether the bound draw framebuffer's depth has the format and samples of `depth`, so that a
/// blit copies it bit for bit.
bool TargetDepthMatches(vtkTextureObject* depth);
}

#endif
