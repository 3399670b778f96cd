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
 * The pass holds how the shafts are computed; what the medium is is a shareable
 * vtkLightShaftMedium (GetMedium), what the last frame did a vtkLightShaftFrameReport
 * (GetLastFrame). Each frame renders the scene through the delegate, each scattering light's
 * shadow map and the in-scattered radiance L_in, then composites out = scene * exp(-sigma_t *
 * t_surface) + Exposure * L_in (docs/methods.md).
 *
 * A medium that neither scatters nor absorbs, or no usable light, leaves the delegate's image
 * unchanged (pixel-identical). Floating-point setters refuse NaN and infinities with an error
 * naming the parameter and clamp other values into their range (docs/parameters.md).
 *
 * @sa vtkLightShaftMedium vtkLightShaftFrameReport vtkLightShaftReference
 */

#ifndef vtkLightShaftPass_h
#define vtkLightShaftPass_h

#include "vtkCommand.h"                 // For vtkCommand::UserEvent (ShadowMapRenderedEvent)
#include "vtkImageProcessingPass.h"     // For the base class and the delegate pass
#include "vtkLightShaftFrameReport.h"   // For GetLastFrame's object (read through the pass)
#include "vtkLightShaftMedium.h"        // For GetMedium's object (set through the pass)
#include "vtkLightShaftsOpenGLModule.h" // For the export macro

#include <memory> // For std::unique_ptr (GL objects and state live in Internals)

class vtkImageData;
class vtkInformationObjectBaseKey;
class vtkLight;
class vtkMatrix4x4;
class vtkTexture;
class vtkTextureObject;

