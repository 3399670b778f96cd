/**
 * @file   vtkLightShaftReferenceJob.h
 * @brief  The float64 reference's work, prepared once and integrated per pixel (private).
 */

#ifndef vtkLightShaftReferenceJob_h
#define vtkLightShaftReferenceJob_h

#include "vtkLightShaftReferenceIntegrator.h" // For the lights' models
#include "vtkLightShaftReferenceScene.h"      // For the captured surfaces and the tracers
#include "vtkType.h"                          // For vtkIdType

#include <atomic> // For the cancel request
#include <memory> // For the tracer pool
#include <string> // For what went wrong
#include <vector> // For the models

class vtkLight;
struct vtkLightShaftReferenceInput;
class vtkObject;
class vtkRenderer;

/**
 * @class   vtkLightShaftReferenceJob
 * @brief   What vtkLightShaftReference integrates, captured from a renderer and a pass on the
 *          main thread (Prepare: lights, medium, density field, the scene's volume, the opaque
 *          and translucent surfaces, the camera's rays), then integrated for any range of
 *          pixels from any thread (Integrate). The capture holds copies only: the scene may
 *          change while threads integrate, and they keep integrating what was captured.
 *
 * vtkLightShaftReference runs it over the whole image with vtkSMPTools; the pass's exact
 * finish (vtkLightShaftExactFinish) tile by tile on its worker threads.
 */
class vtkLightShaftReferenceJob
{
public:
  vtkLightShaftReferenceJob();
  ~vtkLightShaftReferenceJob();

  /// How the job integrates (vtkLightShaftReference's parameters).
  struct Options
  {
    bool ShadowMapVisibility = false;
    double RelativeTolerance = 1e-9;
    int VisibilitySamples = 32;
    bool UseClosedForms = true;
    /// Integrand evaluations one pixel's ray may spend over its lights (0: no bound): where
    /// it ends the refinement, the pixel keeps its quadrature's error estimate.
    long long MaximumEvaluations = DefaultMaximumEvaluations;
  };
  /// The bound on a ray's evaluations unless told otherwise: about a second of a core at
  /// the slowest evaluations measured (a dense field on both legs), and hundreds of times
  /// what a converged pixel of the tests spends.
  static constexpr long long DefaultMaximumEvaluations = 1000000;

  /// What integrating a range of pixels did.
  struct Tally
  {
    vtkIdType ClosedFormPixels = 0; ///< of them, where a closed form computed a light's share
    vtkIdType ExhaustedPixels = 0;  ///< of them, where MaximumEvaluations ended the refinement
    long long MostEvaluations = 0;  ///< the most evaluations one pixel spent
    bool Cancelled = false;         ///< `cancel` stopped it
  };

  /**
   * Capture `renderer`'s scene with the `input`'s lights and medium (as the pass sees them), for
   * a `width` x `height` image of its active camera. `caller` updates the medium's density
   * pipeline. Returns what is wrong (empty: ready; a job with no usable light integrates
   * zeros).
   */
  std::string Prepare(vtkRenderer* renderer,
    const vtkLightShaftReferenceInput& input,
    vtkObject* caller,
    int width,
    int height,
    const Options& options);

  /// The lights captured (the pass's choice).
  int GetNumberOfLights() const { return static_cast<int>(this->Models.size()); }
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /**
   * Add the in-scatter (and the quadrature's error estimate, when `error` is not null) of the
   * pixels [first, last) (row-major, row 0 at the bottom) into `radiance` and `error`, three
   * doubles per pixel, the first pixel's at index 0. Thread-safe. `cancel` (when not null) is
   * watched within each pixel's integration: once it is set, the call returns within
   * milliseconds, the pixels before the one in flight added, that one and the rest not.
   */
  Tally Integrate(vtkIdType first,
    vtkIdType last,
    double* radiance,
    double* error,
    const std::atomic<bool>* cancel = nullptr) const;

  /**
   * The surface term of the pixels [first, last) into `surfaceLight`, 3 doubles per light per
   * pixel: for the first opaque surface each pixel's ray hits, the fraction of each light's
   * surface light that reaches it (the transmittance of the casters, opaque and translucent,
   * times Model::SurfaceLight); 0 where the ray hits none. Thread-safe.
   */
  void SurfaceLight(vtkIdType first, vtkIdType last, double* surfaceLight) const;

private:
  vtkLightShaftReferenceJob(const vtkLightShaftReferenceJob&) = delete;
  void operator=(const vtkLightShaftReferenceJob&) = delete;

  /// Pixel `pixel`'s view ray and the distance along it to the first opaque surface (the far
  /// plane where it hits none: returns false).
  bool PixelRay(vtkLightShaftReferenceScene::Tracer& tracer,
    vtkIdType pixel,
    vtkLightShaftReferenceIntegrator::Vec& origin,
    vtkLightShaftReferenceIntegrator::Vec& dir,
    double& tSurface) const;
  bool IntegratePixel(vtkLightShaftReferenceScene::Tracer& tracer,
    vtkIdType pixel,
    vtkLightShaftReferenceIntegrator::Effort& effort,
    vtkLightShaftReferenceIntegrator::RGB& radiance,
    vtkLightShaftReferenceIntegrator::RGB& error) const;

  struct Rays;
  std::unique_ptr<Rays> Camera;
  std::vector<vtkLightShaftReferenceIntegrator::Model> Models;
  std::vector<char> ClosedForms;
  vtkLightShaftReferenceScene Scene;
  std::unique_ptr<vtkLightShaftReferenceScene::TracerPool> Tracers;
  Options Settings;
  int Width = 1;
  int Height = 1;
};

#endif
