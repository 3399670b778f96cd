/**
 * @class   vtkLightShaftPass
 * @brief   Adds physically based volumetric light shafts (single scattering of a spotlight in a
 *          homogeneous participating medium, shadowed by the scene) to any VTK scene.
 *
 * Use it as the renderer's pass:
 * @code{.cpp}
 *   vtkNew<vtkLightShaftPass> shafts;
 *   shafts->SetScatteringCoefficient(0.2, 0.2, 0.2);
 *   renderer->SetPass(shafts);
 * @endcode
 *
 * Every frame the pass
 *  1. renders the scene through its delegate pass into an off-screen colour + depth target
 *     (with no delegate set it renders as VTK's default vtkRenderStepsPass would, and keeps the
 *     2D overlay step for the end so text and scalar bars stay on top and unfogged);
 *  2. renders a depth map of the scene's opaque geometry from the spotlight (shadow map);
 *  3. draws view-aligned slabs covering only the part of the view volume inside the light's
 *     cone, each fragment integrating the in-scattered radiance over its slab of the pixel's
 *     view ray, and accumulates them additively in a 32-bit float target;
 *  4. composites: out = scene * exp(-sigma_t * t_surface) + Exposure * L_in.
 *
 * The in-scattered radiance along the pixel-centre view ray x = eye + t d, up to the first
 * surface (or the far clipping plane) at distance t_s, is
 *
 *   L_in = int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t r) exp(-sigma_t t) dt
 *
 * with r = |x - light|, I = intensity * diffuse colour, S the VTK spot term (0 outside the cone
 * half-angle GetConeAngle(), else cos(angle to the axis)^GetExponent()), A = 1 / (c0 + c1 r +
 * c2 r^2) from GetAttenuationValues(), V the shadow-map visibility, sigma_t = sigma_s + sigma_a
 * per colour channel, and p the phase function normalised over the sphere. theta is the
 * scattering angle between the light's propagation direction (x - light) / r and the direction
 * towards the eye, -d: cos theta = -d . (x - light) / r, so Henyey-Greenstein with g > 0 is
 * forward scattering (brightest looking into the light).
 *
 * Within each slab the pass clips the ray exactly to the cone and the surface, integrates A(r)
 * in closed form (exact when c1 = 0), weights the phase, spot and extinction factors with
 * 3-point Gauss-Legendre in the equiangular angle, and looks up the shadow map once, at the
 * segment's midpoint; the error shrinks as the number of slices grows (docs/accuracy.md).
 * Slab fragments that start behind the scene surface are culled by the depth test.
 *
 * With both coefficients zero, or with no usable light, the pass renders the delegate's image
 * unchanged (pixel-identical; one warning for a missing light).
 *
 * The lit pool on surfaces comes from VTK's own lighting, which has no shadows. With
 * ShadowSurfaces on (and no delegate set) the scene is rendered with VTK's vtkShadowMapPass in
 * the opaque step, so the floor shows the same occluder shadows as the shafts; with your own
 * delegate, put a vtkShadowMapPass in it (see README "Shadows on surfaces").
 *
 * @sa vtkImageProcessingPass vtkShadowMapPass
 */

#ifndef vtkLightShaftPass_h
#define vtkLightShaftPass_h

#include "vtkImageProcessingPass.h" // For the base class and the delegate pass
#include "vtkLightShaftsModule.h"   // For the export macro

#include <memory> // For std::unique_ptr (GL objects and state live in Internals)

class vtkImageData;
class vtkLight;

