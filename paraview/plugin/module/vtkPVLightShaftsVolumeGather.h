/**
 * @file   vtkPVLightShaftsVolumeGather.h
 * @brief  A distributed light-shaft view's volume: the pieces the processes render, gathered
 *         into the whole image the pass models (private to the ParaView plugin's module).
 */

#ifndef vtkPVLightShaftsVolumeGather_h
#define vtkPVLightShaftsVolumeGather_h

#include "vtkNew.h"         // For the whole volume and its image, held
#include "vtkType.h"        // For vtkMTimeType
#include "vtkWeakPointer.h" // For the local volume last seen

class vtkImageData;
class vtkMatrix4x4;
class vtkMultiProcessController;
class vtkPVLightShaftsFieldGather;
class vtkVolume;

/**
 * @class   vtkPVLightShaftsVolumeGather
 * @brief   Under MPI each process's vtkVolume draws its piece of the image (ParaView splits an
 *          image by extents), while the shafts need the whole of it on every process: the
 *          light leg crosses every piece, and each process computes rows whose view rays do.
 *
 * Update is collective (every process calls it in the same render): each process gives the
 * volume it renders (the renderer's first visible one, nullptr: none), and the scalars its
 * mapper renders (first component) are gathered into the whole image on every process, with
 * vtkPVLightShaftsFieldGather (float32; past `resolution` samples along an axis, each piece
 * resampled onto the bounded grid). The result is a volume that draws nothing, with the local
 * volume's property and placement and the whole image as its input; the local volume's
 * vtkLightShaftPass::MODELLED_PROP key names it, so that the pass models it in the local
 * volume's place (and it is the medium with MediumFromVolume). The image is gathered again only
 * when some process's volume, mapper or input changed (one small reduction a render otherwise).
 */
class vtkPVLightShaftsVolumeGather
{
public:
  vtkPVLightShaftsVolumeGather();
  ~vtkPVLightShaftsVolumeGather();

  /// The whole volume modelled in `local`'s place (nullptr: `local` is nullptr, or no process's
  /// volume has scalars to render).
  vtkVolume* Update(vtkVolume* local, vtkMultiProcessController* controller, int resolution);

  /// The bytes this process sent and received in its last gather (0 while it is kept).
  double GetBytes() const { return this->Bytes; }

private:
  vtkPVLightShaftsVolumeGather(const vtkPVLightShaftsVolumeGather&) = delete;
  void operator=(const vtkPVLightShaftsVolumeGather&) = delete;

  bool Gather(vtkVolume* local, vtkMultiProcessController* controller, int resolution);
  void Place(vtkVolume* local);

  vtkNew<vtkVolume> Whole;
  vtkNew<vtkImageData> Image;
  vtkNew<vtkMatrix4x4> Matrix;
  vtkNew<vtkPVLightShaftsFieldGather> Gatherer;
  vtkWeakPointer<vtkVolume> Local;
  const void* LocalMapper = nullptr; ///< (compared only: ParaView may swap a volume's mapper)
  vtkMTimeType LocalTime = 0;
  int Resolution = 0;
  bool Valid = false;
  double Bytes = 0.0;
};

#endif
