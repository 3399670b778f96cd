/**
 * @file   vtkLightShaftFrame.h
 * @brief  One frame of vtkLightShaftPass, as its components share it (private, not installed):
 *         the parameters it runs with, the camera, light and medium, the scene's render, and
 *         the statistics the frame reports.
 *
 * The pass fills a vtkLightShaftFrame when the frame starts (parameters snapshot, camera and
 * viewport), the components read it and add what they produce (scene image, light frame), and
 * write what they did into its Statistics, which the pass publishes in one place when the frame
 * ends.
 */

#ifndef vtkLightShaftFrame_h
#define vtkLightShaftFrame_h

#include "vtkLightShaftErrorModel.h" // For the error model's features
#include "vtkLightShaftGeometry.h"   // For the camera and light frames
#include "vtkLightShaftModel.h"      // For the medium
#include "vtkWeakPointer.h"          // For the statistics' light

#include <string> // For the shader variant
#include <vector> // For the per-light statistics and the image piece's rows

class vtkLight;
class vtkLightShaftDensityField;
class vtkLightShaftFieldTableTexture;
class vtkLightShaftMediumTexture;
class vtkLightShaftMethod;
class vtkLightShaftShadowMap;
class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkProp;
class vtkRenderState;
class vtkTextureObject;
class vtkVolume;

/**
 * The pass's parameters for one frame (the presets and setters already applied, clamped),
 * copied from the pass when the frame starts: the pass's header holds their defaults and
 * ranges, nothing here does.
 */
struct vtkLightShaftParameters
{
  int Method{};
  bool MethodNamed{}; ///< Method set by the user (warns where unusable), not chosen
  double Exposure{};
  bool AttenuateScene{};
  bool AttenuateSurfaceLight{}; ///< (with ShadowSurfaces)
  int NumberOfSlices{};
  bool AutomaticSliceCount{};
  int MaximumNumberOfSlices{};
  bool Jitter{};
  int LatticeResolution{};
  int ShadowMapSize{};
  int BlurRadius{};
  int DownsampleFactor{};
  int AccumulationPrecision{};
  double NoiseAmplitude{};
  double NoiseScale{};
  double NoiseShift[4]{}; ///< vtkLightShaftModel::NoiseShifts at Time
  int NumberOfSteps{};
  int InterleaveSize{};
  int RadialSamples{};
  int EpipolarLines{};
  int EpipolarSamples{};
  int EpipolarStep{};
  int LightVolumeResolution{};
  int MediumShadowResolution{};
  int TranslucentLayers{}; ///< the most layers of translucent casters (0: they cast nothing)
  int CameraLayers{};      ///< the most translucent layers the camera leg peels
  double Decay{};
  double Density{};
  double Weight{};
  bool RadialJitter{};
  double RadialGuardBand{};
  const double* ShadowCasterBounds = nullptr; ///< set for distributed rendering, else nullptr
  bool PaintBackground{}; ///< a compositor blends the background in after the pass
  const double* PaintedBackground = nullptr; ///< the background it blends in (RGB)
  int ImagePiece{};                          ///< this process's piece of the in-scatter's rows
  int ImagePieces{};                         ///< (1: the whole image)
  bool ProgressiveRefinement{};
  int RefinementFrames{};
  bool ExactFinish{};
  bool SplitLongFrames{}; ///< (with ProgressiveRefinement)
  double TimeBudget{};
  bool UseAllocatedRenderTime{};
  double TargetError{}; ///< 0: off; else the SLICES parameters above are the ladder's choice
};

/**
 * What a frame did for one of its lights; published as vtkLightShaftFrameReport's GetLight*
 * read-outs.
 */
