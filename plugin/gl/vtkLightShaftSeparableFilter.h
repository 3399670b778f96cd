/**
 * @file   vtkLightShaftSeparableFilter.h
 * @brief  The depth-aware separable filter of vtkLightShaftPass (private, not installed).
 */

#ifndef vtkLightShaftSeparableFilter_h
#define vtkLightShaftSeparableFilter_h

#include "vtkLightShaftResources.h" // For the owned textures and pass
#include "vtkSmartPointer.h"        // For the framebuffer held

#include <vector> // For a kernel's weights

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

  /// The taps along one axis: a Gaussian of standard deviation Sigma over |i| <= Radius, or
  /// with BoxWidth > 0 a box of that width (even widths: BoxWidth + 1 taps, half-weight ends).
  struct Kernel
  {
    double Sigma = 0.5;
    int Radius = 0;
    int BoxWidth = 0;

    /// The blur of BlurRadius `radius`: its standard deviation is half of it (at least 0.5).
    static Kernel Blur(int radius);
    /// The gather of interleaved sampling over `width` pixels.
    static Kernel Gather(int width);
    /// A Gaussian of standard deviation `sigma`, cut at two of them (at least one tap a side).
    static Kernel Gaussian(double sigma);
    /// The weights of the taps from -Radius (or the box's first) to the last.
    std::vector<double> Weights() const;
  };

  /**
   * How many independent samples a filter of these weights averages along its axis (its
   * variance reduction of uncorrelated noise): (sum w)^2 / sum w^2. 1 for a single tap.
   */
  static double EffectiveSamples(const std::vector<double>& weights);

  /// The weights of one filter followed by the other (their convolution).
  static std::vector<double> Convolve(const std::vector<double>& a, const std::vector<double>& b);

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

  /// Filter `source` of `width` x `height` pixels with the depth `depth` of the same size by
  /// `kernel` along x, then along y. Returns the filtered texture; counts two post passes.
  vtkTextureObject* Apply(vtkLightShaftFrame& frame,
    vtkTextureObject* source,
    vtkTextureObject* depth,
    const Kernel& kernel,
    int width,
    int height);

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
