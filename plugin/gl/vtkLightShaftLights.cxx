#include "vtkLightShaftLights.h"

#include "vtkLightShaftModel.h"

#include "vtkLight.h"
#include "vtkObject.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkLightShaftLightState::vtkLightShaftLightState() = default;
vtkLightShaftLightState::~vtkLightShaftLightState() = default;

vtkLightShaftLights::vtkLightShaftLights() = default;
vtkLightShaftLights::~vtkLightShaftLights() = default;

//------------------------------------------------------------------------------
bool vtkLightShaftLights::Set(vtkLight* light)
{
  if (!light)
  {
    return this->RemoveAll();
  }
  if (this->Given.size() == 1 && this->Given[0] == light)
  {
    return false;
  }
  this->Given.assign(1, light);
  this->WarnedNoLight = false;
  return true;
}

bool vtkLightShaftLights::Add(vtkLight* light)
{
  if (!light || std::find(this->Given.begin(), this->Given.end(), light) != this->Given.end())
  {
    return false;
  }
  this->Given.emplace_back(light);
  this->WarnedNoLight = false;
  return true;
}

bool vtkLightShaftLights::Remove(vtkLight* light)
{
  auto found = std::find(this->Given.begin(), this->Given.end(), light);
  if (found == this->Given.end())
  {
    return false;
  }
  this->Given.erase(found);
  this->WarnedNoLight = false;
  return true;
}

bool vtkLightShaftLights::RemoveAll()
{
  if (this->Given.empty())
  {
    return false;
  }
  this->Given.clear();
  this->WarnedNoLight = false;
  return true;
}

int vtkLightShaftLights::GetNumberOfGiven() const
{
  return static_cast<int>(this->Given.size());
}

vtkLight* vtkLightShaftLights::GetGiven(int index) const
{
  return index >= 0 && index < this->GetNumberOfGiven() ? this->Given[index].Get() : nullptr;
}

//------------------------------------------------------------------------------
std::vector<vtkLight*> vtkLightShaftLights::Choose(vtkObject* owner, vtkRenderer* renderer)
{
  std::vector<vtkLight*> given;
  for (const auto& light : this->Given)
  {
    given.push_back(light);
  }
  std::vector<vtkLight*> lights = vtkLightShaftModel::FindLights(given, renderer);
  const bool leftOut = this->LeaveOutUnusable(owner, lights);
  if (!lights.empty())
  {
    this->WarnedNoLight = false;
  }
  else if (!this->WarnedNoLight && !leftOut)
  {
    if (!given.empty())
    {
      vtkWarningWithObjectMacro(owner,
        "The light(s) given to the pass are switched off: rendering the scene without shafts.");
    }
    else
    {
      vtkWarningWithObjectMacro(owner,
        "No spot or point light in the renderer (a switched-on positional light; directional "
        "lights scatter only when given with SetLight or AddLight): rendering the scene "
        "without shafts.");
    }
    this->WarnedNoLight = true;
  }
  return lights;
}

//------------------------------------------------------------------------------
// Junk that VTK's vtkLight takes (a NaN exponent, colour or attenuation, a transform with NaN,
// no direction) would fill the beam with NaN: such a light is left out of the frame, with one
// warning naming it and its value, not repeated until the value changes.
bool vtkLightShaftLights::LeaveOutUnusable(vtkObject* owner, std::vector<vtkLight*>& lights)
{
  bool leftOut = false;
  std::vector<std::pair<vtkWeakPointer<vtkLight>, std::string>> unusable;
  for (auto it = lights.begin(); it != lights.end();)
  {
    const std::string value = vtkLightShaftModel::UnusableLightValue(*it);
    if (value.empty())
    {
      ++it;
      continue;
    }
    const bool warned = std::any_of(this->Unusable.begin(),
      this->Unusable.end(),
      [&](const std::pair<vtkWeakPointer<vtkLight>, std::string>& entry)
      { return entry.first == *it && entry.second == value; });
    if (!warned)
    {
      vtkWarningWithObjectMacro(
        owner, "Light " << *it << " is left out of the shafts: " << value << ".");
    }
    unusable.emplace_back(*it, value);
    it = lights.erase(it);
    leftOut = true;
  }
  this->Unusable = std::move(unusable);
  return leftOut;
}

//------------------------------------------------------------------------------
vtkLightShaftLightState& vtkLightShaftLights::StateOf(vtkLight* light)
{
  for (auto& state : this->States)
  {
    if (state->Light == light)
    {
      return *state;
    }
  }
  this->States.push_back(std::unique_ptr<vtkLightShaftLightState>(new vtkLightShaftLightState));
  this->States.back()->Light = light;
  return *this->States.back();
}

void vtkLightShaftLights::KeepOnly(const std::vector<vtkLight*>& used, vtkWindow* window)
{
  for (auto it = this->States.begin(); it != this->States.end();)
  {
    vtkLight* light = (*it)->Light;
    if (light && std::find(used.begin(), used.end(), light) != used.end())
    {
      ++it;
      continue;
    }
    (*it)->ShadowMap.ReleaseGraphicsResources(window);
    (*it)->FieldShadow.ReleaseGraphicsResources(window);
    (*it)->RefinedFieldShadow.ReleaseGraphicsResources(window);
    (*it)->VolumeShadow.ReleaseGraphicsResources(window);
    (*it)->Timer.ReleaseGraphicsResources();
    it = this->States.erase(it);
  }
}

vtkLightShaftLightState* vtkLightShaftLights::GetEventState()
{
  for (auto& state : this->States)
  {
    if (state->ShadowMap.GetEventTexture())
    {
      return state.get();
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkLightShaftLights::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& state : this->States)
  {
    state->ShadowMap.ReleaseGraphicsResources(window);
    state->FieldShadow.ReleaseGraphicsResources(window);
    state->RefinedFieldShadow.ReleaseGraphicsResources(window);
    state->VolumeShadow.ReleaseGraphicsResources(window);
    state->Timer.ReleaseGraphicsResources();
  }
}