struct vtkLightShaftLightStatistics
{
  int Kind = -1;
  int Method = -1;
  int SlicesDrawn = 0;
  bool ShadowMapRendered = false;
  bool ShadowMapReused = false;
  int ShadowCasters = 0;
  double LightDepthRange[2] = { 0.0, 0.0 }; ///< of its shadow map, when it had one
  double ShadowBias = 0.0;                  ///< of its shadow map, when it had one
  double Time = -1.0;                       ///< GPU milliseconds (timer queries), -1: unknown
  /// The field's light-leg texture (vtkLightShaftFieldTableTexture): its bytes (0: none) and the
  /// milliseconds its build took this frame (0: reused).
  double FieldShadowBytes = 0.0;
  double FieldShadowBuildTime = 0.0;
  /// The same for the scene's vtkVolume's light-leg texture.
  double VolumeShadowBytes = 0.0;
  double VolumeShadowBuildTime = 0.0;
  /// Its translucent casters' layers (vtkLightShaftTranslucentLayers): how many (0: none),
  /// their bytes, and whether they were peeled this frame (not reused).
  int TranslucentLayers = 0;
  double TranslucentBytes = 0.0;
  bool TranslucentLayersRendered = false;
  std::string ShaderVariant;
  /// Why the light's method gave way to another, or was used with a caveat (empty: as set).
  std::string MethodFallback;
  vtkWeakPointer<vtkLight> Light;
};

/**
 * What a frame did; published as the pass's GetLast* read-outs when the frame ends (the
 * per-light ones, and the totals and first light's values the pass's older read-outs report).
 */
struct vtkLightShaftStatistics
{
  int SlabBatches = 0;
  int LatticeResolution = 0;
  int NumberOfSteps = 0; ///< RAY_MARCH's and EPIPOLAR's steps after the segment budget (fewest)
  int LightVolumeResolution = 0; ///< LIGHT_VOLUME's mesh cells across (fewest)
  int PostPasses = 0;
  int SceneRenders = 0;
  int RenderedProps = 0;
  int MultiSamples = 0;
  bool PlainScene = false;
  bool RendererFXAA = false;
  /// The camera leg's translucent layers peeled this frame and the GL memory they hold.
  int CameraLayers = 0;
  double CameraLayerBytes = 0.0;
  /// The vtkVolume that dims and shadows the shafts (nullptr: none).
  vtkVolume* Volume = nullptr;
  double SliceDepthRange[2] = { 0.0, 0.0 }; ///< of the first light whose shafts were computed
  double RadialGuardBand = 0.0;
  std::vector<vtkLightShaftLightStatistics> Lights; ///< one per used light, in order
  /// The error model: its prediction for the frame's setting (-1: none), the ladder setting
  /// used (-1: none) and the first lit light's features.
  double PredictedError = -1.0;
  int ErrorModelSetting = -1;
  vtkLightShaftErrorModel::Features ErrorFeatures;
  /// Progressive refinement: the estimates averaged into the picture (0: off), whether it is
  /// converged, whether the in-scatter was the converged one, not computed again, and the
  /// width of the Gaussian that filtered the average (pixels; 0: none).
  int RefinementEstimates = 0;
  bool RefinementConverged = false;
  bool InScatterReused = false;
  double RefinementFilterWidth = 0.0;
  /// Estimates per frame of the still setting (1: not split) and whether the picture shown is
  /// an earlier one, held (the moving one, or the last complete group's of a split setting).
  int RefinementSplit = 1;
  bool RefinementHeld = false;
  /// The exact finish: its state (vtkLightShaftExactFinish::State as an int: 0 off, 1
  /// running, 2 complete, 3 unsupported, 4 failed), the share of pixels shown exact, and why
  /// it does not run (empty: nothing).
  int ExactFinishState = 0;
  double ExactFinishFraction = 0.0;
  std::string ExactFinishProblem;
  /// How long this frame waited for the finish's workers to stop (seconds; 0: none ran), and
  /// the finished pixels whose integration the reference's bound on evaluations ended.
  double ExactFinishStopTime = 0.0;
  long long ExactFinishExhaustedPixels = 0;
  /// The frame budget (seconds; 0: none), the frame time the cost model predicted for the
  /// choice (-1: none), the measured time of the shafts' part of the frame (-1: not measured,
  /// measured only under a budget), and the lit lights the budget counted.
  double TimeBudget = 0.0;
  double PredictedFrameTime = -1.0;
  double FrameTime = -1.0;
  int BudgetLights = 0;
  /// Image pieces: the rows of the in-scatter this process computed (0: not split) and the
  /// fragments its split methods shaded (-1: not counted; counted only when split).
  int ImagePieceRows = 0;
  long long InScatterFragments = -1;
};

