#include "vtkPVLightShaftsVolumeGather.h"

#include "vtkPVLightShaftsFieldGather.h"

#include "vtkLightShaftVolumeField.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkLightShaftPass.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkVolume.h"

#include <algorithm>
#include <limits>
#include <string>

namespace
{
// The whole volume's mapper: it holds the gathered image for the pass to model and draws
// nothing (the volume is in no renderer).
class ModelledMapper : public vtkAbstractVolumeMapper
{
public:
  static ModelledMapper* New();
  vtkTypeMacro(ModelledMapper, vtkAbstractVolumeMapper);
  void Render(vtkRenderer*, vtkVolume*) override {}
};
vtkStandardNewMacro(ModelledMapper);

// When what `volume` renders last changed: its mapper (which ParaView may swap) and its input.
vtkMTimeType DataTime(vtkVolume* volume)
{
  auto* mapper = volume ? vtkAbstractVolumeMapper::SafeDownCast(volume->GetMapper()) : nullptr;
  if (!mapper)
  {
    return 0;
  }
  vtkDataSet* input = mapper->GetDataSetInput();
  return std::max(mapper->GetMTime(), input ? input->GetMTime() : 0);
}
}

//------------------------------------------------------------------------------
vtkPVLightShaftsVolumeGather::vtkPVLightShaftsVolumeGather()
{
  vtkNew<ModelledMapper> mapper;
  mapper->SetInputDataObject(this->Image);
  this->Whole->SetMapper(mapper);
  this->Whole->SetUserMatrix(this->Matrix);
}

vtkPVLightShaftsVolumeGather::~vtkPVLightShaftsVolumeGather() = default;

//------------------------------------------------------------------------------
vtkVolume* vtkPVLightShaftsVolumeGather::Update(vtkVolume* local,
  vtkMultiProcessController* controller,
  int resolution)
{
  const vtkMTimeType time = DataTime(local);
  vtkObject* mapper = local ? local->GetMapper() : nullptr;
  int changed = (local != this->Local || mapper != this->LocalMapper || time != this->LocalTime ||
                  resolution != this->Resolution)
                  ? 1
                  : 0;
  int anyChanged = changed;
  controller->AllReduce(&changed, &anyChanged, 1, vtkCommunicator::MAX_OP);
  this->Bytes = 0.0;
  if (anyChanged)
  {
    this->Valid = this->Gather(local, controller, resolution);
    this->Local = local;
    this->LocalMapper = mapper;
    this->LocalTime = time;
    this->Resolution = resolution;
  }
  if (!local)
  {
    return nullptr;
  }
  vtkInformation* keys = local->GetPropertyKeys();
  if (!this->Valid)
  {
    if (keys && keys->Has(vtkLightShaftPass::MODELLED_PROP()))
    {
      keys->Remove(vtkLightShaftPass::MODELLED_PROP());
    }
    return nullptr;
  }
  this->Place(local);
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    local->SetPropertyKeys(created);
    keys = created;
  }
  if (keys->Get(vtkLightShaftPass::MODELLED_PROP()) != this->Whole.GetPointer())
  {
    keys->Set(vtkLightShaftPass::MODELLED_PROP(), this->Whole);
  }
  return this->Whole;
}

//------------------------------------------------------------------------------
// Collective: the pieces' scalars gathered into Image, placed as the pieces agree. False when
// no process has scalars to render.
bool vtkPVLightShaftsVolumeGather::Gather(vtkVolume* local,
  vtkMultiProcessController* controller,
  int resolution)
{
  // The scalars this process's piece renders (none: an empty piece, or no local volume).
  vtkImageData* input = nullptr;
  bool cells = false;
  std::string why;
  vtkDataArray* scalars = vtkLightShaftVolumeField::RenderedScalars(local, input, cells, why);
  // The whole extent: the pieces' union (their lower bounds' minimum, upper bounds' maximum).
  constexpr int none = std::numeric_limits<int>::max();
  int extent[6] = { none, none, none, none, none, none };
  if (scalars)
  {
    const int* e = input->GetExtent();
    for (int axis = 0; axis < 3; ++axis)
    {
      extent[2 * axis] = e[2 * axis];
      extent[2 * axis + 1] = -e[2 * axis + 1];
    }
  }
  int reduced[6];
  controller->AllReduce(extent, reduced, 6, vtkCommunicator::MIN_OP);
  if (reduced[0] == none)
  {
    this->Image->Initialize();
    return false;
  }
  int whole[6];
  for (int axis = 0; axis < 3; ++axis)
  {
    whole[2 * axis] = reduced[2 * axis];
    whole[2 * axis + 1] = -reduced[2 * axis + 1];
  }
  // The placement, the same on every process that has a piece (origin, spacing, direction).
  double placement[15];
  std::fill(placement, placement + 15, -std::numeric_limits<double>::max());
  if (scalars)
  {
    std::copy(input->GetOrigin(), input->GetOrigin() + 3, placement);
    std::copy(input->GetSpacing(), input->GetSpacing() + 3, placement + 3);
    std::copy(input->GetDirectionMatrix()->GetData(),
      input->GetDirectionMatrix()->GetData() + 9,
      placement + 6);
  }
  double agreed[15];
  controller->AllReduce(placement, agreed, 15, vtkCommunicator::MAX_OP);
  vtkNew<vtkImageData> piece;
  if (scalars)
  {
    piece->SetExtent(input->GetExtent());
    (cells ? static_cast<vtkDataSetAttributes*>(piece->GetCellData())
           : static_cast<vtkDataSetAttributes*>(piece->GetPointData()))
      ->SetScalars(scalars);
  }
  else
  {
    piece->SetExtent(0, -1, 0, -1, 0, -1);
  }
  piece->SetOrigin(agreed);
  piece->SetSpacing(agreed + 3);
  piece->SetDirectionMatrix(agreed + 6);
  this->Gatherer->SetController(controller);
  this->Gatherer->SetArrayName("");
  this->Gatherer->SetResolution(resolution);
  this->Gatherer->GatherImage(piece, whole, this->Image);
  this->Image->Modified();
  vtkDataArray* gathered = this->Image->GetPointData()->GetScalars()
                             ? this->Image->GetPointData()->GetScalars()
                             : this->Image->GetCellData()->GetScalars();
  // A MAX reduction of the whole grid: each process sends and receives it.
  this->Bytes = gathered ? 2.0 * 4.0 * static_cast<double>(gathered->GetNumberOfTuples()) : 0.0;
  return gathered != nullptr;
}

//------------------------------------------------------------------------------
// The whole volume looks as `local` does: its property (shared) and its placement.
void vtkPVLightShaftsVolumeGather::Place(vtkVolume* local)
{
  this->Whole->SetProperty(local->GetProperty());
  this->Whole->SetVisibility(local->GetVisibility());
  vtkMatrix4x4* matrix = local->GetMatrix();
  bool same = true;
  for (int i = 0; i < 16; ++i)
  {
    same = same && matrix->GetData()[i] == this->Matrix->GetData()[i];
  }
  if (!same)
  {
    this->Matrix->DeepCopy(matrix);
    this->Whole->Modified();
  }
}
