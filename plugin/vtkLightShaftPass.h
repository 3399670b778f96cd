/**
 * @class   vtkLightShaftPass
 * @brief   Adds physically based volumetric light shafts (single scattering of the scene's
 *          lights in a participating medium, homogeneous or from data, shadowed by the scene)
 *          to any VTK scene.
 *
 * Use it as the renderer's pass:
 * @code{.cpp}
 *   vtkNew<vtkLightShaftPass> shafts;
 *   shafts->SetScatteringCoefficient(0.2, 0.2, 0.2);
 *   renderer->SetPass(shafts);
 * @endcode
 *
 * Every frame the pass renders the scene through its delegate (else as vtkRenderStepsPass
 * would, the 2D overlays kept for the end) off screen; for each light that scatters (SetLight,
 * AddLight, else the renderer's spot and point lights) renders a depth map of what can shadow
 * it (perspective, a cube of six for a point light, orthographic for a directional one; kept
 * while nothing that decides it changes) and adds the in-scattered radiance where it shines;
 * then composites: out = scene * exp(-sigma_t * t_surface) + Exposure * L_in.
 *
 * The in-scattered radiance along the pixel-centre view ray x = eye + t d, up to the first
 * surface (or the far clipping plane) at distance t_s, is the sum over the lights of
 *
 *   L_in = int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t r) exp(-sigma_t t) dt
 *
 * with I = intensity * diffuse colour, V the shadow map's visibility (times the transmittance
 * of the translucent casters in front), sigma_t = sigma_s + sigma_a per colour channel, and p the
 * phase function normalised over the sphere. theta is the scattering angle between the light's
 * propagation direction l and the direction towards the eye, -d: cos theta = -d . l, so
 * Henyey-Greenstein with g > 0 is forward scattering (brightest looking into the light). Per kind
 * of light (LightKindType):
 *  - spot (positional, cone angle below 90 degrees): r = |x - light|, l = (x - light) / r, S the
 *    VTK spot term (0 outside the cone half-angle GetConeAngle(), else cos(angle to the
 *    axis)^GetExponent()), A = 1 / (c0 + c1 r + c2 r^2) from GetAttenuationValues();
 *  - point (positional, cone angle of 90 degrees or more): as a spot without the cone: S = 1;
 *  - directional (not positional): parallel light travelling from Position towards FocalPoint
 *    (unit direction a) that lights the half-space beyond the plane through Position
 *    perpendicular to a: r = (x - Position) . a is the distance from that plane (so a sun placed
 *    above the scene crosses an explicit depth of medium), l = a, S = A = 1.
 *
 * The default method, SLICES, clips the ray within each slab to where the light shines,
 * integrates A(r) in closed form and the rest with Gauss-Legendre, and looks the shadow map up
 * once per segment (docs/accuracy.md); SetMethod() selects another (README "Methods"). A
 * medium from data (SetMediumDensity) scales sigma_s and sigma_a by its density.
 *
 * With both coefficients zero, or with no usable light, the pass renders the delegate's image
 * unchanged (pixel-identical; one warning for a missing light).
 *
 * @sa vtkImageProcessingPass vtkLightShaftReference
 */

#ifndef vtkLightShaftPass_h
#define vtkLightShaftPass_h

#include "vtkCommand.h"             // For vtkCommand::UserEvent (ShadowMapRenderedEvent)
#include "vtkImageProcessingPass.h" // For the base class and the delegate pass
#include "vtkLightShaftsModule.h"   // For the export macro

#include <memory> // For std::unique_ptr (GL objects and state live in Internals)

