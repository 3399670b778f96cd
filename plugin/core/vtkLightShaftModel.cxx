#include "vtkLightShaftModel.h"

#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace vtkLightShaftModel
{
//------------------------------------------------------------------------------
LightKind KindOf(vtkLight* light)
{
  if (!light->GetPositional())
  {
    return LightKind::Directional;
  }
  return light->GetConeAngle() < 90.0 ? LightKind::Spot : LightKind::Point;
}

bool IsSpotLight(vtkLight* light)
{
  return KindOf(light) == LightKind::Spot;
}

//------------------------------------------------------------------------------
std::vector<vtkLight*> FindLights(const std::vector<vtkLight*>& requested, vtkRenderer* renderer)
{
  std::vector<vtkLight*> lights;
  if (!requested.empty())
  {
    for (vtkLight* light : requested)
    {
      if (light && light->GetSwitch())
      {
        lights.push_back(light);
      }
    }
    return lights;
  }
  vtkLightCollection* candidates = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  candidates->InitTraversal(it);
  while (vtkLight* candidate = candidates->GetNextLight(it))
  {
    if (candidate->GetSwitch() && KindOf(candidate) != LightKind::Directional)
    {
      lights.push_back(candidate);
    }
  }
  return lights;
}

//------------------------------------------------------------------------------
namespace
{
std::string Values(const double* values, int n)
{
  std::ostringstream text;
  text << (n > 1 ? "(" : "");
  for (int i = 0; i < n; ++i)
  {
    text << (i ? ", " : "") << values[i];
  }
  text << (n > 1 ? ")" : "");
  return text.str();
}

bool AllFinite(const double* values, int n, bool nonNegative)
{
  return std::all_of(values,
    values + n,
    [nonNegative](double v) { return std::isfinite(v) && (!nonNegative || v >= 0.0); });
}
}

std::string UnusableLightValue(vtkLight* light)
{
  const double* position = light->GetTransformedPosition();
  if (!AllFinite(position, 3, false))
  {
    return "its position is " + Values(position, 3);
  }
  const double* focal = light->GetTransformedFocalPoint();
  if (!AllFinite(focal, 3, false))
  {
    return "its focal point is " + Values(focal, 3);
  }
  const LightKind kind = KindOf(light);
  if (kind != LightKind::Point && std::equal(position, position + 3, focal))
  {
    return "its position equals its focal point " + Values(focal, 3) + " (no direction)";
  }
  const double intensity = light->GetIntensity();
  if (!AllFinite(&intensity, 1, true))
  {
    return "its intensity is " + Values(&intensity, 1);
  }
  const double* color = light->GetDiffuseColor();
  if (!AllFinite(color, 3, true))
  {
    return "its diffuse colour is " + Values(color, 3);
  }
  const double* attenuation = light->GetAttenuationValues();
  if (kind != LightKind::Directional && !AllFinite(attenuation, 3, true))
  {
    return "its attenuation is " + Values(attenuation, 3);
  }
  const double cone = light->GetConeAngle();
  const double exponent = light->GetExponent();
  // A NaN cone angle is no spot (KindOf: not below 90 degrees), but is no light either.
  if (light->GetPositional() && !AllFinite(&cone, 1, false))
  {
    return "its cone angle is " + Values(&cone, 1);
  }
  if (kind == LightKind::Spot && !AllFinite(&exponent, 1, true))
  {
    return "its exponent is " + Values(&exponent, 1);
  }
  return std::string();
}

bool UsableBounds(const double bounds[6])
{
  return AllFinite(bounds, 6, false) && bounds[0] <= bounds[1] && bounds[2] <= bounds[3] &&
         bounds[4] <= bounds[5];
}

namespace
{
// `bounds` grown to hold `more` where that is a box (VTK's uninitialised and huge bounds are not).
void Grow(double bounds[6], const double* more)
{
  if (!more || !UsableBounds(more) ||
      std::any_of(more, more + 6, [](double v) { return std::abs(v) > 1e299; }))
  {
    return;
  }
  const bool had = UsableBounds(bounds);
  for (int axis = 0; axis < 3; ++axis)
  {
    bounds[2 * axis] = had ? std::min(bounds[2 * axis], more[2 * axis]) : more[2 * axis];
    bounds[2 * axis + 1] =
      had ? std::max(bounds[2 * axis + 1], more[2 * axis + 1]) : more[2 * axis + 1];
  }
}
}

bool SceneBounds(vtkRenderer* renderer, const double* given, vtkImageData* field, double bounds[6])
{
  // As vtkRenderer::ComputeVisiblePropBounds, without its event (a parallel render manager
  // may answer that one with a collective reduction).
  std::fill(bounds, bounds + 6, 0.0);
  bounds[0] = bounds[2] = bounds[4] = 1.0;
  bounds[1] = bounds[3] = bounds[5] = -1.0;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && prop->GetUseBounds())
    {
      Grow(bounds, prop->GetBounds());
    }
  }
  Grow(bounds, given);
  Grow(bounds, field ? field->GetBounds() : nullptr);
  return UsableBounds(bounds);
}

double BackdropDepth(const glm::dmat4& worldToView, const double bounds[6])
{
  double deepest = -std::numeric_limits<double>::max();
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 cornerWC(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)], 1.0);
    const glm::dvec4 cornerVC = worldToView * cornerWC;
    deepest = std::max(deepest, -cornerVC.z / cornerVC.w);
  }
  return deepest;
}

//------------------------------------------------------------------------------
namespace
{
// The scene's box grown to hold a positional light: its diagonal.
double FittedLength(const double bounds[6], const Light& light)
{
  double box[6];
  std::copy(bounds, bounds + 6, box);
  if (light.Kind != LightKind::Directional)
  {
    const double at[6] = { light.Position.x,
      light.Position.x,
      light.Position.y,
      light.Position.y,
      light.Position.z,
      light.Position.z };
    Grow(box, at);
  }
  return glm::length(glm::dvec3(box[1] - box[0], box[3] - box[2], box[5] - box[4]));
}
}

