/**
 * @file   vtkLightShaftAnalyticMethod.h
 * @brief  ANALYTIC: the unshadowed integral per pixel (private, not installed).
 */

#ifndef vtkLightShaftAnalyticMethod_h
#define vtkLightShaftAnalyticMethod_h

#include "vtkLightShaftGeometrySlabs.h" // For LitVolume and SlabFootprint
#include "vtkLightShaftMethod.h"        // For the base class

#include <vector> // For the footprint

class vtkLightShaftSlabDrawer;

/**
 * @class   vtkLightShaftAnalyticMethod
 * @brief   ANALYTIC: one slab over the lit depth range; nothing occludes, so each pixel
 *          integrates its whole lit interval in pieces fine enough for float precision (A(r) in
 *          closed form, the smooth factors by Gauss-Legendre, pieces across which the
 *          extinction stays below ~0.5). Ignores shadows and keeps the cookie and the noise.
 *          The alpha channel holds the light distance at the lit interval's middle, which the
 *          radial blur compares its occluders with.
 */
class vtkLightShaftAnalyticMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftAnalyticMethod(vtkLightShaftSlabDrawer& drawer);
  ~vtkLightShaftAnalyticMethod() override;

  const char* GetName() const override { return "analytic"; }
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// The unshadowed integral, its shader variant described as `methodName`'s (RADIAL_BLUR
  /// starts from it).
  vtkTextureObject* RenderUnshadowed(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target,
    const char* methodName);

private:
  vtkLightShaftSlabDrawer& Drawer;
  std::vector<vtkLightShaftGeometry::SlabFootprint> Footprints;
};

#endif
