/**
 * @class   vtkPVLightShaftsFieldGather
 * @brief   The light-shaft view's medium from data on several processes: each process updates
 *          only its piece of the source's image, and the pieces of the density array are
 *          gathered into the whole image on every process.
 *
 * The input is the view's MediumDensity source. Each process asks it for piece rank of size (its
 * extent; one ghost level when cell data is resampled: the pieces of point data share their
 * boundary planes), so the source computes and holds only that part; the output has the input's
 * whole extent and rho alone (the first component of vtkLightShaftDensityField's array: the named
 * point or cell array, else the scalars) as float32, as the pass keeps it, combined with a MAX
 * reduction over the processes: every sample comes from a process that computed it (the points two
 * pieces share are equal there), a slab of planes at a time: a process holds its piece, the whole
 * grid and one slab of at most 2^20 samples (4 MiB). The pass then sees the serial image.
 * RequestData is collective: every process executes it in the same render (their pipelines are
 * the same).
 */

#ifndef vtkPVLightShaftsFieldGather_h
#define vtkPVLightShaftsFieldGather_h

#include "vtkImageAlgorithm.h"      // For the base class
#include "vtkPVLightShaftsModule.h" // For the export macro

#include <functional> // For the slabs' filling
#include <string>     // For the array's name

class vtkDataArray;
class vtkFloatArray;
class vtkMultiProcessController;

class VTKLIGHTSHAFTS_EXPORT vtkPVLightShaftsFieldGather : public vtkImageAlgorithm
{
public:
  static vtkPVLightShaftsFieldGather* New();
  vtkTypeMacro(vtkPVLightShaftsFieldGather, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The density array's name (empty: the scalars), as the medium's DensityArrayName. Default
   * is empty.
   */
  void SetArrayName(const char* name);
  const char* GetArrayName() const { return this->ArrayName.c_str(); }
  ///@}

  ///@{
  /**
   * The most samples per axis of the output (the medium's FieldResolution): a source with more
   * along an axis is resampled piece by piece onto the grid the pass would resample the whole
   * image to, so that no process holds the whole image at its resolution. Default is 2048.
   */
  void SetResolution(int resolution);
  int GetResolution() const { return this->Resolution; }
  ///@}

  ///@{
  /**
   * The processes that share the source (nullptr: the global controller). Default is nullptr.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  /**
   * The gather itself, collective (every process calls it in the same order): this process's
   * `piece` (nullptr or empty: none) of an image of extent `whole`, whose array (ArrayName, else
   * the scalars) is gathered into `output`, the whole image (or its grid, past Resolution). The
   * output's placement is the piece's (the caller places it where this process has none).
   */
  void GatherImage(vtkImageData* piece, const int whole[6], vtkImageData* output);

protected:
  vtkPVLightShaftsFieldGather();
  ~vtkPVLightShaftsFieldGather() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPVLightShaftsFieldGather(const vtkPVLightShaftsFieldGather&) = delete;
  void operator=(const vtkPVLightShaftsFieldGather&) = delete;

  // The planes of a grid of `counts` samples a slab at a time: `fill` writes this process's
  // samples of the planes [planes[0], planes[1]) into the slab, a MAX reduction gathers them.
  void ReduceSlabs(const vtkIdType counts[3],
    vtkFloatArray* gathered,
    const std::function<void(float*, const vtkIdType[2])>& fill);
  void GatherResampled(vtkImageData* input,
    vtkImageData* piece,
    vtkImageData* output,
    const int whole[6],
    bool cells);
  // Whether an image of extent `whole` is resampled: more samples (points, or cells) along an
  // axis than Resolution.
  bool Resampled(const int whole[6], bool cells) const;
  // Collective: whether any process's piece has the density array, and whether it is cell
  // data; `local`, this process's array (nullptr: none, or an empty piece).
  bool AgreeOnArray(vtkImageData* piece, vtkDataArray*& local, bool& cells);

  std::string ArrayName;
  vtkMultiProcessController* Controller = nullptr;
  int Resolution = 2048;
  // The last input's array was cell data: resampled, its pieces are asked for a ghost level.
  bool CellSamples = false;
};

#endif
