/**
 * @class   vtkLightShaftFieldTableTexture
 * @brief   The light leg through a medium from data: a light's vtkLightShaftFieldTable,
 *          uploaded as a 3D texture and built again when the field or the light moves
 *          (private, not installed).
 *
 * The extinction of the light that reaches a sample of a view ray is exp(-sigma_t * tau), tau
 * the optical depth from the light to the sample. Marching that leg for every sample costs a
 * loop per step; instead, as Frostbite's and Unreal's volumetric shadows do, tau of the field is
 * tabulated once per light in the light's frame (vtkLightShaftFieldTable: its layout and
 * values), and each sample looks it up. The texture holds the integral of rho alone:
 * MediumDensityScale and the background (a straight length) are applied in the shader, so
 * changing them rebuilds nothing.
 */
#ifndef vtkLightShaftFieldTableTexture_h
#define vtkLightShaftFieldTableTexture_h

#include "vtkLightShaftFieldTable.h" // For the table's layout
#include "vtkLightShaftModel.h"      // For the light
#include "vtkSmartPointer.h"         // For the texture held
#include "vtkType.h"                 // For vtkMTimeType

#include <glm/glm.hpp> // For the light's position and axis

class vtkLightShaftDensityField;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkLightShaftFieldTableTexture
{
public:
  vtkLightShaftFieldTableTexture();
  ~vtkLightShaftFieldTableTexture();

  using Layout = vtkLightShaftFieldTable::Layout;

  /**
   * The texture for `light` through `field` (uploaded at `fieldTime`), built again when either
   * changed or `resolution` did.
   */
  vtkTextureObject* Ready(vtkOpenGLRenderWindow* window,
    const vtkLightShaftDensityField& field,
    vtkMTimeType fieldTime,
    const vtkLightShaftModel::Light& light,
    int resolution);

  const Layout& GetLayout() const { return this->Current; }

  /// The last build's time (ms; 0: the texture was reused) and the texture's size (bytes).
  double GetBuildTime() const { return this->BuildTime; }
  std::size_t GetBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftFieldTableTexture(const vtkLightShaftFieldTableTexture&) = delete;
  void operator=(const vtkLightShaftFieldTableTexture&) = delete;

  vtkSmartPointer<vtkTextureObject> Texture;
  Layout Current;
  // What the texture was built for.
  vtkMTimeType FieldTime = 0;
  glm::dvec3 Position{ 0.0 };
  glm::dvec3 Axis{ 0.0 };
  int Kind = -1;
  int Resolution = 0;
  double BuildTime = 0.0;
};

#endif
