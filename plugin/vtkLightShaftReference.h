/**
 * @class   vtkLightShaftReference
 * @brief   Float64 CPU reference of the in-scattered radiance vtkLightShaftPass renders.
 *
 * Integrates exactly the model vtkLightShaftPass documents, for every pixel-centre view ray of
 * a renderer's camera:
 *
 *   L_in = int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t r) exp(-sigma_t t) dt
 *
 * with the same light choice, spot term, attenuation, phase functions (cos theta = -d.(x -
 * light)/r) and medium, read from a vtkLightShaftPass. The surfaces and the visibility V are
 * exact: the opaque polygonal props (vtkActor with a vtkPolyDataMapper input, in world
 * coordinates) are put in a vtkModifiedBSPTree; t_s is the first hit of the ray (or the far
 * clipping plane) and V(x) tests the segment from x to the light. The ray is split at the
 * cone's entry and exit (closed form) and at every change of visibility (found on a sampling in
 * the equiangular angle, then bisected to 1e-12 of the ray's length); each piece is integrated
 * by adaptive Gauss-Kronrod (7/15 points) in the equiangular variable when A(r) falls off (in t
 * otherwise), or by the closed forms of shared/notes (A: no extinction; B: homogeneous
 * extinction, Sun et al. 2005) when the spot is a plain cone (exponent 0), the phase isotropic
 * and A = 1/r^2 (UseClosedForms, default on).
 *
 * Output: a vtkImageData laid out like vtkLightShaftPass::GetInScatteredRadiance (viewport
 * size, row 0 at the bottom) with "InScatteredRadiance" (double RGB) and "ErrorEstimate" (the
 * quadrature's estimated absolute error per pixel, summed over the pieces, double RGB).
 * Pixels run in parallel with vtkSMPTools.
 *
 * Visibility: EXACT (default) as above, or SHADOW_MAP: the depth map the pass rendered in its
 * last frame, looked up as the pass does (nearest texel, same relative bias), so that comparing
 * the pass with both references separates the shadow map's error from the integration's.
 *
 * No regularisation of A(r) near the light, as in the pass: both integrate the model exactly.
 *
 * The pass's cookie and noise density are modelled (level 0 of their images, bilinear, laid out
 * as the pass lays them out). Parallel projection is supported.
 *
 * @sa vtkLightShaftPass
 */

#ifndef vtkLightShaftReference_h
#define vtkLightShaftReference_h

#include "vtkImageAlgorithm.h"    // For the base class
#include "vtkLightShaftsModule.h" // For the export macro
#include "vtkSmartPointer.h"      // For the renderer and pass held

class vtkLightShaftPass;
class vtkRenderer;

class VTKLIGHTSHAFTS_EXPORT vtkLightShaftReference : public vtkImageAlgorithm
{
public:
  static vtkLightShaftReference* New();
  vtkTypeMacro(vtkLightShaftReference, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How V(x) is decided.
  enum VisibilityModeType
  {
    EXACT = 0,     ///< rays to the light against the scene's polygons
    SHADOW_MAP = 1 ///< the pass's last shadow map, nearest texel
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
   * The renderer whose camera, viewport size, light and props are integrated. Default is
   * nullptr (required).
   */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  ///@}

  ///@{
  /**
   * The pass whose medium, phase function and light choice are used. Default is nullptr
   * (required).
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
   * Visibility samples per lit cone interval before bisection, in [2, 100000]: a shadow
   * feature narrower than one spacing (in the equiangular angle) can be missed. Default is 32.
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

  /**
   * Number of pixels of the last Update() computed by a closed form.
   */
  vtkGetMacro(LastClosedFormPixels, vtkIdType);

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
  vtkIdType LastClosedFormPixels = 0;

private:
  vtkLightShaftReference(const vtkLightShaftReference&) = delete;
  void operator=(const vtkLightShaftReference&) = delete;

  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkLightShaftPass> Pass;
};

#endif
