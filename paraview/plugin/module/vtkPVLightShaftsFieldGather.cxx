#include "vtkPVLightShaftsFieldGather.h"

#include "vtkLightShaftDensityField.h"

#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkPVLightShaftsFieldGather);

namespace
{
// The samples reduced at a time (whole planes; 4 MiB of float32).
constexpr vtkIdType SlabSamples = vtkIdType(1) << 20;

// Samples along each axis of an extent: points, or cells (at least one along a flat axis).
void Counts(const int extent[6], bool cells, vtkIdType counts[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const vtkIdType points = std::max(extent[2 * axis + 1] - extent[2 * axis] + 1, 0);
    counts[axis] = cells ? std::max<vtkIdType>(points - 1, points > 0 ? 1 : 0) : points;
  }
}

// Copy `piece`'s samples' first component (of extent `pieceExtent`) whose plane index k of the
// whole lies in [planes[0], planes[1]) into `slab`, those planes of `wholeExtent`'s samples, as
// float32.
void Place(vtkDataArray* piece,
  const int pieceExtent[6],
  float* slab,
  const int wholeExtent[6],
  bool cells,
  const vtkIdType planes[2])
{
  vtkIdType pieceCounts[3];
  vtkIdType wholeCounts[3];
  Counts(pieceExtent, cells, pieceCounts);
  Counts(wholeExtent, cells, wholeCounts);
  const vtkIdType offset[3] = { pieceExtent[0] - wholeExtent[0],
    pieceExtent[2] - wholeExtent[2],
    pieceExtent[4] - wholeExtent[4] };
  const vtkIdType kFirst = std::max<vtkIdType>(planes[0] - offset[2], 0);
  const vtkIdType kEnd = std::min<vtkIdType>(planes[1] - offset[2], pieceCounts[2]);
  for (vtkIdType k = kFirst; k < kEnd; ++k)
  {
    for (vtkIdType j = 0; j < pieceCounts[1]; ++j)
    {
      for (vtkIdType i = 0; i < pieceCounts[0]; ++i)
      {
        const vtkIdType from = i + pieceCounts[0] * (j + pieceCounts[1] * k);
        const vtkIdType to =
          (i + offset[0]) +
          wholeCounts[0] * ((j + offset[1]) + wholeCounts[1] * (k + offset[2] - planes[0]));
        slab[to] = static_cast<float>(piece->GetComponent(from, 0));
      }
    }
  }
}

// Grid plane `plane` of vtkLightShaftDensityField::Resampled(resolution) of the whole image
// (extent `whole`, `points` points per axis) from `piece`'s samples of `array` (the planes
// along z that the grid plane reads, copied), into `slab` where the piece holds them.
void ResamplePlane(vtkImageData* piece,
  vtkDataArray* array,
  bool cells,
  const int whole[6],
  const int points[3],
  int resolution,
  int plane,
  float* slab)
{
  int needed[2];
  vtkLightShaftDensityField::ResampledPlaneSamples(resolution, points, cells, plane, needed);
  const int* extent = piece->GetExtent();
  vtkIdType pieceCounts[3];
  Counts(extent, cells, pieceCounts);
  const int first = extent[4] - whole[4]; // the piece's first sample along z, in the whole's
  const int from = std::max(needed[0], first);
  const int to = std::min(needed[1], first + static_cast<int>(pieceCounts[2]) - 1);
  if (from > to)
  {
    return;
  }
  // Those planes of the piece as an image of their own (their samples' first component).
  vtkNew<vtkImageData> part;
  part->SetExtent(extent[0],
    extent[1],
    extent[2],
    extent[3],
    whole[4] + from,
    whole[4] + to + (cells && points[2] > 1 ? 1 : 0));
  const vtkIdType planeSamples = pieceCounts[0] * pieceCounts[1];
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(planeSamples * (to - from + 1));
  const vtkIdType start = planeSamples * (from - first);
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, static_cast<float>(array->GetComponent(start + i, 0)));
  }
  (cells ? static_cast<vtkDataSetAttributes*>(part->GetCellData())
         : static_cast<vtkDataSetAttributes*>(part->GetPointData()))
    ->SetScalars(values);
  vtkLightShaftDensityField field;
  if (!field.Read(part, "density").empty())
  {
    return;
  }
  const int offset[3] = { extent[0] - whole[0], extent[2] - whole[2], from };
  const int planes[2] = { plane, plane + 1 };
  field.ResamplePiece(resolution, offset, points, planes, slab);
}
}

//------------------------------------------------------------------------------
vtkPVLightShaftsFieldGather::vtkPVLightShaftsFieldGather() = default;

