/**
 * @file   vtkLightShaftLights.h
 * @brief  vtkLightShaftPass's lights (private, not installed): the lights given to the pass,
 *         the choice each frame, and each used light's own state (shadow map, timer, what the
 *         last frame did for it).
 */

#ifndef vtkLightShaftLights_h
#define vtkLightShaftLights_h

#include "vtkLightShaftFieldTableTexture.h" // For the per-light light leg through a field
#include "vtkLightShaftShadowMap.h"         // For the per-light shadow map
#include "vtkOpenGLRenderTimer.h"           // For the per-light timer
#include "vtkSmartPointer.h"                // For the given lights
#include "vtkWeakPointer.h"                 // For the used lights

#include <memory>  // For the per-light states
#include <string>  // For the shader variants, the unusable values
#include <utility> // For the unusable lights' pairs
#include <vector>  // For the light lists

class vtkLight;
class vtkObject;
class vtkRenderer;
class vtkWindow;

/**
 * One used light's state, kept from frame to frame while the light is used: its shadow map
 * (reused while nothing that decides it changes) and the timer of its in-scatter.
 */
struct vtkLightShaftLightState
{
  vtkLightShaftLightState();
  ~vtkLightShaftLightState();

  vtkWeakPointer<vtkLight> Light;
  vtkLightShaftShadowMap ShadowMap;
  vtkLightShaftFieldTableTexture FieldShadow; ///< the light leg through a medium from data
  /// The same at the resolution a target error or a still view's refinement chose.
  vtkLightShaftFieldTableTexture RefinedFieldShadow;
  vtkLightShaftFieldTableTexture VolumeShadow; ///< the light leg through the scene's vtkVolume
  vtkOpenGLRenderTimer Timer;
};

/**
 * @class   vtkLightShaftLights
 * @brief   The lights that scatter: the given list (SetLight, AddLight, ...) and the choice of
 *          each frame (vtkLightShaftModel::FindLights, one warning while there is none), and
 *          each used light's state.
 */
class vtkLightShaftLights
{
public:
  vtkLightShaftLights();
  ~vtkLightShaftLights();

  ///@{
  /// The given lights; each returns whether the list changed.
  bool Set(vtkLight* light);
  bool Add(vtkLight* light);
  bool Remove(vtkLight* light);
  bool RemoveAll();
  int GetNumberOfGiven() const;
  vtkLight* GetGiven(int index) const;
  ///@}

  /**
   * This frame's lights (see vtkLightShaftModel::FindLights); with none, one warning from
   * `owner` until there is one again or the given lights change.
   */
  std::vector<vtkLight*> Choose(vtkObject* owner, vtkRenderer* renderer);

  /// The state of `light` (made on first use). States of lights not used by the frame are
  /// freed by KeepOnly.
  vtkLightShaftLightState& StateOf(vtkLight* light);
  /// Free the states (and GL objects) of the lights not in `used`.
  void KeepOnly(const std::vector<vtkLight*>& used, vtkWindow* window);

  /// The state whose shadow map is being handed to ShadowMapRenderedEvent observers.
  vtkLightShaftLightState* GetEventState();

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// Remove from `lights` those with a value they cannot be used with (warned once); whether
  /// any was removed.
  bool LeaveOutUnusable(vtkObject* owner, std::vector<vtkLight*>& lights);

  vtkLightShaftLights(const vtkLightShaftLights&) = delete;
  void operator=(const vtkLightShaftLights&) = delete;

  std::vector<vtkSmartPointer<vtkLight>> Given;
  std::vector<std::unique_ptr<vtkLightShaftLightState>> States;
  bool WarnedNoLight = false;
  /// The lights left out for a value they cannot be used with, and that value's description
  /// (warned once until it changes).
  std::vector<std::pair<vtkWeakPointer<vtkLight>, std::string>> Unusable;
};

#endif
