#include "vtkLightShaftReferenceScene.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkLightShaftPass.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkModifiedBSPTree.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>

using namespace vtkLightShaftRayIntegrator;

namespace
{
// Whether the segment from -> to meets an axis-aligned box (slab test, slightly padded).
bool SegmentMeetsBox(const Vec& from, const Vec& to, const double bounds[6])
{
  double lo = 0.0;
  double hi = 1.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double pad = 1e-9 * (std::abs(bounds[2 * axis]) + std::abs(bounds[2 * axis + 1]) + 1.0);
    const double d = to[axis] - from[axis];
    const double a = bounds[2 * axis] - pad - from[axis];
    const double b = bounds[2 * axis + 1] + pad - from[axis];
    if (d == 0.0)
    {
      if (a > 0.0 || b < 0.0)
      {
        return false;
      }
      continue;
    }
    double t0 = a / d;
    double t1 = b / d;
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
    if (lo > hi)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkLightShaftReferenceScene::vtkLightShaftReferenceScene() = default;
vtkLightShaftReferenceScene::~vtkLightShaftReferenceScene() = default;

//------------------------------------------------------------------------------
void vtkLightShaftReferenceScene::Capture(vtkRenderer* renderer)
{
  this->Occluders.clear();
  vtkCollectionSimpleIterator it;
  renderer->GetViewProps()->InitTraversal(it);
  while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility() || !actor->GetMapper())
    {
      continue;
    }
    // The surface's transmittance, the pass's rule (vtkLightShaftTranslucentPeel): opacity a
    // and diffuse colour c pass 1 - a (1 - c); opaque: none, transparent: no occluder.
    vtkProperty* property = actor->GetProperty();
    const double opacity = std::min(std::max(property->GetOpacity(), 0.0), 1.0);
    if (opacity <= 0.0)
    {
      continue;
    }
    RGB transmittance{};
    if (opacity < 1.0)
    {
      const double* color = property->GetDiffuseColor();
      for (int c = 0; c < 3; ++c)
      {
        const double diffuse = std::min(std::max(property->GetDiffuse() * color[c], 0.0), 1.0);
        transmittance[c] = 1.0 - opacity * (1.0 - diffuse);
      }
    }
    actor->GetMapper()->Update();
    auto* polydata = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
    if (!polydata || polydata->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(actor->GetMatrix());
    vtkNew<vtkTransformPolyDataFilter> toWorld;
    toWorld->SetInputData(polydata);
    toWorld->SetTransform(transform);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(toWorld->GetOutputPort());
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    if (triangles->GetOutput()->GetNumberOfCells() == 0)
    {
      continue;
    }
    Occluder occluder;
    occluder.Mesh = vtkSmartPointer<vtkPolyData>::New();
    occluder.Mesh->DeepCopy(triangles->GetOutput());
    occluder.Mesh->BuildCells(); // read-only from the threads afterwards
    occluder.Mesh->GetBounds(occluder.Bounds);
    occluder.Translucent = opacity < 1.0;
    occluder.Transmittance = transmittance;
    occluder.Kept = 1.0 - opacity;
    this->Occluders.push_back(occluder);
  }
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::UseShadowMap(vtkLightShaftPass* pass,
  int index,
  const vtkLightShaftRayIntegrator::Model& light)
{
  if (light.Kind == vtkLightShaftModel::LightKind::Point ||
      !pass->GetLastShadowMap(this->ShadowDepths, this->WorldToLightClip, index))
  {
    return false;
  }
  this->ShadowMap = true;
  this->ShadowSize = this->ShadowDepths->GetDimensions()[0];
  this->ShadowTexels =
    vtkFloatArray::SafeDownCast(this->ShadowDepths->GetPointData()->GetScalars())->GetPointer(0);
  this->LightNear = pass->GetLastFrame()->GetLightDepthRange()[0];
  this->LightFar = pass->GetLastFrame()->GetLightDepthRange()[1];
  this->ShadowBias = pass->GetLastFrame()->GetShadowBias();
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::ShadowMapVisible(const Vec& x,
  const vtkLightShaftRayIntegrator::Model& light) const
{
  double clip[4];
  const double point[4] = { x[0], x[1], x[2], 1.0 };
  this->WorldToLightClip->MultiplyPoint(point, clip);
  if (clip[3] <= 0.0)
  {
    return true;
  }
  const double u = clip[0] / clip[3];
  const double v = clip[1] / clip[3];
  if (std::abs(u) > 1.0 || std::abs(v) > 1.0)
  {
    return true;
  }
  const int size = this->ShadowSize;
  const int i = std::min(static_cast<int>((0.5 * u + 0.5) * size), size - 1);
  const int j = std::min(static_cast<int>((0.5 * v + 0.5) * size), size - 1);
  const double stored = this->ShadowTexels[static_cast<size_t>(j) * size + i];
  if (stored >= 1.0)
  {
    return true;
  }
  const double n = this->LightNear;
  const double f = this->LightFar;
  if (light.Directional())
  {
    // Orthographic (w = 1): the stored depth is linear in r, the bias in world units.
    return light.Distance(x) <= n + stored * (f - n) + this->ShadowBias;
  }
  const double caster = 2.0 * n * f / ((f + n) - (2.0 * stored - 1.0) * (f - n));
  return clip[3] <= caster * (1.0 + this->ShadowBias);
}

//------------------------------------------------------------------------------
vtkLightShaftReferenceScene::Tracer::Tracer(const vtkLightShaftReferenceScene& scene)
  : Scene(scene)
  , Cell(vtkSmartPointer<vtkGenericCell>::New())
  , Hits(vtkSmartPointer<vtkIdList>::New())
  , HitPoints(vtkSmartPointer<vtkPoints>::New())
{
  for (const Occluder& occluder : scene.Occluders)
  {
    auto locator = vtkSmartPointer<vtkModifiedBSPTree>::New();
    locator->SetDataSet(occluder.Mesh);
    locator->BuildLocator();
    this->Locators.push_back(locator);
  }
}

vtkLightShaftReferenceScene::Tracer::~Tracer() = default;

//------------------------------------------------------------------------------
vtkLightShaftReferenceScene::TracerPool::TracerPool(const vtkLightShaftReferenceScene& scene)
  : Scene(scene)
{
}

vtkLightShaftReferenceScene::TracerPool::~TracerPool() = default;

std::unique_ptr<vtkLightShaftReferenceScene::Tracer> vtkLightShaftReferenceScene::TracerPool::Take()
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (!this->Free.empty())
    {
      std::unique_ptr<Tracer> tracer = std::move(this->Free.back());
      this->Free.pop_back();
      return tracer;
    }
  }
  return std::unique_ptr<Tracer>(new Tracer(this->Scene));
}

void vtkLightShaftReferenceScene::TracerPool::Give(std::unique_ptr<Tracer> tracer)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Free.push_back(std::move(tracer));
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::Tracer::FirstHit(const Vec& from, const Vec& to, double& nearest)
{
  bool any = false;
  nearest = 1.0;
  for (size_t k = 0; k < this->Scene.Occluders.size(); ++k)
  {
    if (this->Scene.Occluders[k].Translucent ||
        !SegmentMeetsBox(from, to, this->Scene.Occluders[k].Bounds))
    {
      continue;
    }
    double t;
    double x[3];
    double pcoords[3];
    int subId;
    vtkIdType cellId;
    if (this->Locators[k]->IntersectWithLine(
          from.data(), to.data(), 0.0, t, x, pcoords, subId, cellId, this->Cell) &&
        t < nearest)
    {
      nearest = t;
      any = true;
    }
  }
  return any;
}

//------------------------------------------------------------------------------
RGB vtkLightShaftReferenceScene::Tracer::Crossings(const Vec& from, const Vec& to)
{
  RGB product{ 1.0, 1.0, 1.0 };
  for (size_t k = 0; k < this->Scene.Occluders.size(); ++k)
  {
    const Occluder& occluder = this->Scene.Occluders[k];
    if (!occluder.Translucent || !SegmentMeetsBox(from, to, occluder.Bounds))
    {
      continue;
    }
    this->Hits->Reset();
    this->Locators[k]->IntersectWithLine(from.data(), to.data(), 0.0, nullptr, this->Hits);
    for (vtkIdType hit = 0; hit < this->Hits->GetNumberOfIds(); ++hit)
    {
      for (int c = 0; c < 3; ++c)
      {
        product[c] *= occluder.Transmittance[c];
      }
    }
  }
  return product;
}

//------------------------------------------------------------------------------
std::vector<std::pair<double, double>> vtkLightShaftReferenceScene::Tracer::CameraCrossings(
  const Vec& from,
  const Vec& to)
{
  std::vector<std::pair<double, double>> crossings;
  const Vec span = to - from;
  const double length2 = vtkLightShaftRayIntegrator::Dot(span, span);
  for (size_t k = 0; k < this->Scene.Occluders.size(); ++k)
  {
    const Occluder& occluder = this->Scene.Occluders[k];
    if (!occluder.Translucent || !SegmentMeetsBox(from, to, occluder.Bounds))
    {
      continue;
    }
    this->HitPoints->Reset();
    this->Hits->Reset();
    this->Locators[k]->IntersectWithLine(from.data(), to.data(), 0.0, this->HitPoints, this->Hits);
    for (vtkIdType hit = 0; hit < this->HitPoints->GetNumberOfPoints(); ++hit)
    {
      double x[3];
      this->HitPoints->GetPoint(hit, x);
      const Vec offset{ x[0] - from[0], x[1] - from[1], x[2] - from[2] };
      crossings.emplace_back(
        vtkLightShaftRayIntegrator::Dot(offset, span) / length2, occluder.Kept);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

//------------------------------------------------------------------------------
RGB vtkLightShaftReferenceScene::Tracer::Transmittance(const Vec& x,
  const vtkLightShaftRayIntegrator::Model& model)
{
  if (this->Scene.ShadowMap)
  {
    const double visible = this->Scene.ShadowMapVisible(x, model) ? 1.0 : 0.0;
    return { visible, visible, visible };
  }
  // The segment to the light, or back to a directional light's plane.
  Vec light = model.Light;
  if (model.Directional())
  {
    const double r = model.Distance(x);
    if (!(r > 0.0))
    {
      return { 1.0, 1.0, 1.0 }; // on (or before) the plane: nothing lies between
    }
    light = x - r * model.Axis;
  }
  const Vec toLight = light - x;
  const double distance = Norm(toLight);
  const Vec step = (1e-9 * (distance + 1.0) / std::max(distance, 1e-300)) * toLight;
  double t;
  if (this->FirstHit(x + step, light - step, t))
  {
    return { 0.0, 0.0, 0.0 };
  }
  return this->Crossings(x + step, light - step);
}
