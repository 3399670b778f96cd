#include "vtkLightShaftReferenceJob.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftReferenceInput.h"
#include "vtkLightShaftVolumeField.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace vtkLightShaftReferenceIntegrator;

//------------------------------------------------------------------------------
namespace
{
// The extinction of the renderer's first visible vtkVolume but the medium's
// (vtkLightShaftVolumeField's rule; nullptr: none, or one that gives no field).
std::shared_ptr<const vtkLightShaftDensityField> VolumeExtinction(vtkRenderer* renderer,
  vtkVolume* medium)
{
  vtkCollectionSimpleIterator it;
  renderer->GetViewProps()->InitTraversal(it);
  while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(it))
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (!volume || volume == medium || !volume->GetVisibility())
    {
      continue;
    }
    if (vtkAbstractMapper* mapper = volume->GetMapper())
    {
      mapper->Update();
    }
    vtkNew<vtkImageData> image;
    auto field = std::make_shared<vtkLightShaftDensityField>();
    if (!vtkLightShaftVolumeField::Build(
          volume, vtkLightShaftVolumeField::Quantity::Extinction, image)
           .empty() ||
        !field->Read(image, nullptr).empty())
    {
      return nullptr;
    }
    return field;
  }
  return nullptr;
}

// The light's share over [t0, t1] of the ray, in pieces between the camera leg's crossings
// (fractions of tSurface, in order, with what each keeps), each dimmed by those in front of it.
Result IntegrateBehindCrossings(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double t0,
  double t1,
  const std::vector<std::pair<double, double>>& crossings,
  double tSurface,
  const vtkLightShaftReferenceIntegrator::Transmittance& transmittance,
  const vtkLightShaftReferenceIntegrator::Transition& transition,
  int samples,
  double tolerance,
  bool closedForms,
  vtkLightShaftReferenceIntegrator::Effort& effort)
{
  Result sum;
  double kept = 1.0;
  double ta = t0;
  for (size_t k = 0; k <= crossings.size() && ta < t1 && kept > 0.0 && !effort.Cancelled; ++k)
  {
    const double tk = k < crossings.size() ? crossings[k].first * tSurface : t1;
    const double tb = std::min(tk, t1);
    if (tb > ta)
    {
      const Result piece = IntegrateRay(model,
        origin,
        dir,
        ta,
        tb,
        transmittance,
        samples,
        tolerance,
        closedForms,
        effort,
        transition);
      sum.ClosedForm = sum.ClosedForm || piece.ClosedForm;
      for (int c = 0; c < 3; ++c)
      {
        sum.Radiance[c] += kept * piece.Radiance[c];
        sum.Error[c] += kept * piece.Error[c];
      }
      ta = tb;
    }
    kept *= k < crossings.size() ? crossings[k].second : 1.0;
  }
  return sum;
}

/// The camera's pixel-centre rays, from VTK's camera parameters (independent of its matrices).
struct CameraRays
{
  Vec Eye{};
  Vec Forward{};
  Vec Right{};
  Vec Up{};
  double FarDistance = 1.0;
  bool Parallel = false;
  double HalfHeight = 1.0;
  double Aspect = 1.0;
  int Width = 1;
  int Height = 1;

  CameraRays(vtkCamera* camera, double backdropDepth, int width, int height)
    : FarDistance(backdropDepth)
    , Width(width)
    , Height(height)
  {
    const double* eye = camera->GetPosition();
    const double* focal = camera->GetFocalPoint();
    const double* viewUp = camera->GetViewUp();
    this->Eye = { eye[0], eye[1], eye[2] };
    this->Forward = Normalized(Vec{ focal[0], focal[1], focal[2] } - this->Eye);
    this->Right = Normalized(Cross(this->Forward, Vec{ viewUp[0], viewUp[1], viewUp[2] }));
    this->Up = Cross(this->Right, this->Forward);
    this->Parallel = camera->GetParallelProjection() != 0;
    this->HalfHeight = this->Parallel
                         ? camera->GetParallelScale()
                         : std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
    this->Aspect = static_cast<double>(width) / height;
  }

  /// The ray of pixel (i, j): origin, unit direction, and the backdrop's parameter.
  void Ray(int i, int j, Vec& origin, Vec& dir, double& tFar) const
  {
    const double sx = (2.0 * (i + 0.5) / this->Width - 1.0) * this->HalfHeight * this->Aspect;
    const double sy = (2.0 * (j + 0.5) / this->Height - 1.0) * this->HalfHeight;
    origin = this->Eye;
    dir = this->Forward;
    tFar = this->FarDistance;
    if (this->Parallel)
    {
      origin = this->Eye + sx * this->Right + sy * this->Up;
    }
    else
    {
      dir = Normalized(this->Forward + sx * this->Right + sy * this->Up);
      tFar = this->FarDistance / Dot(dir, this->Forward);
    }
  }
};

/**
 * Set `scene` to decide visibility with the `input`'s last shadow map of the one light used;
 * what is wrong otherwise (empty: nothing). One light only: the pass publishes the depth range
 * and bias of its first mapped light; a point light's cube map is not read back.
 */
