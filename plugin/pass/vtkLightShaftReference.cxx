#include "vtkLightShaftReference.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightShaftMedium.h"
#include "vtkLightShaftModel.h"
#include "vtkLightShaftPass.h"
#include "vtkLightShaftPassInternals.h"
#include "vtkLightShaftReferenceJob.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightShaftReference);

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

void vtkLightShaftReference::SetMaximumEvaluations(double evaluations)
{
  if (!std::isfinite(evaluations))
  {
    vtkErrorMacro("MaximumEvaluations: non-finite value refused; the previous value is kept.");
    return;
  }
  evaluations = std::min(std::max(std::floor(evaluations), 1000.0), 1e12);
  if (evaluations != this->MaximumEvaluations)
  {
    this->MaximumEvaluations = evaluations;
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
int vtkLightShaftReference::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  vtkRenderer* ren = this->Renderer;
  vtkLightShaftPass* pass = this->Pass;
  this->LastClosedFormPixels = 0;
  this->LastExhaustedPixels = 0;
  this->LastMostEvaluations = 0.0;
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

  vtkLightShaftReferenceJob::Options options;
  options.ShadowMapVisibility = this->VisibilityMode == SHADOW_MAP;
  options.RelativeTolerance = this->RelativeTolerance;
  options.VisibilitySamples = this->VisibilitySamples;
  options.UseClosedForms = this->UseClosedForms;
  options.MaximumEvaluations = static_cast<long long>(this->MaximumEvaluations);
  vtkLightShaftReferenceJob job;
  const std::string problem =
    job.Prepare(ren, vtkLightShaftPassReferenceInput(pass), this, width, height, options);
  this->LastNumberOfLights = job.GetNumberOfLights();
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 0;
  }
  const int lights = job.GetNumberOfLights();
  vtkNew<vtkDoubleArray> surfaceLight;
  surfaceLight->SetName("SurfaceLight");
  surfaceLight->SetNumberOfComponents(3 * std::max(lights, 1));
  surfaceLight->SetNumberOfTuples(vtkIdType(width) * height);
  surfaceLight->Fill(0.0);
  output->GetPointData()->AddArray(surfaceLight);
  this->IntegrateInBatches(job, width, height, surfaceLight, radiance, errors);
  return 1;
}

//------------------------------------------------------------------------------
// The pixels in batches of about BatchSeconds each: the threads take a few pixels at a time, in
// order, until the batch's time is up, so the pixels done are always the first ones; between
// batches progress is reported and an abort honoured.
void vtkLightShaftReference::IntegrateInBatches(const vtkLightShaftReferenceJob& job,
  int width,
  int height,
  vtkDoubleArray* surfaceLight,
  vtkDoubleArray* radiance,
  vtkDoubleArray* errors)
{
  using Clock = std::chrono::steady_clock;
  constexpr double BatchSeconds = 0.2;
  constexpr vtkIdType PixelsTaken = 8;
  const int lights = job.GetNumberOfLights();
  double* surfaceOut = surfaceLight->GetPointer(0);
  double* radianceOut = radiance->GetPointer(0);
  double* errorOut = errors->GetPointer(0);
  const vtkIdType total = vtkIdType(width) * height;
  const vtkIdType threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  std::atomic<vtkIdType> next(0);
  std::atomic<vtkIdType> closedFormPixels(0);
  std::atomic<vtkIdType> exhaustedPixels(0);
  std::atomic<long long> mostEvaluations(0);
  this->UpdateProgress(0.0);
  while (next < total && !this->GetAbortExecute())
  {
    const Clock::time_point deadline =
      Clock::now() +
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(BatchSeconds));
    vtkSMPTools::For(0,
      threads,
      1,
      [&](vtkIdType, vtkIdType)
      {
        while (Clock::now() < deadline)
        {
          const vtkIdType first = next.fetch_add(PixelsTaken);
          if (first >= total)
          {
            return;
          }
          const vtkIdType last = std::min(total, first + PixelsTaken);
          job.SurfaceLight(first, last, surfaceOut + 3 * lights * first);
          const vtkLightShaftReferenceJob::Tally tally =
            job.Integrate(first, last, radianceOut + 3 * first, errorOut + 3 * first);
          closedFormPixels += tally.ClosedFormPixels;
          exhaustedPixels += tally.ExhaustedPixels;
          long long most = mostEvaluations.load();
          while (tally.MostEvaluations > most &&
                 !mostEvaluations.compare_exchange_weak(most, tally.MostEvaluations))
          {
          }
        }
      });
    this->UpdateProgress(double(std::min(total, next.load())) / double(total));
  }
  this->LastClosedFormPixels = closedFormPixels;
  this->LastExhaustedPixels = exhaustedPixels;
  this->LastMostEvaluations = static_cast<double>(mostEvaluations.load());
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
  os << indent << "MaximumEvaluations: " << this->MaximumEvaluations << "\n";
  os << indent << "LastExhaustedPixels: " << this->LastExhaustedPixels << "\n";
  os << indent << "LastMostEvaluations: " << this->LastMostEvaluations << "\n";
}
