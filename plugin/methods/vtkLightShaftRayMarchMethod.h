/**
 * @file   vtkLightShaftRayMarchMethod.h
 * @brief  RAY_MARCH: a per-pixel march with interleaved sampling (private, not installed).
 */

#ifndef vtkLightShaftRayMarchMethod_h
#define vtkLightShaftRayMarchMethod_h

#include "vtkLightShaftGeometrySlabs.h"   // For LitVolume and SlabFootprint
#include "vtkLightShaftMethod.h"          // For the base class
#include "vtkLightShaftSeparableFilter.h" // For the gather

#include <vector> // For the footprint and the rows

class vtkLightShaftSlabDrawer;

/**
 * @class   vtkLightShaftRayMarchMethod
 * @brief   RAY_MARCH (Toth & Umenhoffer 2009): one slab over the lit depth range; each pixel
 *          marches NumberOfSteps segments of its lit interval, shorter towards the light when
 *          A falls off, with one shadow-map lookup per segment. Interleaved sampling: the
 *          pixels of an InterleaveSize^2 block shift their step boundaries by different
 *          fractions of a step, and two separable, depth-aware gather passes average the block
 *          back.
 */
class vtkLightShaftRayMarchMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftRayMarchMethod(vtkLightShaftSlabDrawer& drawer);
  ~vtkLightShaftRayMarchMethod() override;

  const char* GetName() const override { return "ray-march"; }
  bool AddsIntoTarget(const vtkLightShaftFrame& frame) const override;
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// Whether the interleaved samples are gathered (not in refinement's later estimates).
  static bool Gathers(const vtkLightShaftFrame& frame);

  vtkLightShaftSlabDrawer& Drawer;
  std::vector<vtkLightShaftGeometry::SlabFootprint> Footprints;
  std::vector<vtkLightShaftGeometry::RowBlock> GatherRows; ///< an image piece's, grown
  vtkLightShaftSeparableFilter Gather;
};

#endif