/**
 * The delegate's render of the scene: colour and depth, multisampled like the target the pass
 * draws into, the single-sample depth the shafts read (the nearest of each pixel's samples),
 * and what the surface lighting takes away where the lights' shadows and cookie fall.
 */
struct vtkLightShaftSceneImage
{
  vtkOpenGLFramebufferObject* Framebuffer = nullptr; ///< holds Color and Depth attached
  vtkTextureObject* Color = nullptr;
  vtkTextureObject* Depth = nullptr;
  vtkTextureObject* ShaftDepth = nullptr;
  /// Float RGB to subtract from Color (multisampled like it): each shadowed or cookie-shaped
  /// light's surface contribution times (1 - its visibility * cookie); nullptr: nothing.
  vtkTextureObject* SurfaceCorrection = nullptr;
  int Samples = 0;
  /// Color (and the scene without a light) in float, unclamped: set where the surface light
  /// takes a light's share as lit - unlit, so that a surface lit beyond white keeps its whole
  /// share (and gets its whole shadow); the composite clamps. (Not half float: a value within
  /// its rounding of an 8-bit level's edge came out a level off VTK's picture.)
  bool HighRange = false;
};

/**
 * One frame, shared by the pass's components.
 */
struct vtkLightShaftFrame
{
  vtkRenderer* Renderer = nullptr;
  const vtkRenderState* State = nullptr;
  /// The render state's visible props as the shafts model them (a prop's
  /// vtkLightShaftPass::MODELLED_PROP key names the prop modelled in its place).
  std::vector<vtkProp*> Props;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkObject* Owner = nullptr; ///< the pass: the source of messages and events

  int Origin[2] = { 0, 0 };  ///< viewport origin in the target, pixels
  int Size[2] = { 0, 0 };    ///< viewport size, pixels
  int Reduced[2] = { 0, 0 }; ///< in-scatter size (Size / DownsampleFactor, rounded up)

  int Number = 0; ///< counts the pass's frames (what was readied this frame is kept)
  vtkLightShaftParameters Parameters;
  vtkLightShaftModel::Medium Medium;
  /// The scene camera; its FarDepth is the backdrop (vtkLightShaftModel::BackdropDepth).
  vtkLightShaftGeometry::CameraFrame Camera;
  /// Whether some of the scene's box (vtkLightShaftModel::SceneBounds) lies in front of the
  /// camera: a renderer with no 3D prop, or with its scene behind the camera, is left as it is.
  bool SceneInView = false;
  /// Whether the frame chose the medium from the scene (vtkLightShaftPass::FitMediumToScene).
  bool MediumFitted = false;
  vtkLightShaftSceneImage Scene;
  /// Whether the frame shows the scene of the last frame, the same way (its sampling aside).
  bool ViewStill = false;

  /// The light being worked on (the components handle one light at a time), its shadow map and
  /// what the frame records of it.
  vtkLightShaftGeometry::LightFrame Light;
  vtkLightShaftShadowMap* ShadowMap = nullptr;
  /// Its translucent casters' layers side by side (nullptr: none) and how many, set when its
  /// shadow map is readied (vtkLightShaftShadowMap::Ready).
  vtkTextureObject* Translucency = nullptr;
  int TranslucentLayers = 0;
  /// The translucent surfaces the camera sees in front of the opaque scene, peeled front to
  /// back (side by side: r the fraction VTK's blending keeps of what lies behind, a the depth;
  /// nullptr: none) and how many: the camera leg of the shafts behind them.
  vtkTextureObject* CameraLayers = nullptr;
  int CameraLayerCount = 0;
  vtkLightShaftLightStatistics* LightStatistics = nullptr;
  /// The lights that radiate this frame: they share the frame's segment budget.
  int RadiatingLights = 1;

