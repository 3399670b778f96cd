/**
 * @class   vtkLightShaftReference
 * @brief   Float64 CPU reference of the in-scattered radiance vtkLightShaftPass renders.
 *
 * Integrates exactly the model vtkLightShaftPass documents, for every pixel-centre view ray of
 * a renderer's camera, summed over the lights the pass uses:
 *
 *   L_in = sum over lights of
 *          int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) M(x) exp(-sigma_t (r + t)) dt
 *
 * with the same light choice (the switched-on lights given to the pass, of any kind; with none
 * given every switched-on spot and point light of the renderer), light description, phase
 * functions (cos theta = -d . l) and medium, read from a vtkLightShaftPass. Per kind of light
 * (P its transformed position, a the unit direction to its focal point):
 *  - spot (positional, cone angle below 90 degrees): r = |x - P|, lit inside the cone's forward
 *    nappe, S = cos(angle to a)^exponent, A = 1 / (c0 + c1 r + c2 r^2), l = (x - P) / r;
 *  - point (positional, cone angle of 90 degrees or more): as a spot without the cone (S = 1);
 *  - directional (not positional): r = (x - P) . a, the distance from the plane through P
 *    perpendicular to a; lit where r >= 0; S = A = 1; l = a.
 * M is the cookie colour times the noise density when the pass has them: on a spot's square
 * (cookie clamped to its edge), on a directional light's square of side |focal point - P|
 * centred on its axis (cookie repeating), and for a point light no cookie and the noise
 * triplanar over the unit direction from the light, in world axes.
 *
 * The surfaces and the visibility V are exact: the opaque polygonal props (vtkActor with a
 * vtkPolyDataMapper input, in world coordinates) are put in a vtkModifiedBSPTree; t_s is the
 * first hit of the ray (or the far clipping plane) and V(x) tests the segment from x to a spot
 * or point light, or from x back along a to a directional light's plane (geometry before the
 * plane casts nothing). For each light the ray is clipped to where the light shines (the cone,
 * in closed form; everywhere; the half-space) and split at every change of visibility (found
 * on a sampling, then bisected to 1e-12 of the ray's length); each piece is integrated by
 * adaptive Gauss-Kronrod (7/15 points), in the equiangular angle about the light when A(r)
 * falls off (in t otherwise), or by a closed form where one holds (UseClosedForms, default
 * on): for a spot (exponent 0) or point light with isotropic phase and A = 1/r^2, those of
 * shared/notes (A: no extinction; B: homogeneous extinction, Sun et al. 2005); for a
 * directional light, any phase, the exact exponential integral (theta is constant). Neither
 * holds with a cookie or noise.
 *
 * Output: a vtkImageData laid out like vtkLightShaftPass::GetInScatteredRadiance (viewport
 * size, row 0 at the bottom) with "InScatteredRadiance" (double RGB) and "ErrorEstimate" (the
 * quadrature's estimated absolute error per pixel, summed over the pieces and lights, double
 * RGB), and "SurfaceLight": the surface term of vtkLightShaftPass::ShadowSurfaces, 3 doubles
 * per light (the pass's order), for the first opaque surface each ray hits: the fraction of that
 * light's VTK lighting that reaches it, V times the cookie (not the noise) times the medium's
 * transmittance along the light leg, exp(-sigma_t times its optical depth), and the volume's
 * (0 where the ray hits no surface). Pixels run in parallel with vtkSMPTools, in batches of
 * about a fifth of a second each: between batches the filter reports its progress
 * (UpdateProgress, ProgressEvent) and honours AbortExecute (set it, for example from a
 * ProgressEvent observer, and the filter stops within a batch: its output is then incomplete
 * and Update() reports no error). Each pixel's work is bounded (SetMaximumEvaluations).
 *
 * Visibility: EXACT (default) as above, or SHADOW_MAP: the depth map the pass rendered in its
 * last frame, looked up as the pass does (nearest texel, the same bias: relative for a spot's
 * perspective map, absolute in world units for a directional light's orthographic map with
 * its linear depth), so that comparing the pass with both references separates the shadow
 * map's error from the integration's. SHADOW_MAP needs exactly one used light, a spot or a
 * directional light, that had a shadow map in the pass's last frame: the pass publishes the
 * depth range and bias of its first mapped light only, and a point light's cube map is not read
 * back. Otherwise Update() reports an error (naming the light) and fails; EXACT supports every
 * kind and any number of lights.
 *
 * No regularisation of A(r) near the light, as in the pass: both integrate the model exactly.
 * Parallel projection is supported.
 *
 * @sa vtkLightShaftPass
 */

#ifndef vtkLightShaftReference_h
#define vtkLightShaftReference_h

#include "vtkImageAlgorithm.h"          // For the base class
#include "vtkLightShaftsOpenGLModule.h" // For the export macro
#include "vtkSmartPointer.h"            // For the renderer and pass held