class VTKLIGHTSHAFTSOPENGL_EXPORT vtkLightShaftPass : public vtkImageProcessingPass
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
    /// After the shadow map is rendered, before it is used: GetShadowMapTexture() is valid.
    ShadowMapRenderedEvent = vtkCommand::UserEvent + 4301,
    /// After a frame whose still picture is refining: render again, never inside the callback.
    RefinementNeededEvent = vtkCommand::UserEvent + 4302,
    /// Before the in-scatter: GetSceneDepthTexture() is valid (a distributed view composites it).
    SceneDepthReadyEvent = vtkCommand::UserEvent + 4303,
    /// With image pieces, before post-processing: GetInScatterPieceTexture() is valid.
    InScatterPieceEvent = vtkCommand::UserEvent + 4304,
    /// Before an observed shadow map is reused: callData an int, 1 if unchanged here; the map
    /// is kept only if observers leave it 1 (distributed: every process's map is unchanged).
    ShadowMapReuseEvent = vtkCommand::UserEvent + 4305,
    /// A budget's frame timed: callData double[2], its shafts' and whole seconds (observers may
    /// rewrite them: distributed, the slowest process's), which the cost model then learns.
    FrameTimedEvent = vtkCommand::UserEvent + 4306
  };

  void Render(const vtkRenderState* s) override; ///< the scene and its shafts (the renderer)

  /// Free every GL object the pass holds (idempotent); nullptr: the window it last rendered in.
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
   * The medium the shafts scatter in (vtkLightShaftMedium), shareable between passes; nullptr
   * gives the pass a new one; the pass's MTime includes it. Default is a medium of its own.
   */
  void SetMedium(vtkLightShaftMedium* medium);
  vtkLightShaftMedium* GetMedium();
  vtkMTimeType GetMTime() override;
  ///@}

  /// What the last frame did: one object, updated at the end of each frame.
  vtkLightShaftFrameReport* GetLastFrame();

  ///@{
  /**
   * Exposure: the scale of the in-scattered radiance added to the picture, in [0, 1e6];
   * AttenuateScene: the scene dimmed by exp(-sigma_t t_surface). Defaults are 1 and on.
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
   * medium's grey ScatteringCoefficient (no absorption) and the Exposure so that a scene of any
   * size gives the same picture up to scale (docs/getting-started.md). A value set after this
   * wins; switching it on again chooses again. Default is off (add_light_shafts and the
   * PyVista and ParaView views switch it on when given no coefficient or exposure).
   */
  void SetFitMediumToScene(bool fit);
  vtkGetMacro(FitMediumToScene, bool);
  vtkBooleanMacro(FitMediumToScene, bool);
  ///@}

  ///@{
  /**
   * ShadowSurfaces: each light's share of a surface's colour shadowed by its shadow map and,
   * with AttenuateSurfaceLight, dimmed by the medium on the light's way (one more render of the
   * scene and a pass per light, also in an empty medium). Defaults are off and on.
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
   * Translucent casters dim and tint the light that passes them (1 - a (1 - c) per channel),
   * peeled into at most TranslucentShadowLayers layers per light, in [1, 8], and as many from
   * the camera (docs/translucent-and-volumes.md). Off, they cast nothing. Defaults are on and 4.
   */
  vtkSetMacro(TranslucentShadows, bool);
  vtkGetMacro(TranslucentShadows, bool);
  vtkBooleanMacro(TranslucentShadows, bool);
  vtkSetClampMacro(TranslucentShadowLayers, int, 1, 8);
  vtkGetMacro(TranslucentShadowLayers, int);
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
   * Cookie (gobo): an RGB image projected from each spot and directional light (not point
   * lights) onto the shafts and surfaces. Default is nullptr.
   */
  void SetCookie(vtkTexture* cookie);
  vtkTexture* GetCookie();
  ///@}

  ///@{
  /**
   * The method that computes the in-scattered radiance (docs/methods.md); the parameters that
   * are not method-specific mean the same in all. AUTOMATIC is ANALYTIC when nothing shadows the
   * light's volume and the noise is off, else SLICES; LIGHT_VOLUME gives way to RAY_MARCH where
   * it cannot model the light. A method set here warns once where it cannot be used as asked
   * (the frame report's GetLightMethodFallback says why). Default is SLICES.
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
   * SLICES: NumberOfSlices view-aligned slabs over the lit depth range, in [1, 4096]; Jitter
   * shifts each pixel of a 4x4 block by its own sixteenth of a slab; AutomaticSliceCount
   * spaces the slabs (far clipping distance) / MaximumNumberOfSlices apart, in [1, 4096]; the
   * smooth part of the integrand on an n x n lattice per slab, LatticeResolution in [0, 256]
   * (0: per pixel). Defaults are 64, on, off, 512 and 0.
   */
  vtkSetClampMacro(NumberOfSlices, int, 1, 4096);
  vtkGetMacro(NumberOfSlices, int);
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  vtkSetMacro(AutomaticSliceCount, bool);
  vtkGetMacro(AutomaticSliceCount, bool);
  vtkBooleanMacro(AutomaticSliceCount, bool);
  vtkSetClampMacro(MaximumNumberOfSlices, int, 1, 4096);
  vtkGetMacro(MaximumNumberOfSlices, int);
  vtkSetClampMacro(LatticeResolution, int, 0, 256);
  vtkGetMacro(LatticeResolution, int);
  ///@}

  ///@{
  /**
   * SLICES: the precision the slabs add up in (ACCUMULATE_8BIT: the GDC 2004 talk's
   * four-channel trick, slab k in channel k mod 4 of an RGBA8 buffer). Default is
   * ACCUMULATE_FLOAT32.
   */
  vtkSetClampMacro(AccumulationPrecision, int, ACCUMULATE_FLOAT32, ACCUMULATE_8BIT);
  vtkGetMacro(AccumulationPrecision, int);
  void SetAccumulationPrecisionToFloat32() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT32); }
  void SetAccumulationPrecisionToFloat16() { this->SetAccumulationPrecision(ACCUMULATE_FLOAT16); }
  void SetAccumulationPrecisionTo8Bit() { this->SetAccumulationPrecision(ACCUMULATE_8BIT); }
  ///@}

  ///@{
  /**
   * Post-processing of the in-scatter: the radius in pixels, in [0, 32] (0: off), of a
   * depth-aware separable Gaussian blur; and its resolution, 1 (full), 2 (half) or 4 (quarter)
   * in each direction, brought back with depth-aware upsampling. Defaults are 2 and 1.
   */
  vtkSetClampMacro(BlurRadius, int, 0, 32);
  vtkGetMacro(BlurRadius, int);
  void SetDownsampleFactor(int factor);
  vtkGetMacro(DownsampleFactor, int);
  ///@}

  ///@{
  /**
   * RAY_MARCH: segments marched per pixel (EPIPOLAR: per marched sample), in [1, 4096]; and the
   * side M of the interleaved-sampling block, in [1, 8]: its M^2 pixels shift their steps by
   * different fractions and depth-aware gathers average them back (1: off). EPIPOLAR: the lines
   * through the light's screen image, in [4, 2048]; the samples on each, in [2, 2048]; every
   * how many samples the in-scatter is marched, in [1, 64] (the others interpolated where
   * depth and in-scatter allow). Defaults are 16, 2, 512, 512 and 16.
   */
  vtkSetClampMacro(NumberOfSteps, int, 1, 4096);
  vtkGetMacro(NumberOfSteps, int);
  vtkSetClampMacro(InterleaveSize, int, 1, 8);
  vtkGetMacro(InterleaveSize, int);
  vtkSetClampMacro(EpipolarLines, int, 4, 2048);
  vtkGetMacro(EpipolarLines, int);
  vtkSetClampMacro(EpipolarSamples, int, 2, 2048);
  vtkGetMacro(EpipolarSamples, int);
  vtkSetClampMacro(EpipolarStep, int, 1, 64);
  vtkGetMacro(EpipolarStep, int);
  ///@}

  ///@{
  /**
   * LIGHT_VOLUME: the cells across the shadow map (a point light: each cube face) of the
   * shadow volume's mesh, in [8, 1024]; no more than the map has texels, nor than a refining
   * frame's allowance (SplitLongFrames; one warning). Default is 256.
   */
  vtkSetClampMacro(LightVolumeResolution, int, 8, 1024);
  vtkGetMacro(LightVolumeResolution, int);
  ///@}

  ///@{
  /**
   * RADIAL_BLUR (GPU Gems 3 ch. 13): samples towards the light's screen position, in [1, 1024];
   * Decay, each farther sample's weight factor, Density, the fraction of the way covered, and
   * Weight, how strongly the blurred occlusion darkens the shafts (0: ANALYTIC's), in [0, 1];
   * RadialJitter, per-pixel sample offsets; the guard band, the occlusion buffer's extent over
   * the screen's, in [1, 4] (occluders off the picture cut shafts). Defaults are 64, 1, 1, 1,
   * on and 1.
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
   * Distributed rendering (ParaView under MPI, docs/paraview-mpi.md): the world bounds of every
   * process's shadow casters; set, all processes render their maps with one light camera, for a
   * ShadowMapRenderedEvent observer to combine. PaintBackground: a compositor (IceT) blends the
   * background in after the pass, so the pass paints PaintedBackground (RGB in [0, 1]) behind
   * the scene's uncovered part before the medium dims it. SetImagePiece: SLICES, RAY_MARCH and
   * ANALYTIC compute only this piece's rows of the in-scatter, for the events' observers to
   * exchange; MODELLED_PROP, a prop's key (PropertyKeys), names the prop whose shadow,
   * translucency or volume is modelled in its place (for a piece: the whole data, not a
   * parameter). Defaults are unset, off, (0, 0, 0) and piece 0 of 1.
   */
  void SetShadowCasterBounds(const double bounds[6]);
  void UnsetShadowCasterBounds();
  bool GetShadowCasterBounds(double bounds[6]);
  vtkSetMacro(PaintBackground, bool);
  vtkGetMacro(PaintBackground, bool);
  vtkBooleanMacro(PaintBackground, bool);
  static vtkInformationObjectBaseKey* MODELLED_PROP();
  void SetPaintedBackground(double r, double g, double b);
  vtkGetVector3Macro(PaintedBackground, double);
  void SetImagePiece(int piece, int numberOfPieces);
  vtkGetMacro(ImagePiece, int);
  vtkGetMacro(NumberOfImagePieces, int);
  ///@}

  ///@{
  /**
   * Quality presets: the cheapest ladder setting whose 90th-percentile error on random scenes
   * meets Draft 5%, Interactive 2% or Final 0.5%; they set the method, its sampling and the
   * post-processing only (docs/quality-and-cost.md). The defaults are none of them.
   */
  void SetQualityToDraft();
  void SetQualityToInteractive();
  void SetQualityToFinal();
  ///@}

  ///@{
  /**
   * Target relative RMS error of the in-scatter against the float64 reference, in [0, 1] (0:
   * off): each frame renders with the error model's cheapest setting predicted to meet it,
   * overriding the method, its sampling, ShadowMapSize and the post-processing; 90% of held-out
   * random scenes meet it (docs/quality-and-cost.md). Default is 0 (off).
   */
  void SetTargetError(double error);
  vtkGetMacro(TargetError, double);
  ///@}

  ///@{
  /**
   * Refinement of a still view (docs/quality-and-cost.md). ProgressiveRefinement: while nothing
   * that decides the picture changes, each frame adds an estimate with shifted samples and shows
   * the mean, until RefinementFrames, in [1, 4096]; until then frames end with
   * RefinementNeededEvent. ExactFinish: from the view's second frame, idle threads integrate
   * the float64 reference tile by tile, shown as they finish, until the picture is the
   * reference (GetExactFinishProblem: why a scene is not). SplitLongFrames: a setting beyond
   * 2^26 segments a frame (RADIAL_BLUR: 2^30 samples) integrates every n-th of its steps, slabs
   * or samples per frame, and a group adds up to the whole setting (docs/robustness.md);
   * LIGHT_VOLUME's mesh is coarser instead. Defaults are off, 16, off and on.
   */
  vtkSetMacro(ProgressiveRefinement, bool);
  vtkGetMacro(ProgressiveRefinement, bool);
  vtkBooleanMacro(ProgressiveRefinement, bool);
  vtkSetClampMacro(RefinementFrames, int, 1, 4096);
  vtkGetMacro(RefinementFrames, int);
  vtkSetMacro(ExactFinish, bool);
  vtkGetMacro(ExactFinish, bool);
  vtkBooleanMacro(ExactFinish, bool);
  vtkSetMacro(SplitLongFrames, bool);
  vtkGetMacro(SplitLongFrames, bool);
  vtkBooleanMacro(SplitLongFrames, bool);
  ///@}

  ///@{
  /**
   * Frame budget in seconds, in [0, 3600] (0: off): each frame renders the most accurate ladder
   * setting that the cost model, learnt from earlier frames, predicts will fit (at full, else
   * half, else quarter resolution; with a TargetError, the cheapest that fits and meets it),
   * overriding the parameters as TargetError does. UseAllocatedRenderTime: the renderer's
   * AllocatedRenderTime, while under 10 s, is a budget too. Defaults are 0 and on.
   */
  void SetTimeBudget(double seconds);
  vtkGetMacro(TimeBudget, double);
  vtkSetMacro(UseAllocatedRenderTime, bool);
  vtkGetMacro(UseAllocatedRenderTime, bool);
  vtkBooleanMacro(UseAllocatedRenderTime, bool);
  ///@}

  /// The name of a setting of the error model's ladder (GetErrorModelSetting; "none": none)
  static const char* GetErrorModelSettingName(int setting);

  /// The last frame's L_in before Exposure: float RGB ("InScatteredRadiance"), one pixel per
  /// viewport pixel, row 0 at the bottom, zeros without shafts. False (`out` empty) when nothing
  /// was rendered yet or the window is gone.
  bool GetInScatteredRadiance(vtkImageData* out);

  /// The last frame's shadow map of its i-th light, for vtkLightShaftReference's ShadowMap
  /// visibility: depths (float, N x N, 1 = nothing) and the light camera's world-to-clip matrix.
  /// False when that light had no map, and for a point light (a cube of six).
  bool GetLastShadowMap(vtkImageData* depths, vtkMatrix4x4* worldToLightClip, int index = 0);

  ///@{
  /**
   * While an event is handled (nullptr at any other time): ShadowMapRenderedEvent's shadow map
   * (32-bit float depth, N x N, 1 = nothing), SceneDepthReadyEvent's scene depth (the
   * viewport's), InScatterPieceEvent's in-scatter (RGBA, DownsampleFactor times smaller).
   */
  vtkTextureObject* GetShadowMapTexture();
  vtkTextureObject* GetSceneDepthTexture();
  vtkTextureObject* GetInScatterPieceTexture();
  ///@}

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

  bool PaintBackground = false;
  double PaintedBackground[3] = { 0.0, 0.0, 0.0 };
  int ImagePiece = 0;
  int NumberOfImagePieces = 1;
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
