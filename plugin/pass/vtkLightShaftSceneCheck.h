/**
 * @file   vtkLightShaftSceneCheck.h
 * @brief  What of the scene the shafts cannot use, said once (private, not installed).
 */

#ifndef vtkLightShaftSceneCheck_h
#define vtkLightShaftSceneCheck_h

#include "vtkWeakPointer.h" // For the props warned about

#include <string>  // For the values warned about
#include <utility> // For the (prop, value) pairs
#include <vector>  // For the props warned about

class vtkObject;
class vtkProp;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftSceneCheck
 * @brief   Junk that VTK takes and the shafts cannot use, found in the frame's camera and props,
 *          each warned about once (naming the object and its value) until its value changes.
 *
 * A camera that cannot be used (vtkLightShaftGeometry::CameraFrame::UnusableValue) leaves the
 * frame without shafts. A visible prop whose transform holds NaN (VTK gives it empty bounds) or
 * whose bounds are not finite casts no shadow (vtkLightShaftGeometry leaves it out of the
 * casters); it still renders as VTK renders it. (NaN points do not reach the bounds, which VTK
 * computes without them: their triangles are dropped by the rasteriser.) The
 * lights' values are checked where the lights are chosen (vtkLightShaftLights), the cookie's
 * and noise's images where they are read (vtkLightShaftLightTextures).
 */
class vtkLightShaftSceneCheck
{
public:
  vtkLightShaftSceneCheck();
  ~vtkLightShaftSceneCheck();

  /// Whether the frame's camera can be used (else one warning from `owner`).
  bool CheckCamera(vtkObject* owner, const vtkLightShaftFrame& frame);
  /// Warn (once each) about the frame's visible props whose bounds are not finite.
  void CheckProps(vtkObject* owner, const vtkLightShaftFrame& frame);

private:
  /// What makes a visible prop unusable as a caster (empty: nothing).
  static std::string UnusableValue(vtkProp* prop);

  vtkLightShaftSceneCheck(const vtkLightShaftSceneCheck&) = delete;
  void operator=(const vtkLightShaftSceneCheck&) = delete;

  std::string Camera; ///< the camera's value last warned about (empty: usable)
  std::vector<std::pair<vtkWeakPointer<vtkProp>, std::string>> Props;
};

#endif