class vtkDoubleArray;
class vtkLightShaftPass;
class vtkLightShaftReferenceJob;
class vtkRenderer;

class VTKLIGHTSHAFTSOPENGL_EXPORT vtkLightShaftReference : public vtkImageAlgorithm
{
public:
  static vtkLightShaftReference* New();
  vtkTypeMacro(vtkLightShaftReference, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How V(x) is decided.
  enum VisibilityModeType
  {
    EXACT = 0,     ///< segments to the light (or its plane) against the scene's polygons
    SHADOW_MAP = 1 ///< the pass's last shadow map of its one light, nearest texel
  };

  ///@{
  /**
   * EXACT or SHADOW_MAP (see the class description). Default is EXACT.
   */
  vtkSetClampMacro(VisibilityMode, int, EXACT, SHADOW_MAP);
  vtkGetMacro(VisibilityMode, int);
  void SetVisibilityModeToExact() { this->SetVisibilityMode(EXACT); }
  void SetVisibilityModeToShadowMap() { this->SetVisibilityMode(SHADOW_MAP); }
  ///@}

  ///@{
  /**
   * The renderer whose camera, viewport size, lights and props are integrated. Default is
   * nullptr (required).
   */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  ///@}

  ///@{
  /**
   * The pass whose medium, phase function, cookie, noise and lights (GetLight(i), or its
   * automatic choice) are used. Default is nullptr (required).
   */
  void SetLightShaftPass(vtkLightShaftPass* pass);
  vtkLightShaftPass* GetLightShaftPass();
  ///@}

  ///@{
  /**
   * Relative tolerance of the adaptive quadrature on each piece, in [1e-14, 1e-2]; non-finite
   * values are refused (error, previous value kept). Default is 1e-9.
   */
  void SetRelativeTolerance(double tolerance);
  vtkGetMacro(RelativeTolerance, double);
  ///@}

  ///@{
  /**
   * Visibility samples per lit interval and light before bisection, in [2, 100000]: a shadow
   * feature narrower than one spacing (in the integration variable) can be missed. Default
   * is 32.
   */
  vtkSetClampMacro(VisibilitySamples, int, 2, 100000);
  vtkGetMacro(VisibilitySamples, int);
  ///@}

  ///@{
  /**
   * Use the closed forms where they hold (see the class description). Off forces quadrature
   * everywhere (their comparison is a test). Default is on.
   */
  vtkSetMacro(UseClosedForms, bool);
  vtkGetMacro(UseClosedForms, bool);
  vtkBooleanMacro(UseClosedForms, bool);
  ///@}

  ///@{
  /**
   * The most integrand evaluations one pixel's ray may spend over its lights, in [1000,
   * 1e12]: the adaptive quadrature refines the panel of largest error first, and where this
   * bound ends it the pixel keeps what it has, its estimated error in "ErrorEstimate" and the
   * pixel counted in LastExhaustedPixels. It bounds the time of a pixel (about a second of a
   * core at the slowest evaluations measured: a dense density field on both legs); converged
   * pixels of ordinary scenes spend far fewer. Non-finite values are refused (error, previous
   * value kept). Default is 1000000.
   */
  void SetMaximumEvaluations(double evaluations);
  vtkGetMacro(MaximumEvaluations, double);
  ///@}

  /**
   * Number of pixels of the last Update() where a closed form computed at least one light's
   * share.
   */
  vtkGetMacro(LastClosedFormPixels, vtkIdType);

  /**
   * Number of pixels of the last Update() whose integration MaximumEvaluations ended (their
   * error estimate may then exceed the tolerance).
   */
  vtkGetMacro(LastExhaustedPixels, vtkIdType);

  /**
   * The most evaluations one pixel of the last Update() spent.
   */
  vtkGetMacro(LastMostEvaluations, double);

  /**
   * Number of lights the last Update() integrated (the pass's choice; 0 when none is usable).
   */
  vtkGetMacro(LastNumberOfLights, int);

protected:
  vtkLightShaftReference();
  ~vtkLightShaftReference() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkMTimeType GetMTime() override;

  int VisibilityMode = EXACT;
  double RelativeTolerance = 1e-9;
  int VisibilitySamples = 32;
  bool UseClosedForms = true;
  double MaximumEvaluations = 1e6;
  vtkIdType LastClosedFormPixels = 0;
  vtkIdType LastExhaustedPixels = 0;
  double LastMostEvaluations = 0.0;
  int LastNumberOfLights = 0;

private:
  vtkLightShaftReference(const vtkLightShaftReference&) = delete;
  void operator=(const vtkLightShaftReference&) = delete;

  void IntegrateInBatches(const vtkLightShaftReferenceJob& job,
    int width,
    int height,
    vtkDoubleArray* surfaceLight,
    vtkDoubleArray* radiance,
    vtkDoubleArray* errors);

  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkLightShaftPass> Pass;
};

#endif
