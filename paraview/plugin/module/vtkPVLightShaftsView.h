/**
 * @class   vtkPVLightShaftsView
 * @brief   ParaView's render view with volumetric light shafts (vtkLightShaftPass).
 *
 * A vtkPVRenderView whose synchronized renderers run vtkLightShaftPass in their
 * image-processing slot, so the shafts are computed from the image and depth of the whole
 * scene (after IceT compositing when the data is distributed). ParaView 5.11 has one such slot
 * and the render view's tone mapping uses it too: this view puts a vtkPVImageProcessingChain
 * there, running the shafts and then the view's own tone-mapping pass when UseToneMapping is
 * on, so tone mapping (and its exposure, contrast, ... properties) keeps working.
 *
 * The pass's parameters are forwarded as view properties (server-manager proxy
 * "LightShaftsRenderView", label "Render View (Light Shafts)"); see LightShafts.xml for their
 * ranges and defaults. The scattering lights are the additional lights (ParaView's Light
 * Inspector, 1-based) listed by ShaftLights, of any kind (spot, point, directional), or with an
 * empty list every switched-on spot and point light of the view (vtkLightShaftPass's automatic
 * choice). The noise's time follows the view time (the animation time) unless
 * LinkShaftTimeToAnimation is off.
 *
 * @sa vtkLightShaftPass vtkPVImageProcessingChain vtkPVRenderView
 */

#ifndef vtkPVLightShaftsView_h
#define vtkPVLightShaftsView_h

#include "vtkPVLightShaftsModule.h" // For the export macro
#include "vtkPVRenderView.h"        // For the base class

#include <memory> // For std::unique_ptr (state lives in Internals)

class vtkAlgorithmOutput;
class vtkLight;
class vtkLightShaftPass;
class vtkMultiProcessController;

