/**
 * @file   vtkLightShaftReferenceScene.h
 * @brief  vtkLightShaftReference's scene: surfaces and visibility per kind of light, exact or
 *         from the pass's shadow map (private, not installed).
 */

#ifndef vtkLightShaftReferenceScene_h
#define vtkLightShaftReferenceScene_h

#include "vtkLightShaftReferenceIntegrator.h"   // For Vec
#include "vtkLightShaftReferenceTriangleTree.h" // For the surfaces' triangles
#include "vtkNew.h"                             // For the shadow map's copies

#include <array>   // For the blockers' corners
#include <memory>  // For the pool's tracers
#include <mutex>   // For the pool
#include <utility> // For the camera leg's crossings
#include <vector>  // For the occluders and crossings

class vtkActor;
class vtkImageData;
class vtkLight;
struct vtkLightShaftReferenceInput;
class vtkMatrix4x4;
class vtkPolyData;
class vtkRenderer;

/**
 * @class   vtkLightShaftReferenceScene
 * @brief   The polygonal props of a renderer in world coordinates (their triangles in two
 *          bounding-volume hierarchies, opaque and translucent), for the reference's surfaces and
 * exact shadows; or the pass's last shadow map of one light, looked up as the pass looks it up.
 *
 * The light's transmittance to a point x, over the segment from x to the light (for a
 * directional light, back along its direction to its plane: geometry before the plane casts
 * nothing): 0 when an opaque actor's surface crosses it, else the product over each crossing
 * of a translucent actor's surface (opacity a in (0, 1), diffuse colour c: Diffuse times the
 * property's colour) of 1 - a (1 - c), per channel. The camera's rays end at the first opaque
 * surface (translucent ones do not stop them, as in the pass); what lies behind each crossing
 * of a translucent surface reaches the camera dimmed by 1 - a, as VTK blends it
 * (CameraCrossings). With the shadow map, the light's transmittance is 0 or 1 (translucent
 * actors left out).
 *
 * Queries go through a Tracer, one per thread (from a TracerPool), which holds the thread's
 * scratch; the hierarchies are shared, read-only. (They replaced one vtkModifiedBSPTree per
 * actor and tracer: VTK's cell-by-cell tests took most of the reference's time.)
 */
class vtkLightShaftReferenceScene
{
public:
  using Vec = vtkLightShaftReferenceIntegrator::Vec;

  vtkLightShaftReferenceScene();
  ~vtkLightShaftReferenceScene();

  /// Capture `renderer`'s visible, opaque actors with polygonal input.
  void Capture(vtkRenderer* renderer);

  /**
   * The polygonal pieces of `actor`'s mapper input, without cells left out: the input itself
   * when it is a vtkPolyData, or the leaves of a composite dataset (ParaView's representations
   * draw one; block visibility and per-block colours are not read). `polygonal` says whether
   * every piece is a vtkPolyData (false: the input, or a leaf, is another kind of data; true
   * for a mapper without input, which draws nothing).
   */
  static std::vector<vtkPolyData*> Surfaces(vtkActor* actor, bool& polygonal);

  /**
   * Decide visibility with the `input`'s last shadow map of `light`, whose model is `model`
   * (nearest texel, the pass's bias), instead of the exact rays: a spot's perspective map
   * (relative bias) or a directional light's orthographic one (linear depth, absolute bias).
   * False when that light had no shadow map in the last frame (and for a point light: its cube
   * map is not read back).
   */
  bool UseShadowMap(const vtkLightShaftReferenceInput& input,
    vtkLight* light,
    const vtkLightShaftReferenceIntegrator::Model& model);

  /**
   * The scene's queries for one thread.
   */
  class Tracer
  {
  public:
    explicit Tracer(const vtkLightShaftReferenceScene& scene);
    ~Tracer();

