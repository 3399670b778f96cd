#include "vtkPVLightShaftsTranslucentGather.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCollection.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkLightShaftPass.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>

namespace
{
// The renderer's visible actors that draw translucent surfaces (opacity below 1), in order.
std::vector<vtkActor*> TranslucentActors(vtkRenderer* renderer)
{
  std::vector<vtkActor*> actors;
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (actor && actor->GetVisibility() && actor->GetMapper() && actor->GetProperty() &&
        actor->GetProperty()->GetOpacity() < 1.0)
    {
      actors.push_back(actor);
    }
  }
  return actors;
}

// When what `actor` draws last changed: its mapper and its input.
vtkMTimeType DataTime(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  return std::max(mapper->GetMTime(), input ? input->GetMTime() : 0);
}

// `actor`'s polygons (a composite input's leaves appended) as one vtkPolyData.
vtkSmartPointer<vtkPolyData> LocalSurface(vtkActor* actor)
{
  vtkDataObject* input = actor->GetMapper()->GetInputDataObject(0, 0);
  vtkNew<vtkAppendPolyData> append;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        append->AddInputData(leaf);
      }
    }
  }
  else if (auto* polygons = vtkPolyData::SafeDownCast(input))
  {
    append->AddInputData(polygons);
  }
  vtkNew<vtkPolyData> surface;
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    surface->ShallowCopy(append->GetOutput());
  }
  return surface;
}
}

//------------------------------------------------------------------------------
vtkPVLightShaftsTranslucentGather::vtkPVLightShaftsTranslucentGather() = default;
vtkPVLightShaftsTranslucentGather::~vtkPVLightShaftsTranslucentGather() = default;

//------------------------------------------------------------------------------
void vtkPVLightShaftsTranslucentGather::Update(vtkRenderer* renderer,
  vtkMultiProcessController* controller)
{
  const std::vector<vtkActor*> actors = TranslucentActors(renderer);
  // Whether any process's translucent surfaces changed, and whether every process has as many
  // (ParaView's properties are the same on every process; should their counts differ, none is
  // gathered, rather than processes waiting on gathers the others do not make).
  int changed = actors.size() != this->Surfaces.size() ? 1 : 0;
  for (size_t i = 0; i < actors.size() && !changed; ++i)
  {
    const Surface& surface = this->Surfaces[i];
    changed = surface.Local != actors[i] || surface.Mapper != actors[i]->GetMapper() ||
              surface.Time != DataTime(actors[i]);
  }
  const int local[3] = {
    changed, static_cast<int>(actors.size()), -static_cast<int>(actors.size())
  };
  int agreed[3];
  controller->AllReduce(local, agreed, 3, vtkCommunicator::MAX_OP);
  this->Bytes = 0.0;
  if (agreed[1] != -agreed[2])
  {
    this->Surfaces.clear();
    return;
  }
  if (agreed[0])
  {
    this->Surfaces.resize(actors.size());
    for (size_t i = 0; i < actors.size(); ++i)
    {
      this->Gather(this->Surfaces[i], actors[i], controller);
    }
  }
  for (size_t i = 0; i < actors.size(); ++i)
  {
    Place(this->Surfaces[i], actors[i]);
    vtkInformation* keys = actors[i]->GetPropertyKeys();
    if (!keys)
    {
      vtkNew<vtkInformation> created;
      actors[i]->SetPropertyKeys(created);
      keys = created;
    }
    if (keys->Get(vtkLightShaftPass::MODELLED_PROP()) != this->Surfaces[i].Whole.GetPointer())
    {
      keys->Set(vtkLightShaftPass::MODELLED_PROP(), this->Surfaces[i].Whole);
    }
  }
}

//------------------------------------------------------------------------------
// Collective: every process's piece of `local`'s surface, appended into `surface`'s actor.
void vtkPVLightShaftsTranslucentGather::Gather(Surface& surface,
  vtkActor* local,
  vtkMultiProcessController* controller)
{
  vtkSmartPointer<vtkPolyData> mine = LocalSurface(local);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(mine, pieces);
  vtkNew<vtkAppendPolyData> append;
  for (const vtkSmartPointer<vtkDataObject>& piece : pieces)
  {
    auto* polygons = vtkPolyData::SafeDownCast(piece);
    if (polygons && polygons->GetNumberOfPoints() > 0)
    {
      append->AddInputData(polygons);
      this->Bytes += 1024.0 * static_cast<double>(polygons->GetActualMemorySize());
    }
  }
  vtkNew<vtkPolyData> whole;
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    whole->ShallowCopy(append->GetOutput());
  }
  // Coloured as the local actor's mapper colours (its lookup table, scalar mode and array).
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->ShallowCopy(local->GetMapper());
  mapper->SetInputData(whole);
  surface.Whole = vtkSmartPointer<vtkActor>::New();
  surface.Whole->SetMapper(mapper);
  surface.Whole->SetUserMatrix(vtkSmartPointer<vtkMatrix4x4>::New());
  surface.Local = local;
  surface.Mapper = local->GetMapper();
  surface.Time = DataTime(local);
}

//------------------------------------------------------------------------------
// The whole surface looks as `local` does: its property (shared), visibility and placement.
void vtkPVLightShaftsTranslucentGather::Place(Surface& surface, vtkActor* local)
{
  vtkActor* whole = surface.Whole;
  whole->SetProperty(local->GetProperty());
  whole->SetBackfaceProperty(local->GetBackfaceProperty());
  whole->SetVisibility(local->GetVisibility());
  vtkMatrix4x4* matrix = local->GetMatrix();
  vtkMatrix4x4* placed = whole->GetUserMatrix();
  if (!std::equal(matrix->GetData(), matrix->GetData() + 16, placed->GetData()))
  {
    placed->DeepCopy(matrix);
    whole->Modified();
  }
}
