/**
 * @file   vtkLightShaftSlabDrawer.h
 * @brief  Draws the slabs of vtkLightShaftPass's methods (private, not installed).
 */

#ifndef vtkLightShaftSlabDrawer_h
#define vtkLightShaftSlabDrawer_h

#include "vtkLightShaftGeometrySlabs.h" // For LitVolume and SlabFootprint
#include "vtkSmartPointer.h"            // For the vertex array and buffer held

#include <vector> // For the footprints and vertices

class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftSlabDrawer
 * @brief   Draws view-aligned slabs with a method's slab program: each slab's screen footprint
 *          (or lattice) at its near view depth, so that the depth test drops it where it starts
 *          behind the scene surface, added into the bound in-scatter target.
 *
 * Every method draws slabs: SLICES many, RAY_MARCH and ANALYTIC one spanning the lit depth
 * range. The drawer sets the uniforms all slab shaders share (view ray, slab depths, light and
 * medium, shadow map, cookie, noise) and builds and draws the triangles in batches of about
 * SlabBatchVertices, so that the vertex memory stays bounded and no single draw holds the GPU
 * for the whole frame; before the next batch the driver finishes this one (drivers that queue
 * the whole frame's triangles, such as llvmpipe, would otherwise hold them all: measured
 * 0.9 GiB instead of 0.2 GiB at 2^21 lattice cells).
 */
class vtkLightShaftSlabDrawer
{
public:
  /// Slab vertices built and drawn in one batch (about 6 MiB of vertex data).
  static constexpr size_t SlabBatchVertices = 6 * 65536;

  /// What to draw, and with what.
  struct Slabs
  {
    const std::vector<vtkLightShaftGeometry::SlabFootprint>* Footprints = nullptr;
    int Lattice = 0;           ///< lattice resolution per slab (0: the footprint itself)
    double Start = 0.0;        ///< view depth where slab 0 starts
    double End = 0.0;          ///< view depth where the last slab ends
    double Thickness = 0.0;    ///< of a slab, in view depth
    int LastSlab = 0;          ///< index of the last slab drawn
    double LatticeShift = 0.0; ///< -0.5 with jitter: the pixels' slabs straddle the nominal one
    vtkTextureObject* Depth = nullptr;     ///< the depth the shafts read
    vtkTextureObject* ShadowMap = nullptr; ///< nullptr: no shadow lookup
    double ShadowBias = 0.0;
    /// The target's rows drawn (image pieces: frame.ComputeRows); nullptr: all of them.
    const std::vector<vtkLightShaftGeometry::RowBlock>* Rows = nullptr;

    /// `count` slabs of equal thickness over the lit volume's depth range, drawn as
    /// `footprints`, reading the depth `depth`.
    static Slabs Over(const vtkLightShaftGeometry::LitVolume& lit,
      const std::vector<vtkLightShaftGeometry::SlabFootprint>& footprints,
      vtkTextureObject* depth,
      int count = 1);
  };

  vtkLightShaftSlabDrawer();
  ~vtkLightShaftSlabDrawer();

  /**
   * Draw `slabs` with `program` (ready, with the method's own uniforms set) into the bound
   * target, added to what it holds, in `slabs.Rows` only when set (one scissor per block; the
   * fragments counted into the frame's statistics). Records the batches there too.
   */
  void Draw(vtkLightShaftFrame& frame, vtkShaderProgram* program, const Slabs& slabs);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkLightShaftSlabDrawer(const vtkLightShaftSlabDrawer&) = delete;
  void operator=(const vtkLightShaftSlabDrawer&) = delete;

  void SetUniforms(vtkLightShaftFrame& frame, vtkShaderProgram* program, const Slabs& slabs);
  void DrawBatch(vtkShaderProgram* program, bool more, vtkLightShaftFrame& frame);
  /// The batch's triangles, once per block of `Rows` (scissored) or once.
  void DrawRows(int vertices, const vtkLightShaftFrame& frame);

  const std::vector<vtkLightShaftGeometry::RowBlock>* Rows = nullptr; ///< of the Draw under way

  vtkSmartPointer<vtkOpenGLVertexArrayObject> VertexArray;
  vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  vtkShaderProgram* VertexArrayProgram = nullptr;
  std::vector<float> Vertices;
};

#endif
