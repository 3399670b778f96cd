/**
 * @file   vtkLightShaftLightVolumeMethod.h
 * @brief  LIGHT_VOLUME: the shadowed in-scatter from the crossings of a mesh of the shadow
 *         map's shadow volume (private, not installed).
 */

#ifndef vtkLightShaftLightVolumeMethod_h
#define vtkLightShaftLightVolumeMethod_h

#include "vtkLightShaftGeometrySlabs.h" // For LitVolume and SlabFootprint
#include "vtkLightShaftMethod.h"        // For the base class
#include "vtkLightShaftResources.h"     // For the owned texture
#include "vtkSmartPointer.h"            // For the framebuffer, vertex array and indices held

#include <vector> // For the footprints

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLVertexArrayObject;
class vtkLightShaftSlabDrawer;

/**
 * @class   vtkLightShaftLightVolumeMethod
 * @brief   LIGHT_VOLUME (after Billeter, Sintorn and Assarsson, HPG 2010): no steps. The part
 *          of the light's volume in shadow, behind the shadow map's casters, is a closed mesh
 *          built from the map on the GPU (a grid of LightVolumeResolution^2 cells per map or
 *          cube face, side walls and a far cap); it is drawn from the camera, and each crossing
 *          adds (leaving) or subtracts (entering) the closed-form unshadowed in-scatter from the
 *          pixel's lit interval's start to the crossing. A resolve subtracts that shadowed part
 *          from the unshadowed integral. A pixel costs one integral per crossing in front of
 *          its surface, whatever the shadows' depth complexity along it, and no step count.
 *
 * Exact with respect to the mesh: the map's depths at the cells' centres, interpolated across
 * cells (a caster's silhouette is a slope one cell wide). The crossings behind the surface
 * count only whether the surface is in shadow, in alpha, an integer, so that their large equal
 * terms do not cancel in the float sum (vtkLightShaftLightVolumeFS). Cookie and noise are not
 * in closed form: the pass uses RAY_MARCH for a light that has them, with one warning.
 */
class vtkLightShaftLightVolumeMethod : public vtkLightShaftMethod
{
public:
  explicit vtkLightShaftLightVolumeMethod(vtkLightShaftSlabDrawer& drawer);
  ~vtkLightShaftLightVolumeMethod() override;

  const char* GetName() const override { return "light-volume"; }
  vtkTextureObject* Render(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkLightShaftInScatterTarget& target) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// The shadow volume's crossings (stage 0) into Crossings, cleared first; false when the
  /// program does not compile.
  bool DrawCrossings(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkTextureObject* shadowMap,
    const vtkLightShaftShaders::Variant& variant,
    vtkLightShaftInScatterTarget& target);
  /// The cells across a mesh of `faces` faces this frame affords (CellsWithinAllowance).
  int CellsWithinAllowance(vtkLightShaftFrame& frame, int faces);
  /// The uniforms of the mesh and its crossings: camera, light, medium, map and far cap.
  void SetMeshUniforms(vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit,
    vtkShaderProgram* program,
    vtkTextureObject* shadowMap,
    vtkTextureObject* depth,
    int texels);
  /// Draw the mesh of each of the map's faces (six for a point light's cube) with `program`.
  void DrawMesh(vtkLightShaftFrame& frame, vtkShaderProgram* program, bool point, int texels);
  /// The grid's triangle indices for `cells` cells across, uploaded when `cells` changes.
  void UploadGrid(int cells);
  /// The light depth of the far cap: beyond every point of the lit volume and every caster.
  static double FarCapDepth(const vtkLightShaftFrame& frame,
    const vtkLightShaftGeometry::LitVolume& lit);

  vtkLightShaftSlabDrawer& Drawer;
  std::vector<vtkLightShaftGeometry::SlabFootprint> Footprints;
  vtkLightShaftShaders::Program CrossingProgram;
  vtkLightShaftResources::OwnedTexture Crossings;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VertexArray;
  vtkSmartPointer<vtkOpenGLBufferObject> Indices;
  int GridCells = 0;
  int IndexCount = 0;
  bool WarnedAllowance = false;
  bool WarnedCubeAllowance = false;
};

#endif
