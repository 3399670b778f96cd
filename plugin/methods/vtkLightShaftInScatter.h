/**
 * @file   vtkLightShaftInScatter.h
 * @brief  The in-scattered radiance of a frame's lights, for vtkLightShaftPass (private, not
 *         installed).
 */

#ifndef vtkLightShaftInScatter_h
#define vtkLightShaftInScatter_h

#include "vtkLightShaftAnalyticMethod.h"    // For a method held
#include "vtkLightShaftEpipolarMethod.h"    // For a method held
#include "vtkLightShaftInScatterTarget.h"   // For the target held
#include "vtkLightShaftLightVolumeMethod.h" // For a method held
#include "vtkLightShaftPostProcess.h"       // For the post chain held
#include "vtkLightShaftRadialBlurMethod.h"  // For a method held
#include "vtkLightShaftRayMarchMethod.h"    // For a method held
#include "vtkLightShaftSlabDrawer.h"        // For the drawer held
#include "vtkLightShaftSlicesMethod.h"      // For a method held
#include "vtkLightShaftTranslucentLayers.h" // For the camera leg's layers held

#include <vector> // For the translucent props

class vtkProp;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftInScatter
 * @brief   Computes L_in, the in-scattered radiance, for each of the frame's lights with the
 *          method chosen for it, adds the lights up, and post-processes the sum.
 *
 * Lights whose method adds into the target's accumulation buffer (SLICES with float
 * accumulation, RAY_MARCH without interleaving, ANALYTIC) add up there directly; the others
 * (8-bit SLICES, interleaved RAY_MARCH, RADIAL_BLUR) compute into a cleared buffer and their
 * result is added into a sum. With one light nothing is copied.
 */
class vtkLightShaftInScatter
{
public:
  vtkLightShaftInScatter();
  ~vtkLightShaftInScatter();

  /// The method for the frame's current light (AUTOMATIC resolved; see
  /// vtkLightShaftPass::SetMethod). Where it gives way to another (or ANALYTIC ignores
  /// possible shadows) the reason goes into the light's statistics, and, for a method the user
  /// named, into one warning.
  int ChooseMethod(vtkLightShaftFrame& frame);
  /// Whether `method` renders a medium from data (the others give way to RAY_MARCH).
  static bool RendersField(int method);
  /// Start the frame: the depth the shafts read, the camera leg's translucent layers
  /// (frame.CameraLayers), no light added.
  void Begin(vtkLightShaftFrame& frame);
  /// The frame's visible props with translucent surfaces: the camera leg's layers are peeled
  /// from them.
  static std::vector<vtkProp*> TranslucentProps(const vtkLightShaftFrame& frame);

  /**
   * Add the in-scatter of the frame's current light computed with `method`. Records what it
   * did in the frame's statistics; nothing when the light lights nothing in view.
   */
  void Add(vtkLightShaftFrame& frame, int method);

  /// The lights' L_in summed, at the target's (reduced) resolution (zeros when no light added
  /// any), and whether any did.
  vtkTextureObject* Sum(vtkLightShaftFrame& frame, bool& computed);
  /// Sum's L_in post-processed, at full resolution.
  vtkTextureObject* PostProcess(vtkLightShaftFrame& frame, vtkTextureObject* lights);

  /// The feature variant and fragment source of the slab program readied last.
  const vtkLightShaftMethod* GetShaderMethod() const { return this->ShaderMethod; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftInScatter(const vtkLightShaftInScatter&) = delete;
  void operator=(const vtkLightShaftInScatter&) = delete;

  vtkLightShaftMethod* GetMethod(int method);
  void ClearTarget(vtkLightShaftFrame& frame, vtkLightShaftMethod* method);

  vtkLightShaftInScatterTarget Target;
  vtkLightShaftSlabDrawer Slabs;
  vtkLightShaftSlicesMethod Slices{ this->Slabs };
  vtkLightShaftRayMarchMethod RayMarch{ this->Slabs };
  vtkLightShaftAnalyticMethod Analytic{ this->Slabs };
  vtkLightShaftRadialBlurMethod RadialBlur{ this->Analytic };
  vtkLightShaftEpipolarMethod Epipolar{ this->Slabs };
  vtkLightShaftLightVolumeMethod LightVolume{ this->Slabs };
  vtkLightShaftPostProcess Post;
  vtkLightShaftTranslucentLayers CameraLayers;

  const vtkLightShaftMethod* ShaderMethod = nullptr;
  bool TargetCleared = false; ///< the accumulation buffer holds this frame's direct lights
  bool TargetHolds = false;   ///< some light added into it
  /// The last light's result when its method did not add into the target (not yet summed).
  vtkTextureObject* Pending = nullptr;
  bool WarnedAnalyticShadows = false;
  bool WarnedLightVolumeFeatures = false;
  bool WarnedFieldMethod = false;
};

#endif
