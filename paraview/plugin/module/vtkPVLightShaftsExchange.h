/**
 * @file   vtkPVLightShaftsExchange.h
 * @brief  What the processes of a distributed light-shafts view exchange each frame (private to
 *         the ParaView plugin's module).
 */

#ifndef vtkPVLightShaftsExchange_h
#define vtkPVLightShaftsExchange_h

#include "vtkNew.h" // For the passes held

#include <vector> // For the exchanges' buffers

class vtkCameraPass;
class vtkLightShaftPass;
class vtkMultiProcessController;
class vtkOpaquePass;
class vtkOpenGLRenderWindow;
class vtkRenderer;

/**
 * @class   vtkPVLightShaftsExchange
 * @brief   The view's side of vtkLightShaftPass's distributed-rendering events, over the
 *          processes of a vtkMultiProcessController, with the bytes each frame moved.
 *
 * Every process renders the same frame in lock step, so each exchange is one collective call
 * that every process makes:
 * - AgreeOnReuse (ShadowMapReuseEvent): a map is kept only where every process's is unchanged;
 * - AgreeOnTimes (FrameTimedEvent): a budget's cost model learns the slowest process's times,
 *   so that every process chooses the same setting for the next frame;
 * - CombineShadowMaps (ShadowMapRenderedEvent): the minimum of the processes' depth maps, so
 *   that every process's map holds every process's occluders;
 * - ShareSceneDepth (SceneDepthReadyEvent): process 0, which holds IceT's composited image and
 *   depth, gives its depth to the others, so that they compute their rows of the in-scatter on
 *   the composited scene; where IceT composites in order (colour only) every process renders its
 *   opaque props' depth again, and the minimum over the processes is every process's;
 * - GatherInScatter (InScatterPieceEvent): each process's rows (vtkLightShaftGeometry's
 *   ImagePieceRows) gathered into process 0's in-scatter, which it filters and composites.
 */
class vtkPVLightShaftsExchange
{
public:
  vtkPVLightShaftsExchange();
  ~vtkPVLightShaftsExchange();

  /// ShadowMapReuseEvent: `reuse` (1: this process's map is unchanged) becomes 1 only where
  /// every process's is (no controller: left as it is).
  void AgreeOnReuse(int* reuse, vtkMultiProcessController* controller);
  /// FrameTimedEvent: `seconds` (the shafts' and the frame's) become the slowest process's.
  void AgreeOnTimes(double* seconds, vtkMultiProcessController* controller);
  void CombineShadowMaps(vtkLightShaftPass* pass, vtkMultiProcessController* controller);
  /// SceneDepthReadyEvent; `opaque` (IceT's ordered compositing): each process's depth is its
  /// renderer's opaque props' rendered again, in `window` (nullptr: the pass's scene depth).
  void ShareSceneDepth(vtkLightShaftPass* pass,
    vtkMultiProcessController* controller,
    vtkRenderer* opaque,
    vtkOpenGLRenderWindow* window);
  void GatherInScatter(vtkLightShaftPass* pass,
    vtkMultiProcessController* controller,
    vtkOpenGLRenderWindow* window);

  /// Start counting a frame's bytes.
  void BeginFrame() { this->Bytes = 0.0; }
  /// The bytes this process sent and received in the frame's exchanges so far.
  double GetBytes() const { return this->Bytes; }

private:
  vtkPVLightShaftsExchange(const vtkPVLightShaftsExchange&) = delete;
  void operator=(const vtkPVLightShaftsExchange&) = delete;

  void RenderOpaqueDepth(vtkRenderer* renderer,
    vtkOpenGLRenderWindow* window,
    int width,
    int height);

  double Bytes = 0.0;
  vtkNew<vtkCameraPass> CameraPass;
  vtkNew<vtkOpaquePass> OpaquePass;
  // The exchanges' host buffers, kept from frame to frame (their capacity reused).
  std::vector<float> Local;
  std::vector<float> Combined;
};

#endif
