#include "vtkLightShaftReferenceScene.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkLightShaftPass.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
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

//------------------------------------------------------------------------------
vtkLightShaftReferenceScene::vtkLightShaftReferenceScene() = default;
vtkLightShaftReferenceScene::~vtkLightShaftReferenceScene() = default;

//------------------------------------------------------------------------------
void vtkLightShaftReferenceScene::Capture(vtkRenderer* renderer)
{
  this->Occluders.clear();
  this->Opaque.Clear();
  this->Translucent.Clear();
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
    occluder.Transmittance = transmittance;
    occluder.Kept = 1.0 - opacity;
    const int owner = static_cast<int>(this->Occluders.size());
    this->Occluders.push_back(occluder);
    vtkLightShaftTriangleTree& tree = opacity < 1.0 ? this->Translucent : this->Opaque;
    vtkPolyData* mesh = triangles->GetOutput();
    vtkCellArray* polys = mesh->GetPolys();
    vtkNew<vtkIdList> ids;
    polys->InitTraversal();
    while (polys->GetNextCell(ids))
    {
      if (ids->GetNumberOfIds() != 3)
      {
        continue;
      }
      Vec corners[3];
      for (int k = 0; k < 3; ++k)
      {
        mesh->GetPoint(ids->GetId(k), corners[k].data());
      }
      tree.Add(corners[0], corners[1], corners[2], owner);
    }
  }
  this->Opaque.Build();
  this->Translucent.Build();
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
{
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
  int owner;
  return this->Scene.Opaque.Nearest(from, to, nearest, owner);
}

//------------------------------------------------------------------------------
RGB vtkLightShaftReferenceScene::Tracer::Crossings(const Vec& from, const Vec& to)
{
  RGB product{ 1.0, 1.0, 1.0 };
  this->Scene.Translucent.All(from, to, this->Hits);
  for (const std::pair<double, int>& hit : this->Hits)
  {
    for (int c = 0; c < 3; ++c)
    {
      product[c] *= this->Scene.Occluders[hit.second].Transmittance[c];
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
  this->Scene.Translucent.All(from, to, this->Hits);
  for (const std::pair<double, int>& hit : this->Hits)
  {
    crossings.emplace_back(hit.first, this->Scene.Occluders[hit.second].Kept);
  }
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
  if (this->Scene.Opaque.Any(x + step, light - step))
  {
    return { 0.0, 0.0, 0.0 };
  }
  return this->Crossings(x + step, light - step);
}