  /// Decided once per frame: the cookie and noise textures in use (nullptr: off); the cookie
  /// shapes spot and directional lights.
  vtkTextureObject* Cookie = nullptr;
  vtkTextureObject* Noise = nullptr;
  /// The medium's density field (nullptr: homogeneous) and its placement and scales.
  vtkTextureObject* Density = nullptr;
  const vtkLightShaftMediumTexture* DensityField = nullptr;
  double DensityScale = 1.0;
  double DensityBackground = 0.0;
  /// The light's precomputed light leg through the field (nullptr: marched per sample).
  vtkTextureObject* FieldShadow = nullptr;
  const vtkLightShaftFieldTableTexture* FieldShadowLayout = nullptr;
  /// The scene's vtkVolume: its extinction (nullptr: none) and placement
  /// (vtkLightShaftVolumeTexture), and the current light's leg through it, tabulated.
  vtkTextureObject* Volume = nullptr;
  const vtkLightShaftDensityField* VolumeField = nullptr;
  vtkTextureObject* VolumeShadow = nullptr;
  const vtkLightShaftFieldTableTexture* VolumeShadowLayout = nullptr;
  /// Progressive refinement's shift of the sampling offsets (steps, slab jitter), in [0, 1) of
  /// the setting's pieces, and where in each piece its light-space lookups are, in (0, 1); 0
  /// and 0.5 (the midpoint) render the picture without refinement.
  double SamplingRotation = 0.0;
  double LookupFraction = 0.5;
  /// Progressive refinement's shift of the shadow maps' texel grid, in texels ([-0.5, 0.5)).
  double ShadowMapOffset[2] = { 0.0, 0.0 };
  /// A refinement estimate after a history's first: the interleaved gather and the blur are
  /// left out, the refined picture filters the average instead (vtkLightShaftRefinement).
  bool Unfiltered = false;
  /// Estimates that add up to one frame of the still setting: a still view after frames under
  /// a budget integrates a RefinementSplit-th of its pieces per estimate where one frame of them
  /// would overrun the budget, and refinement shows the moving picture until they add up to
  /// one, then each complete group's (vtkLightShaftPass::Internals::SplitStillSetting). 1: not
  /// split. A setting whose frame would integrate more than
  /// vtkLightShaftGeometry::FrameSegmentAllowance segments is split so too, every frame, moving
  /// or still (SplitLongFrames).
  int RefinementSplit = 1;
  /// Which share of a split setting's pieces (steps, slabs) the frame integrates, in
  /// [0, RefinementSplit): pieces SamplePart, SamplePart + RefinementSplit, ..., each weighted
  /// RefinementSplit, so that a group of shares adds up to one frame of the setting, piece for
  /// piece (vtkLightShaftRefinement::Begin sets it).
  int SamplePart = 0;
  /// Image pieces (vtkLightShaftPass::SetImagePiece): the rows of the in-scatter this process
  /// computes (empty: all), and those the current light's method limits its drawing to
  /// (nullptr: all; set for the methods that split, vtkLightShaftInScatter::Add).
  std::vector<vtkLightShaftGeometry::RowBlock> PieceRows;
  const std::vector<vtkLightShaftGeometry::RowBlock>* ComputeRows = nullptr;

  /// The method whose slab program the frame readied (the frame report's GetShaderVariant names
  /// it).
  const vtkLightShaftMethod* ShaderMethod = nullptr;

  vtkLightShaftStatistics Statistics;
};

#endif