double FittedScattering(const double bounds[6], const Light& light)
{
  const double length = FittedLength(bounds, light);
  return std::isfinite(length) && length > 0.0 ? FittedOpticalDepth / length : 0.0;
}

double FittedExposure(const double bounds[6], const Light& light, double sigmaS)
{
  const double length = FittedLength(bounds, light);
  const glm::dvec3 centre(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const double d = light.Kind == LightKind::Directional ? 0.0 : light.Distance(centre);
  const double width = light.Kind == LightKind::Spot
                         ? std::min(2.0 * d * std::tan(light.ConeHalfAngle), length)
                         : length;
  const double falloff =
    light.Kind == LightKind::Directional
      ? 1.0
      : 1.0 / (light.Attenuation[0] + light.Attenuation[1] * d + light.Attenuation[2] * d * d);
  const double intensity = *std::max_element(light.RadiantIntensity, light.RadiantIntensity + 3);
  const double inScatter = sigmaS / (4.0 * vtkMath::Pi()) * intensity * falloff * width;
  const double exposure = FittedInScatter / inScatter;
  return std::isfinite(exposure) && exposure > 0.0 ? exposure : 0.0;
}

//------------------------------------------------------------------------------
glm::dvec2 Light::SquareWidth() const
{
  switch (this->Kind)
  {
    case LightKind::Directional:
      return glm::dvec2(0.0, this->SquareSide);
    case LightKind::Point:
      return glm::dvec2(2.0, 0.0);
    default:
      return glm::dvec2(2.0 * this->SquareTangent, 0.0);
  }
}

double Light::Distance(const glm::dvec3& point) const
{
  return this->Kind == LightKind::Directional ? glm::dot(point - this->Position, this->Axis)
                                              : glm::length(point - this->Position);
}

//------------------------------------------------------------------------------
Light DescribeLight(vtkLight* light)
{
  Light model;
  model.Kind = KindOf(light);
  const double* position = light->GetTransformedPosition();
  const double* focal = light->GetTransformedFocalPoint();
  model.Position = glm::dvec3(position[0], position[1], position[2]);
  const glm::dvec3 axis = glm::dvec3(focal[0], focal[1], focal[2]) - model.Position;
  model.Axis = glm::length(axis) > 0.0 ? glm::normalize(axis) : glm::dvec3(0.0, 0.0, -1.0);
  model.SquareSide = glm::length(axis) > 0.0 ? glm::length(axis) : 1.0;
  if (model.Kind == LightKind::Spot)
  {
    model.ConeHalfAngle = vtkMath::RadiansFromDegrees(light->GetConeAngle());
    model.Exponent = light->GetExponent();
  }
  else
  {
    model.ConeHalfAngle = vtkMath::Pi(); // no cone
    model.Exponent = 0.0;
  }
  if (model.Kind != LightKind::Directional)
  {
    light->GetAttenuationValues(model.Attenuation);
  }
  if (model.Attenuation[0] <= 0.0 && model.Attenuation[1] <= 0.0 && model.Attenuation[2] <= 0.0)
  {
    model.Attenuation[0] = 1.0;
  }
  const double* color = light->GetDiffuseColor();
  for (int c = 0; c < 3; ++c)
  {
    model.RadiantIntensity[c] = light->GetSwitch() ? light->GetIntensity() * color[c] : 0.0;
  }
  model.ViewUp =
    std::abs(model.Axis.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  model.Right = glm::normalize(glm::cross(model.Axis, model.ViewUp));
  model.Up = glm::cross(model.Right, model.Axis);
  model.SquareTangent = std::tan(std::min(model.ConeHalfAngle, MaximumSquareHalfAngle));
  return model;
}

//------------------------------------------------------------------------------
bool Medium::Scatters() const
{
  return this->SigmaS[0] > 0.0 || this->SigmaS[1] > 0.0 || this->SigmaS[2] > 0.0;
}

bool Medium::Extinguishes() const
{
  return this->SigmaT[0] > 0.0 || this->SigmaT[1] > 0.0 || this->SigmaT[2] > 0.0;
}

double Medium::MaximumSigmaT() const
{
  return std::max({ this->SigmaT[0], this->SigmaT[1], this->SigmaT[2] });
}

//------------------------------------------------------------------------------
Medium DescribeMedium(const double sigmaS[3], const double sigmaA[3], int phase, double g)
{
  Medium medium;
  for (int c = 0; c < 3; ++c)
  {
    medium.SigmaS[c] = sigmaS[c];
    medium.SigmaT[c] = sigmaS[c] + sigmaA[c];
  }
  medium.Phase = phase;
  medium.Anisotropy = g;
  return medium;
}

//------------------------------------------------------------------------------
void NoiseShifts(const double velocity1[2],
  const double velocity2[2],
  double time,
  double shifts[4])
{
  auto wrap = [](double value) { return value - std::floor(value); };
  shifts[0] = wrap(velocity1[0] * time);
  shifts[1] = wrap(velocity1[1] * time);
  shifts[2] = wrap(velocity2[0] * time + 0.37);
  shifts[3] = wrap(velocity2[1] * time + 0.61);
}

//------------------------------------------------------------------------------
glm::dvec3 TriplanarWeights(const glm::dvec3& d)
{
  const glm::dvec3 d2 = d * d;
  const glm::dvec3 d4 = d2 * d2;
  const double sum = d4.x + d4.y + d4.z;
  return sum > 0.0 ? d4 / sum : glm::dvec3(1.0 / 3.0);
}
}