std::string UseShadowMap(const vtkLightShaftReferenceInput& input,
  vtkLightShaftReferenceScene& scene,
  const std::vector<vtkLight*>& lights,
  const std::vector<Model>& models)
{
  std::ostringstream problem;
  if (lights.size() != 1)
  {
    problem << "SHADOW_MAP visibility supports exactly one light; " << lights.size()
            << " lights are used (use EXACT visibility).";
    return problem.str();
  }
  if (models[0].Kind == vtkLightShaftModel::LightKind::Point)
  {
    problem << "SHADOW_MAP visibility: point light " << lights[0]
            << " has a cube shadow map, which the pass does not read back (use EXACT"
               " visibility).";
    return problem.str();
  }
  if (!scene.UseShadowMap(input, lights[0], models[0]))
  {
    problem << "SHADOW_MAP visibility: the pass rendered no shadow map for light " << lights[0]
            << " in its last frame.";
  }
  return problem.str();
}

/// The backdrop's view depth as the pass takes it (vtkLightShaftModel::BackdropDepth); 0, no
/// ray, when the scene is not in view.
double Backdrop(vtkRenderer* renderer,
  const vtkLightShaftReferenceInput& input,
  vtkImageData* density)
{
  double bounds[6];
  const double* given = input.CasterBoundsGiven ? input.CasterBounds : nullptr;
  if (!vtkLightShaftModel::SceneBounds(renderer, given, density, bounds))
  {
    return 0.0;
  }
  const glm::dmat4 worldToView =
    vtkLightShaftGeometry::FromVTKMatrix(renderer->GetActiveCamera()->GetViewTransformMatrix());
  return std::max(vtkLightShaftModel::BackdropDepth(worldToView, bounds), 0.0);
}
}

struct vtkLightShaftReferenceJob::Rays : CameraRays
{
  using CameraRays::CameraRays;
};

vtkLightShaftReferenceJob::vtkLightShaftReferenceJob() = default;
vtkLightShaftReferenceJob::~vtkLightShaftReferenceJob() = default;

//------------------------------------------------------------------------------
std::string vtkLightShaftReferenceJob::Prepare(vtkRenderer* renderer,
  const vtkLightShaftReferenceInput& input,
  vtkObject* caller,
  int width,
  int height,
  const Options& options)
{
  this->Settings = options;
  this->Width = std::max(width, 1);
  this->Height = std::max(height, 1);
  this->Models.clear();
  this->ClosedForms.clear();
  this->Tracers.reset();

  // The lights, chosen as the pass chooses them, and the model of each with the medium.
  std::shared_ptr<vtkLightShaftDensityField> field;
  vtkImageData* density = input.Medium->UpdateDensityField(caller);
  this->Camera.reset(new Rays(
    renderer->GetActiveCamera(), Backdrop(renderer, input, density), this->Width, this->Height));
  if (density)
  {
    field = std::make_shared<vtkLightShaftDensityField>();
    const std::string why = field->Read(density, input.Medium->GetDensityArrayName());
    if (!why.empty())
    {
      return "DensityField: the image " + why + ".";
    }
  }
  // The scene's volume (the first visible vtkVolume, as the pass takes it): its extinction
  // dims both legs.
  std::shared_ptr<const vtkLightShaftDensityField> extinction =
    VolumeExtinction(renderer, input.Medium->GetDensityVolume());
  std::vector<vtkLight*> used;
  for (vtkLight* light : vtkLightShaftModel::FindLights(input.Lights, renderer))
  {
    this->Models.push_back(MakeModel(light, input, field));
    this->Models.back().Extinction = extinction;
    used.push_back(light);
  }
  for (const Model& model : this->Models)
  {
    this->ClosedForms.push_back(options.UseClosedForms && model.ClosedFormsHold());
  }
  if (this->Models.empty())
  {
    return std::string(); // no usable light: no in-scatter
  }

  // The opaque polygonal props for surfaces and exact shadows; or the pass's shadow map.
  this->Scene.Capture(renderer);
  if (options.ShadowMapVisibility)
  {
    const std::string problem = UseShadowMap(input, this->Scene, used, this->Models);
    if (!problem.empty())
    {
      this->Models.clear();
      return problem;
    }
  }
  this->Tracers.reset(new vtkLightShaftReferenceScene::TracerPool(this->Scene));
  return std::string();
}

