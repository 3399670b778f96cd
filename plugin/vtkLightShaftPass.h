/**
 * @class   vtkLightShaftPass
 * @brief   Adds physically based volumetric light shafts (single scattering of the scene's
 *          lights in a participating medium, shadowed by the scene) to any VTK scene.
 *
 * Use it as the renderer's pass:
 * @code{.cpp}
 *   vtkNew<vtkLightShaftPass> shafts;
 *   shafts->GetMedium()->SetScatteringCoefficient(0.2);
 *   shafts->SetQualityToInteractive();
 *   renderer->SetPass(shafts);
 * @endcode
 *
 * The pass holds how the shafts are computed: the method and its sampling, quality presets,
 * target error, frame budget, refinement, exposure, the lights, cookie, shadows on surfaces
 * and translucency. What the medium is (coefficients, phase function, noise, density field)
 * is a vtkLightShaftMedium, shareable between passes (GetMedium, SetMedium); what the last
 * frame did is a vtkLightShaftFrameReport (GetLastFrame).
 *
 * Every frame the pass renders the scene through its delegate off screen, a depth map of what
 * shadows each scattering light (kept while nothing that decides it changes), and the
 * in-scattered radiance L_in (the integral along each view ray up to the first surface of
 * sigma_s, the phase function, the light's intensity, cone, attenuation and visibility, and
 * the transmittance of both legs: docs/methods.md), then composites
 * out = scene * exp(-sigma_t * t_surface) + Exposure * L_in.
 *
 * With a medium that neither scatters nor absorbs, or with no usable light, the pass renders
 * the delegate's image unchanged (pixel-identical; one warning for a missing light).
 * Floating-point setters refuse NaN and infinities with an error naming the parameter (the
 * previous value is kept) and clamp other values into their range (docs/parameters.md).
 *
 * @sa vtkLightShaftMedium vtkLightShaftFrameReport vtkLightShaftReference
 */

#ifndef vtkLightShaftPass_h
#define vtkLightShaftPass_h

#include "vtkCommand.h"               // For vtkCommand::UserEvent (ShadowMapRenderedEvent)
#include "vtkImageProcessingPass.h"   // For the base class and the delegate pass
#include "vtkLightShaftFrameReport.h" // For GetLastFrame's object (read through the pass)
#include "vtkLightShaftMedium.h"      // For GetMedium's object (set through the pass)
#include "vtkLightShaftsModule.h"     // For the export macro

