/**
 * @file   vtkLightShaftPassInternals.h
 * @brief  What vtkLightShaftPass holds besides its parameters (private, not installed), shared
 *         by its source files: vtkLightShaftPass.cxx (parameters and the frame's recipe),
 *         vtkLightShaftPassSampling.cxx (the frame's sampling) and vtkLightShaftPassReadouts.cxx
 *         (what the last frame left to read back).
 */
#ifndef vtkLightShaftPassInternals_h
#define vtkLightShaftPassInternals_h

#include "vtkLightShaftPass.h"

#include "vtkLightShaftComposite.h"      // For the composite
#include "vtkLightShaftCostModel.h"      // For the frame budget's cost model
#include "vtkLightShaftErrorModel.h"     // For the error model's features
#include "vtkLightShaftExactFinish.h"    // For the exact finish
#include "vtkLightShaftFrame.h"          // For the frame
#include "vtkLightShaftFrameReport.h"    // For the last frame's read-outs
#include "vtkLightShaftInScatter.h"      // For the in-scatter
#include "vtkLightShaftLightTextures.h"  // For the cookie and noise
#include "vtkLightShaftLights.h"         // For the lights
#include "vtkLightShaftMedium.h"         // For the medium
#include "vtkLightShaftMediumTexture.h"  // For the medium's density field
#include "vtkLightShaftReferenceInput.h" // For the reference's input
#include "vtkLightShaftRefinement.h"     // For the progressive refinement
#include "vtkLightShaftSceneCheck.h"     // For what of the scene cannot be used
#include "vtkLightShaftSceneRenderer.h"  // For the scene
#include "vtkLightShaftSurfaceLight.h"   // For the surface light
#include "vtkLightShaftVolumeTexture.h"  // For the scene's volume

#include "vtkCallbackCommand.h"         // For the window's deletion
#include "vtkNew.h"                     // For vtkNew
#include "vtkOpenGLFramebufferObject.h" // For the read-back framebuffer
#include "vtkOpenGLRenderWindow.h"      // For the window
#include "vtkPropCollection.h"          // For the props as modelled
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTimeStamp.h"               // For the fit's times
#include "vtkWeakPointer.h"             // For vtkWeakPointer

#include <string> // For the shader variants
#include <vector> // For the lights

/**
 * Everything the pass holds besides its parameters: its components (each owning its GL
 * objects, freed by ReleaseGraphicsResources), the lights, and what the last frame left for
 * the read-outs.
 */
class vtkLightShaftPass::Internals
{
public:
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkCallbackCommand> WindowDeleted;
  unsigned long WindowDeletedTag = 0;
  vtkNew<vtkCallbackCommand> WindowRendered;
  unsigned long WindowRenderedTag = 0;
  unsigned long WindowStartedTag = 0;
  bool WarnedPointCookie = false;
  int FrameCounter = 0;
  /// FitMediumToScene: whether a fit is due, when it was asked, and when the user last set the
  /// exposure (a value set after the request wins).
  bool FitPending = false;
  vtkTimeStamp FitRequested;
  vtkTimeStamp ExposureSet;
  /// Each lit light's table error (vtkLightShaftFieldError::TableError) and what it was
  /// measured for: measured again only when the field, the light or the resolution change.
  struct TableErrorEntry
  {
    std::size_t Index = 0; ///< among the lights that radiate
    vtkMTimeType FieldVersion = 0;
    vtkLightShaftModel::Light Light;
    int Resolution = -1;
    double Extinction = -1.0;
    double Error = 0.0;
  };
  std::vector<TableErrorEntry> TableErrors;
  double TableError(std::size_t index,
    const vtkLightShaftModel::Light& light,
    int resolution,
    double extinction);
  /// The frame's MediumShadowResolution: the coarsest, from the one set, doubling up to 256,
  /// whose table's term (FieldMargin times its error) is within `aim` on every light, else 0
  /// (the leg marched). Unchanged where no table is used.
  void ResolveTable(vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
    double aim);
  /// With a TargetError: the table's term within half the target.
  void ResolveTableForTarget(vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights);
  /// A still view refining: the table's term within half of what the setting's samples are
  /// predicted to make (vtkLightShaftPassSampling.cxx).
  void RefineTableWhenStill(vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights);
  /// The last ApplyErrorModel's features, one per radiating light (the table's term as the
  /// frame's table has it).
  std::vector<vtkLightShaftErrorModel::Features> Features;
  /// The lights as DescribeLights found them, kept while the view is still.
  std::vector<vtkLightShaftErrorModel::Features> Described;
  bool DescribedValid = false;
  void DescribeLights(const vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights);
  vtkSmartPointer<vtkLightShaftMedium> Medium; ///< never nullptr (SetMedium)
  vtkNew<vtkLightShaftFrameReport> LastFrame;
  vtkNew<vtkPropCollection> ModelledProps; ///< the frame's view props as modelled (per frame)

  // The components, in the order a frame uses them.
  vtkLightShaftSceneCheck Check;
  vtkLightShaftLights Lights;
  vtkLightShaftSceneRenderer Scene;
  vtkLightShaftLightTextures Textures;
  vtkLightShaftMediumTexture DensityTexture;
  vtkLightShaftVolumeTexture VolumeTexture;
  vtkLightShaftInScatter InScatter;
  vtkLightShaftSurfaceLight SurfaceLight;
  vtkLightShaftComposite Composite;
  vtkLightShaftRefinement Refinement;
  vtkLightShaftExactFinish Finish;
  vtkLightShaftCostModel Costs;
  vtkLightShaftCostModel::Choice BudgetChoice; ///< kept while the view is still
  double BudgetOfChoice = 0.0;                 ///< the budget BudgetChoice was made for
  bool HasBudgetChoice = false;
  vtkLightShaftCostModel::Choice MovingChoice; ///< the budget's last while the view moved
  bool HasMovingChoice = false;

