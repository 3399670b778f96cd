#include "vtkLightShaftReferenceScene.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightShaftReferenceInput.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace vtkLightShaftReferenceIntegrator;

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
    bool polygonal = false;
    std::vector<vtkPolyData*> pieces = Surfaces(actor, polygonal);
    if (pieces.empty())
    {
      continue;
    }
    Occluder occluder;
    occluder.Transmittance = transmittance;
    occluder.Kept = 1.0 - opacity;
    const int owner = static_cast<int>(this->Occluders.size());
    this->Occluders.push_back(occluder);
    vtkLightShaftReferenceTriangleTree& tree = opacity < 1.0 ? this->Translucent : this->Opaque;
    for (vtkPolyData* piece : pieces)
    {
      this->AddTriangles(piece, actor, owner, tree);
    }
  }
  this->Opaque.Build();
  this->Translucent.Build();
}

//------------------------------------------------------------------------------
std::vector<vtkPolyData*> vtkLightShaftReferenceScene::Surfaces(vtkActor* actor, bool& polygonal)
{
  std::vector<vtkPolyData*> pieces;
  vtkDataObject* input =
    actor->GetMapper() ? actor->GetMapper()->GetInputDataObject(0, 0) : nullptr;
  polygonal = !input || vtkPolyData::SafeDownCast(input); // no input draws nothing
  if (input && polygonal)
  {
    pieces.push_back(vtkPolyData::SafeDownCast(input));
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    // A composite dataset (ParaView's representations): its leaves, all of them polygonal.
    polygonal = true;
    vtkSmartPointer<vtkCompositeDataIterator> leaf;
    leaf.TakeReference(composite->NewIterator());
    for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
    {
      auto* piece = vtkPolyData::SafeDownCast(leaf->GetCurrentDataObject());
      polygonal = polygonal && (piece || !leaf->GetCurrentDataObject());
      if (piece)
      {
        pieces.push_back(piece);
      }
    }
  }
  pieces.erase(std::remove_if(pieces.begin(),
                 pieces.end(),
                 [](vtkPolyData* piece) { return piece->GetNumberOfCells() == 0; }),
    pieces.end());
  return pieces;
}