//------------------------------------------------------------------------------
vtkLightShaftReferenceJob::Tally vtkLightShaftReferenceJob::Integrate(vtkIdType first,
  vtkIdType last,
  double* radiance,
  double* error,
  const std::atomic<bool>* cancel) const
{
  Tally tally;
  if (this->Models.empty() || !this->Tracers)
  {
    return tally;
  }
  std::unique_ptr<vtkLightShaftReferenceScene::Tracer> tracer = this->Tracers->Take();
  for (vtkIdType pixel = first; pixel < last; ++pixel)
  {
    RGB pixelRadiance{};
    RGB pixelError{};
    vtkLightShaftReferenceIntegrator::Effort effort;
    effort.Limit = this->Settings.MaximumEvaluations;
    effort.Cancel = cancel;
    const bool closed = this->IntegratePixel(*tracer, pixel, effort, pixelRadiance, pixelError);
    if (effort.Cancelled)
    {
      tally.Cancelled = true; // the partial pixel is dropped
      break;
    }
    double* out = radiance + 3 * (pixel - first);
    double* outError = error ? error + 3 * (pixel - first) : nullptr;
    for (int c = 0; c < 3; ++c)
    {
      out[c] += pixelRadiance[c];
      if (outError)
      {
        outError[c] += pixelError[c];
      }
    }
    tally.ClosedFormPixels += closed ? 1 : 0;
    tally.ExhaustedPixels += effort.Exhausted ? 1 : 0;
    tally.MostEvaluations = std::max(tally.MostEvaluations, effort.Evaluations);
  }
  this->Tracers->Give(std::move(tracer));
  return tally;
}

//------------------------------------------------------------------------------
// One pixel's in-scatter and error, summed over the lights; true when a closed form computed a
// light's share.
bool vtkLightShaftReferenceJob::IntegratePixel(vtkLightShaftReferenceScene::Tracer& tracer,
  vtkIdType pixel,
  vtkLightShaftReferenceIntegrator::Effort& effort,
  RGB& radiance,
  RGB& error) const
{
  Vec origin;
  Vec dir;
  double tSurface;
  this->PixelRay(tracer, pixel, origin, dir, tSurface);
  // The camera leg: what lies behind each translucent surface in front of the opaque one
  // reaches the camera dimmed as VTK blends it.
  const auto crossings = tracer.CameraCrossings(origin, origin + tSurface * dir);
  // Each light's share over the part of the ray it lights.
  bool closed = false;
  for (size_t l = 0; l < this->Models.size() && !effort.Cancelled; ++l)
  {
    const Model& model = this->Models[l];
    if (!model.Scatters())
    {
      continue; // (an absorbing medium: no in-scatter, only the surfaces' light leg)
    }
    double t0;
    double t1;
    LitInterval(model, origin, dir, t0, t1);
    t0 = std::max(t0, 0.0);
    t1 = std::min(t1, tSurface);
    if (!(t1 > t0))
    {
      continue;
    }
    auto transmittance = [&](const Vec& x) { return tracer.Transmittance(x, model); };
    auto transition = [&](const Vec& o, const Vec& d, double tFrom, double tTo, double& t)
    { return tracer.Transition(model, o, d, tFrom, tTo, t); };
    const Result result = IntegrateBehindCrossings(model,
      origin,
      dir,
      t0,
      t1,
      crossings,
      tSurface,
      transmittance,
      transition,
      this->Settings.VisibilitySamples,
      this->Settings.RelativeTolerance,
      this->ClosedForms[l] != 0,
      effort);
    closed = closed || result.ClosedForm;
    for (int c = 0; c < 3; ++c)
    {
      radiance[c] += result.Radiance[c];
      error[c] += result.Error[c];
    }
  }
  return closed;
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceJob::PixelRay(vtkLightShaftReferenceScene::Tracer& tracer,
  vtkIdType pixel,
  Vec& origin,
  Vec& dir,
  double& tSurface) const
{
  double tFar;
  this->Camera->Ray(static_cast<int>(pixel % this->Width),
    static_cast<int>(pixel / this->Width),
    origin,
    dir,
    tFar);
  double hit;
  const bool surface = tracer.FirstHit(origin, origin + tFar * dir, hit);
  tSurface = surface ? hit * tFar : tFar;
  return surface;
}

//------------------------------------------------------------------------------
void vtkLightShaftReferenceJob::SurfaceLight(vtkIdType first,
  vtkIdType last,
  double* surfaceLight) const
{
  const size_t lights = this->Models.size();
  std::fill(surfaceLight, surfaceLight + 3 * lights * (last - first), 0.0);
  if (lights == 0 || !this->Tracers)
  {
    return;
  }
  std::unique_ptr<vtkLightShaftReferenceScene::Tracer> tracer = this->Tracers->Take();
  for (vtkIdType pixel = first; pixel < last; ++pixel)
  {
    Vec origin;
    Vec dir;
    double tSurface;
    if (!this->PixelRay(*tracer, pixel, origin, dir, tSurface))
    {
      continue;
    }
    // Just in front of the surface, on the camera's side (where a surface lit from that side
    // is lit): its own polygon is not between it and the light.
    const Vec x = origin + ((1.0 - 1e-9) * tSurface) * dir;
    double* out = surfaceLight + 3 * lights * (pixel - first);
    for (size_t l = 0; l < lights; ++l)
    {
      const Model& model = this->Models[l];
      const RGB reaching = tracer->Transmittance(x, model);
      const RGB surface = model.SurfaceLight(x);
      for (int c = 0; c < 3; ++c)
      {
        out[3 * l + c] = reaching[c] * surface[c];
      }
    }
  }
  this->Tracers->Give(std::move(tracer));
}