#include <memory> // For std::unique_ptr (GL objects and state live in Internals)

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
    AUTOMATIC = 4,   ///< ANALYTIC when the scene allows it, else SLICES (the frame report says)
    EPIPOLAR = 5,    ///< marched along lines through the light's image, interpolated (Yusov 2013)
    LIGHT_VOLUME = 6 ///< crossings of the shadow map's shadow volume, closed form (Billeter 2010)
  };

  /// Events the pass invokes.
  enum EventIds
  {
    /// After the shadow map is rendered and before it is used: GetShadowMapTexture() is valid
    /// (and may be rewritten, e.g. combined over distributed processes), the context current.
    ShadowMapRenderedEvent = vtkCommand::UserEvent + 4301,
    /// After a frame whose still picture is refining: render again, from a timer or the event
    /// loop (lightshafts.refine_while_still), never inside the callback.
    RefinementNeededEvent = vtkCommand::UserEvent + 4302
  };

  /// Render the scene and its light shafts (called by the renderer).
  void Render(const vtkRenderState* s) override;

  /**
   * Free every GL object the pass holds; safe to call more than once. nullptr stands for the
   * window the pass last rendered in (none: nothing to free).
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// The kinds of VTK light (docs/lights-and-cookies.md).
  enum LightKindType
  {
    SPOT_LIGHT = 0,       ///< positional, cone angle below 90 degrees
    POINT_LIGHT = 1,      ///< positional, cone angle of 90 degrees or more (no cone)
    DIRECTIONAL_LIGHT = 2 ///< not positional: parallel light from Position towards FocalPoint
  };

  ///@{
  /**
   * The lights that scatter, of any kind (a switched-off one adds nothing). With none given,
   * every switched-on spot and point light of the renderer (VTK's default headlight and light
   * kits are directional: those only when given). SetLight(l) means "only l", nullptr or
   * RemoveAllLights the automatic choice. Default is none given (automatic).
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
   * The medium the shafts scatter in (vtkLightShaftMedium: coefficients, phase function, noise,
   * density field), shareable between passes; nullptr gives the pass a new one. The pass's
   * MTime includes its medium's. Default is a vtkLightShaftMedium of its own.
   */
  void SetMedium(vtkLightShaftMedium* medium);
  vtkLightShaftMedium* GetMedium();
  vtkMTimeType GetMTime() override;
  ///@}

  /// What the last frame did: one object, updated at the end of each frame.
  vtkLightShaftFrameReport* GetLastFrame();

  ///@{
  /**
   * Exposure: the scale of the in-scattered radiance added to the picture, in [0, 1e6]
   * (GetInScatteredRadiance returns it before the scale). AttenuateScene: the scene dimmed by
   * the medium's transmittance exp(-sigma_t t_surface) (aerial perspective). Defaults are 1
   * and on.
   */
  void SetExposure(double exposure);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(AttenuateScene, bool);
  vtkGetMacro(AttenuateScene, bool);
  vtkBooleanMacro(AttenuateScene, bool);
  ///@}

  ///@{
  /**
   * Choose the medium from the scene: the next frame with a 3D prop and a light sets the
   * medium's ScatteringCoefficient (grey; AbsorptionCoefficient 0) and the Exposure so that a scene
   * 1, 100 or 10,000 units across gives the same picture up to scale: an optical depth of 0.9
   * across the scene's box, and the in-scatter across the first light's beam at the box's centre
   * brought to 0.6 (vtkLightShaftModel::FittedScattering, FittedExposure; docs/getting-started.md).
   * The values chosen are then the medium's and the pass's, as their getters report (the frame
   * report's GetMediumFitted marks the frame that chose them), and stay. A coefficient (scattering
   * or absorption) or an exposure set after this was switched on wins and is kept; the rest is
   * chosen around it. Switching it on again chooses again. Default is off (add_light_shafts
   * and the PyVista and ParaView views switch it on when given no coefficient or exposure).
   */
  void SetFitMediumToScene(bool fit);
  vtkGetMacro(FitMediumToScene, bool);
  vtkBooleanMacro(FitMediumToScene, bool);
  ///@}

  ///@{
  /**
   * ShadowSurfaces: light the surfaces as the shafts are lit (VTK's lighting has no shadows):
   * each light's share of a surface's colour is shadowed by its shadow map (opaque and
   * translucent casters, the scene's volume) and, with AttenuateSurfaceLight, dimmed by the
   * medium on the light's way to the surface: exp(-sigma_t times the optical depth of that
   * leg), homogeneous or through the density field. For every kind of light: one more render
   * of the scene and a full-screen pass per light, also when the medium is empty
   * (docs/lights-and-cookies.md). AttenuateSurfaceLight off keeps VTK's own surface lighting
   * but for the shadows. Defaults are off and on.
   */
  vtkSetMacro(ShadowSurfaces, bool);
  vtkGetMacro(ShadowSurfaces, bool);
  vtkBooleanMacro(ShadowSurfaces, bool);
  vtkSetMacro(AttenuateSurfaceLight, bool);
  vtkGetMacro(AttenuateSurfaceLight, bool);
  vtkBooleanMacro(AttenuateSurfaceLight, bool);
  ///@}

  ///@{
  /**
   * Translucent casters (opacity below 1) dim and tint the light that passes them: a surface
   * of opacity a and diffuse colour c passes 1 - a (1 - c) per channel, and surfaces multiply.
   * They are peeled into at most TranslucentShadowLayers layers per light, in [1, 8] (fewer
   * when no surface is left; at most 512 MiB a light), kept with its shadow map, and as many
   * from the camera: the shafts behind a surface are dimmed by 1 - a, as VTK blends the scene
   * behind it (docs/translucent-and-volumes.md). Off, they cast nothing (the camera leg
   * stays). Defaults are on and 4.
   */
  vtkSetMacro(TranslucentShadows, bool);
  vtkGetMacro(TranslucentShadows, bool);
  vtkBooleanMacro(TranslucentShadows, bool);
  vtkSetClampMacro(TranslucentShadowLayers, int, 1, 8);
  vtkGetMacro(TranslucentShadowLayers, int);
  ///@}

  ///@{
  /**
   * SLICES: view-aligned slabs spanning the lit depth range in view, in [1, 4096]; Jitter
   * shifts each pixel of a 4x4 block by its own sixteenth of a slab (deterministic), turning
   * banding into fine noise that BlurRadius removes. Defaults are 64 and on (with blur 2 they
   * beat 128 plain slices in time and error).
   */
  vtkSetClampMacro(NumberOfSlices, int, 1, 4096);
  vtkGetMacro(NumberOfSlices, int);
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  ///@}

  ///@{
  /**
   * Side of each light's square shadow map (a point light's: of each cube face) in texels, in
   * [16, 16384], further limited to what the GL holds. Default is 1024.
   */
  vtkSetClampMacro(ShadowMapSize, int, 16, 16384);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

  ///@{
  /**
   * Cookie (gobo): an RGB image projected from each spot and directional light onto the
   * shafts and the surfaces it lights (a spot's fills the square around its cone; a sun's
   * repeats over squares of side |FocalPoint - Position|); point lights get none (one warning).
   * 8-bit images map 255 to 1 (docs/lights-and-cookies.md). Default is nullptr (none).
   */
  void SetCookie(vtkTexture* cookie);
  vtkTexture* GetCookie();
  ///@}

  ///@{
  /**
   * SLICES: automatic slice count. On, slabs of thickness (far clipping distance) /
   * MaximumNumberOfSlices, as many as the lit part of the view needs (a small or distant light
   * volume gets few); off, NumberOfSlices slabs span the lit depth range. The cap is in
   * [1, 4096]. Defaults are off and 512.
   */
  vtkSetMacro(AutomaticSliceCount, bool);
  vtkGetMacro(AutomaticSliceCount, bool);
  vtkBooleanMacro(AutomaticSliceCount, bool);
  vtkSetClampMacro(MaximumNumberOfSlices, int, 1, 4096);
  vtkGetMacro(MaximumNumberOfSlices, int);
  ///@}

  ///@{
  /**
   * Post-processing of the in-scatter: the radius in pixels, in [0, 32] (0: off), of a
   * depth-aware separable Gaussian blur that does not bleed across silhouettes; and its
   * resolution, 1 (full), 2 (half) or 4 (quarter) in each direction (other values rounded
   * down), brought back with depth-aware upsampling. Defaults are 2 and 1.
   */
  vtkSetClampMacro(BlurRadius, int, 0, 32);
  vtkGetMacro(BlurRadius, int);
  void SetDownsampleFactor(int factor);
  vtkGetMacro(DownsampleFactor, int);
  ///@}

  ///@{
  /**
   * SLICES: precision of the buffer the slabs add up in. ACCUMULATE_8BIT reproduces the GDC
   * 2004 talk (slab k adds into channel k mod 4 of an RGBA8 buffer, rounded to 1/255 each).
   * Default is ACCUMULATE_FLOAT32.
   */
  vtkSetClampMacro(AccumulationPrecision, int, ACCUMULATE_FLOAT32, ACCUMULATE_8BIT);
  vtkGetMacro(AccumulationPrecision, int);
  void SetAccumulationPrecisionToFloat32() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT32); }
  void SetAccumulationPrecisionToFloat16() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT16); }
  void SetAccumulationPrecisionTo8Bit() { this->SetAccumulationPrecision(ACCUMULATE_8BIT); }
  ///@}

  ///@{
  /**
   * The method that computes the in-scattered radiance (docs/methods.md: how each works, its
   * cost and error); the parameters that are not method-specific mean the same in all.
   * ANALYTIC ignores shadows and noise; AUTOMATIC is ANALYTIC when nothing casts a shadow into
   * the light's volume and the noise is off, else SLICES; LIGHT_VOLUME gives way to RAY_MARCH
   * for a light with a cookie, noise, translucent casters or a density field. A method set
   * here warns once where it cannot be used as asked; one chosen by a preset, TargetError or
   * the budget gives way silently (the frame report's GetLightMethodFallback says why).
   * GetMethodName names a method ("slices", "ray-march", ...). Default is SLICES.
   */
  virtual void SetMethod(int method);
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
   * SLICES: the smooth part of the integrand evaluated at the vertices of an n x n lattice
   * over each slab and interpolated (Chen, Li and Wang); shadows, cookie and noise stay per
   * pixel. In [0, 256]; 0: per pixel. Default is 0.
   */
  vtkSetClampMacro(LatticeResolution, int, 0, 256);
  vtkGetMacro(LatticeResolution, int);
  ///@}

  ///@{
  /**
   * RAY_MARCH: segments marched per pixel through the lit part of its ray (EPIPOLAR: per
   * marched sample), in [1, 4096]; and the side M of the interleaved-sampling block, in
   * [1, 8]: the M^2 pixels of a block shift their steps by different fractions and
   * depth-aware gathers average them back, so each pixel sees M^2 x NumberOfSteps samples for
   * the price of NumberOfSteps (1: off). Defaults are 16 and 2.
   */
  vtkSetClampMacro(NumberOfSteps, int, 1, 4096);
  vtkGetMacro(NumberOfSteps, int);
  vtkSetClampMacro(InterleaveSize, int, 1, 8);
  vtkGetMacro(InterleaveSize, int);
  ///@}

  ///@{
  /**
   * EPIPOLAR: the lines through the light's screen image, in [4, 2048] (ends evenly spaced
   * along the in-scatter target's boundary, at most one per boundary pixel); the samples on
   * each line, in [2, 2048] (at most two per pixel of the target's diagonal); and every how
   * many samples the in-scatter is marched, in [1, 64] (the others are interpolated unless the
   * depth breaks or the in-scatter changes by more than a quarter). Defaults are 512, 512
   * and 16.
   */
  vtkSetClampMacro(EpipolarLines, int, 4, 2048);
  vtkGetMacro(EpipolarLines, int);
  vtkSetClampMacro(EpipolarSamples, int, 2, 2048);
  vtkGetMacro(EpipolarSamples, int);
  vtkSetClampMacro(EpipolarStep, int, 1, 64);
  vtkGetMacro(EpipolarStep, int);
  ///@}

  ///@{
  /**
   * LIGHT_VOLUME: the cells across the shadow map (a point light: across each cube face) of
   * the shadow volume's mesh, in [8, 1024]; each cell takes the depth of the map's texel at its
   * centre, so no more are used than the map has texels, and with SplitLongFrames and
   * ProgressiveRefinement on no more than a frame's allowance (2^22 cells over the lights at
   * 640x480, fewer on larger frames; one warning). Default is 256.
   */
  vtkSetClampMacro(LightVolumeResolution, int, 8, 1024);
  vtkGetMacro(LightVolumeResolution, int);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR (after GPU Gems 3 ch. 13): samples from each pixel towards the light's screen
   * position, in [1, 1024]; Decay, the factor by which each farther sample's influence falls,
   * in [0, 1]; Density, the fraction of the way to the light the samples cover, in [0, 1];
   * Weight, how strongly the blurred occlusion darkens the shafts, in [0, 1] (0: ANALYTIC's
   * picture); RadialJitter, each pixel's samples offset by its own fraction of a step; and
   * the guard band, the occlusion buffer's extent relative to the screen, in [1, 4] (above 1
   * the casters are rendered again in a widened frustum so that occluders off the picture
   * still cut its shafts). Defaults are 64, 1, 1, 1, on and 1.
   */
  vtkSetClampMacro(RadialSamples, int, 1, 1024);
  vtkGetMacro(RadialSamples, int);
  void SetDecay(double decay);
  vtkGetMacro(Decay, double);
  void SetDensity(double density);
  vtkGetMacro(Density, double);
  void SetWeight(double weight);
  vtkGetMacro(Weight, double);
  vtkSetMacro(RadialJitter, bool);
  vtkGetMacro(RadialJitter, bool);
  vtkBooleanMacro(RadialJitter, bool);
  void SetRadialGuardBand(double extent);
  vtkGetMacro(RadialGuardBand, double);
  ///@}

  ///@{
  /**
   * Distributed rendering (e.g. ParaView under MPI): the world bounds of every process's
   * shadow casters. When set, all processes render their shadow maps with one light camera,
   * so that an observer of ShadowMapRenderedEvent can combine them (docs/paraview.md).
   * Default is unset (this process's props).
   */
  void SetShadowCasterBounds(const double bounds[6]);
  void UnsetShadowCasterBounds();
  bool GetShadowCasterBounds(double bounds[6]);
  ///@}

  ///@{
  /**
   * Quality presets: each the cheapest setting of the error model's ladder whose
   * 90th-percentile error on random training scenes meets its aim (Draft 5%, Interactive 2%,
   * Final 0.5%): Draft is EPIPOLAR with a 512^2 map, Interactive LIGHT_VOLUME with 256 cells
   * and a 1024^2 map, Final RAY_MARCH with 256 steps and a 2048^2 map. They set the method, its
   * sampling, blur 0, full resolution and float32 accumulation; other parameters are unchanged
   * (docs/quality-and-cost.md). The defaults are none of them.
   */
  void SetQualityToDraft();
  void SetQualityToInteractive();
  void SetQualityToFinal();
  ///@}

  ///@{
  /**
   * Target relative RMS error of the in-scatter against the float64 reference, in [0, 1]; 0
   * turns it off. When on, each frame renders with the cheapest setting of the error model's
   * measured ladder whose predicted error for this scene meets the target (the most accurate
   * one when none does), overriding the method, its sampling, ShadowMapSize, BlurRadius,
   * DownsampleFactor and AccumulationPrecision for that frame (docs/quality-and-cost.md). On
   * held-out random scenes at least 90% meet it. Default is 0 (off).
   */
  void SetTargetError(double error);
  vtkGetMacro(TargetError, double);
  ///@}

  ///@{
  /**
   * Progressive refinement of a still view: while nothing that decides the picture changes,
   * each frame computes one more estimate with its samples shifted and shows the mean so far;
   * after RefinementFrames estimates, in [1, 4096] (one where nothing shifts), the picture is
   * converged and later frames reuse it. Until then each frame ends with
   * RefinementNeededEvent. Any change starts again (docs/quality-and-cost.md). Defaults are
   * off and 16.
   */
  vtkSetMacro(ProgressiveRefinement, bool);
  vtkGetMacro(ProgressiveRefinement, bool);
  vtkBooleanMacro(ProgressiveRefinement, bool);
  vtkSetClampMacro(RefinementFrames, int, 1, 4096);
  vtkGetMacro(RefinementFrames, int);
  ///@}

  ///@{
  /**
   * The exact finish of a still view (with ProgressiveRefinement): from the second frame of
   * the same view, worker threads at idle priority integrate the float64 reference
   * (vtkLightShaftReference) tile by tile, brightest first, and each frame shows the tiles
   * finished so far in place of the estimate; the picture ends at the reference. While it
   * runs no further estimate is computed (the view keeps its last one, so it is never worse
   * than the last moving frame, and frames cost only the scene and the composite), and each
   * frame ends with RefinementNeededEvent; any change stops it and discards what it computed.
   * A scene the reference cannot model (a visible prop other than a polygonal vtkActor drawn
   * as a surface or a vtkVolume, or an off-axis camera) is refined as without it; the frame
   * report says why (GetExactFinishProblem). Default is off.
   */
  vtkSetMacro(ExactFinish, bool);
  vtkGetMacro(ExactFinish, bool);
  vtkBooleanMacro(ExactFinish, bool);
  ///@}

  ///@{
  /**
   * Spread a long frame's work over frames (with ProgressiveRefinement): where the setting's
   * in-scatter would integrate more than 2^26 segments in a frame (a step of a march or a slab
   * across a pixel; at most about 2 s a frame on a CPU's llvmpipe), RAY_MARCH, SLICES and EPIPOLAR
   * integrate a power-of-two share of its steps or slabs per frame (every n-th of them, each
   * standing for n), the fewest shares that fit (one step or slab each at least), moving or
   * still; RADIAL_BLUR so shares its samples beyond 2^30 a frame. Refinement accumulates a
   * group of shares into one frame of the setting, piece for piece, and the frame report's
   * GetRefinementSplit() says how many shares a frame's work was split into. (Through a medium
   * from data, a share counts the extinction of the steps it leaves at the density of the one it
   * takes: there a group is close to one frame of the setting, not equal. EPIPOLAR's shares may
   * choose other samples to interpolate than the whole frame.) ANALYTIC is not split, nor is
   * LIGHT_VOLUME's mesh: beyond a frame's allowance it is coarser (SetLightVolumeResolution).
   * Off, or with ProgressiveRefinement off: every frame computes the whole setting (a batch
   * render that wants it in one frame). Default is on.
   */
  vtkSetMacro(SplitLongFrames, bool);
  vtkGetMacro(SplitLongFrames, bool);
  vtkBooleanMacro(SplitLongFrames, bool);
  ///@}

  ///@{
  /**
   * Frame budget in seconds, in [0, 3600] (0: off): each frame renders the most accurate
   * setting of the error model's ladder that a cost model, learnt from the frames rendered
   * under a budget, predicts will fit it (at full resolution if any fits, else half, else
   * quarter; with a TargetError, the cheapest that fits and meets it); kept while the view is
   * still; it overrides the parameters as TargetError does. UseAllocatedRenderTime follows
   * VTK's interaction idiom: the renderer's AllocatedRenderTime, while under 10 s (an
   * interactor's DesiredUpdateRate while the user drags), is the budget too (the smaller of
   * the two). Defaults are 0 and on.
   */
  void SetTimeBudget(double seconds);
  vtkGetMacro(TimeBudget, double);
  vtkSetMacro(UseAllocatedRenderTime, bool);
  vtkGetMacro(UseAllocatedRenderTime, bool);
  vtkBooleanMacro(UseAllocatedRenderTime, bool);
  ///@}

  /// The name of a setting of the error model's ladder ("none" out of range), for
  /// vtkLightShaftFrameReport::GetErrorModelSetting.
  static const char* GetErrorModelSettingName(int setting);

  /**
   * The last frame's in-scattered radiance L_in before Exposure: float RGB (array
   * "InScatteredRadiance"), one pixel per viewport pixel, row 0 at the bottom; zeros when it
   * added no shafts. False (`out` empty) when nothing was rendered yet or the window is gone.
   */
  bool GetInScatteredRadiance(vtkImageData* out);

  /**
   * The last frame's shadow map of its i-th used light, for a reference with the same
   * visibility (vtkLightShaftReference::SetVisibilityModeToShadowMap): depths (float, N x N,
   * 1 = nothing) and the light camera's world-to-clip matrix. False when that light had no
   * map, and for a point light (a cube of six).
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
  double Exposure = 1.0;
  bool FitMediumToScene = false;
  bool AttenuateScene = true;
  bool ShadowSurfaces = false;
  bool AttenuateSurfaceLight = true;
  bool TranslucentShadows = true;
  int TranslucentShadowLayers = 4;
  int NumberOfSlices = 64;
  int ShadowMapSize = 1024;
  bool AutomaticSliceCount = false;
  int MaximumNumberOfSlices = 512;
  bool Jitter = true;
  int BlurRadius = 2;
  int DownsampleFactor = 1;
  int AccumulationPrecision = ACCUMULATE_FLOAT32;
  int Method = SLICES;
  bool MethodNamed = false; ///< set by SetMethod, not by a preset
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
  bool ExactFinish = false;
  bool SplitLongFrames = true;
  double TimeBudget = 0.0;
  bool UseAllocatedRenderTime = true;

  bool UseShadowCasterBounds = false;
  double ShadowCasterBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };

private:
  void RenderFrame(const vtkRenderState* s);
  bool FitMedium(vtkRenderer* renderer);

  vtkLightShaftPass(const vtkLightShaftPass&) = delete;
  void operator=(const vtkLightShaftPass&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
