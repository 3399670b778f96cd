/**
 * @file   vtkLightShaftGeometryLights.h
 * @brief  Each light's frame, without GL (private, not installed): its casters among the
 *         scene's props and the cameras that render their depth (part of the namespace
 *         vtkLightShaftGeometry, vtkLightShaftGeometry.h).
 */

#ifndef vtkLightShaftGeometryLights_h
#define vtkLightShaftGeometryLights_h

#include "vtkLightShaftGeometry.h" // For LightFrame and CameraFrame

class vtkPropCollection;

namespace vtkLightShaftGeometry
{

/**
 * The light frame of `light` for `camera`: casters among `props` (visible props whose bounds
 * reach into the light's volume, and for a directional light whose shadow can fall in the
 * lit part of the view volume), and the cameras that render their depth. With `casterBounds`
 * (distributed rendering: every process's casters) the cameras' extent and depth range, and
 * whether shadows are possible, come from those bounds instead.
 */
LightFrame ComputeLightFrame(const vtkLightShaftModel::Light& light,
  const CameraFrame& camera,
  vtkPropCollection* props,
  const double* casterBounds);

/**
 * Shift the texel grid of `light`'s shadow cameras by (dx, dy) in their normalised device
 * coordinates (a texel of an N^2 map is 2 / N): progressive refinement's estimates render the
 * map shifted by parts of a texel, so that their mean smooths the map's staircase. Every
 * matrix that renders or looks up the map moves together; the cookie's square does not.
 */
void OffsetShadowCameras(LightFrame& light, double dx, double dy);

}

#endif
