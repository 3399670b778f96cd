/**
 * @file   vtkLightShaftMethod.h
 * @brief  The common interface of vtkLightShaftPass's methods (private, not installed).
 */

#ifndef vtkLightShaftMethod_h
#define vtkLightShaftMethod_h

#include "vtkLightShaftGeometrySlabs.h" // For LitVolume and SlabFootprint
#include "vtkLightShaftResources.h"     // For TextureKind
#include "vtkLightShaftShaders.h"       // For the slab program

#include <string> // For the shader variant
#include <vector> // For the slab footprints

class vtkTextureObject;
class vtkWindow;
class vtkLightShaftInScatterTarget;
struct vtkLightShaftFrame;
struct vtkLightShaftParameters;

/**
 * @class   vtkLightShaftMethod
 * @brief   One way to compute the in-scattered radiance L_in of a frame (SLICES, RAY_MARCH,
 *          RADIAL_BLUR, ANALYTIC): the same model, light and medium, at the frame's reduced
 *          resolution, into the in-scatter target.
 *
 * A new method is a subclass in its own file, with its fragment shader in its own GLSL file
 * (sharing the integrand and segment chunks), added to the pass's list of methods.
 */
class vtkLightShaftMethod
{
public:
  virtual ~vtkLightShaftMethod() = default;

  /// The method's name, as vtkLightShaftPass::GetMethodName and the shader variant say it.
  virtual const char* GetName() const = 0;

  /**
   * The accumulation buffers the method adds into: their kind, and how many (`buffers`: 1, or 3
   * for the 8-bit mode). By default one float buffer of the precision asked for.
   */
  virtual vtkLightShaftResources::TextureKind AccumulationKind(
    const vtkLightShaftParameters& parameters,
    int& buffers) const;

  /**
   * Whether Render's result is the target's first accumulation buffer, added into without
   * clearing it: then several lights add up there directly; otherwise each light's result is
   * added into a sum. By default true.
   */
  virtual bool AddsIntoTarget(const vtkLightShaftFrame&) const { return true; }

  /**
   * Compute L_in over the lit volume `lit` into `target` (prepared: cleared and bound). Returns
   * the texture holding it (reduced resolution, RGB radiance; alpha as the method uses it) for
   * the post chain, or nullptr when nothing was drawn (the target then holds zeros).
   */
  virtual vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) = 0;

  virtual void ReleaseGraphicsResources(vtkWindow* window) = 0;

  /// The feature variant and fragment source of the slab program this method readied last.
  const std::string& GetShaderVariant() const { return this->Variant; }
  const std::string& GetShaderSource() const { return this->SlabProgram.GetFragmentSource(); }

protected:
  /// Ready the slab program of `variant` (the vertex shader is shared by every method),
  /// remembering its description for GetShaderVariant and this method as the frame's
  /// ShaderMethod; nullptr (and an error from the frame's owner) when it does not compile.
  vtkShaderProgram* ReadySlabProgram(vtkLightShaftFrame& frame,
    const char* fragment,
    const vtkLightShaftShaders::Variant& variant);
  /// The same for a method's other slab programs (`program`; its variant is not reported).
  static vtkShaderProgram* ReadySlabProgram(vtkLightShaftFrame& frame,
    vtkLightShaftShaders::Program& program,
    const char* fragment,
    const vtkLightShaftShaders::Variant& variant);

  /**
   * The set-up of a march over one slab (RAY_MARCH, EPIPOLAR): the lit volume's footprint into
   * `footprints` (false when it is empty: nothing to draw), the light's shadow map readied into
   * `shadowMap` (nullptr without casters), and the integrand variant with `define` (may be
   * nullptr) and the float accumulation.
   */
  bool PrepareMarch(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    const char* define,
    std::vector<vtkLightShaftGeometry::SlabFootprint>& footprints,
    vtkTextureObject*& shadowMap,
    vtkLightShaftShaders::Variant& variant) const;

  /**
   * `requested` steps or slabs per ray (the parameter `name`), or fewer when `rays` rays (by
   * default the frame's in-scatter pixels) would integrate more than this light's share of
   * vtkLightShaftGeometry::SegmentBudget segments with them (shared by the frame's radiating
   * lights): then one warning from the frame's owner, until it fits again.
   */
  int SamplesWithinBudget(vtkLightShaftFrame& frame,
    const char* name,
    int requested,
    long long rays = -1);

  /// Whether a reduction should be said now: `reduced` this frame and not the frame before
  /// (`warned` keeps that), so one warning until the request fits again.
  static bool SayReduction(bool reduced, bool& warned);

  /// " (shared by N lights)" when the frame's budgets are shared by N > 1 lights, else "".
  static std::string SharedBy(const vtkLightShaftFrame& frame);

  /// SamplesWithinBudget for the frame's NumberOfSteps (the setting's: a split setting's share
  /// integrates a frame.RefinementSplit-th of them), recorded in the frame's statistics (the
  /// fewest of its lights: the frame report's GetNumberOfSteps).
  int StepsWithinBudget(vtkLightShaftFrame& frame, long long rays = -1);

  /// " accumulate=float32" or " accumulate=float16": the description of a float accumulation.
  static const char* FloatAccumulation(const vtkLightShaftParameters& parameters);

  vtkLightShaftShaders::Program SlabProgram;
  std::string Variant;
  bool WarnedSegmentBudget = false;
};

#endif
