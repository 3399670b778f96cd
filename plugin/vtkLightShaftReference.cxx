#include "vtkLightShaftReference.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightShaftDensityField.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftPass.h"
#include "vtkLightShaftRayIntegrator.h"
#include "vtkLightShaftReferenceScene.h"
#include "vtkLightShaftVolumeField.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolume.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightShaftReference);

using namespace vtkLightShaftRayIntegrator;

//------------------------------------------------------------------------------
vtkLightShaftReference::vtkLightShaftReference()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkLightShaftReference::~vtkLightShaftReference() = default;

void vtkLightShaftReference::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkLightShaftReference::GetRenderer()
{
  return this->Renderer;
}

void vtkLightShaftReference::SetLightShaftPass(vtkLightShaftPass* pass)
{
  if (this->Pass != pass)
  {
    this->Pass = pass;
    this->Modified();
  }
}

vtkLightShaftPass* vtkLightShaftReference::GetLightShaftPass()
{
  return this->Pass;
}

void vtkLightShaftReference::SetRelativeTolerance(double tolerance)
{
  if (!std::isfinite(tolerance))
  {
    vtkErrorMacro("RelativeTolerance: non-finite value refused; the previous value is kept.");
    return;
  }
  tolerance = std::min(std::max(tolerance, 1e-14), 1e-2);
  if (tolerance != this->RelativeTolerance)
  {
    this->RelativeTolerance = tolerance;
    this->Modified();
  }
}

vtkMTimeType vtkLightShaftReference::GetMTime()
{
  // The scene changes without telling us: any change of the renderer, its camera, lights or
  // props, or of the pass or the lights given to it, makes the next Update() recompute.
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Pass)
  {
    time = std::max(time, this->Pass->GetMTime());
    for (int i = 0; i < this->Pass->GetNumberOfLights(); ++i)
    {
      if (vtkLight* light = this->Pass->GetLight(i))
      {
        time = std::max(time, light->GetMTime()); // given lights need not be the renderer's
      }
    }
  }
  if (vtkRenderer* ren = this->Renderer)
  {
    time = std::max({ time,
      ren->GetMTime(),
      ren->GetActiveCamera()->GetMTime(),
      ren->GetLights()->GetMTime(),
      ren->GetViewProps()->GetMTime() });
    vtkCollectionSimpleIterator it;
    ren->GetLights()->InitTraversal(it);
    while (vtkLight* light = ren->GetLights()->GetNextLight(it))
    {
      time = std::max(time, light->GetMTime());
    }
    ren->GetViewProps()->InitTraversal(it);
    while (vtkProp* prop = ren->GetViewProps()->GetNextProp(it))
    {
      time = std::max(time, prop->GetMTime());
    }
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkLightShaftReference::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  int size[2] = { 0, 0 };
  if (this->Renderer)
  {
    const int* rendererSize = this->Renderer->GetSize();
    size[0] = rendererSize[0];
    size[1] = rendererSize[1];
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, std::max(size[0], 1) - 1, 0, std::max(size[1], 1) - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_DOUBLE, 3);
  return 1;
}

