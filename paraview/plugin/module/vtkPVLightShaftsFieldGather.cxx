#include "vtkPVLightShaftsFieldGather.h"

#include "vtkLightShaftDensityField.h"

#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <limits>

vtkStandardNewMacro(vtkPVLightShaftsFieldGather);

namespace
{
// Samples along each axis of an extent: points, or cells (at least one along a flat axis).
void Counts(const int extent[6], bool cells, vtkIdType counts[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const vtkIdType points = std::max(extent[2 * axis + 1] - extent[2 * axis] + 1, 0);
    counts[axis] = cells ? std::max<vtkIdType>(points - 1, points > 0 ? 1 : 0) : points;
  }
}

// Copy `piece`'s samples' first component (of extent `pieceExtent`) into `whole` (of extent
// `wholeExtent`), as float32.
void Place(vtkDataArray* piece,
  const int pieceExtent[6],
  vtkFloatArray* whole,
  const int wholeExtent[6],
  bool cells)
{
  vtkIdType pieceCounts[3];
  vtkIdType wholeCounts[3];
  Counts(pieceExtent, cells, pieceCounts);
  Counts(wholeExtent, cells, wholeCounts);
  const vtkIdType offset[3] = { pieceExtent[0] - wholeExtent[0],
    pieceExtent[2] - wholeExtent[2],
    pieceExtent[4] - wholeExtent[4] };
  for (vtkIdType k = 0; k < pieceCounts[2]; ++k)
  {
    for (vtkIdType j = 0; j < pieceCounts[1]; ++j)
    {
      for (vtkIdType i = 0; i < pieceCounts[0]; ++i)
      {
        const vtkIdType from = i + pieceCounts[0] * (j + pieceCounts[1] * k);
        const vtkIdType to =
          (i + offset[0]) + wholeCounts[0] * ((j + offset[1]) + wholeCounts[1] * (k + offset[2]));
        whole->SetValue(to, static_cast<float>(piece->GetComponent(from, 0)));
      }
    }
  }
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
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
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
  output->SetExtent(whole);
  if (input)
  {
    output->SetOrigin(input->GetOrigin());
    output->SetSpacing(input->GetSpacing());
    output->SetDirectionMatrix(input->GetDirectionMatrix());
  }

  // The density array of this process's piece, and whether any process has it and where
  // (a process whose piece is empty has none).
  bool cells = false;
  std::string why;
  vtkDataArray* local =
    (input && input->GetNumberOfPoints() > 0)
      ? vtkLightShaftDensityField::FindArray(input, this->ArrayName.c_str(), cells, why)
      : nullptr;
  int described[2] = { local ? 1 : -1, local ? int(cells) : -1 };
  int agreed[2] = { described[0], described[1] };
  vtkMultiProcessController* controller = this->GetController();
  if (controller)
  {
    controller->AllReduce(described, agreed, 2, vtkCommunicator::MAX_OP);
  }
  if (agreed[0] < 0)
  {
    return 1; // no process found it: the medium says which array is missing
  }
  cells = agreed[1] == 1;
  vtkIdType counts[3];
  Counts(whole, cells, counts);
  const vtkIdType samples = counts[0] * counts[1] * counts[2];
  // rho (the first component) as float32, as the pass keeps its samples: every sample from a
  // process that computed it (the lowest float elsewhere; the largest wins).
  vtkNew<vtkFloatArray> mine;
  mine->SetNumberOfTuples(samples);
  mine->Fill(-std::numeric_limits<float>::max());
  if (local)
  {
    Place(local, input->GetExtent(), mine, whole, cells);
  }
  vtkNew<vtkFloatArray> gathered;
  gathered->SetNumberOfTuples(samples);
  if (controller)
  {
    controller->AllReduce(mine, gathered, vtkCommunicator::MAX_OP);
  }
  else
  {
    gathered->DeepCopy(mine);
  }
  gathered->SetName(
    !this->ArrayName.empty() ? this->ArrayName.c_str() : (local ? local->GetName() : "density"));
  vtkDataSetAttributes* attributes = cells
                                       ? static_cast<vtkDataSetAttributes*>(output->GetCellData())
                                       : static_cast<vtkDataSetAttributes*>(output->GetPointData());
  attributes->SetScalars(gathered);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsFieldGather::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
