#include "vtkLightShaftGeometryLights.h"

#include "vtkLightShaftGeometryLitVolume.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vtkLightShaftGeometry
{
namespace
{
// Extend [nearest, deepest] by the depths along `axis` (from `apex`) of a box's eight corners.
void ExtendDepthRange(const double bounds[6],
  const glm::dvec3& apex,
  const glm::dvec3& axis,
  double& nearest,
  double& deepest)
{
  for (int corner = 0; corner < 8; ++corner)
  {
    const double depth = glm::dot(BoxCorner(bounds, corner) - apex, axis);
    nearest = std::min(nearest, depth);
    deepest = std::max(deepest, depth);
  }
}

// A unit vector pair (u, v) across `axis`, (axis, u, v) right-handed.
void PerpendicularBasis(const glm::dvec3& axis, glm::dvec3& u, glm::dvec3& v)
{
  u = glm::normalize(glm::cross(
    axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
  v = glm::cross(axis, u);
}
}

//------------------------------------------------------------------------------
namespace
{
// The view and world-to-clip matrices of a camera at `position` looking at `focal`, with
// `projection`, computed by VTK's camera exactly as the shadow map's render will.
LightView MakeView(const glm::dvec3& position,
  const glm::dvec3& focal,
  const glm::dvec3& viewUp,
  const glm::dmat4& projection,
  const CameraFrame& camera)
{
  LightView view;
  view.Position = position;
  view.FocalPoint = focal;
  view.ViewUp = viewUp;
  view.Projection = projection;
  vtkNew<vtkCamera> lightCamera;
  lightCamera->SetPosition(position.x, position.y, position.z);
  lightCamera->SetFocalPoint(focal.x, focal.y, focal.z);
  lightCamera->SetViewUp(viewUp.x, viewUp.y, viewUp.z);
  const glm::dmat4 lightView = FromVTKMatrix(lightCamera->GetViewTransformMatrix());
  view.WorldToClip = projection * lightView;
  view.ViewToClip = view.WorldToClip * glm::inverse(camera.WorldToView);
  return view;
}

// Visible props with usable bounds (finite: NaN points leave a prop out) that `reaches`
// accepts.
std::vector<vtkProp*> SelectCasters(vtkPropCollection* props,
  const std::function<bool(const double*)>& reaches)
{
  std::vector<vtkProp*> casters;
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const double* bounds = prop->GetVisibility() ? prop->GetBounds() : nullptr;
    if (bounds && vtkLightShaftModel::UsableBounds(bounds) && reaches(bounds))
    {
      casters.push_back(prop);
    }
  }
  return casters;
}

// The light camera's depth range from [nearest, deepest] (the casters'), else as far as the
// view volume reaches; perspective cameras keep near above 1e-4 far.
void SetDepthRange(LightFrame& frame, const CameraFrame& camera, double nearest, double deepest)
{
  if (deepest <= 0.0)
  {
    deepest = std::max(FarthestViewPoint(camera, frame.PositionVC), 1e-30);
    nearest = 0.0;
  }
  frame.Far = deepest * 1.001;
  frame.Near = std::max(nearest * 0.999, frame.Far * 1e-4);
}

// A spotlight: the bounding pyramid, its casters, a perspective camera over its square.
void ComputeSpotFrame(LightFrame& frame,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds)
{
  const vtkLightShaftModel::Light& light = frame.Model;
  // The bounding pyramid, across the view-space axis; the same pyramid in world coordinates
  // (the view transform is a rotation and a translation: its transpose undoes the rotation).
  const double halfAngle =
    std::min(light.ConeHalfAngle, vtkLightShaftModel::MaximumSquareHalfAngle);
  Pyramid& vc = frame.BoundsVC;
  vc.Apex = frame.PositionVC;
  vc.Axis = frame.AxisVC;
  PerpendicularBasis(vc.Axis, vc.U, vc.V);
  vc.Tangent = std::tan(halfAngle);
  Pyramid& wc = frame.BoundsWC;
  wc.Apex = light.Position;
  wc.Axis = light.Axis;
  wc.U = frame.ViewToWorld * vc.U;
  wc.V = frame.ViewToWorld * vc.V;
  wc.Tangent = vc.Tangent;

  // Casters: visible props (culled from the camera's view or not) whose bounds reach into the
  // pyramid; only they can shadow the shafts.
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  frame.Casters = SelectCasters(props, [&](const double* bounds) { return wc.Reaches(bounds); });
  for (vtkProp* prop : frame.Casters)
  {
    ExtendDepthRange(prop->GetBounds(), light.Position, light.Axis, nearest, deepest);
  }
  frame.ShadowsPossible = !frame.Casters.empty();
  if (casterBounds)
  {
    // Distributed: every process uses the global casters' bounds, and so the same light camera.
    nearest = std::numeric_limits<double>::max();
    deepest = 0.0;
    frame.ShadowsPossible = vtkMath::AreBoundsInitialized(casterBounds) && wc.Reaches(casterBounds);
    if (frame.ShadowsPossible)
    {
      ExtendDepthRange(casterBounds, light.Position, light.Axis, nearest, deepest);
    }
  }

  // The light camera's depth range: the casters' (tight: best shadow-map precision), else as
  // far as the view volume reaches.
  SetDepthRange(frame, camera, nearest, deepest);
  frame.Projection = glm::perspective(2.0 * halfAngle, 1.0, frame.Near, frame.Far);
  frame.Views.push_back(
    MakeView(light.Position, light.Position + light.Axis, light.ViewUp, frame.Projection, camera));
  frame.Views[0].Casters = frame.Casters;
  frame.MapExtent = 2.0 * vc.Tangent;
  frame.ViewToLightSquare = frame.Views[0].ViewToClip;
}

// A point light: casters anywhere, a cube of six 90-degree cameras, each rendering the casters
// whose bounds reach into its pyramid.
void ComputePointFrame(LightFrame& frame,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds)
{
  const vtkLightShaftModel::Light& light = frame.Model;
  frame.Casters = SelectCasters(props, [](const double*) { return true; });
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  auto extend = [&](const double* bounds)
  {
    // The box's distance range from the light (0 inside it).
    glm::dvec3 closest;
    for (int i = 0; i < 3; ++i)
    {
      closest[i] = vtkMath::ClampValue(light.Position[i], bounds[2 * i], bounds[2 * i + 1]);
    }
    nearest = std::min(nearest, glm::length(closest - light.Position));
    for (int corner = 0; corner < 8; ++corner)
    {
      deepest = std::max(deepest, glm::length(BoxCorner(bounds, corner) - light.Position));
    }
  };
  for (vtkProp* prop : frame.Casters)
  {
    extend(prop->GetBounds());
  }
  frame.ShadowsPossible = !frame.Casters.empty();
  if (casterBounds)
  {
    nearest = std::numeric_limits<double>::max();
    deepest = 0.0;
    frame.ShadowsPossible = vtkMath::AreBoundsInitialized(casterBounds);
    if (frame.ShadowsPossible)
    {
      extend(casterBounds);
    }
  }
  // The faces' near plane is at an axial depth: a caster at distance d from the light lies at an
  // axial depth of d / sqrt(3) in a face's corner. With the distance as the near plane, a
  // caster seen near a face's edge or corner was clipped away and cast no shadow (measured: a
  // box near the seam of two faces, 1.5% of the image and 8% of the pixels beside it).
  if (nearest < std::numeric_limits<double>::max())
  {
    nearest /= std::sqrt(3.0);
  }
  SetDepthRange(frame, camera, nearest, deepest);
  frame.Projection = glm::perspective(vtkMath::Pi() / 2.0, 1.0, frame.Near, frame.Far);
  for (int face = 0; face < 6; ++face)
  {
    glm::dvec3 axis(0.0);
    axis[face / 2] = (face % 2) ? -1.0 : 1.0;
    const glm::dvec3 up = (face / 2 == 1) ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(0.0, 1.0, 0.0);
    LightView view = MakeView(light.Position, light.Position + axis, up, frame.Projection, camera);
    Pyramid pyramid;
    pyramid.Apex = light.Position;
    pyramid.Axis = axis;
    pyramid.U = glm::cross(axis, up);
    pyramid.V = up;
    pyramid.Tangent = 1.0;
    for (vtkProp* prop : frame.Casters)
    {
      if (pyramid.Reaches(prop->GetBounds()))
      {
        view.Casters.push_back(prop);
      }
    }
    frame.Views.push_back(std::move(view));
  }
  frame.MapExtent = 2.0;
}

// A directional light: the lit part of the view volume lies beyond its plane; the casters are
// the props beyond the plane whose shadow can fall there, and one orthographic camera covers
// the part of the plane above both (the receivers' and the casters' footprints).
void ComputeDirectionalFrame(LightFrame& frame,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds)
{
  const vtkLightShaftModel::Light& light = frame.Model;
  const glm::dvec3& origin = light.Position;
  // Footprints on the light's plane: (Right, Up) coordinates, and depth along the axis.
  struct Footprint
  {
    glm::dvec2 Low{ std::numeric_limits<double>::max() };
    glm::dvec2 High{ -std::numeric_limits<double>::max() };
    double Nearest = std::numeric_limits<double>::max();
    double Deepest = -std::numeric_limits<double>::max();
    void Add(const glm::dvec3& p, const vtkLightShaftModel::Light& l)
    {
      const glm::dvec3 d = p - l.Position;
      const glm::dvec2 q(glm::dot(d, l.Right), glm::dot(d, l.Up));
      this->Low = glm::min(this->Low, q);
      this->High = glm::max(this->High, q);
      this->Nearest = std::min(this->Nearest, glm::dot(d, l.Axis));
      this->Deepest = std::max(this->Deepest, glm::dot(d, l.Axis));
    }
    void Merge(const Footprint& o)
    {
      this->Low = glm::min(this->Low, o.Low);
      this->High = glm::max(this->High, o.High);
      this->Nearest = std::min(this->Nearest, o.Nearest);
      this->Deepest = std::max(this->Deepest, o.Deepest);
    }
    bool Overlaps(const Footprint& o) const
    {
      return this->Low.x <= o.High.x && o.Low.x <= this->High.x && this->Low.y <= o.High.y &&
             o.Low.y <= this->High.y;
    }
  };
  Footprint receivers;
  const glm::dmat4 viewToWorld = glm::inverse(camera.WorldToView);
  for (const auto& face : ComputeLitVolume(frame, camera).Polytope.Faces)
  {
    for (const glm::dvec3& p : face)
    {
      receivers.Add(glm::dvec3(viewToWorld * glm::dvec4(p, 1.0)), light);
    }
  }
  auto boxFootprint = [&](const double* bounds)
  {
    Footprint box;
    for (int corner = 0; corner < 8; ++corner)
    {
      box.Add(BoxCorner(bounds, corner), light);
    }
    return box;
  };
  // A box casts into the lit view volume when it reaches beyond the plane, lies over the
  // receivers and is not entirely behind them.
  auto casts = [&](const double* bounds)
  {
    const Footprint box = boxFootprint(bounds);
    return box.Deepest > 0.0 && box.Nearest < receivers.Deepest && box.Overlaps(receivers);
  };
  Footprint casters;
  frame.Casters = SelectCasters(props, casts);
  for (vtkProp* prop : frame.Casters)
  {
    casters.Merge(boxFootprint(prop->GetBounds()));
  }
  frame.ShadowsPossible = !frame.Casters.empty();
  if (casterBounds)
  {
    frame.ShadowsPossible = vtkMath::AreBoundsInitialized(casterBounds) && casts(casterBounds);
    casters = frame.ShadowsPossible ? boxFootprint(casterBounds) : Footprint();
  }

  // The camera's rectangle: where the casters' and the receivers' footprints overlap (light
  // from elsewhere reaches no receiver, or meets no caster), with a margin of a thousandth.
  glm::dvec2 low(-1.0);
  glm::dvec2 high(1.0);
  double nearest = 0.0;
  double deepest = 1.0;
  if (frame.ShadowsPossible)
  {
    low = glm::max(receivers.Low, casters.Low);
    high = glm::min(receivers.High, casters.High);
    const glm::dvec2 margin = 1e-3 * glm::max(high - low, glm::dvec2(1e-30)) + 1e-30;
    low -= margin;
    high += margin;
    nearest = std::max(casters.Nearest, 0.0);
    deepest = std::max(casters.Deepest, nearest + 1e-30);
  }
  const double span = deepest - nearest;
  frame.Near = std::max(nearest - 1e-3 * span, 0.0);
  frame.Far = deepest + 1e-3 * span + 1e-30;
  const glm::dvec2 centre = 0.5 * (low + high);
  const glm::dvec2 half = 0.5 * (high - low);
  frame.Projection = glm::ortho(-half.x, half.x, -half.y, half.y, frame.Near, frame.Far);
  const glm::dvec3 eye = origin + centre.x * light.Right + centre.y * light.Up;
  frame.Views.push_back(MakeView(eye, eye + light.Axis, light.ViewUp, frame.Projection, camera));
  frame.Views[0].Casters = frame.Casters;
  frame.MapExtent = 2.0 * std::max(half.x, half.y);

  // The cookie's and noise's square: side SquareSide, centred on the axis through Position.
  const double scale = 2.0 / light.SquareSide;
  glm::dmat4 square(0.0);
  for (int i = 0; i < 3; ++i)
  {
    square[i][0] = scale * light.Right[i];
    square[i][1] = scale * light.Up[i];
  }
  square[3][0] = -scale * glm::dot(origin, light.Right);
  square[3][1] = -scale * glm::dot(origin, light.Up);
  square[3][3] = 1.0;
  frame.ViewToLightSquare = square * viewToWorld;
}
}

//------------------------------------------------------------------------------
LightFrame ComputeLightFrame(const vtkLightShaftModel::Light& light,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds)
{
  LightFrame frame;
  frame.Model = light;
  frame.PositionVC = glm::dvec3(camera.WorldToView * glm::dvec4(light.Position, 1.0));
  frame.AxisVC = glm::normalize(glm::dvec3(camera.WorldToView * glm::dvec4(light.Axis, 0.0)));
  frame.ViewToWorld = glm::transpose(glm::dmat3(camera.WorldToView));
  switch (light.Kind)
  {
    case vtkLightShaftModel::LightKind::Point:
      ComputePointFrame(frame, camera, props, casterBounds);
      break;
    case vtkLightShaftModel::LightKind::Directional:
      ComputeDirectionalFrame(frame, camera, props, casterBounds);
      break;
    default:
      ComputeSpotFrame(frame, camera, props, casterBounds);
      break;
  }
  frame.WorldToLightClip = frame.Views[0].WorldToClip;
  frame.ViewToLightClip = frame.Views[0].ViewToClip;
  return frame;
}

//------------------------------------------------------------------------------
void OffsetShadowCameras(LightFrame& light, double dx, double dy)
{
  // In clip coordinates an NDC shift is a shift by w: x' = x + dx w.
  glm::dmat4 shift(1.0);
  shift[3][0] = dx;
  shift[3][1] = dy;
  for (LightView& view : light.Views)
  {
    view.Projection = shift * view.Projection;
    view.WorldToClip = shift * view.WorldToClip;
    view.ViewToClip = shift * view.ViewToClip;
  }
  light.Projection = shift * light.Projection;
  light.WorldToLightClip = shift * light.WorldToLightClip;
  light.ViewToLightClip = shift * light.ViewToLightClip;
}
}
