/**
 * @file   vtkLightShaftEpipolarMethod.h
 * @brief  EPIPOLAR: in-scatter marched along lines through the light's image and interpolated
 *         (private, not installed).
 */

#ifndef vtkLightShaftEpipolarMethod_h
#define vtkLightShaftEpipolarMethod_h

#include "vtkLightShaftEpipolarGeometry.h" // For the layout
#include "vtkLightShaftGeometrySlabs.h"    // For LitVolume and SlabFootprint
#include "vtkLightShaftMethod.h"           // For the base class
#include "vtkLightShaftResources.h"        // For the owned textures
#include "vtkLightShaftSlabDrawer.h"       // For the slabs drawn
#include "vtkSmartPointer.h"               // For the framebuffer held

#include <vector> // For the footprints and the lines' ends

class vtkOpenGLFramebufferObject;

/**
 * @class   vtkLightShaftEpipolarMethod
 * @brief   EPIPOLAR (Engelhardt and Dachsbacher 2010; Yusov 2013): the in-scatter changes
 *          smoothly along the screen's lines through the light's image except where the depth
 *          jumps, so it is marched (as RAY_MARCH marches a pixel, NumberOfSteps segments) at
 *          every EpipolarStep-th of EpipolarSamples samples on each of EpipolarLines lines,
 *          and at the samples where the depth breaks or the coarse in-scatter changes sharply;
 *          the other samples are interpolated along their line, and each pixel from the four
 *          samples around it on its two neighbouring lines whose surface is its own. A pixel
 *          with no such sample (a thin prop between lines), or within 1.5 pixels of a point or
 *          spot light's image, is marked and marched itself, behind a depth mask of the marks
 *          (llvmpipe shades every pixel of a draw through a branch none of them takes; only
 *          blocks the depth test rejects whole are skipped).
 *
 * Works for every light kind: the epipole is a spot or point light's image or a directional
 * light's vanishing point; lines are parallel when it lies at infinity (a parallel camera) and
 * arbitrary when it is undefined (the light at the eye). The layout is
 * vtkLightShaftEpipolarGeometry's, computed in double on the CPU; the lines' ends are uploaded.
 */
class vtkLightShaftEpipolarMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftEpipolarMethod(vtkLightShaftSlabDrawer& drawer);
  ~vtkLightShaftEpipolarMethod() override;

  const char* GetName() const override { return "epipolar"; }
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// The lines and samples per line the frame's layout has at most (the parameters, bounded by
  /// the in-scatter target's size).
  static void LinesAndSamples(const vtkLightShaftFrame& frame, int& lines, int& samples);
  /// The rays a frame marches at most: every sample of every line and every pixel.
  static long long MarchedRays(const vtkLightShaftFrame& frame);

private:
  void UploadEnds(vtkLightShaftFrame& frame, const vtkLightShaftEpipolarGeometry::Layout& layout);
  static void SetLayoutUniforms(vtkShaderProgram* program,
    const vtkLightShaftEpipolarGeometry::Layout& layout,
    int step);
  /// The program of stage `stage` (0 to 5) in `variant`, bound.
  vtkShaderProgram* ReadyStage(vtkLightShaftFrame& frame,
    int stage,
    const vtkLightShaftShaders::Variant& variant);
  /// MarkDepth: 1 where the unwarp marked a pixel in `marked` (to be marched), else 0.
  void MarkForMarch(vtkLightShaftFrame& frame, vtkTextureObject* marked);
  /// Draw a stage's program over the whole of `output`, cleared first.
  void DrawStage(vtkLightShaftFrame& frame,
    vtkShaderProgram* program,
    vtkTextureObject* output,
    const vtkLightShaftSlabDrawer::Slabs& slabs);

  vtkLightShaftSlabDrawer& Drawer;
  std::vector<vtkLightShaftGeometry::SlabFootprint> Footprints;
  std::vector<vtkLightShaftGeometry::SlabFootprint> WholeTexture;
  std::vector<float> EndTexels;
  vtkLightShaftShaders::Program StagePrograms[5]; ///< stages 0 to 4; the base's is the march
  vtkLightShaftResources::OwnedTexture Ends;
  vtkLightShaftResources::OwnedTexture Coordinates;
  vtkLightShaftResources::OwnedTexture Coarse;
  vtkLightShaftResources::OwnedTexture Refined;
  vtkLightShaftResources::OwnedTexture Fine;
  vtkLightShaftResources::OwnedTexture Marked;
  vtkLightShaftResources::OwnedTexture MarkDepth;
  vtkLightShaftResources::FullScreenPass Mark;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
};

#endif