class vtkAlgorithmOutput;
class vtkImageData;
class vtkLight;
class vtkMatrix4x4;
class vtkTexture;
class vtkTextureObject;

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

  /// Precision of the buffer the slabs add up in.
  enum AccumulationPrecisionType
  {
    ACCUMULATE_FLOAT32 = 0, ///< 32-bit float RGBA
    ACCUMULATE_FLOAT16 = 1, ///< 16-bit float RGBA
    ACCUMULATE_8BIT = 2     ///< 8-bit fixed point, the GDC 2004 talk's four-channel trick
  };

  /// How the in-scattered radiance is computed (the same model and parameters for all).
  enum MethodType
  {
    SLICES = 0,      ///< view-aligned slabs, shadow-mapped (Mitchell, GDC 2004; Dobashi et al.)
    RAY_MARCH = 1,   ///< per-pixel march with interleaved sampling (Toth & Umenhoffer 2009)
    RADIAL_BLUR = 2, ///< screen-space radial blur of an occlusion buffer (GPU Gems 3, ch. 13)
    ANALYTIC = 3,    ///< unshadowed closed form per pixel (exact when nothing occludes)
    AUTOMATIC = 4,   ///< ANALYTIC when the scene allows it, else SLICES (GetLastMethod says)
    EPIPOLAR = 5,    ///< marched along lines through the light's image, interpolated (Yusov 2013)
    LIGHT_VOLUME = 6 ///< crossings of the shadow map's shadow volume, closed form (Billeter 2010)
  };

  /// Events the pass invokes.
  enum EventIds
  {
    /// After the shadow map is rendered and before it is used: GetShadowMapTexture() is valid
    /// (and may be rewritten, e.g. combined over distributed processes), the context current.
    ShadowMapRenderedEvent = vtkCommand::UserEvent + 4301,
    /// After a frame whose picture is still refining (ProgressiveRefinement on, the view
    /// still, GetLastRefinementConverged() false): render again to refine it. Answer it from a
    /// timer or the event loop (lightshafts.refine_while_still does), not by rendering inside
    /// the callback: the renderer is still rendering this frame.
    RefinementNeededEvent = vtkCommand::UserEvent + 4302
  };

  /**
   * Render the scene and its light shafts. Called by the renderer.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Free every GL object the pass (and its internal passes) hold. Safe to call more than once
   * and with any window; the pass rebuilds what it needs on the next Render(). nullptr stands
   * for the window the pass last rendered in (made current first), and does nothing when there
   * is none: no GL object exists then.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The kinds of VTK light (README "Light kinds" has each one's conventions and formulas).
  enum LightKindType
  {
    SPOT_LIGHT = 0,       ///< positional, cone angle below 90 degrees
    POINT_LIGHT = 1,      ///< positional, cone angle of 90 degrees or more (no cone)
    DIRECTIONAL_LIGHT = 2 ///< not positional: parallel light from Position towards FocalPoint
  };

  ///@{
  /**
   * The lights that scatter. With none given, every switched-on spot and point light of the
   * renderer scatters (directional lights only when given: VTK's default headlight and light
   * kits are directional). Given lights may be of any kind; a given light that is switched
   * off contributes nothing. SetLight(l) means "only l" (SetLight(nullptr): automatic);
   * AddLight adds one more (ignored when already given), RemoveLight takes one out,
   * RemoveAllLights goes back to the automatic choice. GetLight() is the first given light
   * (nullptr: automatic), GetLight(i) the i-th. Default is none given (automatic choice).
   */
  void SetLight(vtkLight* light);
  void AddLight(vtkLight* light);
  void RemoveLight(vtkLight* light);
  void RemoveAllLights();
  int GetNumberOfLights();
  vtkLight* GetLight();
  vtkLight* GetLight(int index);
  ///@}

  ///@{
  /**
   * The lights the last frame used (the given ones that were switched on, or the automatic
   * choice), in the order their in-scatter was added: how many, and the i-th (nullptr out of
   * range). GetLastUsedLight() is the first; nullptr when the last frame found no usable light.
   */
  int GetLastNumberOfUsedLights();
  vtkLight* GetLastUsedLight(int index = 0);
  ///@}

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
   * A medium from data: sigma_s and sigma_a at x are scaled by MediumBackgroundDensity +
   * MediumDensityScale * rho(x), rho the first component of the named array (point or cell
   * data; the scalars when no name), trilinear inside the image's bounds (placed by its origin,
   * spacing and direction matrix) and 0 outside (README, "A medium from data"). An image that
   * cannot be one (no such array, not 3D, over 2^27 samples, NaN or negative values) is refused
   * with an error saying why; the previous field is kept. RAY_MARCH renders it (other methods
   * give way to it with one warning). Default is nullptr (homogeneous) and no name.
   */
  void SetMediumDensity(vtkImageData* density);
  vtkImageData* GetMediumDensity();
  /**
   * The field from a pipeline (replacing SetMediumDensity's image, and the reverse): brought
   * up to date every frame; an output that cannot be a field gets one error, and the last
   * usable field is kept. Default is nullptr.
   */
  void SetMediumDensityConnection(vtkAlgorithmOutput* output);
  vtkAlgorithmOutput* GetMediumDensityConnection();
  void SetMediumDensityArrayName(const char* name);
  const char* GetMediumDensityArrayName();
  ///@}

  ///@{
  /**
   * The field's scale and the density added everywhere (also outside the field), each in
   * [0, 1e6]; non-finite values are refused. Default is 1 and 0.
   */
  void SetMediumDensityScale(double scale);
  vtkGetMacro(MediumDensityScale, double);
  void SetMediumBackgroundDensity(double density);
  vtkGetMacro(MediumBackgroundDensity, double);
  ///@}

  ///@{
  /**
   * The light leg through the field: texels per axis of each light's table of the field's
   * optical depth (half as many per face of a cube around a light inside the field), built on
   * the CPU when the field or light moves; 0 marches it at every sample (slower; README, "A
   * medium from data"). In [0, 256]. Default is 64.
   */
  vtkSetClampMacro(MediumShadowResolution, int, 0, 256);
  vtkGetMacro(MediumShadowResolution, int);
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
   * Shadow the surfaces too (VTK's lighting has no shadows): take off the surfaces the light
   * that each scattering light's shadow map (the shafts' own) shadows, for every kind of light
   * and any delegate; one more render of the scene and one full-screen pass per light with
   * casters (README "Shadows on surfaces"), also when the medium is empty. Default is off.
   */
  vtkSetMacro(ShadowSurfaces, bool);
  vtkGetMacro(ShadowSurfaces, bool);
  vtkBooleanMacro(ShadowSurfaces, bool);
  ///@}

  ///@{
  /**
   * Translucent casters (props with opacity below 1) dim and tint the light that passes them,
   * in the shafts and with ShadowSurfaces on the surfaces: a surface of opacity a and diffuse
   * colour c passes 1 - a (1 - c) per channel, and the surfaces a ray crosses multiply. They
   * are peeled front to back into at most TranslucentShadowLayers layers per light, next to
   * its shadow map and kept with it (README "Translucent casters"). Off, they cast nothing.
   * Default is on.
   */
  vtkSetMacro(TranslucentShadows, bool);
  vtkGetMacro(TranslucentShadows, bool);
  vtkBooleanMacro(TranslucentShadows, bool);
  /// In [1, 8]; fewer when no surface is left or more would not fit side by side in the GL's
  /// largest texture; a light's layers hold at most 512 MiB (coarser if need be). Default is 4.
  vtkSetClampMacro(TranslucentShadowLayers, int, 1, 8);
  vtkGetMacro(TranslucentShadowLayers, int);
  ///@}

  ///@{
  /**
   * Number of view-aligned slabs spanning the depth range of the light volume inside the view,
   * in [1, 4096]. More slices: less error, more fill. Default is 64 (with Jitter and a blur of
   * radius 2: the measured front beats 128 plain slices in time and error, docs/benchmark.md).
   */
  vtkSetClampMacro(NumberOfSlices, int, 1, 4096);
  vtkGetMacro(NumberOfSlices, int);
  ///@}

  ///@{
  /**
   * Side of each light's square shadow map in texels, in [16, 16384] (further limited at render
   * time to the GL implementation's maximum texture size; a point light's six cube faces each
   * have this side, at most a third of that maximum). Default is 1024.
   */
  vtkSetClampMacro(ShadowMapSize, int, 16, 16384);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

  ///@{
  /**
   * Cookie (gobo): an RGB image projected from each spot and directional light. It multiplies
   * the light's intensity per direction (a directional light's per position across its beam),
   * in the shafts and on the surfaces the light lights (the scene is then rendered once more
   * per such light, without it). For a spotlight the image fills the square that circumscribes
   * the cone's cross-section, centred on the axis (clamped beyond it); for a directional light
   * it covers a square of side |FocalPoint - Position| centred on the axis through Position and
   * repeats across the light's plane (clouds, a canopy). Its rows run along the light camera's
   * view-up (world +Y projected, or +X for lights aiming along Y). Point lights get no cookie
   * (one warning). 8-bit images map 255 to 1, float images are used as they are (clamped to >= 0).
   * Mipmapped; the level follows each sample's footprint, so small cookie details near the
   * light are smoothed rather than aliased. nullptr turns it off. Default is nullptr.
   */
  void SetCookie(vtkTexture* cookie);
  vtkTexture* GetCookie();
  ///@}

  ///@{
  /**
   * Scrolling-noise density (the GDC 2004 talk's two scrolling layers): the scattering
   * coefficient at x is sigma_s * (1 + NoiseAmplitude * (N1 * N2 - 1)), N1 and N2 two tileable
   * noise layers projected from each light (a spot's and a directional light's square, as the
   * cookie; a point light's unit sphere of directions, triplanar), each of mean 1 over its tile,
   * scaled by NoiseScale (tiles across the light's square) and moved by NoiseVelocity1/2 (tiles
   * per unit of Time). The mean density is therefore sigma_s (exactly, when the layers are
   * uncorrelated): the amplitude changes the texture, not the average brightness. Extinction keeps
   * the mean coefficient. NoiseAmplitude in [0, 1], 0 = homogeneous (no noise code runs). Default
   * is 0.
   */
  void SetNoiseAmplitude(double amplitude);
  vtkGetMacro(NoiseAmplitude, double);
  ///@}

  ///@{
  /**
   * Noise tiles across the light's square, in [0.01, 1000]. Default is 3.
   */
  void SetNoiseScale(double scale);
  vtkGetMacro(NoiseScale, double);
  ///@}

  ///@{
  /**
   * Scroll velocities of the two noise layers, in tiles per unit of Time, each component in
   * [-1e3, 1e3]. Defaults are (0.04, 0.01) and (-0.015, 0.03).
   */
  void SetNoiseVelocity1(double u, double v);
  vtkGetVector2Macro(NoiseVelocity1, double);
  void SetNoiseVelocity2(double u, double v);
  vtkGetVector2Macro(NoiseVelocity2, double);
  ///@}

  ///@{
  /**
   * Animation time (any finite value, in the units of the velocities): the noise, and the
   * jitter pattern, are pure functions of it, so the same Time renders the same image.
   * Default is 0.
   */
  void SetTime(double time);
  vtkGetMacro(Time, double);
  ///@}

  ///@{
  /**
   * Your own noise instead of the generated one: the first component of the image, tiled
   * (repeat), rescaled to mean 1. nullptr uses the project's tileable noise (256x256,
   * five-octave gradient noise). Default is nullptr.
   */
  void SetNoiseTexture(vtkTexture* noise);
  vtkTexture* GetNoiseTexture();
  ///@}

  ///@{
  /**
   * Automatic slice count: slabs of thickness (far clipping distance) / MaximumNumberOfSlices,
   * as many as the lit part of the view volume needs, so a small or distant light volume gets
   * few slabs and one that spans the view gets up to MaximumNumberOfSlices. When off,
   * NumberOfSlices slabs always span the lit depth range. Default is off.
   */
  vtkSetMacro(AutomaticSliceCount, bool);
  vtkGetMacro(AutomaticSliceCount, bool);
  vtkBooleanMacro(AutomaticSliceCount, bool);
  ///@}

  ///@{
  /**
   * Cap of the automatic slice count, in [1, 4096]. Default is 512.
   */
  vtkSetClampMacro(MaximumNumberOfSlices, int, 1, 4096);
  vtkGetMacro(MaximumNumberOfSlices, int);
  ///@}

  ///@{
  /**
   * Interleaved slab offsets: each pixel of a 4x4 block shifts its slab boundaries by a
   * different sixteenth of a slab (an ordered pattern, so the image is deterministic), which
   * turns banding into fine noise that BlurRadius can remove. Default is on.
   */
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  ///@}

  ///@{
  /**
   * Radius in pixels (of the in-scatter buffer) of a depth-aware separable Gaussian blur of the
   * in-scattered radiance, in [0, 32]; samples whose surface depth differs from the centre's by
   * more than a few percent are left out, so shafts do not bleed across silhouettes. 0 = off.
   * Default is 2.
   */
  vtkSetClampMacro(BlurRadius, int, 0, 32);
  vtkGetMacro(BlurRadius, int);
  ///@}

  ///@{
  /**
   * In-scatter resolution: 1 (full), 2 (half) or 4 (quarter) in each direction; other values
   * are rounded down to one of these. The buffer is brought back to full resolution with
   * depth-aware (nearest-depth) upsampling, so no halo appears around foreground edges.
   * Default is 1.
   */
  void SetDownsampleFactor(int factor);
  vtkGetMacro(DownsampleFactor, int);
  ///@}

  ///@{
  /**
   * Precision of the buffer the slabs add up in: ACCUMULATE_FLOAT32, ACCUMULATE_FLOAT16 or
   * ACCUMULATE_8BIT. The 8-bit mode reproduces the GDC 2004 talk: slab k adds
   * Exposure * L into channel k mod 4 of an RGBA8 buffer (one per colour), the four channels
   * are summed at the end; each slab's contribution is rounded to 1/255, so its error grows
   * with the number of slices. Default is ACCUMULATE_FLOAT32.
   */
  vtkSetClampMacro(AccumulationPrecision, int, ACCUMULATE_FLOAT32, ACCUMULATE_8BIT);
  vtkGetMacro(AccumulationPrecision, int);
  void SetAccumulationPrecisionToFloat32() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT32); }
  void SetAccumulationPrecisionToFloat16() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT16); }
  void SetAccumulationPrecisionTo8Bit() { this->SetAccumulationPrecision(ACCUMULATE_8BIT); }
  ///@}

  ///@{
  /**
   * The method that computes the in-scattered radiance (README "Methods": how each works, its
   * cost and error); the parameters that are not method-specific mean the same in all.
   * - SLICES: view-aligned slabs (NumberOfSlices, Jitter, AutomaticSliceCount, precision).
   * - RAY_MARCH: NumberOfSteps segments per pixel through the lit part of its ray (1/r^2
   *   exact per step), interleaved over InterleaveSize^2 pixel blocks and gathered back.
   * - RADIAL_BLUR: ANALYTIC's in-scatter darkened by a screen-space radial blur of an
   *   occlusion buffer (RadialSamples, Decay, Weight, Density, RadialJitter); no shadow map.
   * - ANALYTIC: the unshadowed integral per pixel (closed form or float precision). Ignores
   *   shadows and noise (a warning says so when they would matter); the cookie is kept.
   * - AUTOMATIC: ANALYTIC when nothing casts a shadow into the light's volume and the noise is
   *   off, else SLICES. GetLastMethod() reports the choice.
   * - EPIPOLAR: RAY_MARCH's march at every EpipolarStep-th of EpipolarSamples samples on
   *   EpipolarLines lines through the light's screen image (and at depth breaks), the rest
   *   interpolated along and across the lines.
   * - LIGHT_VOLUME: the closed-form unshadowed in-scatter up to each crossing of the shadow
   *   map's shadow volume (LightVolumeResolution cells across the map). A light with a cookie,
   *   noise or translucent casters' layers gets RAY_MARCH, with one warning.
   * Default is SLICES.
   */
  vtkSetClampMacro(Method, int, SLICES, LIGHT_VOLUME);
  vtkGetMacro(Method, int);
  void SetMethodToSlices() { this->SetMethod(SLICES); }
  void SetMethodToRayMarch() { this->SetMethod(RAY_MARCH); }
  void SetMethodToRadialBlur() { this->SetMethod(RADIAL_BLUR); }
  void SetMethodToAnalytic() { this->SetMethod(ANALYTIC); }
  void SetMethodToAutomatic() { this->SetMethod(AUTOMATIC); }
  void SetMethodToEpipolar() { this->SetMethod(EPIPOLAR); }
  void SetMethodToLightVolume() { this->SetMethod(LIGHT_VOLUME); }
  static const char* GetMethodName(int method);
  ///@}

  ///@{
  /**
   * SLICES: evaluate the smooth part of the integrand (the mean of phase, spot and extinction
   * over each slab) at the vertices of an n x n lattice laid over each slab's footprint and
   * interpolate it, as Chen, Li and Wang do; the closed-form A(r) integral, the cone and
   * surface clipping, shadow, cookie and noise stay per pixel. In [0, 256]; 0 = per pixel.
   * Default is 0.
   */
  vtkSetClampMacro(LatticeResolution, int, 0, 256);
  vtkGetMacro(LatticeResolution, int);
  ///@}

  ///@{
  /**
   * RAY_MARCH: segments marched per pixel through the lit part of its ray (EPIPOLAR: per
   * marched sample), in [1, 4096]. Default is 16.
   */
  vtkSetClampMacro(NumberOfSteps, int, 1, 4096);
  vtkGetMacro(NumberOfSteps, int);
  ///@}

  ///@{
  /**
   * RAY_MARCH: side M of the interleaved-sampling block, in [1, 8]: the M^2 pixels of a block
   * shift their step boundaries by different fractions of a step, and two separable,
   * depth-aware gather passes (M pixels wide) average the block back, so each pixel sees
   * M^2 x NumberOfSteps samples for the price of NumberOfSteps. 1 = off. Even sizes gather
   * over M + 1 pixels with half-weight ends (centred, no half-pixel shift). Default is 2
   * (measured best on the benchmark: docs/benchmark.md).
   */
  vtkSetClampMacro(InterleaveSize, int, 1, 8);
  vtkGetMacro(InterleaveSize, int);
  ///@}

  ///@{
  /**
   * EPIPOLAR: the lines through the light's screen image along which the in-scatter is
   * sampled, in [4, 2048]. Their ends are evenly spaced along the in-scatter target's
   * boundary; no more lines are used than the boundary has pixels. Default is 512.
   */
  vtkSetClampMacro(EpipolarLines, int, 4, 2048);
  vtkGetMacro(EpipolarLines, int);
  ///@}

  ///@{
  /**
   * EPIPOLAR: the samples on each line, evenly spaced from where it enters the in-scatter
   * target to where it leaves it, in [2, 2048]; no more are used than two per pixel of the
   * target's diagonal. Default is 512.
   */
  vtkSetClampMacro(EpipolarSamples, int, 2, 2048);
  vtkGetMacro(EpipolarSamples, int);
  ///@}

  ///@{
  /**
   * EPIPOLAR: every how many samples of a line the in-scatter is marched, in [1, 64]; the
   * samples between are interpolated unless the depth breaks or the in-scatter changes by more
   * than a quarter between them. 1 marches every sample. Default is 16.
   */
  vtkSetClampMacro(EpipolarStep, int, 1, 64);
  vtkGetMacro(EpipolarStep, int);
  ///@}

  ///@{
  /**
   * LIGHT_VOLUME: the cells across the shadow map (a point light: across each cube face) of
   * the shadow volume's mesh, in [8, 1024]; each cell takes the depth of the map's texel at its
   * centre, so no more are used than the map has texels. Default is 256.
   */
  vtkSetClampMacro(LightVolumeResolution, int, 8, 1024);
  vtkGetMacro(LightVolumeResolution, int);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR (after GPU Gems 3 ch. 13): samples taken from each pixel towards the light's
   * screen position, in [1, 1024]. Default is 64.
   */
  vtkSetClampMacro(RadialSamples, int, 1, 1024);
  vtkGetMacro(RadialSamples, int);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR: the factor by which each farther sample's influence falls, in [0, 1] (1: all
   * equal). Non-finite values are refused. Default is 1.
   */
  void SetDecay(double decay);
  vtkGetMacro(Decay, double);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR: the fraction of the way to the light the samples cover, in [0, 1]. Non-finite
   * values are refused. Default is 1.
   */
  void SetDensity(double density);
  vtkGetMacro(Density, double);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR: how strongly the blurred occlusion darkens the shafts, in [0, 1] (0 gives the
   * unshadowed ANALYTIC image). The chapter's Exposure is the shared Exposure. Non-finite
   * values are refused. Default is 1.
   */
  void SetWeight(double weight);
  vtkGetMacro(Weight, double);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR: offset each pixel's samples by its own fraction of a step (stochastic
   * sampling: banding becomes noise). Default is on.
   */
  vtkSetMacro(RadialJitter, bool);
  vtkGetMacro(RadialJitter, bool);
  vtkBooleanMacro(RadialJitter, bool);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR: extent of the occlusion buffer relative to the screen, in [1, 4] (the
   * chapter's guard band): above 1 the casters' depth is rendered again with the frustum
   * widened by this factor, so occluders off the picture still cut the shafts on it (1: the
   * screen's depth; always 1 for explicit projections and off-centre windows). Measured in
   * README "Methods". Non-finite values are refused. Default is 1.
   */
  void SetRadialGuardBand(double extent);
  vtkGetMacro(RadialGuardBand, double);
  ///@}

  ///@{
  /**
   * Distributed rendering (each process holding part of the scene, e.g. ParaView under MPI):
   * the world bounds of every process's shadow casters. When set, all processes render their
   * shadow maps with one light camera (each one, cleared when it holds no caster, whenever any
   * caster reaches into the light's volume), so that an observer of ShadowMapRenderedEvent can
   * combine them (their minimum); AUTOMATIC and RADIAL_BLUR decide from them too. Default is
   * unset (this process's props).
   */
  void SetShadowCasterBounds(const double bounds[6]);
  void UnsetShadowCasterBounds();
  bool GetShadowCasterBounds(double bounds[6]);
  ///@}

  ///@{
  /**
   * Quality presets: each the cheapest setting of the error model's ladder whose 90th-percentile
   * error on random training scenes meets its aim (Draft 5%, Interactive 2%, Final 0.5%, the
   * most accurate setting when none does; docs/error-model.md, validated on other seeds in
   * docs/random-scenes.md):
   * - Draft: EPIPOLAR, 16 steps per sample, 128 lines of 256 samples, every 8th marched,
   *   512^2 shadow map;
   * - Interactive: LIGHT_VOLUME, 256 cells, 1024^2 shadow map;
   * - Final: RAY_MARCH, 256 steps, no interleaving, 2048^2 shadow map.
   * They set the method, its sampling, blur 0, full resolution, 32-bit float accumulation and
   * a fixed slice count; other parameters are unchanged. The defaults (64 jittered slabs, blur
   * 2) are none of them: smooth and cheap, but they spread a light seen in the picture.
   */
  void SetQualityToDraft();
  void SetQualityToInteractive();
  void SetQualityToFinal();
  ///@}

  ///@{
  /**
   * Target relative RMS error of the in-scatter against the float64 reference (over the pixels
   * above 1% of its peak), in [0, 1]; 0 turns it off. When on, each frame the pass computes
   * what its lights' geometry asks of the sampling (GetLastDepthRangeInBeamWidths and the
   * other error-model read-outs) and renders with the cheapest setting of its measured ladder
   * (EPIPOLAR, LIGHT_VOLUME and RAY_MARCH settings: the method, its sampling and the
   * shadow-map size; LIGHT_VOLUME's are left out when a cookie or noise is on) whose
   * predicted error meets the target, or with the most accurate one when none does; it then
   * overrides Method, the method's sampling parameters, AutomaticSliceCount, Jitter,
   * InterleaveSize, BlurRadius, DownsampleFactor, ShadowMapSize and AccumulationPrecision for
   * that frame (the values set apply again at 0). On held-out random scenes at least 90% meet
   * the target (README "Target error"). Non-finite values are refused. Default is 0 (off).
   */
  void SetTargetError(double error);
  vtkGetMacro(TargetError, double);
  ///@}

  ///@{
  /**
   * Progressive refinement of a still view. While nothing that decides the picture changes
   * (camera, viewport, the pass's parameters and Time, the lights, the props and their data,
   * cookie and noise images), each frame computes one more estimate of the in-scatter with
   * its samples shifted (the steps of RAY_MARCH and EPIPOLAR, SLICES' jittered slab
   * boundaries, and where in each step the shadow, cookie and noise are looked up) and shows
   * the mean of the estimates so far: the first is the picture without refinement, and n
   * estimates of s steps come close to one frame of n * s. After RefinementFrames estimates
   * (after one where nothing shifts: ANALYTIC, LIGHT_VOLUME, RADIAL_BLUR, unjittered slices)
   * the picture is converged: later frames reuse it without computing the shafts (unless
   * ShadowSurfaces or a cookie needs the surfaces' light) and it does not change. Any change
   * starts again from one estimate. Until converged, each frame ends with
   * RefinementNeededEvent. Default is off.
   */
  vtkSetMacro(ProgressiveRefinement, bool);
  vtkGetMacro(ProgressiveRefinement, bool);
  vtkBooleanMacro(ProgressiveRefinement, bool);
  ///@}

  ///@{
  /**
   * The estimates a still view's picture converges with, in [1, 4096]. Default is 16.
   */
  vtkSetClampMacro(RefinementFrames, int, 1, 4096);
  vtkGetMacro(RefinementFrames, int);
  ///@}

  ///@{
  /**
   * Frame budget in seconds, in [0, 3600]; 0 turns it off. While a budget applies, each frame
   * renders the most accurate sampling the pass predicts will fit it: a setting of the error
   * model's ladder (EPIPOLAR, LIGHT_VOLUME and RAY_MARCH settings, as TargetError's), at full
   * resolution if any fits, else at half, else at quarter resolution (DownsampleFactor), the
   * lowest predicted error first; with a TargetError as well, the cheapest of those that fit
   * and meet it at full resolution; when nothing fits, the cheapest. A cost model learnt from
   * the frames rendered under a budget (each ended with glFinish) predicts the time. While the
   * view is still the choice is kept. It overrides the parameters as TargetError does.
   * Non-finite values are refused. Default is 0 (off).
   */
  void SetTimeBudget(double seconds);
  vtkGetMacro(TimeBudget, double);
  ///@}

  ///@{
  /**
   * Follow VTK's interaction idiom: while the renderer's AllocatedRenderTime is under 10 s (an
   * interactor sets the window's DesiredUpdateRate while the user drags, 15 frames per second
   * by default: 1/15 s), it is the frame budget (the smaller of the two with TimeBudget); at
   * rest (StillUpdateRate: 10000 s) and in scripts that never set a rate there is none. Default
   * is on.
   */
  vtkSetMacro(UseAllocatedRenderTime, bool);
  vtkGetMacro(UseAllocatedRenderTime, bool);
  vtkBooleanMacro(UseAllocatedRenderTime, bool);
  ///@}

  ///@{
  /**
   * The frame budget after the last frame: the budget it had (seconds; 0: none), the frame time
   * predicted for the sampling chosen (-1: no budget), the time it measured (the shafts' part
   * of the frame, scene and composite included; -1: not measured, only frames under a budget
   * are), and the in-scatter's resolution factor it rendered with (DownsampleFactor, or the
   * budget's or target's choice). GetLastErrorModelSetting() names the setting.
   */
  vtkGetMacro(LastTimeBudget, double);
  vtkGetMacro(LastPredictedFrameTime, double);
  vtkGetMacro(LastFrameTime, double);
  vtkGetMacro(LastDownsampleFactor, int);
  ///@}

  ///@{
  /**
   * Progressive refinement's state after the last frame: the estimates averaged into its
   * picture (0: refinement off, or nothing computed), whether that picture is converged, and
   * whether the frame reused the converged in-scatter instead of computing it.
   */
  vtkGetMacro(LastRefinementEstimates, int);
  vtkGetMacro(LastRefinementConverged, bool);
  vtkGetMacro(LastInScatterReused, bool);
  ///@}

  ///@{
  /**
   * The error model's view of the last frame. The predicted relative RMS error: that of the
   * setting TargetError chose, or of the parameters set when they equal a setting of the
   * model's ladder (the presets do); -1 when there was no prediction (another method or
   * setting, or no lit light). The ladder setting used (-1: none) and its name.
   */
  vtkGetMacro(LastPredictedError, double);
  vtkGetMacro(LastErrorModelSetting, int);
  static const char* GetErrorModelSettingName(int setting);
  /// What the first lit light's geometry asks of the sampling: the lit volume's view-depth
  /// range over the beam's width at its centre, that width in pixels, the medium's optical
  /// depth over the range, the width of a 1024^2 shadow map's texel there in pixels (0: no
  /// caster, no map), and whether the light projects inside the view (all 0 when no light
  /// was lit).
  vtkGetMacro(LastDepthRangeInBeamWidths, double);
  vtkGetMacro(LastBeamWidthInPixels, double);
  vtkGetMacro(LastOpticalDepth, double);
  vtkGetMacro(LastShadowTexelInPixels, double);
  vtkGetMacro(LastLightInView, bool);
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
   * What the last frame did, for tests and tuning.
   */
  /// The method it used (AUTOMATIC resolved; -1 when no shafts were computed).
  vtkGetMacro(LastMethod, int);
  /// Slabs drawn (0 when the shafts were skipped), and the clipped view-depth range they span.
  vtkGetMacro(LastNumberOfSlicesDrawn, int);
  vtkGetVector2Macro(LastSliceDepthRange, double);
  /// Draw calls the slabs took (they are drawn in batches of bounded size).
  vtkGetMacro(LastNumberOfSlabBatches, int);
  /// The lattice resolution the slabs used: LatticeResolution, or less when that would exceed
  /// the per-frame budget of 2^21 lattice cells (0: no lattice).
  vtkGetMacro(LastLatticeResolution, int);
  /// The steps RAY_MARCH and EPIPOLAR took per ray: NumberOfSteps, or fewer when the frame's
  /// rays would integrate more than 2^30 segments with them, shared by the frame's radiating
  /// lights (one warning; the fewest of the lights; 0: neither method). SLICES' slabs obey
  /// the same budget (GetLastNumberOfSlicesDrawn).
  vtkGetMacro(LastNumberOfSteps, int);
  /// Full-screen-sized passes run after the slabs/march (gather, blur, guard band, ...).
  vtkGetMacro(LastNumberOfPostPasses, int);
  /// The guard band RADIAL_BLUR used (0 when it did not run).
  vtkGetMacro(LastRadialGuardBand, double);
  /// How many times the scene was rendered (2 with a cookie: with and without the spotlight).
  vtkGetMacro(LastNumberOfSceneRenders, int);
  /// Samples per pixel the scene was rendered with: those of the target the pass draws into
  /// (the window's MultiSamples), 0 when it is not multisampled.
  vtkGetMacro(LastMultiSamples, int);
  /// True when the render drew only the plain scene, exactly as without the pass: the renderer
  /// was rendering for a hardware selector (picking, selection), for an enclosing pass that
  /// renders the props with its own shaders (a shadow-map baker, a value pass) or by their
  /// keys, or into a target without colour; the shafts come back on the next frame.
  vtkGetMacro(LastPlainScene, bool);
  /// Whether the pass applied the renderer's FXAA (vtkRenderer::UseFXAA) to its picture, as
  /// VTK's own render does with no pass: on, into a single-sampled target, and not a plain
  /// render (an enclosing pass or a selector decides there).
  vtkGetMacro(LastRendererFXAA, bool);
  /// The viewport's size in pixels.
  vtkGetVector2Macro(LastViewportSize, int);
  /// OpenGL errors raised while the frame rendered (the pass, its delegate and its internal
  /// passes); 0 when all is well. Errors pending before the frame are not counted.
  vtkGetMacro(LastGLErrorCount, int);
  /// The features compiled into the slab shader (e.g. "method=slices phase=isotropic shadow
  /// cookie noise jitter accumulate=float32"), and that shader's fragment source.
  const char* GetLastShaderVariant();
  const char* GetLastSliceShaderSource();
  ///@}

  ///@{
  /**
   * The last frame's shadow maps: whether any light's shafts were shadowed by one (rendered
   * this frame or reused), and how many casters they had (summed over the lights: the props
   * whose bounds reach into each light's volume). The light camera's near and far distances
   * and the depth tolerance of the lookup are the first shadowed light's: for spot and point
   * lights relative (lit when w <= stored depth * (1 + bias), nearest texel), for a directional
   * light absolute, in world units (lit when depth <= stored depth + bias).
   */
  vtkGetMacro(LastShadowMapRendered, bool);
  vtkGetMacro(LastNumberOfShadowCasters, int);
  vtkGetVector2Macro(LastLightDepthRange, double);
  vtkGetMacro(LastShadowBias, double);
  ///@}

  ///@{
  /**
   * What the last frame did for its i-th used light (0 <= i < GetLastNumberOfUsedLights();
   * out of range: -1, 0 or false): its kind (LightKindType); the method that computed its
   * in-scatter (-1: none, e.g. its light is outside the view); the slabs drawn for it; whether
   * its shadow map was rendered this frame, or reused from an earlier frame because nothing
   * that decides it changed (the light, its casters and their data, the map's size and
   * extent); its casters; and the GPU time its in-scatter took (its shadow map, slabs or march
   * and own passes), in milliseconds, measured with OpenGL timer queries of the most recent
   * frame whose queries completed (-1 where timer queries are not available); its light-leg
   * table through a medium from data: bytes (0: none) and build milliseconds (0: reused); its
   * translucent casters' layers: how many (0: none) and their bytes.
   */
  int GetLastLightKind(int index);
  int GetLastLightMethod(int index);
  int GetLastLightSlicesDrawn(int index);
  bool GetLastLightShadowMapRendered(int index);
  bool GetLastLightShadowMapReused(int index);
  int GetLastLightShadowCasters(int index);
  double GetLastLightTime(int index);
  double GetLastLightFieldShadowBytes(int index);
  double GetLastLightFieldShadowBuildTime(int index);
  int GetLastLightTranslucentLayers(int index);
  double GetLastLightTranslucentBytes(int index);
  ///@}

  /**
   * The last frame's shadow map of its i-th used light (default the first), for a reference
   * that uses the same visibility (vtkLightShaftReference::SetVisibilityModeToShadowMap):
   * `depths` gets the depth-buffer values (float, N x N, 1 = nothing), `worldToLightClip` the
   * light camera's world-to-clip matrix (perspective for a spot, orthographic for a
   * directional light). Returns false when that light had no shadow map, and for a point
   * light (its map is a cube: six cameras).
   */
  bool GetLastShadowMap(vtkImageData* depths, vtkMatrix4x4* worldToLightClip, int index = 0);

  /**
   * The shadow map's depth texture (32-bit float depth, N x N, 1 = nothing) while
   * ShadowMapRenderedEvent is being handled; nullptr at any other time.
   */
  vtkTextureObject* GetShadowMapTexture();

protected:
  vtkLightShaftPass();
  ~vtkLightShaftPass() override;

  // Parameters.
  double ScatteringCoefficient[3] = { 0.1, 0.1, 0.1 };
  double AbsorptionCoefficient[3] = { 0.0, 0.0, 0.0 };
  double MediumDensityScale = 1.0;
  double MediumBackgroundDensity = 0.0;
  int MediumShadowResolution = 64;
  int PhaseFunction = ISOTROPIC;
  double Anisotropy = 0.0;
  double Exposure = 1.0;
  bool AttenuateScene = true;
  bool ShadowSurfaces = false;
  bool TranslucentShadows = true;
  int TranslucentShadowLayers = 4;
  int NumberOfSlices = 64;
  int ShadowMapSize = 1024;
  double NoiseAmplitude = 0.0;
  double NoiseScale = 3.0;
  double NoiseVelocity1[2] = { 0.04, 0.01 };
  double NoiseVelocity2[2] = { -0.015, 0.03 };
  double Time = 0.0;
  bool AutomaticSliceCount = false;
  int MaximumNumberOfSlices = 512;
  bool Jitter = true;
  int BlurRadius = 2;
  int DownsampleFactor = 1;
  int AccumulationPrecision = ACCUMULATE_FLOAT32;
  int Method = SLICES;
  int LatticeResolution = 0;
  int NumberOfSteps = 16;
  int InterleaveSize = 2;
  int RadialSamples = 64;
  int EpipolarLines = 512;
  int EpipolarSamples = 512;
  int EpipolarStep = 16;
  int LightVolumeResolution = 256;
  double Decay = 1.0;
  double Density = 1.0;
  double Weight = 1.0;
  bool RadialJitter = true;
  double RadialGuardBand = 1.0;
  double TargetError = 0.0;
  bool ProgressiveRefinement = false;
  int RefinementFrames = 16;
  double TimeBudget = 0.0;
  bool UseAllocatedRenderTime = true;

  // Last-frame statistics.
  int LastNumberOfSlicesDrawn = 0;
  bool LastShadowMapRendered = false;
  double LastSliceDepthRange[2] = { 0.0, 0.0 };
  int LastViewportSize[2] = { 0, 0 };
  int LastGLErrorCount = 0;
  int LastNumberOfShadowCasters = 0;
  double LastLightDepthRange[2] = { 0.0, 0.0 };
  double LastShadowBias = 0.0;
  int LastNumberOfSceneRenders = 0;
  int LastMethod = -1;
  bool UseShadowCasterBounds = false;
  double ShadowCasterBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  int LastNumberOfPostPasses = 0;
  double LastRadialGuardBand = 0.0;
  int LastLatticeResolution = 0;
  int LastNumberOfSteps = 0;
  int LastNumberOfSlabBatches = 0;
  int LastMultiSamples = 0;
  bool LastPlainScene = false;
  bool LastRendererFXAA = false;
  double LastPredictedError = -1.0;
  int LastErrorModelSetting = -1;
  double LastDepthRangeInBeamWidths = 0.0;
  double LastBeamWidthInPixels = 0.0;
  double LastOpticalDepth = 0.0;
  double LastShadowTexelInPixels = 0.0;
  bool LastLightInView = false;
  int LastRefinementEstimates = 0;
  bool LastRefinementConverged = false;
  bool LastInScatterReused = false;
  double LastTimeBudget = 0.0;
  double LastPredictedFrameTime = -1.0;
  double LastFrameTime = -1.0;
  int LastDownsampleFactor = 1;

private:
  void RenderFrame(const vtkRenderState* s);

  vtkLightShaftPass(const vtkLightShaftPass&) = delete;
  void operator=(const vtkLightShaftPass&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