  // The last frame's L_in (full resolution) when InScatterValid.
  vtkTextureObject* FinalInScatter = nullptr;
  bool InScatterValid = false;
  /// What the last frame that computed the shafts did per light (a converged frame's too).
  std::vector<vtkLightShaftLightStatistics> ComputedLights;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ReadFramebuffer;
  /// Image pieces: the textures an observer of SceneDepthReadyEvent or InScatterPieceEvent
  /// reads and rewrites while the event is handled (nullptr otherwise).
  vtkTextureObject* SceneDepthForEvent = nullptr;
  vtkTextureObject* InScatterForEvent = nullptr;

  void Track(vtkOpenGLRenderWindow* window);
  void Untrack();
  void ReleaseOwnResources(vtkWindow* w);

  static vtkLightShaftParameters Snapshot(vtkLightShaftPass& self, vtkLightShaftMedium& medium);
  bool BeginFrame(vtkLightShaftPass& self, const vtkRenderState* s, vtkLightShaftFrame& frame);
  void RenderShafts(vtkLightShaftFrame& frame,
    vtkRenderPass* delegate,
    const std::vector<vtkLight*>& lights,
    bool shadowSurfaces);
  /// The light's leg through the medium's field, tabulated (vtkLightShaftPassSampling.cxx):
  /// `asSet` at the resolution set, `refined` at another a target or a still view chose (both
  /// kept, so that neither is rebuilt when the view moves again).
  void ReadyFieldShadow(vtkLightShaftFrame& frame,
    vtkLightShaftFieldTableTexture& asSet,
    vtkLightShaftFieldTableTexture& refined);
  /// The light's leg through the scene's vtkVolume, tabulated (vtkLightShaftPassSampling.cxx).
  void ReadyVolumeShadow(vtkLightShaftFrame& frame, vtkLightShaftFieldTableTexture& shadow);
  /// Cookie and noise readied, the sampling chosen, refinement begun (and its shadow-map
  /// shift applied to `lightFrames`); returns the cookie texture (vtkLightShaftPassSampling.cxx).
  vtkTextureObject* ChooseSampling(vtkLightShaftFrame& frame,
    const std::vector<vtkLight*>& lights,
    std::vector<vtkLightShaftGeometry::LightFrame>& lightFrames);
  /// The frame's budget in seconds (0: none): TimeBudget, or the renderer's allocated time
  /// while interacting (vtkLightShaftPassSampling.cxx).
  static double FrameBudget(const vtkLightShaftFrame& frame);
  void ApplyErrorModel(vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
    bool noLightVolume,
    bool still);
  /// A still view after frames under a budget: their setting kept where the still setting is
  /// not predicted better (vtkLightShaftPassSampling.cxx).
  void KeepMovingSampling(vtkLightShaftFrame& frame,
    const std::vector<vtkLightShaftGeometry::LightFrame>& lights,
    bool finishes);
  /// A still view after frames under a budget: a ray march that would overrun the budget's
  /// frame split among estimates (vtkLightShaftPassSampling.cxx).
  void SplitStillSetting(vtkLightShaftFrame& frame);
  void SplitLongFrame(vtkLightShaftFrame& frame);
  /// The frame's refinement and exact-finish read-outs.
  void PublishRefinement(vtkLightShaftFrame& frame);
  /// A measured frame: `shafts` seconds of in-scatter of `total` (the cost model learns).
  void ObserveFrameTime(vtkLightShaftFrame& frame, double shafts, double total);
  /// Image pieces: this process's rows (frame.PieceRows), and the scene depth handed to the
  /// observers of SceneDepthReadyEvent (which give every process the composited one).
  void BeginImagePiece(vtkLightShaftFrame& frame);
  vtkPropCollection* ResolveModelledProps(vtkLightShaftFrame& frame);
  /// Every light's in-scatter added up, post-processed, refined (each light's surface light
  /// too); false when nothing was computed (the target holds zeros).
  vtkTextureObject* ComputeInScatter(vtkLightShaftFrame& frame,
    vtkRenderPass* delegate,
    const std::vector<vtkLight*>& lights,
    std::vector<vtkLightShaftGeometry::LightFrame>& lightFrames,
    vtkTextureObject* cookie,
    bool shadowSurfaces,
    bool& computed);
  void RenderLight(vtkLightShaftFrame& frame,
    vtkRenderPass* delegate,
    vtkLight* light,
    vtkLightShaftGeometry::LightFrame&& lightFrame,
    vtkTextureObject* cookie,
    bool shadowSurfaces);
  /// The frame's shader variants, each light's joined by "; " (the last readied program's
  /// when no light computed any), and that program's fragment source.
  std::string ShaderVariants(const vtkLightShaftFrame& frame) const;
  const char* ShaderSource() const;
};

/**
 * The float64 reference's input from `pass`, through its public read-outs: its lights, medium,
 * cookie, shadow casters' bounds, and the last frame's shadow maps (for vtkLightShaftReference
 * and the exact finish: the reference never reads the pass).
 */
vtkLightShaftReferenceInput vtkLightShaftPassReferenceInput(vtkLightShaftPass* pass);

#endif