class VTKLIGHTSHAFTS_EXPORT vtkLightShaftPass : public vtkImageProcessingPass
{
public:
  static vtkLightShaftPass* New();
  vtkTypeMacro(vtkLightShaftPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Phase functions, normalised over the sphere.
  enum PhaseFunctionType
  {
    ISOTROPIC = 0,         ///< 1 / (4 pi)
    HENYEY_GREENSTEIN = 1, ///< (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^1.5)
    RAYLEIGH = 2           ///< 3 / (16 pi) (1 + cos^2 theta)
  };

  /**
   * Render the scene and its light shafts. Called by the renderer.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Free every GL object the pass (and its internal passes) hold. Safe to call more than once
   * and with any window; the pass rebuilds what it needs on the next Render().
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The spotlight that scatters. With none set (nullptr), the pass uses the first light of the
   * renderer that is switched on, positional, and has a cone angle below 90 degrees.
   * Default is nullptr (automatic choice).
   */
  void SetLight(vtkLight* light);
  vtkLight* GetLight();
  ///@}

  /**
   * The light used by the last frame (the one set, or the automatic choice); nullptr when the
   * last frame found no usable light.
   */
  vtkLight* GetLastUsedLight();

  ///@{
  /**
   * Scattering coefficient sigma_s per world unit, per colour channel, in [0, 1e6].
   * Non-finite values are refused (error, previous value kept). The one-argument form sets
   * all three channels. Default is (0.1, 0.1, 0.1).
   */
  void SetScatteringCoefficient(double r, double g, double b);
  void SetScatteringCoefficient(const double rgb[3]);
  void SetScatteringCoefficient(double grey);
  vtkGetVector3Macro(ScatteringCoefficient, double);
  ///@}

  ///@{
  /**
   * Absorption coefficient sigma_a per world unit, per colour channel, in [0, 1e6].
   * The extinction is sigma_t = sigma_s + sigma_a. Non-finite values are refused.
   * Default is (0, 0, 0).
   */
  void SetAbsorptionCoefficient(double r, double g, double b);
  void SetAbsorptionCoefficient(const double rgb[3]);
  void SetAbsorptionCoefficient(double grey);
  vtkGetVector3Macro(AbsorptionCoefficient, double);
  ///@}

  ///@{
  /**
   * Phase function: ISOTROPIC, HENYEY_GREENSTEIN or RAYLEIGH (values outside are clamped).
   * Default is ISOTROPIC.
   */
  vtkSetClampMacro(PhaseFunction, int, ISOTROPIC, RAYLEIGH);
  vtkGetMacro(PhaseFunction, int);
  void SetPhaseFunctionToIsotropic() { this->SetPhaseFunction(ISOTROPIC); }
  void SetPhaseFunctionToHenyeyGreenstein() { this->SetPhaseFunction(HENYEY_GREENSTEIN); }
  void SetPhaseFunctionToRayleigh() { this->SetPhaseFunction(RAYLEIGH); }
  ///@}

  ///@{
  /**
   * Henyey-Greenstein anisotropy g in [-0.99, 0.99]: g > 0 scatters forward (towards where the
   * light travels), g < 0 backward. Used only by HENYEY_GREENSTEIN. Non-finite values are
   * refused. Default is 0.
   */
  void SetAnisotropy(double g);
  vtkGetMacro(Anisotropy, double);
  ///@}

  ///@{
  /**
   * Scale applied to the in-scattered radiance when it is added to the image, in [0, 1e6].
   * GetInScatteredRadiance() returns the radiance before this scale. Non-finite values are
   * refused. Default is 1.
   */
  void SetExposure(double exposure);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /**
   * Attenuate the scene by the medium's transmittance exp(-sigma_t t_surface) (aerial
   * perspective). Default is on.
   */
  vtkSetMacro(AttenuateScene, bool);
  vtkGetMacro(AttenuateScene, bool);
  vtkBooleanMacro(AttenuateScene, bool);
  ///@}

  ///@{
  /**
   * Shadow the surfaces too: when no delegate is set, render the scene's opaque step through
   * VTK's vtkShadowMapPass (shadow maps of ShadowMapSize texels for every shadow-casting light),
   * so the pool of light on the floor shows the same shadows as the shafts. Ignored when a
   * delegate is set. Default is off (the scene renders exactly as vtkRenderStepsPass would).
   */
  vtkSetMacro(ShadowSurfaces, bool);
  vtkGetMacro(ShadowSurfaces, bool);
  vtkBooleanMacro(ShadowSurfaces, bool);
  ///@}

  ///@{
  /**
   * Number of view-aligned slabs spanning the depth range of the light volume inside the view,
   * in [1, 4096]. More slices: less error, more fill. Default is 128.
   */
  vtkSetClampMacro(NumberOfSlices, int, 1, 4096);
  vtkGetMacro(NumberOfSlices, int);
  ///@}

  ///@{
  /**
   * Side of the square shadow map in texels, in [16, 16384] (further limited at render time to
   * the GL implementation's maximum texture size). Default is 1024.
   */
  vtkSetClampMacro(ShadowMapSize, int, 16, 16384);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

  /**
   * Fill `out` with the last frame's in-scattered radiance L_in: linear float RGB (3
   * components, array "InScatteredRadiance"), one pixel per viewport pixel, row 0 at the bottom
   * (VTK image convention), before Exposure and compositing. Zeros when the last frame added
   * no shafts. Returns false (and leaves `out` empty) when nothing was rendered yet or the
   * window is gone.
   */
  bool GetInScatteredRadiance(vtkImageData* out);

  ///@{
  /**
   * What the last frame did, for tests and tuning: slabs drawn (0 when the shafts were skipped),
   * whether a shadow map was rendered, the clipped view-depth range the slabs spanned, and the
   * viewport size.
   */
  vtkGetMacro(LastNumberOfSlicesDrawn, int);
  vtkGetMacro(LastShadowMapRendered, bool);
  vtkGetVector2Macro(LastSliceDepthRange, double);
  vtkGetVector2Macro(LastViewportSize, int);
  ///@}

  /**
   * Number of OpenGL errors raised while the last frame rendered (the pass, its delegate and
   * its internal passes); 0 when all is well. Errors pending before the frame are not counted.
   */
  vtkGetMacro(LastGLErrorCount, int);

protected:
  vtkLightShaftPass();
  ~vtkLightShaftPass() override;

  // Parameters.
  double ScatteringCoefficient[3] = { 0.1, 0.1, 0.1 };
  double AbsorptionCoefficient[3] = { 0.0, 0.0, 0.0 };
  int PhaseFunction = ISOTROPIC;
  double Anisotropy = 0.0;
  double Exposure = 1.0;
  bool AttenuateScene = true;
  bool ShadowSurfaces = false;
  int NumberOfSlices = 128;
  int ShadowMapSize = 1024;

  // Last-frame statistics.
  int LastNumberOfSlicesDrawn = 0;
  bool LastShadowMapRendered = false;
  double LastSliceDepthRange[2] = { 0.0, 0.0 };
  int LastViewportSize[2] = { 0, 0 };
  int LastGLErrorCount = 0;

private:
  void RenderFrame(const vtkRenderState* s);

  vtkLightShaftPass(const vtkLightShaftPass&) = delete;
  void operator=(const vtkLightShaftPass&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
