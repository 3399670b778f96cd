/**
 * @file   vtkPVLightShaftsTranslucentGather.h
 * @brief  A distributed light-shaft view's translucent surfaces: each process's piece of them
 *         gathered into the whole surface the pass peels (private to the ParaView plugin's
 *         module).
 */

#ifndef vtkPVLightShaftsTranslucentGather_h
#define vtkPVLightShaftsTranslucentGather_h

#include "vtkSmartPointer.h" // For the whole surfaces, held
#include "vtkType.h"         // For vtkMTimeType

#include <vector> // For the surfaces

class vtkActor;
class vtkMultiProcessController;
class vtkRenderer;

/**
 * @class   vtkPVLightShaftsTranslucentGather
 * @brief   Under MPI each process's actor draws its piece of a translucent surface, and IceT
 *          composites them in order; the shafts peel translucent surfaces (the light leg's
 *          tint, the camera leg's dimming) from the props a process holds, so that a surface
 *          held by another process would tint and dim nothing there.
 *
 * Update is collective (every process calls it in the same render): the renderer's visible
 * actors whose property's opacity is below 1 (the same on every process: ParaView's properties
 * are), in order, each gathered into an actor of the whole surface on every process (its
 * polygons, as vtkPolyData, with the local actor's property, placement and colouring), which
 * the local actor's vtkLightShaftPass::MODELLED_PROP key names. A surface is gathered again
 * only when some process's piece changed (one small reduction a render otherwise). The whole
 * surface is held on every process: translucent surfaces are expected to be small beside the
 * data.
 */
class vtkPVLightShaftsTranslucentGather
{
public:
  vtkPVLightShaftsTranslucentGather();
  ~vtkPVLightShaftsTranslucentGather();

  /// Gather the translucent actors of `renderer` over `controller`'s processes.
  void Update(vtkRenderer* renderer, vtkMultiProcessController* controller);

  /// The bytes this process sent and received in its last gather (0 while they are kept).
  double GetBytes() const { return this->Bytes; }

private:
  vtkPVLightShaftsTranslucentGather(const vtkPVLightShaftsTranslucentGather&) = delete;
  void operator=(const vtkPVLightShaftsTranslucentGather&) = delete;

  struct Surface
  {
    vtkSmartPointer<vtkActor> Whole; ///< draws nothing: in no renderer
    const void* Local = nullptr;     ///< the actor it stands for (compared only)
    const void* Mapper = nullptr;    ///< its mapper (ParaView swaps them with the level of detail)
    vtkMTimeType Time = 0;           ///< its mapper's and input's MTime when gathered
  };
  void Gather(Surface& surface, vtkActor* local, vtkMultiProcessController* controller);
  static void Place(Surface& surface, vtkActor* local);

  std::vector<Surface> Surfaces;
  double Bytes = 0.0;
};

#endif