//------------------------------------------------------------------------------
namespace
{
/**
 * The camera's pixel-centre rays, from VTK's camera parameters (independent of its matrices).
 */
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
  const vtkLightShaftRayIntegrator::Transmittance& transmittance,
  int samples,
  double tolerance,
  bool closedForms)
{
  Result sum;
  double kept = 1.0;
  double ta = t0;
  for (size_t k = 0; k <= crossings.size() && ta < t1 && kept > 0.0; ++k)
  {
    const double tk = k < crossings.size() ? crossings[k].first * tSurface : t1;
    const double tb = std::min(tk, t1);
    if (tb > ta)
    {
      const Result piece =
        IntegrateRay(model, origin, dir, ta, tb, transmittance, samples, tolerance, closedForms);
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

  CameraRays(vtkCamera* camera, int width, int height)
    : Width(width)
    , Height(height)
  {
    const double* eye = camera->GetPosition();
    const double* focal = camera->GetFocalPoint();
    const double* viewUp = camera->GetViewUp();
    this->Eye = { eye[0], eye[1], eye[2] };
    this->Forward = Normalized(Vec{ focal[0], focal[1], focal[2] } - this->Eye);
    this->Right = Normalized(Cross(this->Forward, Vec{ viewUp[0], viewUp[1], viewUp[2] }));
    this->Up = Cross(this->Right, this->Forward);
    this->FarDistance = camera->GetClippingRange()[1];
    this->Parallel = camera->GetParallelProjection() != 0;
    this->HalfHeight = this->Parallel
                         ? camera->GetParallelScale()
                         : std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
    this->Aspect = static_cast<double>(width) / height;
  }

  /// The ray of pixel (i, j): origin, unit direction, and the far plane's parameter.
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
 * Set `scene` to decide visibility with the pass's shadow map of the one light used; what is
 * wrong otherwise (empty: nothing). One light only: the pass publishes the depth range and
 * bias of its first mapped light; a point light's cube map is not read back.
 */
std::string UseShadowMap(vtkLightShaftPass* pass,
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
  int index = -1;
  vtkLightShaftFrameReport* last = pass->GetLastFrame();
  for (int i = 0; i < last->GetNumberOfUsedLights(); ++i)
  {
    if (last->GetUsedLight(i) == lights[0])
    {
      index = i;
    }
  }
  if (index < 0 || !scene.UseShadowMap(pass, index, models[0]))
  {
    problem << "SHADOW_MAP visibility: the pass rendered no shadow map for light " << lights[0]
            << " in its last frame.";
  }
  return problem.str();
}
}

//------------------------------------------------------------------------------
int vtkLightShaftReference::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  vtkRenderer* ren = this->Renderer;
  vtkLightShaftPass* pass = this->Pass;
  this->LastClosedFormPixels = 0;
  this->LastNumberOfLights = 0;
  if (!ren || !pass)
  {
    vtkErrorMacro("SetRenderer and SetLightShaftPass are required.");
    return 0;
  }
  const int width = std::max(ren->GetSize()[0], 1);
  const int height = std::max(ren->GetSize()[1], 1);
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName("InScatteredRadiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(vtkIdType(width) * height);
  radiance->Fill(0.0);
  vtkNew<vtkDoubleArray> errors;
  errors->SetName("ErrorEstimate");
  errors->SetNumberOfComponents(3);
  errors->SetNumberOfTuples(vtkIdType(width) * height);
  errors->Fill(0.0);
  output->GetPointData()->SetScalars(radiance);
  output->GetPointData()->AddArray(errors);

  // The lights, chosen as the pass chooses them, and the model of each with the medium.
  std::vector<vtkLight*> given;
  for (int i = 0; i < pass->GetNumberOfLights(); ++i)
  {
    given.push_back(pass->GetLight(i));
  }
  std::shared_ptr<vtkLightShaftDensityField> field;
  if (vtkImageData* density = pass->GetMedium()->UpdateDensityField(this))
  {
    field = std::make_shared<vtkLightShaftDensityField>();
    const std::string why = field->Read(density, pass->GetMedium()->GetDensityArrayName());
    if (!why.empty())
    {
      vtkErrorMacro("DensityField: the image " << why << ".");
      return 0;
    }
  }
  // The scene's volume (the first visible vtkVolume, as the pass takes it): its extinction
  // dims both legs.
  std::shared_ptr<const vtkLightShaftDensityField> extinction =
    VolumeExtinction(ren, pass->GetMedium()->GetDensityVolume());
  std::vector<Model> models;
  std::vector<vtkLight*> used;
  for (vtkLight* light : vtkLightShaftModel::FindLights(given, ren))
  {
    models.push_back(MakeModel(light, pass, field));
    models.back().Extinction = extinction;
    used.push_back(light);
  }
  this->LastNumberOfLights = static_cast<int>(models.size());
  if (models.empty())
  {
    return 1; // no usable light: no in-scatter
  }

  // The opaque polygonal props for surfaces and exact shadows; or the pass's shadow map.
  vtkLightShaftReferenceScene scene;
  scene.Capture(ren);
  if (this->VisibilityMode == SHADOW_MAP)
  {
    const std::string problem = UseShadowMap(pass, scene, used, models);
    if (!problem.empty())
    {
      vtkErrorMacro(<< problem);
      return 0;
    }
  }

  const CameraRays rays(ren->GetActiveCamera(), width, height);
  const double tolerance = this->RelativeTolerance;
  const int samples = this->VisibilitySamples;
  std::vector<char> closedForms;
  for (const Model& model : models)
  {
    closedForms.push_back(this->UseClosedForms && model.ClosedFormsHold());
  }
  std::atomic<vtkIdType> closedFormPixels(0);
  vtkLightShaftReferenceScene::TracerPool tracers(scene);
  double* radianceOut = radiance->GetPointer(0);
  double* errorOut = errors->GetPointer(0);
  vtkSMPTools::For(0,
    vtkIdType(width) * height,
    [&](vtkIdType first, vtkIdType last)
    {
      std::unique_ptr<vtkLightShaftReferenceScene::Tracer> tracer = tracers.Take();
      vtkIdType closedHere = 0;
      for (vtkIdType pixel = first; pixel < last; ++pixel)
      {
        Vec origin;
        Vec dir;
        double tFar;
        rays.Ray(
          static_cast<int>(pixel % width), static_cast<int>(pixel / width), origin, dir, tFar);
        // The first surface along the ray, else the far plane.
        double tSurface = tFar;
        double hit;
        if (tracer->FirstHit(origin, origin + tFar * dir, hit))
        {
          tSurface = hit * tFar;
        }
        // The camera leg: what lies behind each translucent surface in front of the opaque one
        // reaches the camera dimmed as VTK blends it.
        const auto crossings = tracer->CameraCrossings(origin, origin + tSurface * dir);
        // Each light's share over the part of the ray it lights.
        bool closed = false;
        for (size_t l = 0; l < models.size(); ++l)
        {
          const Model& model = models[l];
          double t0;
          double t1;
          LitInterval(model, origin, dir, t0, t1);
          t0 = std::max(t0, 0.0);
          t1 = std::min(t1, tSurface);
          if (!(t1 > t0))
          {
            continue;
          }
          auto transmittance = [&](const Vec& x) { return tracer->Transmittance(x, model); };
          const Result result = IntegrateBehindCrossings(model,
            origin,
            dir,
            t0,
            t1,
            crossings,
            tSurface,
            transmittance,
            samples,
            tolerance,
            closedForms[l] != 0);
          closed = closed || result.ClosedForm;
          for (int c = 0; c < 3; ++c)
          {
            radianceOut[3 * pixel + c] += result.Radiance[c];
            errorOut[3 * pixel + c] += result.Error[c];
          }
        }
        closedHere += closed ? 1 : 0;
      }
      closedFormPixels += closedHere;
      tracers.Give(std::move(tracer));
    });
  this->LastClosedFormPixels = closedFormPixels;
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightShaftReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer.Get() << "\n";
  os << indent << "LightShaftPass: " << this->Pass.Get() << "\n";
  os << indent << "VisibilityMode: " << this->VisibilityMode << "\n";
  os << indent << "RelativeTolerance: " << this->RelativeTolerance << "\n";
  os << indent << "VisibilitySamples: " << this->VisibilitySamples << "\n";
  os << indent << "UseClosedForms: " << this->UseClosedForms << "\n";
  os << indent << "LastNumberOfLights: " << this->LastNumberOfLights << "\n";
  os << indent << "LastClosedFormPixels: " << this->LastClosedFormPixels << "\n";
}
