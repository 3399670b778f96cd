#include "vtkLightShaftReference.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftPass.h"
#include "vtkLightShaftRayIntegrator.h"
#include "vtkLightShaftReferenceScene.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

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
  // props, or of the pass, makes the next Update() recompute.
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Pass)
  {
    time = std::max(time, this->Pass->GetMTime());
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

  // The light, chosen as the pass chooses it, and the model of light and medium.
  std::vector<vtkLight*> given;
  for (int i = 0; i < pass->GetNumberOfLights(); ++i)
  {
    given.push_back(pass->GetLight(i));
  }
  const std::vector<vtkLight*> lights = vtkLightShaftModel::FindLights(given, ren);
  vtkLight* light = lights.empty() ? nullptr : lights[0];
  if (!light || !light->GetSwitch())
  {
    return 1; // no usable light: no in-scatter
  }
  const Model model = MakeModel(light, pass);

  // The opaque polygonal props for surfaces and exact shadows; or the pass's shadow map.
  vtkLightShaftReferenceScene scene;
  scene.Capture(ren);
  if (this->VisibilityMode == SHADOW_MAP && !scene.UseShadowMap(pass))
  {
    vtkErrorMacro("SHADOW_MAP visibility: the pass rendered no shadow map in its last frame.");
    return 0;
  }

  const CameraRays rays(ren->GetActiveCamera(), width, height);
  const double tolerance = this->RelativeTolerance;
  const int samples = this->VisibilitySamples;
  const bool closedForms = this->UseClosedForms && model.ClosedFormsHold();
  std::atomic<vtkIdType> closedFormPixels(0);
  vtkSMPThreadLocal<std::shared_ptr<vtkLightShaftReferenceScene::Tracer>> tracers;
  double* radianceOut = radiance->GetPointer(0);
  double* errorOut = errors->GetPointer(0);
  vtkSMPTools::For(0,
    vtkIdType(width) * height,
    [&](vtkIdType first, vtkIdType last)
    {
      std::shared_ptr<vtkLightShaftReferenceScene::Tracer>& tracer = tracers.Local();
      if (!tracer)
      {
        tracer = std::make_shared<vtkLightShaftReferenceScene::Tracer>(scene);
      }
      auto visible = [&](const Vec& x) { return tracer->Visible(x, model.Light); };
      vtkIdType closedHere = 0;
      for (vtkIdType pixel = first; pixel < last; ++pixel)
      {
        Vec origin;
        Vec dir;
        double tFar;
        rays.Ray(
          static_cast<int>(pixel % width), static_cast<int>(pixel / width), origin, dir, tFar);
        // The first surface along the ray, else the far plane; the part inside the cone.
        double tSurface = tFar;
        double hit;
        if (tracer->FirstHit(origin, origin + tFar * dir, hit))
        {
          tSurface = hit * tFar;
        }
        double t0;
        double t1;
        ConeInterval(model, origin, dir, t0, t1);
        t0 = std::max(t0, 0.0);
        t1 = std::min(t1, tSurface);
        if (!(t1 > t0))
        {
          continue;
        }
        const Result result =
          IntegrateRay(model, origin, dir, t0, t1, visible, samples, tolerance, closedForms);
        closedHere += result.ClosedForm ? 1 : 0;
        for (int c = 0; c < 3; ++c)
        {
          radianceOut[3 * pixel + c] = result.Radiance[c];
          errorOut[3 * pixel + c] = result.Error[c];
        }
      }
      closedFormPixels += closedHere;
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
}
