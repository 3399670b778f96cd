/**
 * @class   vtkLightShaftFrameReport
 * @brief   What vtkLightShaftPass's last frame did: the setting it chose, its predicted error,
 *          times, resolution, refinement state, and per light its method, shadow map, tables
 *          and layers. Read-only.
 *
 * vtkLightShaftPass::GetLastFrame() returns it; the pass updates the same object at the end of
 * each frame (keep the pointer, read it after a render). For tests, tuning and read-outs in a
 * GUI:
 * @code{.py}
 *   window.Render()
 *   frame = shafts.GetLastFrame()
 *   print(frame.GetMethod(), frame.GetPredictedError(), frame.GetLightTime(0))
 * @endcode
 * Before the first frame every value is its default (documented with it).
 *
 * @sa vtkLightShaftPass
 */

#ifndef vtkLightShaftFrameReport_h
#define vtkLightShaftFrameReport_h

#include "vtkLightShaftsOpenGLModule.h" // For the export macro
#include "vtkObject.h"                  // For the base class

#include <memory> // For std::unique_ptr (the per-light values)

class vtkLight;
class vtkVolume;
struct vtkLightShaftFrame;

class VTKLIGHTSHAFTSOPENGL_EXPORT vtkLightShaftFrameReport : public vtkObject
{
public:
  static vtkLightShaftFrameReport* New();
  vtkTypeMacro(vtkLightShaftFrameReport, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * What the frame drew. The method it used (AUTOMATIC resolved; -1 when no shafts were
   * computed; vtkLightShaftPass::GetMethodName names it). The viewport's size in pixels.
   * How many times the scene was rendered (2 with a cookie: with and without the light). Its
   * samples per pixel: those of the target the pass draws into (0: not multisampled). Whether
   * the frame drew only the plain scene, exactly as without the pass (the renderer rendered
   * for a hardware selector, an enclosing pass with its own shaders, or into a target without
   * colour; the shafts come back on the next frame). Whether the pass applied the renderer's
   * FXAA. OpenGL errors raised while it rendered (0 when all is well; errors pending before
   * the frame are not counted). Defaults are -1, (0, 0), 0, 0, false, false and 0.
   */
  vtkGetMacro(Method, int);
  vtkGetVector2Macro(ViewportSize, int);
  vtkGetMacro(NumberOfSceneRenders, int);
  vtkGetMacro(MultiSamples, int);
  vtkGetMacro(PlainScene, bool);
  vtkGetMacro(RendererFXAA, bool);
  vtkGetMacro(GLErrorCount, int);
  ///@}

  ///@{
  /**
   * The sampling. SLICES: slabs drawn over all lights, the view-depth range the first light's
   * slabs span, and their draw calls. The lattice resolution the slabs used (less than asked
   * where the frame's budget of 2^21 lattice cells required; 0: none). The steps of RAY_MARCH's
   * and EPIPOLAR's rays (fewer than asked where the frame would integrate more than 2^30
   * segments; the fewest of the lights; 0: neither method; a split setting's frame integrates a
   * GetRefinementSplit()-th of them, and of the slabs). LIGHT_VOLUME's mesh cells across a map
   * (fewer than asked where the map has fewer texels, or a refining view's frame would draw more
   * than 2^22 cells: SplitLongFrames; the fewest of the lights; 0: not run). Full-screen passes
   * after the in-scatter (gather, blur, ...). RADIAL_BLUR's guard band (0: not run). The
   * in-scatter's resolution factor (DownsampleFactor, or the budget's or target's choice).
   * Defaults are 0, (0, 0), 0, 0, 0, 0, 0, 0 and 1.
   */
  vtkGetMacro(NumberOfSlicesDrawn, int);
  vtkGetVector2Macro(SliceDepthRange, double);
  vtkGetMacro(NumberOfSlabBatches, int);
  vtkGetMacro(LatticeResolution, int);
  vtkGetMacro(NumberOfSteps, int);
  vtkGetMacro(LightVolumeResolution, int);
  vtkGetMacro(NumberOfPostPasses, int);
  vtkGetMacro(RadialGuardBand, double);
  vtkGetMacro(DownsampleFactor, int);
  ///@}

  /**
   * The backdrop: the view depth where a ray that hits no surface ends, the deepest corner of
   * the scene's bounds (the visible props', the distributed scene's and the density field's),
   * whatever the camera's clipping range. The renderer's background stands there, dimmed by the
   * medium in front of it. 0 when no 3D prop is in front of the camera (the picture is then
   * left as it is). Default is 0.
   */
  vtkGetMacro(BackdropDepth, double);

  ///@{
  /**
   * Image pieces (vtkLightShaftPass::SetImagePiece): the in-scatter's rows this process
   * computed (0: the frame was not split), and the fragments its SLICES, RAY_MARCH or ANALYTIC
   * slabs shaded there (-1: not split, not counted). Defaults are 0 and -1.
   */
  vtkGetMacro(ImagePieceRows, int);
  vtkGetMacro(InScatterFragments, long long);
  ///@}

  /**
   * Whether this frame chose the medium's ScatteringCoefficient and the pass's Exposure from
   * the scene (vtkLightShaftPass::SetFitMediumToScene); their getters give the values. Default
   * is false.
   */
  vtkGetMacro(MediumFitted, bool);

  ///@{
  /**
   * The shader variants compiled (each light's features, e.g. "method=slices phase=isotropic
   * shadow cookie noise jitter accumulate=float32", joined by "; "), and the slab or march
   * program's fragment source. Default is "".
   */
  const char* GetShaderVariant();
  const char* GetSliceShaderSource();
  ///@}

  ///@{
  /**
   * The shadow maps: whether any light's shafts were shadowed by one (rendered this frame or
   * reused), and their casters summed over the lights. The first shadowed light's camera near
   * and far distances and depth tolerance: relative for spot and point lights (lit when
   * w <= stored depth * (1 + bias)), in world units for a directional light. Defaults are
   * false, 0, (0, 0) and 0.
   */
  vtkGetMacro(ShadowMapRendered, bool);
  vtkGetMacro(NumberOfShadowCasters, int);
  vtkGetVector2Macro(LightDepthRange, double);
  vtkGetMacro(ShadowBias, double);
  ///@}

  ///@{
  /**
   * The error model's view. The predicted relative RMS error (of the setting TargetError or
   * the budget chose, or of the parameters when they are a setting of the model's ladder; -1:
   * none), that setting (-1: none; vtkLightShaftPass::GetErrorModelSettingName names it), and
   * the first lit light's features: the lit volume's view-depth range over the beam's width,
   * that width in pixels, the optical depth over the range, a 1024^2 map's texel in pixels (0:
   * no caster), whether the light projects inside the view, and with a medium from data the
   * field's own error at that setting (what its steps miss of the density along view rays
   * through the lit volume, and the light-leg table's error, before the model's margin; -1: no
   * field or no setting). Defaults are -1, -1, 0, 0, 0, 0, false and -1.
   */
  vtkGetMacro(PredictedError, double);
  vtkGetMacro(ErrorModelSetting, int);
  vtkGetMacro(DepthRangeInBeamWidths, double);
  vtkGetMacro(BeamWidthInPixels, double);
  vtkGetMacro(OpticalDepth, double);
  vtkGetMacro(ShadowTexelInPixels, double);
  vtkGetMacro(LightInView, bool);
  vtkGetMacro(FieldError, double);
  ///@}

  ///@{
  /**
   * The frame budget: the budget the frame had (seconds; 0: none), the frame time predicted
   * for the sampling chosen (-1: no budget), and the time measured (the shafts' part of the
   * frame, scene and composite included; -1: only frames under a budget are measured).
   * Defaults are 0, -1 and -1.
   */
  vtkGetMacro(TimeBudget, double);
  vtkGetMacro(PredictedFrameTime, double);
  vtkGetMacro(FrameTime, double);
  ///@}

  ///@{
  /**
   * Progressive refinement: the estimates averaged into the picture (0: off, or nothing
   * computed; a picture of two estimates shows the first while the next is computed), whether
   * it is converged, whether the frame reused the converged in-scatter instead of computing
   * it, and the standard deviation in pixels of the Gaussian that filtered the average of
   * estimates (0: none; the first estimate is filtered as the parameters say, the later ones
   * are not: docs/quality-and-cost.md#interaction-frame-budget-and-refinement); the estimates
   * that make one frame of the still setting (more than 1 where a still view after frames under
   * a budget splits a ray march that would overrun the budget's frame among estimates, or a
   * setting would stall the frame: SplitLongFrames), and
   * whether the picture shown is an earlier one, held (the moving one until they add up to one
   * frame of the setting, then the last complete group's). Defaults are 0, false, false, 0, 1
   * and false.
   */
  vtkGetMacro(RefinementEstimates, int);
  vtkGetMacro(RefinementConverged, bool);
  vtkGetMacro(InScatterReused, bool);
  vtkGetMacro(RefinementFilterWidth, double);
  vtkGetMacro(RefinementSplit, int);
  vtkGetMacro(RefinementHeld, bool);
  ///@}

  /// The exact finish's states (vtkLightShaftPass::SetExactFinish).
  enum ExactFinishStates
  {
    EXACT_FINISH_OFF = 0,         ///< not running: the view moves, or the finish is off
    EXACT_FINISH_RUNNING = 1,     ///< tiles are being integrated in the background
    EXACT_FINISH_COMPLETE = 2,    ///< the picture's in-scatter is the reference's
    EXACT_FINISH_UNSUPPORTED = 3, ///< the scene has what the reference cannot model
    EXACT_FINISH_FAILED = 4       ///< the reference could not capture the scene
  };
  ///@{
  /**
   * The exact finish: its state (ExactFinishStates), the share of the picture's pixels whose
   * in-scatter is the reference's, in [0, 1], and why it does not run (UNSUPPORTED, FAILED;
   * else empty). The predicted error of a complete picture is 0. Defaults are
   * EXACT_FINISH_OFF, 0 and empty.
   */
  vtkGetMacro(ExactFinishState, int);
  vtkGetMacro(ExactFinishFraction, double);
  const char* GetExactFinishProblem();
  ///@}

  ///@{
  /**
   * The exact finish's responsiveness and bounds: how long this frame waited for its workers
   * to stop after a change (seconds; 0 when none ran: the workers watch the request inside
   * each pixel, so this is milliseconds), and the pixels finished so far whose integration the
   * reference's bound on evaluations ended (their error then above the tolerance; see
   * vtkLightShaftReference::SetMaximumEvaluations). Defaults are 0 and 0.
   */
  vtkGetMacro(ExactFinishStopTime, double);
  vtkGetMacro(ExactFinishExhaustedPixels, vtkIdType);
  ///@}

  ///@{
  /**
   * The camera leg through translucent surfaces: the layers of translucent surfaces in front of
   * the opaque scene that the frame peeled from the camera (0: none in view, or no shafts
   * computed) and the GL memory they hold, bytes; the vtkVolume that dimmed the shafts behind
   * it and the light through it (nullptr: none; docs/translucent-and-volumes.md). Defaults are
   * 0, 0 and nullptr.
   */
  vtkGetMacro(CameraTranslucentLayers, int);
  vtkGetMacro(CameraTranslucentBytes, double);
  vtkVolume* GetVolume();
  ///@}

  ///@{
  /**
   * Per used light: how many lights the frame used (the given ones switched on, or the
   * automatic choice) and the i-th (default the first), in the order their in-scatter was added;
   * its kind (vtkLightShaftPass::LightKindType); the method that computed its in-scatter (-1: none,
   * e.g. outside the view); its slabs; whether its shadow map was rendered this frame, or reused
   * because nothing that decides it changed; its casters; the GPU milliseconds its in-scatter
   * took (timer queries of the latest frame whose queries completed; -1: not available); its
   * light-leg table through a density field: bytes (0: none) and build milliseconds (0:
   * reused); its translucent casters' layers: how many (0: none) and their bytes; its light-leg
   * texture through the scene's volume: bytes and build milliseconds. Out of range: nullptr, -1,
   * -1, 0, false, false, 0, -1, 0, 0, 0, 0, 0 and 0.
   */
  int GetNumberOfUsedLights();
  vtkLight* GetUsedLight(int index = 0);
  int GetLightKind(int index);
  int GetLightMethod(int index);
  /**
   * Why the i-th light's method gave way to the one GetLightMethod reports, or is used with a
   * caveat (ANALYTIC ignoring shadows), as the warning a named method gives; "" when the
   * method was used as set, and out of range. A method chosen by a preset, a target error or
   * the budget gives way silently: this says so.
   */
  const char* GetLightMethodFallback(int index);
  int GetLightSlicesDrawn(int index);
  bool GetLightShadowMapRendered(int index);
  bool GetLightShadowMapReused(int index);
  int GetLightShadowCasters(int index);
  double GetLightTime(int index);
  double GetLightFieldShadowBytes(int index);
  double GetLightFieldShadowBuildTime(int index);
  int GetLightTranslucentLayers(int index);
  double GetLightTranslucentBytes(int index);
  double GetLightVolumeShadowBytes(int index);
  double GetLightVolumeShadowBuildTime(int index);
  ///@}

protected:
  vtkLightShaftFrameReport();
  ~vtkLightShaftFrameReport() override;

  int Method = -1;
  int ViewportSize[2] = { 0, 0 };
  int NumberOfSceneRenders = 0;
  int MultiSamples = 0;
  bool PlainScene = false;
  bool RendererFXAA = false;
  int GLErrorCount = 0;
  int NumberOfSlicesDrawn = 0;
  double SliceDepthRange[2] = { 0.0, 0.0 };
  double BackdropDepth = 0.0;
  int ImagePieceRows = 0;
  long long InScatterFragments = -1;
  bool MediumFitted = false;
  int NumberOfSlabBatches = 0;
  int LatticeResolution = 0;
  int NumberOfSteps = 0;
  int LightVolumeResolution = 0;
  int NumberOfPostPasses = 0;
  double RadialGuardBand = 0.0;
  int DownsampleFactor = 1;
  bool ShadowMapRendered = false;
  int NumberOfShadowCasters = 0;
  double LightDepthRange[2] = { 0.0, 0.0 };
  double ShadowBias = 0.0;
  double PredictedError = -1.0;
  int ErrorModelSetting = -1;
  double DepthRangeInBeamWidths = 0.0;
  double BeamWidthInPixels = 0.0;
  double OpticalDepth = 0.0;
  double ShadowTexelInPixels = 0.0;
  double FieldError = -1.0;
  bool LightInView = false;
  double TimeBudget = 0.0;
  double PredictedFrameTime = -1.0;
  double FrameTime = -1.0;
  int RefinementEstimates = 0;
  bool RefinementConverged = false;
  double RefinementFilterWidth = 0.0;
  int RefinementSplit = 1;
  bool RefinementHeld = false;
  bool InScatterReused = false;
  int ExactFinishState = EXACT_FINISH_OFF;
  double ExactFinishFraction = 0.0;
  double ExactFinishStopTime = 0.0;
  vtkIdType ExactFinishExhaustedPixels = 0;
  int CameraTranslucentLayers = 0;
  double CameraTranslucentBytes = 0.0;

private:
  vtkLightShaftFrameReport(const vtkLightShaftFrameReport&) = delete;
  void operator=(const vtkLightShaftFrameReport&) = delete;

  // Only the pass writes it.
  friend class vtkLightShaftPass;
  /// The frame's values, with the shader variants and source it compiled.
  void Publish(const vtkLightShaftFrame& frame, const char* variant, const char* source);
  void SetGLErrorCount(int count) { this->GLErrorCount = count; }

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