class VTKLIGHTSHAFTS_EXPORT vtkPVLightShaftsView : public vtkPVRenderView
{
public:
  static vtkPVLightShaftsView* New();
  vtkTypeMacro(vtkPVLightShaftsView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Quality presets of the ShaftQuality property.
  enum QualityType
  {
    CUSTOM = 0,      ///< the individual sampling properties
    DRAFT = 1,       ///< vtkLightShaftPass::SetQualityToDraft()
    INTERACTIVE = 2, ///< vtkLightShaftPass::SetQualityToInteractive()
    FINAL = 3        ///< vtkLightShaftPass::SetQualityToFinal()
  };

  /**
   * The pass the view runs (for C++ users and tests; scripts use the view properties).
   */
  vtkLightShaftPass* GetLightShaftPass();

  ///@{
  /**
   * What the last render did (vtkLightShaftFrameReport's GetRefinementConverged,
   * GetRefinementEstimates, GetTimeBudget, GetPredictedError, GetExactFinishState,
   * GetExactFinishFraction and GetExactFinishProblem), for scripts: the view's information
   * properties RefinementConverged, RefinementEstimates, LastTimeBudget, LastPredictedError,
   * ExactFinishState, ExactFinishFraction and ExactFinishProblem.
   */
  bool GetRefinementConverged();
  int GetRefinementEstimates();
  double GetLastTimeBudget();
  double GetLastPredictedError();
  int GetExactFinishState();
  double GetExactFinishFraction();
  const char* GetExactFinishProblem();
  ///@}

  ///@{
  /**
   * The last render's shader variant and its first light's light-leg table build time
   * (vtkLightShaftFrameReport::GetShaderVariant, GetLightFieldShadowBuildTime(0)), for
   * scripts: the information properties LastShaderVariant and LastMediumShadowBuildTime.
   */
  const char* GetLastShaderVariant();
  double GetLastMediumShadowBuildTime();
  ///@}

  ///@{
  /**
   * The scattering coefficient and the exposure in use (those chosen from the scene, or set),
   * for scripts and the GUI: the information properties ScatteringCoefficientInUse and
   * ShaftExposureInUse.
   */
  double* GetScatteringCoefficientInUse() VTK_SIZEHINT(3);
  double GetShaftExposureInUse();
  ///@}

  ///@{
  /**
   * Light shafts on or off. Off: the view renders exactly as a plain render view (tone mapping
   * included). Default is on.
   */
  void SetLightShafts(bool enabled);
  vtkGetMacro(LightShafts, bool);
  ///@}

  ///@{
  /**
   * Which lights scatter (the ShaftLights property, a list): empty = automatic (every
   * switched-on spot and point light of the view; directional lights only when listed, since
   * the light kit's are directional); k >= 1 = the k-th additional light (the Light
   * Inspector's list, in the order the lights were added), of any kind. Entries beyond the
   * list are ignored (none left: automatic). Default is empty.
   */
  void AddShaftLight(int index);
  void RemoveAllShaftLights();
  int GetNumberOfShaftLights() const;
  int GetShaftLight(int i) const;
  ///@}

  ///@{
  /**
   * The additional lights (ParaView's AdditionalLights property, the Light Inspector): hide the
   * superclass's methods to remember their order for ShaftLights, then forward.
   */
  void AddLight(vtkLight* light);
  void RemoveLight(vtkLight* light);
  ///@}

  ///@{
  /**
   * The medium (forwarded to the pass's vtkLightShaftMedium) and the image (to
   * vtkLightShaftPass), with the same ranges and defaults; ShaftExposure is the pass's
   * Exposure, the render view's own Exposure being tone mapping's.
   */
  void SetScatteringCoefficient(double r, double g, double b);
  void SetAbsorptionCoefficient(double r, double g, double b);
  void SetPhaseFunction(int phase);
  void SetAnisotropy(double g);
  void SetShaftExposure(double exposure);
  void SetAttenuateScene(bool attenuate);
  ///@}

  /**
   * The medium chosen from the scene (vtkLightShaftPass::SetFitMediumToScene), asked at the
   * next render after it is switched on: the coefficients and the exposure the view was given
   * are kept where they differ from the defaults (a script's or the user's values; ParaView
   * pushes every property's default when it creates the view), and the rest is chosen. Off:
   * the values as given. Default is on.
   */
  void SetFitMediumToScene(bool fit);

  /**
   * Surfaces shadowed by the scattering lights' shadow maps (and shaped by the cookie),
   * forwarded to vtkLightShaftPass::SetShadowSurfaces. Default is off.
   */
  void SetShadowSurfaces(bool shadow);

  /**
   * With ShadowSurfaces, the surfaces' light dimmed by the medium on its way from the light,
   * forwarded to vtkLightShaftPass::SetAttenuateSurfaceLight. Default is on.
   */
  void SetAttenuateSurfaceLight(bool attenuate);

  /**
   * Translucent representations (opacity below 1) dim and tint the light by their opacity and
   * colour, forwarded to vtkLightShaftPass::SetTranslucentShadows. Default is on.
   */
  void SetTranslucentShadows(bool translucent);

  ///@{
  /**
   * The method and its own controls, forwarded to vtkLightShaftPass (SetMethod,
   * SetLatticeResolution, SetNumberOfSteps, SetInterleaveSize, SetRadialSamples, SetDecay,
   * SetDensity, SetWeight, SetRadialJitter, SetRadialGuardBand, SetEpipolarLines,
   * SetEpipolarSamples, SetEpipolarStep, SetLightVolumeResolution; same ranges and defaults).
   */
  void SetShaftMethod(int method);
  void SetLatticeResolution(int resolution);
  void SetNumberOfSteps(int steps);
  void SetInterleaveSize(int size);
  void SetRadialSamples(int samples);
  void SetDecay(double decay);
  void SetDensity(double density);
  void SetWeight(double weight);
  void SetRadialJitter(bool jitter);
  void SetRadialGuardBand(double extent);
  void SetEpipolarLines(int lines);
  void SetEpipolarSamples(int samples);
  void SetEpipolarStep(int step);
  void SetLightVolumeResolution(int cells);
  ///@}

  /**
   * The target error (vtkLightShaftPass::SetTargetError; 0, the default, is off): when set
   * the pass chooses its sampling each frame, over the preset and the sampling properties.
   */
  void SetShaftTargetError(double error);

  ///@{
  /**
   * Interaction (forwarded to vtkLightShaftPass: SetTimeBudget, SetUseAllocatedRenderTime,
   * SetProgressiveRefinement, SetRefinementFrames, SetExactFinish, SetSplitLongFrames; same
   * ranges and defaults,
   * except that the
   * view's ProgressiveRefinement property is on by default: the GUI's pqLightShaftsRefinement
   * renders a still view until it converges).
   */
  void SetTimeBudget(double seconds);
  void SetUseAllocatedRenderTime(bool use);
  void SetProgressiveRefinement(bool refine);
  void SetRefinementFrames(int frames);
  void SetExactFinish(bool finish);
  void SetSplitLongFrames(bool split);
  ///@}

  ///@{
  /**
   * Sampling: forwarded to vtkLightShaftPass, unless ShaftQuality is a preset (DRAFT,
   * INTERACTIVE, FINAL), which then decides slices, jitter, blur, downsampling and shadow-map
   * size (the values set here are kept and come back with CUSTOM). Default is CUSTOM with the
   * pass's defaults. A preset sets the method too (ShaftMethod, NumberOfSteps and
   * InterleaveSize apply again with Custom).
   */
  void SetShaftQuality(int quality);
  vtkGetMacro(ShaftQuality, int);
  void SetNumberOfSlices(int slices);
  void SetShadowMapSize(int size);
  void SetAutomaticSliceCount(bool automatic);
  void SetMaximumNumberOfSlices(int slices);
  void SetShaftJitter(bool jitter);
  void SetShaftBlurRadius(int radius);
  void SetShaftDownsampleFactor(int factor);
  void SetAccumulationPrecision(int precision);
  ///@}

  ///@{
  /**
   * Spotlight cookie read from an image file (any format vtkImageReader2Factory knows: PNG,
   * JPEG, TIFF, ...); empty or nullptr turns it off; an unreadable file is reported and turns
   * it off. Default is off.
   */
  void SetCookieFileName(const char* fileName);
  const char* GetCookieFileName();
  ///@}

  ///@{
  /**
   * Scrolling-noise density: forwarded to the pass's vtkLightShaftMedium.
   */
  void SetNoiseAmplitude(double amplitude);
  void SetNoiseScale(double scale);
  void SetNoiseVelocity1(double u, double v);
  void SetNoiseVelocity2(double u, double v);
  ///@}

  ///@{
  /**
   * A medium from data, forwarded to the pass's vtkLightShaftMedium (SetDensityFieldConnection,
   * SetDensityArrayName, SetDensityScale, SetBackgroundDensity, SetFieldShadowResolution,
   * SetFieldResolution: same ranges and defaults; the property names are those of earlier
   * versions): the MediumDensity property's pipeline output (a vtkImageData, brought up to
   * date at each render; none: the homogeneous medium), its array (MediumDensityArray: point
   * or cell data, the first component; empty: the scalars), scale, background density, the
   * light leg's table resolution and the most samples per axis the shafts read (under MPI each
   * process resamples its piece to that grid).
   */
  void SetMediumDensityConnection(vtkAlgorithmOutput* output);
  void SetMediumDensityArray(const char* name);
  void SetMediumDensityScale(double scale);
  void SetMediumBackgroundDensity(double density);
  void SetMediumShadowResolution(int resolution);
  void SetMediumFieldResolution(int resolution);
  ///@}

  ///@{
  /**
   * A volume representation as the medium (vtkLightShaftMedium::SetDensityVolume): on, the
   * first visible volume the view renders scatters the light, its opacity transfer function as
   * the density (the MediumDensity property is set aside meanwhile); off, every volume dims and
   * shadows the shafts (docs/paraview.md). Default is off.
   */
  void SetMediumFromVolume(bool on);
  vtkGetMacro(MediumFromVolume, bool);
  ///@}

  ///@{
  /**
   * The noise's time: with LinkShaftTimeToAnimation on (default), the view time (ParaView's
   * animation time); off, ShaftTime (default 0).
   */
  void SetLinkShaftTimeToAnimation(bool link);
  vtkGetMacro(LinkShaftTimeToAnimation, bool);
  void SetShaftTime(double time);
  vtkGetMacro(ShaftTime, double);
  void SetViewTime(double value) override;
  ///@}

  /**
   * Tone mapping, chained after the shafts instead of taking the image-processing slot from
   * them (hides vtkPVRenderView::SetUseToneMapping; the proxy's UseToneMapping property calls
   * this one).
   */
  void SetUseToneMapping(bool use);

  ///@{
  /**
   * Under MPI (each process rendering its part of the data), make every process's shadow map
   * see every process's occluders: the processes use one light camera (from the view's global
   * geometry bounds) and combine their depth maps with a minimum over processes before the
   * shafts are computed. Off: each process's shadow map holds only its own geometry (occluders
   * held by other processes cast no shadow into the shafts; docs/paraview-mpi.md). No effect in
   * a single process. Default is on.
   */
  vtkSetMacro(DistributedShadowMap, bool);
  vtkGetMacro(DistributedShadowMap, bool);
  ///@}

  ///@{
  /**
   * Under MPI, divide the shafts' work: each process computes the in-scatter of its piece of
   * the picture's rows (SLICES, RAY_MARCH and ANALYTIC; the other methods compute all of it on
   * every process) on the composited depth, and process 0 gathers the pieces
   * (vtkLightShaftPass::SetImagePiece; docs/paraview-mpi.md). Off: every process computes the
   * whole in-scatter. No effect in a single process. Default is on.
   */
  vtkSetMacro(DivideShaftWork, bool);
  vtkGetMacro(DivideShaftWork, bool);
  ///@}

  ///@{
  /**
   * This process's share of the last render under MPI, for scripts (information properties of
   * the same names): the bytes it sent and received in the exchanges (shadow maps, depth,
   * in-scatter pieces; 0 in a single process), the in-scatter's rows it computed and the
   * fragments it shaded there (vtkLightShaftFrameReport::GetImagePieceRows,
   * GetInScatterFragments: 0 and -1 when the work was not divided).
   */
  double GetLastBytesExchanged();
  int GetLastImagePieceRows();
  double GetLastInScatterFragments();
  ///@}

protected:
  vtkPVLightShaftsView();
  ~vtkPVLightShaftsView() override;

  // Hands the global geometry bounds to the pass before each local render (distributed).
  void AboutToRenderOnLocalProcess(bool interactive) override;
  // The pass's distributed-rendering events: ShadowMapReuseEvent (whether every process's map
  // is unchanged), ShadowMapRenderedEvent (the processes' maps combined), SceneDepthReadyEvent
  // (process 0's depth given to all), InScatterPieceEvent (the pieces gathered on process 0).
  void Exchange(unsigned long event, void* data);
  void UpdateVolumes(vtkMultiProcessController* controller);

  bool DistributedShadowMap = true;
  bool DivideShaftWork = true;

  bool LightShafts = true;
  int ShaftQuality = CUSTOM;
  bool LinkShaftTimeToAnimation = true;
  bool MediumFromVolume = false;
  double ShaftTime = 0.0;

private:
  vtkPVLightShaftsView(const vtkPVLightShaftsView&) = delete;
  void operator=(const vtkPVLightShaftsView&) = delete;

  // Puts the chain (or tone mapping alone, or nothing) in the image-processing slot.
  void UpdateImageProcessing();
  // Pushes the sampling parameters, then the preset if one is chosen.
  void UpdateQuality();
  // Gives the pass the lights ShaftLights lists (none: its automatic choice).
  void UpdateLight();
  // Pushes the linked or fixed time.
  void UpdateTime();

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
