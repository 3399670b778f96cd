#include "vtkLightShaftModel.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftModel
{
//------------------------------------------------------------------------------
bool IsSpotLight(vtkLight* light)
{
  return light->GetPositional() && light->GetConeAngle() < 90.0;
}

//------------------------------------------------------------------------------
vtkLight* FindLight(vtkLight* requested, vtkRenderer* renderer)
{
  if (requested)
  {
    return IsSpotLight(requested) ? requested : nullptr;
  }
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* candidate = lights->GetNextLight(it))
  {
    if (candidate->GetSwitch() && IsSpotLight(candidate))
    {
      return candidate;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
Light DescribeLight(vtkLight* light)
{
  Light model;
  const double* position = light->GetTransformedPosition();
  const double* focal = light->GetTransformedFocalPoint();
  model.Position = glm::dvec3(position[0], position[1], position[2]);
  const glm::dvec3 axis = glm::dvec3(focal[0], focal[1], focal[2]) - model.Position;
  model.Axis = glm::length(axis) > 0.0 ? glm::normalize(axis) : glm::dvec3(0.0, 0.0, -1.0);
  model.ConeHalfAngle = vtkMath::RadiansFromDegrees(light->GetConeAngle());
  model.Exponent = light->GetExponent();
  light->GetAttenuationValues(model.Attenuation);
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
}
