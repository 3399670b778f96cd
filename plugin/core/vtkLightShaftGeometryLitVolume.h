/**
 * @file   vtkLightShaftGeometryLitVolume.h
 * @brief  The part of the view volume a light reaches, without GL (private, not installed;
 *         part of the namespace vtkLightShaftGeometry, vtkLightShaftGeometry.h).
 */

#ifndef vtkLightShaftGeometryLitVolume_h
#define vtkLightShaftGeometryLitVolume_h

#include "vtkLightShaftGeometry.h"         // For LightFrame and CameraFrame
#include "vtkLightShaftGeometryClipping.h" // For ConvexPolytope

namespace vtkLightShaftGeometry
{
/**
 * The part of the view volume the light reaches (view coordinates): inside a spot's bounding
 * pyramid, beyond a directional light's plane, all of it for a point light; and the view-depth
 * range it spans.
 */
struct LitVolume
{
  ConvexPolytope Polytope;
  double Nearest = 0.0;
  double Deepest = 0.0;

  bool Empty() const { return !(this->Deepest > this->Nearest); }
};

LitVolume ComputeLitVolume(const LightFrame& light, const CameraFrame& camera);
}

#endif
