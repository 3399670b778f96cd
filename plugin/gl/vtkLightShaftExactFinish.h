/**
 * @file   vtkLightShaftExactFinish.h
 * @brief  A still view's exact finish: the float64 reference in tiles, in the background
 *         (private, not installed).
 */

#ifndef vtkLightShaftExactFinish_h
#define vtkLightShaftExactFinish_h

#include "vtkLightShaftResources.h" // For the owned textures and the full-screen pass
#include "vtkSmartPointer.h"        // For the framebuffer held

#include <memory> // For the work shared with the threads
#include <string> // For why a scene is not finished
#include <thread> // For the workers
#include <vector> // For the workers and the tiles

struct vtkLightShaftReferenceInput;
class vtkOpenGLFramebufferObject;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;
struct vtkLightShaftFrame;

/**
 * @class   vtkLightShaftExactFinish
 * @brief   While the view is still, worker threads integrate the exact in-scatter
 *          (vtkLightShaftReferenceJob, float64) tile by tile, brightest tiles of the picture
 *          first; each frame shows the tiles finished so far in place of the estimate, and
 *          once all are, the exact picture alone.
 *
 * The workers run at the idle scheduling class where the system has one (Linux's SCHED_IDLE):
 * they take only the processor time rendering leaves, so the frames keep their pace. The
 * scene is captured when the finish starts (copies: the workers never read VTK's objects);
 * Stop() (any change of the view) cancels the workers within milliseconds (they watch the
 * request inside each pixel's integration) and forgets what they computed. A scene the reference
 * cannot model (a visible prop other than a polygonal vtkActor or a vtkVolume) is not finished:
 * Start() records why.
 */
class vtkLightShaftExactFinish
{
public:
  vtkLightShaftExactFinish();
  ~vtkLightShaftExactFinish();

  /// What the finish is doing for the current view.
  enum class State
  {
    Off,         ///< not started (the view moves, or the finish is not asked for)
    Running,     ///< tiles are being integrated
    Complete,    ///< every tile is exact
    Unsupported, ///< the scene has a prop the reference cannot model (GetProblem says which)
    Failed       ///< the reference could not capture the scene (GetProblem says why)
  };

  /**
   * Start the finish of the frame's still view of the `input`'s lights and medium, the tiles
   * ordered by the brightness of `estimate` (the picture shown, full resolution; read back
   * once). Does nothing unless Off.
   */
  void Start(vtkLightShaftFrame& frame,
    const vtkLightShaftReferenceInput& input,
    vtkTextureObject* estimate);
  /**
   * Cancel the workers and forget what they computed: the next Start() begins again. The
   * workers watch the request inside each pixel's integration, so this returns within
   * milliseconds however slow the pixels in flight are. Returns how long it waited for them
   * (seconds; 0 when none ran).
   */
  double Stop();
  /// Pixels finished so far whose integration the reference's bound on evaluations ended
  /// (vtkLightShaftReferenceJob::Options::MaximumEvaluations).
  long long GetExhaustedPixels() const;
  /// Hold the workers (within a row of pixels; a second at most) while a frame renders, or let
  /// them go on.
  void Hold(bool held);
  /// Off: become Unsupported when the reference cannot model `renderer`'s scene.
  void Check(vtkRenderer* renderer);

  State GetState() const { return this->Current; }
  /// Whether the finish supersedes the estimates: running or complete.
  bool IsActive() const
  {
    return this->Current == State::Running || this->Current == State::Complete;
  }
  /// Why the scene is not finished (Unsupported or Failed), else empty.
  const std::string& GetProblem() const { return this->Problem; }

  /**
   * Upload the tiles finished since the last frame and return the picture to show: `estimate`
   * with the finished tiles replaced, or the exact picture alone once complete (`estimate`
   * itself when no tile is finished). Moves to Complete when the last tile is shown.
   * `estimateChanged`: false when `estimate` holds what it held at the last Apply() (the
   * picture reused), which then costs the new tiles' upload only.
   */
  vtkTextureObject* Apply(vtkLightShaftFrame& frame,
    vtkTextureObject* estimate,
    bool estimateChanged);
  /// The share of the picture's pixels shown exact by the last Apply(), in [0, 1].
  double GetFinishedFraction() const;
  /// Tiles in the view, and those shown exact.
  int GetNumberOfTiles() const { return static_cast<int>(this->Tiles.size()); }
  int GetFinishedTiles() const { return this->Shown; }

  /// Stop, and free the textures and programs.
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Why `renderer`'s visible props cannot be integrated exactly (empty: they can).
  static std::string Unmodelled(vtkRenderer* renderer);

private:
  vtkLightShaftExactFinish(const vtkLightShaftExactFinish&) = delete;
  void operator=(const vtkLightShaftExactFinish&) = delete;

  struct Tile
  {
    int X, Y, W, H;
  };
  struct Work;
  void OrderTiles(vtkLightShaftFrame& frame, vtkTextureObject* estimate);
  void Upload(vtkLightShaftFrame& frame, vtkTextureObject* shown);

  State Current = State::Off;
  std::string Problem;
  std::vector<Tile> Tiles; ///< in the order the workers take them
  std::shared_ptr<Work> Shared;
  std::vector<std::thread> Workers;
  int Shown = 0;
  int Size[2] = { 0, 0 };
  long long FinishedPixels = 0;
  long long Exhausted = 0;                    ///< GetExhaustedPixels once the workers are gone
  vtkLightShaftResources::OwnedTexture Exact; ///< rgb: the exact in-scatter, a: 1 where exact
  vtkLightShaftResources::OwnedTexture Mixed; ///< the estimate with the finished tiles
  vtkTextureObject* MixedEstimate = nullptr;  ///< the estimate Mixed was made of
  bool MixedValid = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkLightShaftResources::FullScreenPass Mix;
  std::vector<int> Finished; ///< the tiles the last Upload() took
};

#endif