//------------------------------------------------------------------------------
void vtkLightShaftReferenceScene::AddTriangles(vtkPolyData* polydata,
  vtkActor* actor,
  int owner,
  vtkLightShaftReferenceTriangleTree& tree)
{
  {
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
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::UseShadowMap(const vtkLightShaftReferenceInput& input,
  vtkLight* light,
  const vtkLightShaftReferenceIntegrator::Model& model)
{
  double depthRange[2] = { 0.0, 0.0 };
  double bias = 0.0;
  if (model.Kind == vtkLightShaftModel::LightKind::Point || !input.LastShadowMap ||
      !input.LastShadowMap(light, this->ShadowDepths, this->WorldToLightClip, depthRange, bias))
  {
    return false;
  }
  this->ShadowMap = true;
  this->ShadowSize = this->ShadowDepths->GetDimensions()[0];
  this->ShadowTexels =
    vtkFloatArray::SafeDownCast(this->ShadowDepths->GetPointData()->GetScalars())->GetPointer(0);
  this->LightNear = depthRange[0];
  this->LightFar = depthRange[1];
  this->ShadowBias = bias;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::ShadowMapVisible(const Vec& x,
  const vtkLightShaftReferenceIntegrator::Model& light) const
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
  const vtkLightShaftReferenceIntegrator::Model& model)
{
  if (this->Scene.ShadowMap)
  {
    const double visible = this->Scene.ShadowMapVisible(x, model) ? 1.0 : 0.0;
    return { visible, visible, visible };
  }
  Vec from;
  Vec to;
  if (!ToLight(x, model, from, to))
  {
    return { 1.0, 1.0, 1.0 }; // on (or before) a directional light's plane: nothing between
  }
  if (this->Scene.Opaque.Any(from, to))
  {
    return { 0.0, 0.0, 0.0 };
  }
  return this->Crossings(from, to);
}

//------------------------------------------------------------------------------
bool vtkLightShaftReferenceScene::Tracer::ToLight(const Vec& x,
  const vtkLightShaftReferenceIntegrator::Model& model,
  Vec& from,
  Vec& to)
{
  Vec light = model.Light;
  if (model.Directional())
  {
    const double r = model.Distance(x);
    if (!(r > 0.0))
    {
      return false;
    }
    light = x - r * model.Axis;
  }
  const Vec toLight = light - x;
  const double distance = Norm(toLight);
  const Vec step = (1e-9 * (distance + 1.0) / std::max(distance, 1e-300)) * toLight;
  from = x + step;
  to = light - step;
  return true;
}

bool vtkLightShaftReferenceScene::Tracer::Shadowed(const Vec& x,
  const vtkLightShaftReferenceIntegrator::Model& model)
{
  Vec from;
  Vec to;
  return ToLight(x, model, from, to) && this->Scene.Opaque.Any(from, to);
}

//------------------------------------------------------------------------------
namespace
{
/// The interval [first, last] of t where triangle p shadows origin + t dir from the light: the
/// ray clipped by the triangle's shadow volume (the half-spaces through each edge and the light,
/// or the light's direction, and beyond the triangle's plane). False where the volume is
/// degenerate: the light in the triangle's plane, a directional light along it, or part of the
/// triangle behind a directional light's plane (it shadows only part of its volume).
bool ShadowVolumeInterval(const Model& light,
  const std::array<Vec, 3>& p,
  const Vec& origin,
  const Vec& dir,
  double& first,
  double& last)
{
  first = -std::numeric_limits<double>::infinity();
  last = std::numeric_limits<double>::infinity();
  // Keep alpha + beta t >= 0.
  auto keep = [&](double alpha, double beta)
  {
    if (beta > 0.0)
    {
      first = std::max(first, -alpha / beta);
    }
    else if (beta < 0.0)
    {
      last = std::min(last, -alpha / beta);
    }
    else if (alpha < 0.0)
    {
      first = std::numeric_limits<double>::infinity();
    }
  };
  const Vec normal = Cross(p[1] - p[0], p[2] - p[0]);
  const double size = Norm(normal);
  // Beyond the plane, seen from the light: away from it, or along a directional light.
  double beyond;
  if (light.Directional())
  {
    for (const Vec& corner : p)
    {
      if (!(light.Distance(corner) > 0.0))
      {
        return false;
      }
    }
    beyond = Dot(normal, light.Axis);
    if (!(std::abs(beyond) > 1e-9 * size))
    {
      return false;
    }
  }
  else
  {
    const Vec toLight = light.Light - p[0];
    beyond = -Dot(normal, toLight);
    if (!(std::abs(beyond) > 1e-9 * size * Norm(toLight)))
    {
      return false;
    }
  }
  const double sign = beyond > 0.0 ? 1.0 : -1.0;
  keep(sign * Dot(normal, origin - p[0]), sign * Dot(normal, dir));
  for (int i = 0; i < 3; ++i)
  {
    const Vec& a = p[i];
    const Vec& b = p[(i + 1) % 3];
    const Vec& c = p[(i + 2) % 3];
    // The plane through the edge ab and the light (or its direction), facing c.
    const Vec apex = light.Directional() ? a : light.Light;
    Vec side = light.Directional() ? Cross(b - a, light.Axis) : Cross(a - apex, b - apex);
    if (Dot(side, c - apex) < 0.0)
    {
      side = -1.0 * side;
    }
    keep(Dot(side, origin - apex), Dot(side, dir));
  }
  return true;
}
}

bool vtkLightShaftReferenceScene::Tracer::ShadowOf(const Vec& x,
  const vtkLightShaftReferenceIntegrator::Model& model,
  const Vec& origin,
  const Vec& dir,
  double& first,
  double& last)
{
  Vec from;
  Vec to;
  if (!ToLight(x, model, from, to))
  {
    return false;
  }
  this->Scene.Opaque.Crossed(from, to, this->Blockers);
  if (this->Blockers.empty())
  {
    return false;
  }
  first = std::numeric_limits<double>::infinity();
  last = -std::numeric_limits<double>::infinity();
  for (const std::array<Vec, 3>& corners : this->Blockers)
  {
    double a;
    double b;
    if (!ShadowVolumeInterval(model, corners, origin, dir, a, b))
    {
      return false;
    }
    first = std::min(first, a);
    last = std::max(last, b);
  }
  return true;
}

bool vtkLightShaftReferenceScene::Tracer::Transition(const Model& model,
  const Vec& origin,
  const Vec& dir,
  double tFrom,
  double tTo,
  double& t)
{
  if (this->Scene.ShadowMap || !this->Scene.Translucent.IsEmpty() || !(tTo > tFrom))
  {
    return false;
  }
  // A hair: far below what float32 output resolves, far above double's rounding of t.
  const double hair = 1e-10 * (std::abs(tFrom) + std::abs(tTo));
  if (!(4.0 * hair < tTo - tFrom))
  {
    return false;
  }
  const bool litFrom = !this->Shadowed(origin + tFrom * dir, model);
  double lit = litFrom ? tFrom : tTo;
  double dark = litFrom ? tTo : tFrom;
  auto between = [&](double x) { return std::min(lit, dark) < x && x < std::max(lit, dark); };
  // From the shadowed end, step to where its shadowing triangles stop shadowing the ray. If
  // others shadow it there (a fine mesh's shadow is many triangles' volumes), go on from there
  // and halve what is left, so that few steps pass any number of triangles.
  for (int step = 0; step < 48; ++step)
  {
    double first;
    double last;
    if (!this->ShadowOf(origin + dark * dir, model, origin, dir, first, last))
    {
      return false;
    }
    const double edge = litFrom ? first : last;
    if (!between(edge))
    {
      return false; // rounding at a shared edge or a grazing ray: bisect
    }
    const double probe = litFrom ? edge - hair : edge + hair;
    if (!between(probe) || !this->Shadowed(origin + probe * dir, model))
    {
      t = edge;
      return true;
    }
    dark = probe;
    const double middle = 0.5 * (lit + dark);
    if (!between(middle))
    {
      return false;
    }
    (this->Shadowed(origin + middle * dir, model) ? dark : lit) = middle;
  }
  return false;
}