    /// The nearest hit of an opaque surface by the segment from -> to, as a fraction of it;
    /// false when none.
    bool FirstHit(const Vec& from, const Vec& to, double& nearest);
    /**
     * The camera leg: where the segment from -> to crosses translucent surfaces (fractions of
     * it, in order) and the fraction 1 - a of what lies behind that VTK's blending keeps at
     * each.
     */
    std::vector<std::pair<double, double>> CameraCrossings(const Vec& from, const Vec& to);
    /// The light's transmittance to x (see the class description).
    vtkLightShaftReferenceIntegrator::RGB Transmittance(const Vec& x,
      const vtkLightShaftReferenceIntegrator::Model& light);
    /**
     * Where the light's visibility changes along origin + t dir between tFrom and tTo, where
     * it differs (vtkLightShaftReferenceIntegrator::Transition): the end of the shadow volumes of
     * the triangles that shadow one end, clipped to the ray, checked a hair beyond and taken
     * further (and the rest halved) while others go on shadowing it. Exact visibility of opaque
     * surfaces only: false with translucent ones or the shadow map (and where a triangle's volume
     * is degenerate).
     */
    bool Transition(const vtkLightShaftReferenceIntegrator::Model& light,
      const Vec& origin,
      const Vec& dir,
      double tFrom,
      double tTo,
      double& t);

  private:
    const vtkLightShaftReferenceScene& Scene;
    /// The segment from x to the light (back to a directional light's plane), shortened at
    /// both ends by a hair; false when there is none (x on or before the plane).
    static bool ToLight(const Vec& x,
      const vtkLightShaftReferenceIntegrator::Model& light,
      Vec& from,
      Vec& to);
    /// Whether an opaque surface shadows x.
    bool Shadowed(const Vec& x, const vtkLightShaftReferenceIntegrator::Model& light);
    /// The interval of t where the triangles that shadow x shadow origin + t dir (their
    /// shadow volumes' union, which holds x); false when one is degenerate.
    bool ShadowOf(const Vec& x,
      const vtkLightShaftReferenceIntegrator::Model& light,
      const Vec& origin,
      const Vec& dir,
      double& first,
      double& last);
    /// The product of the translucent surfaces' transmittance over their crossings by the
    /// segment from -> to.
    vtkLightShaftReferenceIntegrator::RGB Crossings(const Vec& from, const Vec& to);

    std::vector<std::pair<double, int>> Hits; ///< scratch: the translucent crossings
    std::vector<std::array<Vec, 3>> Blockers; ///< scratch: the triangles shadowing a point
  };

  /**
   * Tracers for the threads of one vtkSMPTools::For: a chunk takes one (made when none is
   * free) and gives it back, so that there are as many as chunks run at once and each is used
   * by one thread at a time. (Not vtkSMPThreadLocal: GCC 14 warns, wrongly, about the
   * std::vector<bool> its sequential backend resizes, -Wstringop-overflow.)
   */
  class TracerPool
  {
  public:
    explicit TracerPool(const vtkLightShaftReferenceScene& scene);
    ~TracerPool();
    std::unique_ptr<Tracer> Take();
    void Give(std::unique_ptr<Tracer> tracer);

  private:
    const vtkLightShaftReferenceScene& Scene;
    std::mutex Mutex;
    std::vector<std::unique_ptr<Tracer>> Free;
  };

private:
  vtkLightShaftReferenceScene(const vtkLightShaftReferenceScene&) = delete;
  void operator=(const vtkLightShaftReferenceScene&) = delete;

  bool ShadowMapVisible(const Vec& x, const vtkLightShaftReferenceIntegrator::Model& light) const;
  /// The triangles of `polydata`, placed by `actor`'s matrix, into `tree` as surface `owner`.
  static void AddTriangles(vtkPolyData* polydata,
    vtkActor* actor,
    int owner,
    vtkLightShaftReferenceTriangleTree& tree);

  struct Occluder
  {
    vtkLightShaftReferenceIntegrator::RGB Transmittance{}; ///< per crossing, when translucent
    double Kept = 0.0; ///< what VTK's blending keeps of what lies behind it: 1 - opacity
  };
  std::vector<Occluder> Occluders; ///< per actor, indexed by its triangles' owner
  vtkLightShaftReferenceTriangleTree Opaque;
  vtkLightShaftReferenceTriangleTree Translucent;

  // The shadow map, when visibility comes from it.
  bool ShadowMap = false;
  vtkNew<vtkImageData> ShadowDepths;
  vtkNew<vtkMatrix4x4> WorldToLightClip;
  int ShadowSize = 0;
  const float* ShadowTexels = nullptr;
  double LightNear = 0.0;
  double LightFar = 0.0;
  double ShadowBias = 0.0;
};

#endif
