#include "vtkLightShaftSceneCheck.h"

#include "vtkLightShaftFrame.h"

#include "vtkMatrix4x4.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

//------------------------------------------------------------------------------
vtkLightShaftSceneCheck::vtkLightShaftSceneCheck() = default;
vtkLightShaftSceneCheck::~vtkLightShaftSceneCheck() = default;

//------------------------------------------------------------------------------
bool vtkLightShaftSceneCheck::CheckCamera(vtkObject* owner, const vtkLightShaftFrame& frame)
{
  const std::string value = frame.Camera.UnusableValue(frame.Renderer->GetActiveCamera());
  if (!value.empty() && value != this->Camera)
  {
    vtkWarningWithObjectMacro(owner,
      "The camera cannot be used for the shafts: " << value
                                                   << ". Rendering the scene without shafts.");
  }
  this->Camera = value;
  return value.empty();
}

//------------------------------------------------------------------------------
// A visible prop's transform with NaN (VTK then gives it empty bounds, and it casts nothing),
// or bounds that are not finite. (NaN points do not reach the bounds: VTK's ranges skip NaN.)
std::string vtkLightShaftSceneCheck::UnusableValue(vtkProp* prop)
{
  if (!prop->GetVisibility())
  {
    return std::string();
  }
  std::ostringstream text;
  if (auto* prop3D = vtkProp3D::SafeDownCast(prop))
  {
    const double* matrix = prop3D->GetMatrix()->GetData();
    const double* bad =
      std::find_if(matrix, matrix + 16, [](double v) { return !std::isfinite(v); });
    if (bad != matrix + 16)
    {
      text << "its transform matrix holds " << *bad << " (at element " << (bad - matrix) << ")";
      return text.str();
    }
  }
  const double* bounds = prop->GetBounds();
  if (bounds && !std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v); }))
  {
    text << "its bounds are (" << bounds[0] << ", " << bounds[1] << ", " << bounds[2] << ", "
         << bounds[3] << ", " << bounds[4] << ", " << bounds[5] << ")";
  }
  return text.str();
}

//------------------------------------------------------------------------------
void vtkLightShaftSceneCheck::CheckProps(vtkObject* owner, const vtkLightShaftFrame& frame)
{
  std::vector<std::pair<vtkWeakPointer<vtkProp>, std::string>> unusable;
  vtkPropCollection* props = frame.Renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const std::string value = UnusableValue(prop);
    if (value.empty())
    {
      continue;
    }
    const bool warned = std::any_of(this->Props.begin(),
      this->Props.end(),
      [&](const std::pair<vtkWeakPointer<vtkProp>, std::string>& entry)
      { return entry.first == prop && entry.second == value; });
    if (!warned)
    {
      vtkWarningWithObjectMacro(owner,
        "Prop " << prop << " (" << prop->GetClassName()
                << ") casts no shadow in the shafts: " << value << ".");
    }
    unusable.emplace_back(prop, value);
  }
  this->Props = std::move(unusable);
}
