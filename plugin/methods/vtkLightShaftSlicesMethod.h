/**
 * @file   vtkLightShaftSlicesMethod.h
 * @brief  SLICES: view-aligned slabs, shadow-mapped (private, not installed).
 */

#ifndef vtkLightShaftSlicesMethod_h
#define vtkLightShaftSlicesMethod_h

#include "vtkLightShaftGeometrySlabs.h" // For LitVolume and SlabFootprint
#include "vtkLightShaftMethod.h"        // For the base class
#include "vtkLightShaftResources.h"     // For the 8-bit resolve's texture and pass
#include "vtkSmartPointer.h"            // For the framebuffer held

#include <vector> // For the footprints

class vtkLightShaftSlabDrawer;
class vtkOpenGLFramebufferObject;

/**
 * @class   vtkLightShaftSlicesMethod
 * @brief   SLICES (Mitchell, GDC 2004; Dobashi et al.): NumberOfSlices view-aligned slabs over
 *          the lit depth range (or, with AutomaticSliceCount, slabs of thickness far /
 *          MaximumNumberOfSlices), each fragment integrating its slab of the pixel's ray, with
 *          one shadow-map lookup per slab; optional 4x4 jitter of the slab boundaries, a lattice
 *          for the smooth factors (Chen, Li and Wang; at most
 *          vtkLightShaftGeometry::LatticeCellBudget cells per frame, one warning when lowered),
 *          and the GDC 2004 talk's 8-bit four-channel accumulation.
 */
class vtkLightShaftSlicesMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftSlicesMethod(vtkLightShaftSlabDrawer& drawer);
  ~vtkLightShaftSlicesMethod() override;

  const char* GetName() const override { return "slices"; }
  vtkLightShaftResources::TextureKind AccumulationKind(const vtkLightShaftParameters& parameters,
    int& buffers) const override;
  bool AddsIntoTarget(const vtkLightShaftFrame& frame) const override;
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  int CountSlices(const vtkLightShaftFrame& frame, const vtkLightShaftGeometry::LitVolume& lit);
  int LatticeWithinBudget(vtkLightShaftFrame& frame, int slabs);
  vtkTextureObject* ResolveEightBit(vtkLightShaftFrame& frame,
    vtkLightShaftInScatterTarget& target);

  vtkLightShaftSlabDrawer& Drawer;
  std::vector<vtkLightShaftGeometry::SlabFootprint> Footprints;
  bool WarnedLatticeBudget = false;
  vtkLightShaftResources::FullScreenPass Resolve;
  vtkLightShaftResources::OwnedTexture Resolved;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};

#endif
