#include "vtkLightShaftGeometry.h"

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
#include <sstream>

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
    const glm::dvec3 p(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
    const double depth = glm::dot(p - apex, axis);
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

// A box's corner (index bits: x, y, z).
glm::dvec3 Corner(const double bounds[6], int corner)
{
  return glm::dvec3(
    bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
}
}

//------------------------------------------------------------------------------
glm::dmat4 FromKeyMatrix(vtkMatrix4x4* key)
{
  return glm::make_mat4(&key->Element[0][0]);
}

glm::dmat4 FromVTKMatrix(vtkMatrix4x4* m)
{
  return glm::transpose(glm::make_mat4(&m->Element[0][0]));
}

void ToVTKMatrix(const glm::dmat4& m, vtkMatrix4x4* out)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      out->SetElement(row, col, m[col][row]);
    }
  }
}

std::array<float, 16> ToFloatColumnMajor(const glm::dmat4& m)
{
  std::array<float, 16> out;
  const double* p = glm::value_ptr(m);
  std::copy(p, p + 16, out.begin());
  return out;
}

std::array<float, 3> ToFloat3(const glm::dvec3& v)
{
  return { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
}

//------------------------------------------------------------------------------
std::string CameraFrame::UnusableValue(vtkCamera* camera) const
{
  std::ostringstream text;
  const double* position = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  const double* range = camera->GetClippingRange();
  const double scale = camera->GetParallelScale();
  if (std::equal(position, position + 3, focal))
  {
    text << "its position equals its focal point (" << focal[0] << ", " << focal[1] << ", "
         << focal[2] << ")";
  }
  else if (camera->GetParallelProjection() && !(std::isfinite(scale) && scale > 0.0))
  {
    text << "its parallel scale is " << scale;
  }
  else if (!(std::isfinite(range[0]) && std::isfinite(range[1]) && range[0] < range[1]))
  {
    text << "its clipping range is (" << range[0] << ", " << range[1] << ")";
  }
  else
  {
    const double* matrices[3] = { glm::value_ptr(this->WorldToView),
      glm::value_ptr(this->ViewToClip),
      glm::value_ptr(this->ClipToView) };
    for (const double* m : matrices)
    {
      if (!std::all_of(m, m + 16, [](double v) { return std::isfinite(v); }))
      {
        text << "its view and projection matrices are not finite";
        break;
      }
    }
  }
  return text.str();
}

CameraFrame CameraFrame::FromMatrices(const glm::dmat4& worldToView, const glm::dmat4& viewToClip)
{
  CameraFrame camera;
  camera.WorldToView = worldToView;
  camera.ViewToClip = viewToClip;
  camera.ClipToView = glm::inverse(viewToClip);
  camera.Perspective = viewToClip[2][3] != 0.0;
  const glm::dvec4 farPoint = camera.ClipToView * glm::dvec4(0.0, 0.0, 1.0, 1.0);
  camera.FarDepth = -farPoint.z / farPoint.w;
  return camera;
}

glm::dvec2 CameraFrame::PixelFootprint(int width) const
{
  const double pixel = 2.0 / (width * this->ViewToClip[0][0]);
  return this->Perspective ? glm::dvec2(pixel, 0.0) : glm::dvec2(0.0, pixel);
}

//------------------------------------------------------------------------------
bool Pyramid::Reaches(const double bounds[6]) const
{
  auto outside = [&](const glm::dvec3& normal, double axial)
  {
    // All corners strictly outside the half-space axial * (d . Axis) - d . normal >= 0.
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::dvec3 d = Corner(bounds, corner) - this->Apex;
      if (axial * glm::dot(d, this->Axis) - glm::dot(d, normal) >= 0.0)
      {
        return false;
      }
    }
    return true;
  };
  if (outside(-this->Axis, 0.0))
  {
    return false; // behind the light
  }
  for (const glm::dvec3& side : { this->U, -this->U, this->V, -this->V })
  {
    if (outside(side, this->Tangent))
    {
      return false;
    }
  }
  return true;
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
      deepest = std::max(deepest, glm::length(Corner(bounds, corner) - light.Position));
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
      box.Add(Corner(bounds, corner), light);
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

//------------------------------------------------------------------------------
void ConvexPolytope::Clip(const glm::dvec4& plane)
{
  const glm::dvec3 n(plane);
  const double scale = glm::length(n);
  if (scale == 0.0)
  {
    return;
  }
  std::vector<std::vector<glm::dvec3>> kept;
  std::vector<glm::dvec3> cut;
  for (const auto& face : this->Faces)
  {
    std::vector<glm::dvec3> out;
    const size_t count = face.size();
    for (size_t i = 0; i < count; ++i)
    {
      const glm::dvec3& a = face[i];
      const glm::dvec3& b = face[(i + 1) % count];
      const double da = (glm::dot(n, a) + plane.w) / scale;
      const double db = (glm::dot(n, b) + plane.w) / scale;
      if (da >= 0.0)
      {
        out.push_back(a);
      }
      if ((da >= 0.0) != (db >= 0.0))
      {
        const glm::dvec3 p = a + (b - a) * (da / (da - db));
        out.push_back(p);
        cut.push_back(p);
      }
    }
    if (out.size() >= 3)
    {
      kept.push_back(std::move(out));
    }
  }
  if (cut.size() >= 3)
  {
    // The cap: the cut points ordered around their centroid in the clipping plane.
    glm::dvec3 centre(0.0);
    for (const auto& p : cut)
    {
      centre += p;
    }
    centre /= static_cast<double>(cut.size());
    const glm::dvec3 axis = n / scale;
    glm::dvec3 u =
      glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    u = glm::normalize(u);
    const glm::dvec3 v = glm::cross(axis, u);
    std::sort(cut.begin(),
      cut.end(),
      [&](const glm::dvec3& p, const glm::dvec3& q)
      {
        return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
               std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
      });
    kept.push_back(std::move(cut));
  }
  this->Faces = std::move(kept);
}

//------------------------------------------------------------------------------
std::vector<glm::dvec2> ClipToConvex(std::vector<glm::dvec2> polygon,
  const std::vector<glm::dvec2>& window)
{
  std::vector<glm::dvec2> next;
  for (size_t e = 0; e < window.size() && !polygon.empty(); ++e)
  {
    const glm::dvec2 a = window[e];
    const glm::dvec2 edge = window[(e + 1) % window.size()] - a;
    auto side = [&](const glm::dvec2& p) { return edge.x * (p.y - a.y) - edge.y * (p.x - a.x); };
    next.clear();
    for (size_t i = 0; i < polygon.size(); ++i)
    {
      const glm::dvec2& p = polygon[i];
      const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
      const double sp = side(p);
      const double sq = side(q);
      if (sp >= 0.0)
      {
        next.push_back(p);
      }
      if ((sp >= 0.0) != (sq >= 0.0))
      {
        next.push_back(p + (q - p) * (sp / (sp - sq)));
      }
    }
    polygon.swap(next);
  }
  return polygon;
}

//------------------------------------------------------------------------------
std::vector<glm::dvec2> ConvexHull(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(),
    points.end(),
    [](const glm::dvec2& a, const glm::dvec2& b)
    { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3)
  {
    return points;
  }
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
  { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i > 0; --i)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

//------------------------------------------------------------------------------
namespace
{
// The part of `polytope` inside the view volume, and its view-depth range.
LitVolume ClipToViewVolume(ConvexPolytope polytope, const CameraFrame& camera)
{
  // Clipped to the view volume: the four sides, the far depth (where rays that hit nothing
  // end), and a depth just in front of the camera plane (slabs must project).
  const glm::dmat4 clipT = glm::transpose(camera.ViewToClip); // rows of the projection
  const glm::dvec4 row0 = clipT[0];
  const glm::dvec4 row1 = clipT[1];
  const glm::dvec4 row3 = clipT[3];
  const double minimumDepth = camera.FarDepth * 1e-7;
  LitVolume lit;
  lit.Polytope = std::move(polytope);
  for (const glm::dvec4& plane : { row3 + row0,
         row3 - row0,
         row3 + row1,
         row3 - row1,
         glm::dvec4(0.0, 0.0, 1.0, camera.FarDepth),
         glm::dvec4(0.0, 0.0, -1.0, -minimumDepth) })
  {
    lit.Polytope.Clip(plane);
  }
  if (lit.Polytope.Empty())
  {
    return lit;
  }
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  for (const auto& face : lit.Polytope.Faces)
  {
    for (const auto& p : face)
    {
      nearest = std::min(nearest, -p.z);
      deepest = std::max(deepest, -p.z);
    }
  }
  lit.Nearest = std::max(nearest, minimumDepth);
  lit.Deepest = deepest;
  return lit;
}

// An axis-aligned cube of half-side `half` about `centre`, as a polytope.
ConvexPolytope Cube(const glm::dvec3& centre, double half)
{
  glm::dvec3 c[8];
  for (int corner = 0; corner < 8; ++corner)
  {
    c[corner] = centre + half * glm::dvec3((corner & 1) ? 1.0 : -1.0,
                                  (corner & 2) ? 1.0 : -1.0,
                                  (corner & 4) ? 1.0 : -1.0);
  }
  ConvexPolytope cube;
  cube.Faces = { { c[0], c[2], c[3], c[1] },
    { c[4], c[5], c[7], c[6] },
    { c[0], c[1], c[5], c[4] },
    { c[2], c[6], c[7], c[3] },
    { c[0], c[4], c[6], c[2] },
    { c[1], c[3], c[7], c[5] } };
  return cube;
}
}

//------------------------------------------------------------------------------
LitVolume ComputeLitVolume(const LightFrame& light, const CameraFrame& camera)
{
  if (light.Model.Kind != vtkLightShaftModel::LightKind::Spot)
  {
    // The view volume (inside a cube about the eye that holds it), beyond a directional
    // light's plane.
    const double reach = std::max(FarthestViewPoint(camera, glm::dvec3(0.0)), 1e-30) * 1.01;
    ConvexPolytope volume = Cube(glm::dvec3(0.0), reach);
    if (light.Model.Kind == vtkLightShaftModel::LightKind::Directional)
    {
      volume.Clip(glm::dvec4(light.AxisVC, -glm::dot(light.AxisVC, light.PositionVC)));
    }
    return ClipToViewVolume(std::move(volume), camera);
  }
  const Pyramid& pyramid = light.BoundsVC;

  // The pyramid, its base beyond everything the view can see.
  const double reach = std::max(FarthestViewPoint(camera, pyramid.Apex), 1e-30);
  const double halfSide = reach * pyramid.Tangent;
  const glm::dvec3& u = pyramid.U;
  const glm::dvec3& v = pyramid.V;
  const glm::dvec3 baseCentre = pyramid.Apex + reach * pyramid.Axis;
  const std::array<glm::dvec3, 4> base = { baseCentre + halfSide * (u + v),
    baseCentre + halfSide * (-u + v),
    baseCentre + halfSide * (-u - v),
    baseCentre + halfSide * (u - v) };
  ConvexPolytope polytope;
  polytope.Faces.push_back({ base[3], base[2], base[1], base[0] });
  for (int i = 0; i < 4; ++i)
  {
    polytope.Faces.push_back({ pyramid.Apex, base[i], base[(i + 1) % 4] });
  }
  return ClipToViewVolume(std::move(polytope), camera);
}

//------------------------------------------------------------------------------
std::vector<SlabFootprint> ComputeSlabFootprints(const LitVolume& lit,
  const CameraFrame& camera,
  int slabs,
  bool jitter,
  int share,
  int part)
{
  const double nearest = lit.Nearest;
  const double deepest = lit.Deepest;
  const double thickness = (deepest - nearest) / slabs;
  const int drawnSlabs = jitter ? slabs + 1 : slabs;
  std::vector<SlabFootprint> footprints;
  std::vector<glm::dvec2> footprint;
  for (int k = part; k < drawnSlabs; k += std::max(share, 1))
  {
    const double za = std::max(nearest, nearest + (jitter ? k - 1 : k) * thickness);
    const double zb = std::min(deepest, nearest + (k + 1) * thickness);
    footprint.clear();
    auto addPoint = [&](const glm::dvec3& p)
    {
      const glm::dvec4 c = camera.ViewToClip * glm::dvec4(p, 1.0);
      footprint.emplace_back(c.x / c.w, c.y / c.w);
    };
    for (const auto& face : lit.Polytope.Faces)
    {
      const size_t count = face.size();
      for (size_t i = 0; i < count; ++i)
      {
        const glm::dvec3& a = face[i];
        const glm::dvec3& b = face[(i + 1) % count];
        const double da = -a.z;
        const double db = -b.z;
        if (da >= za && da <= zb)
        {
          addPoint(a);
        }
        for (double plane : { za, zb })
        {
          if ((da - plane) * (db - plane) < 0.0)
          {
            addPoint(a + (b - a) * ((plane - da) / (db - da)));
          }
        }
      }
    }
    std::vector<glm::dvec2> hull = ConvexHull(footprint);
    if (hull.size() >= 3)
    {
      footprints.push_back({ k, za, std::move(hull) });
    }
  }
  return footprints;
}

//------------------------------------------------------------------------------
void AppendSlabTriangles(const SlabFootprint& slab, int lattice, std::vector<float>& vertices)
{
  const std::vector<glm::dvec2>& hull = slab.Hull;
  glm::dvec2 low = hull[0];
  glm::dvec2 high = hull[0];
  for (const glm::dvec2& p : hull)
  {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  // The hull without its near-coincident vertices: the direction of an edge a rounding error
  // long is noise (its half-plane would cut a sliver out of the slab), and a triangle with
  // two such vertices is degenerate once in float (llvmpipe was seen to drop a whole draw of a
  // fan ending in one).
  const double tiny = 1e-9 * glm::length(high - low);
  std::vector<glm::dvec2> window;
  for (const glm::dvec2& p : hull)
  {
    if (window.empty() || glm::length(p - window.back()) > tiny)
    {
      window.push_back(p);
    }
  }
  while (window.size() > 1 && glm::length(window.front() - window.back()) <= tiny)
  {
    window.pop_back();
  }
  // Triangles with a positive area in float, as the GL will see them.
  auto emit = [&](const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
  {
    const std::array<float, 6> f = { static_cast<float>(a.x),
      static_cast<float>(a.y),
      static_cast<float>(b.x),
      static_cast<float>(b.y),
      static_cast<float>(c.x),
      static_cast<float>(c.y) };
    const double area = (static_cast<double>(f[2]) - f[0]) * (static_cast<double>(f[5]) - f[1]) -
                        (static_cast<double>(f[3]) - f[1]) * (static_cast<double>(f[4]) - f[0]);
    if (!(area > 0.0))
    {
      return;
    }
    for (int v = 0; v < 3; ++v)
    {
      vertices.insert(vertices.end(),
        { f[2 * v],
          f[2 * v + 1],
          static_cast<float>(slab.Index),
          static_cast<float>(slab.NearDepth) });
    }
  };
  auto fan = [&](const std::vector<glm::dvec2>& polygon)
  {
    for (size_t i = 1; i + 1 < polygon.size(); ++i)
    {
      emit(polygon[0], polygon[i], polygon[i + 1]);
    }
  };
  if (lattice <= 0)
  {
    fan(window);
    return;
  }
  auto corner = [&](int i, int j)
  { return low + (high - low) * glm::dvec2(double(i) / lattice, double(j) / lattice); };
  for (int j = 0; j < lattice; ++j)
  {
    for (int i = 0; i < lattice; ++i)
    {
      fan(ClipToConvex(
        { corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1) }, window));
    }
  }
}

//------------------------------------------------------------------------------
int AffordableLattice(int requested, int slabs, int lights)
{
  if (requested <= 0)
  {
    return 0;
  }
  const double share = static_cast<double>(LatticeCellBudget) / std::max(lights, 1);
  const int affordable =
    std::max(1, static_cast<int>(std::floor(std::sqrt(share / std::max(slabs, 1)))));
  return std::min(requested, affordable);
}

//------------------------------------------------------------------------------
int AffordableSamples(int requested, long long pixels, int lights)
{
  const long long share = SegmentBudget / std::max(lights, 1);
  const long long affordable = std::max(1LL, share / std::max(pixels, 1LL));
  return static_cast<int>(std::min<long long>(requested, affordable));
}

//------------------------------------------------------------------------------
int AffordableLightVolume(int requested, int faces, int lights, long long pixels)
{
  const double scale = static_cast<double>(FrameLightVolumePixels) /
                       static_cast<double>(std::max(pixels, FrameLightVolumePixels));
  const double share = scale * static_cast<double>(FrameLightVolumeCellAllowance) /
                       (static_cast<double>(std::max(lights, 1)) * std::max(faces, 1));
  const int affordable = std::max(8, static_cast<int>(std::floor(std::sqrt(share))));
  return std::min(requested, affordable);
}

//------------------------------------------------------------------------------
double FarthestViewPoint(const CameraFrame& camera, const glm::dvec3& pointVC)
{
  double farthest = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double sx = (corner & 1) ? 1.0 : -1.0;
    const double sy = (corner & 2) ? 1.0 : -1.0;
    const glm::dvec4 nearPoint = camera.ClipToView * glm::dvec4(sx, sy, -1.0, 1.0);
    const glm::dvec4 farPoint = camera.ClipToView * glm::dvec4(sx, sy, 1.0, 1.0);
    const glm::dvec3 n3 = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 f3 = glm::dvec3(farPoint) / farPoint.w;
    const glm::dvec3 dir = f3 - n3;
    const glm::dvec3 start = n3 - dir * (n3.z / dir.z);
    // The corner's ray at the far depth (the backdrop, beyond or before the far plane).
    const glm::dvec3 end = start + dir * ((-camera.FarDepth - start.z) / dir.z);
    farthest = std::max({ farthest, glm::length(start - pointVC), glm::length(end - pointVC) });
  }
  return farthest;
}
}