vtkPVLightShaftsFieldGather::~vtkPVLightShaftsFieldGather()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::SetArrayName(const char* name)
{
  const std::string given = name ? name : "";
  if (given != this->ArrayName)
  {
    this->ArrayName = given;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::SetController(vtkMultiProcessController* controller)
{
  vtkSetObjectBodyMacro(Controller, vtkMultiProcessController, controller);
}

vtkMultiProcessController* vtkPVLightShaftsFieldGather::GetController()
{
  return this->Controller ? this->Controller : vtkMultiProcessController::GetGlobalController();
}

//------------------------------------------------------------------------------
int vtkPVLightShaftsFieldGather::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  vtkMultiProcessController* controller = this->GetController();
  const int piece = controller ? controller->GetLocalProcessId() : 0;
  const int pieces = controller ? controller->GetNumberOfProcesses() : 1;
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), pieces);
  // A grid point between two pieces: for point data both hold the plane they share, so each grid
  // point lies between samples one of them holds. Cell data resampled to a coarser grid needs
  // the cells on both sides: one ghost level (learned from the last execution: RequestData
  // updates the source again the first time it finds cell data).
  int whole[6];
  in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
    this->CellSamples && this->Resampled(whole, true) ? 1 : 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVLightShaftsFieldGather::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int whole[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  vtkDataArray* local = nullptr;
  bool cells = false;
  const bool found = this->AgreeOnArray(input, local, cells);
  if (found && cells && !this->CellSamples && this->Resampled(whole, cells))
  {
    // Cell data, asked for without ghost cells: the source's pieces again with one ghost
    // level (every process, as each agreed on `cells`), and from now on.
    vtkInformation* request = inputVector[0]->GetInformationObject(0);
    int port = 0;
    vtkAlgorithm* source = this->GetInputAlgorithm(0, 0, port);
    vtkNew<vtkInformationVector> requests;
    requests->SetNumberOfInformationObjects(source->GetNumberOfOutputPorts());
    vtkInformation* ghosted = requests->GetInformationObject(port);
    ghosted->CopyEntry(request, vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    ghosted->CopyEntry(request, vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    ghosted->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 1);
    source->Update(port, requests);
    input = vtkImageData::GetData(inputVector[0]);
  }
  this->CellSamples = found && cells;
  this->GatherImage(input, whole, output);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkPVLightShaftsFieldGather::Resampled(const int whole[6], bool cells) const
{
  vtkIdType counts[3];
  Counts(whole, cells, counts);
  return counts[0] > this->Resolution || counts[1] > this->Resolution ||
         counts[2] > this->Resolution;
}

//------------------------------------------------------------------------------
bool vtkPVLightShaftsFieldGather::AgreeOnArray(vtkImageData* piece,
  vtkDataArray*& local,
  bool& cells)
{
  // (A process whose piece is empty has no array.)
  bool pieceCells = false;
  std::string why;
  local = (piece && piece->GetNumberOfPoints() > 0)
            ? vtkLightShaftDensityField::FindArray(piece, this->ArrayName.c_str(), pieceCells, why)
            : nullptr;
  int described[2] = { local ? 1 : -1, local ? int(pieceCells) : -1 };
  int agreed[2] = { described[0], described[1] };
  if (vtkMultiProcessController* controller = this->GetController())
  {
    controller->AllReduce(described, agreed, 2, vtkCommunicator::MAX_OP);
  }
  cells = agreed[1] == 1;
  return agreed[0] > 0;
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::GatherImage(vtkImageData* input,
  const int whole[6],
  vtkImageData* output)
{
  output->Initialize();
  output->SetExtent(whole[0], whole[1], whole[2], whole[3], whole[4], whole[5]);
  if (input)
  {
    output->SetOrigin(input->GetOrigin());
    output->SetSpacing(input->GetSpacing());
    output->SetDirectionMatrix(input->GetDirectionMatrix());
  }

  // This process's density array, and whether any process has it and where.
  vtkDataArray* local = nullptr;
  bool cells = false;
  if (!this->AgreeOnArray(input, local, cells))
  {
    return; // no process found it: the medium says which array is missing
  }
  if (this->Resampled(whole, cells))
  {
    this->GatherResampled(input, local ? input : nullptr, output, whole, cells);
    return;
  }
  vtkIdType counts[3];
  Counts(whole, cells, counts);
  const vtkIdType samples = counts[0] * counts[1] * counts[2];
  // rho (the first component) as float32, as the pass keeps its samples: every sample from a
  // process that computed it (the lowest float elsewhere; the largest wins). Reduced a slab of
  // planes at a time, so that a process holds its piece, the whole grid the pass reads, and
  // one slab of at most SlabSamples besides (not a second whole grid).
  vtkNew<vtkFloatArray> gathered;
  gathered->SetNumberOfTuples(samples);
  this->ReduceSlabs(counts,
    gathered,
    [&](float* slab, const vtkIdType planes[2])
    {
      if (local)
      {
        Place(local, input->GetExtent(), slab, whole, cells, planes);
      }
    });
  gathered->SetName(
    !this->ArrayName.empty() ? this->ArrayName.c_str() : (local ? local->GetName() : "density"));
  vtkDataSetAttributes* attributes = cells
                                       ? static_cast<vtkDataSetAttributes*>(output->GetCellData())
                                       : static_cast<vtkDataSetAttributes*>(output->GetPointData());
  attributes->SetScalars(gathered);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::ReduceSlabs(const vtkIdType counts[3],
  vtkFloatArray* gathered,
  const std::function<void(float*, const vtkIdType[2])>& fill)
{
  vtkMultiProcessController* controller = this->GetController();
  const vtkIdType plane = counts[0] * counts[1];
  const vtkIdType slabPlanes = std::max<vtkIdType>(SlabSamples / std::max<vtkIdType>(plane, 1), 1);
  std::vector<float> slab;
  for (vtkIdType first = 0; first < counts[2]; first += slabPlanes)
  {
    const vtkIdType planes[2] = { first, std::min(first + slabPlanes, counts[2]) };
    const vtkIdType length = plane * (planes[1] - planes[0]);
    slab.assign(static_cast<size_t>(length), -std::numeric_limits<float>::max());
    fill(slab.data(), planes);
    float* into = gathered->GetPointer(plane * planes[0]);
    if (controller)
    {
      controller->AllReduce(slab.data(), into, length, vtkCommunicator::MAX_OP);
    }
    else
    {
      std::copy(slab.begin(), slab.end(), into);
    }
  }
}

//------------------------------------------------------------------------------
// More samples along an axis than Resolution: each process resamples its piece onto the grid
// vtkLightShaftDensityField::Resampled makes of the whole image (the grid points whose
// neighbours it holds, computed as from the whole), and the grid is gathered; the output is
// the grid, as point data over the image's bounds.
void vtkPVLightShaftsFieldGather::GatherResampled(vtkImageData* input,
  vtkImageData* piece,
  vtkImageData* output,
  const int whole[6],
  bool cells)
{
  int points[3];
  int samples[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    points[axis] = whole[2 * axis + 1] - whole[2 * axis] + 1;
    samples[axis] = cells ? std::max(points[axis] - 1, 1) : points[axis];
  }
  int grid[3];
  double step[3];
  vtkLightShaftDensityField::ResampledGrid(points, samples, this->Resolution, grid, step);
  // The grid's placement: the whole image's first point, its spacing times the step.
  double origin[3];
  double spacing[3];
  vtkMatrix3x3* direction = input->GetDirectionMatrix();
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = input->GetOrigin()[r];
    spacing[r] = input->GetSpacing()[r] * step[r];
    for (int c = 0; c < 3; ++c)
    {
      origin[r] += direction->GetElement(r, c) * input->GetSpacing()[c] * whole[2 * c];
    }
  }
  output->SetExtent(0, grid[0] - 1, 0, grid[1] - 1, 0, grid[2] - 1);
  output->SetOrigin(origin);
  output->SetSpacing(spacing);
  // This process's samples, read the planes each grid plane needs at a time (a copy of the
  // whole piece as float32 would hold a quarter of the field again, at np 4).
  bool pieceCells = false;
  std::string why;
  vtkDataArray* array =
    (piece && piece->GetNumberOfPoints() > 0)
      ? vtkLightShaftDensityField::FindArray(piece, this->ArrayName.c_str(), pieceCells, why)
      : nullptr;
  const vtkIdType counts[3] = { grid[0], grid[1], grid[2] };
  vtkNew<vtkFloatArray> gathered;
  gathered->SetNumberOfTuples(counts[0] * counts[1] * counts[2]);
  this->ReduceSlabs(counts,
    gathered,
    [&](float* slab, const vtkIdType planes[2])
    {
      for (vtkIdType z = planes[0]; array && z < planes[1]; ++z)
      {
        ResamplePlane(piece,
          array,
          cells,
          whole,
          points,
          this->Resolution,
          static_cast<int>(z),
          slab + (z - planes[0]) * counts[0] * counts[1]);
      }
    });
  gathered->SetName(!this->ArrayName.empty() ? this->ArrayName.c_str() : "density");
  output->GetPointData()->SetScalars(gathered);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::SetResolution(int resolution)
{
  resolution = std::max(resolution, 2);
  if (resolution != this->Resolution)
  {
    this->Resolution = resolution;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
}
