/**
 * @file   vtkLightShaftRefinement.h
 * @brief  Progressive refinement of a still view's in-scatter (private, not installed).
 */

#ifndef vtkLightShaftRefinement_h
#define vtkLightShaftRefinement_h

#include "vtkLightShaftResources.h"       // For the owned textures and the full-screen pass
#include "vtkLightShaftSeparableFilter.h" // For the picture's filter
#include "vtkSmartPointer.h"              // For the framebuffer held
#include "vtkType.h"                      // For vtkMTimeType

#include <glm/glm.hpp> // For the camera matrices of the signature

#include <utility> // For the signature's (object, MTime) pairs
#include <vector>  // For the signature's objects

class vtkLight;
class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftRefinement
 * @brief   While nothing that decides the picture changes, each frame's in-scatter is one more
 *          estimate, its samples shifted (step and slab offsets, lookups, the shadow map's
 *          texel grid), averaged into a float history; after RefinementFrames estimates (or
 *          one, when nothing of the frame's sampling shifts) the history is converged and the
 *          shafts need not be computed again.
 *
 * What decides the picture (the signature): the camera's matrices, the viewport, the pass's
 * parameters (its MTime, Time included), each light's values, each visible prop, cookie and
 * noise image with its MTime (a prop's redraw MTime: its mapper and input data), and the
 * sampling the frame renders with (a budget or target may choose it). Any change starts a new
 * history.
 */
class vtkLightShaftRefinement
{
public:
  vtkLightShaftRefinement();
  ~vtkLightShaftRefinement();

  /// What decides the picture: the frame's camera and viewport, and (object, MTime) pairs.
  struct Signature
  {
    glm::dmat4 WorldToView{ 1.0 };
    glm::dmat4 ViewToClip{ 1.0 };
    int Origin[2] = { 0, 0 };
    int Size[2] = { 0, 0 };
    std::vector<std::pair<const vtkObject*, vtkMTimeType>> Objects;
    /// The lights as the pass reads them (vtkLightShaftModel::DescribeLight), not their MTimes:
    /// the surface light switches a light off and on again within each frame.
    std::vector<double> Lights;
    /// The sampling the frame renders with (SetSampling): a target error or a frame budget
    /// may choose another than the parameters set, for the same scene.
    std::vector<double> Sampling;
    /// Everything but the sampling is equal: the same scene seen the same way.
    bool SameScene(const Signature& other) const;
    bool operator==(const Signature& other) const;
  };
  /**
   * What decides the frame's picture: its camera and viewport, the pass (frame.Owner), the
   * `lights` and their values, the renderer's visible props with their redraw MTimes, and
   * `imagesTime`, the cookie and noise images' (vtkLightShaftLightTextures::GetImagesTime).
   */
  static Signature Sign(const vtkLightShaftFrame& frame,
    const std::vector<vtkLight*>& lights,
    vtkMTimeType imagesTime);

  /// Record in `signature` the sampling of the frame's parameters (after the error model).
  static void SetSampling(Signature& signature, const vtkLightShaftFrame& frame);
  /// Whether `signature` shows the scene of the last frame's, the same way (sampling aside).
  bool IsStill(const Signature& signature) const;

  /**
   * Start the frame: a new history when `signature` differs from the last one's or refinement
   * is off. Sets the frame's SamplingRotation, LookupFraction and ShadowMapOffset for its
   * estimate: 0, 0.5 and 0 for a history's first (the picture without refinement), then the
   * R4 sequence; and for a split setting the SamplePart its estimate integrates.
   */
  void Begin(vtkLightShaftFrame& frame, Signature&& signature);
  /// Whether the history already holds the converged picture of this frame's signature.
  bool IsConverged() const { return this->Converged; }

  /**
   * Add the frame's estimate (full resolution) into the history and return the picture:
   * `rotates` says whether the estimate's samples moved with the rotation (when not, one
   * estimate is the converged picture). Refinement off: returns `estimate` unchanged.
   *
   * The first estimate is the picture without refinement, filtered as the parameters say (the
   * interleaved gather, the blur); the later ones are not (frame.Unfiltered), so that the
   * average converges to the unfiltered answer instead of keeping the filters' blur. The
   * picture of n estimates is the average filtered by a Gaussian that holds the first
   * picture's noise reduction: its samples along an axis times sqrt(n) are the first
   * filters' (PictureSigma), none once the estimates alone hold that many. A split setting's
   * group of estimates counts as one: the first group is filtered, each estimate (the filters
   * are linear: its mean is one frame of the setting, filtered).
   */
  vtkTextureObject* Accumulate(vtkLightShaftFrame& frame, vtkTextureObject* estimate, bool rotates);
  /// The picture of the history (the converged one when IsConverged()).
  vtkTextureObject* GetHistory() const;
  /// Estimates in the picture the last frame showed (0: refinement off).
  int GetEstimates() const { return this->Estimates; }
  /// Estimates per frame of the still setting (frame.RefinementSplit at the history's start).
  int GetSplit() const { return this->Split; }
  /**
   * Whether the picture shown is an earlier one, held: a split still setting
   * (frame.RefinementSplit > 1) shows the picture before its history (where that shows the same
   * scene) until its estimates add up to one frame of the setting, whose picture the error
   * model predicts (never worse when the camera stops, docs/quality-and-cost.md), and then the
   * picture of its last complete group of estimates (a partial group's lookups cover only part
   * of each piece).
   */
  bool IsHolding() const
  {
    return this->Holding && this->Estimates % this->Split != 0 && !this->Converged;
  }
  /// Whether the picture held is the one before the history (no group of estimates complete).
  bool IsHoldingEarlierPicture() const
  {
    return this->IsHolding() && this->Estimates < this->Split;
  }
  /// The standard deviation, in pixels, of the Gaussian that filtered the last picture's
  /// average (0: none).
  double GetPictureSigma() const { return this->Sigma; }

  /**
   * The Gaussian's standard deviation (pixels of the estimates' resolution) for a picture of
   * `estimates` estimates whose first was filtered to `firstSamples` effective samples along
   * an axis (vtkLightShaftSeparableFilter::EffectiveSamples): 0 where the estimates alone
   * average as many (firstSamples <= sqrt(estimates)).
   */
  static double PictureSigma(double firstSamples, int estimates);

  /// Forget the history (the next frame starts a new one).
  void Reset();
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftRefinement(const vtkLightShaftRefinement&) = delete;
  void operator=(const vtkLightShaftRefinement&) = delete;

  /// The picture of the history after an estimate: `average`, filtered, or the one before.
  vtkTextureObject* ChoosePicture(vtkLightShaftFrame& frame,
    vtkTextureObject* previous,
    vtkTextureObject* average);
  /// `source` (the picture before the history, or a complete group's) copied into Held.
  void HoldPicture(vtkLightShaftFrame& frame, vtkTextureObject* source);

  Signature Last;
  bool HasLast = false;
  int Estimates = 0;
  bool Converged = false;
  int Split = 1;                          ///< estimates per frame of the still setting
  vtkTextureObject* HoldSource = nullptr; ///< the picture to hold, until the first estimate
  bool Holding = false;                   ///< Held holds a picture to show
  vtkLightShaftResources::OwnedTexture Held;
  int Current = 0; ///< which of History holds the average
  vtkLightShaftResources::OwnedTexture History[2];
  double FirstSamples = 1.0; ///< the first estimate's filters, along an axis
  double Sigma = 0.0;
  vtkTextureObject* Picture = nullptr; ///< the filtered average, or the average
  vtkLightShaftSeparableFilter PictureFilter;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkLightShaftResources::FullScreenPass Average;
};

#endif
