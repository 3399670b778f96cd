/**
 * @file   vtkLightShaftReferenceInput.h
 * @brief  What the float64 reference integrates besides the renderer's scene, as plain data
 *         (private, not installed): the lights, the medium, the cookie, the shadow casters'
 *         bounds, and where asked the last frame's shadow map. The pass fills it
 *         (vtkLightShaftPass::Internals::DescribeForReference): the reference never reads the
 *         pass.
 */
#ifndef vtkLightShaftReferenceInput_h
#define vtkLightShaftReferenceInput_h

#include <functional> // For the shadow map's read-back
#include <vector>     // For the lights

class vtkImageData;
class vtkLight;
class vtkLightShaftMedium;
class vtkMatrix4x4;
class vtkTexture;

struct vtkLightShaftReferenceInput
{
  /// The lights given (none: the renderer's, chosen as vtkLightShaftModel::FindLights does).
  std::vector<vtkLight*> Lights;
  /// The medium (coefficients, phase function, noise, density field).
  vtkLightShaftMedium* Medium = nullptr;
  /// The cookie (nullptr: none).
  vtkTexture* Cookie = nullptr;
  /// The shadow casters' bounds where they are given (distributed rendering: every process's).
  bool CasterBoundsGiven = false;
  double CasterBounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  /**
   * The last frame's shadow map of `light` (SHADOW_MAP visibility): its depths, its world to
   * light clip matrix, the light depth range and the lookup's bias; false when no map of that
   * light is at hand. Unset: none is.
   */
  std::function<bool(vtkLight* light,
    vtkImageData* depths,
    vtkMatrix4x4* worldToLightClip,
    double depthRange[2],
    double& bias)>
    LastShadowMap;
};

#endif
