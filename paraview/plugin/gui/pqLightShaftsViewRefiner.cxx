#include "pqLightShaftsViewRefiner.h"

#include <pqView.h>
#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkPVLogger.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMViewProxy.h>

namespace
{
// One information property of the view, fetched from where the view renders.
int FetchInformation(vtkSMProxy* proxy, const char* name)
{
  proxy->UpdatePropertyInformation(proxy->GetProperty(name));
  return vtkSMPropertyHelper(proxy, name).GetAsInt();
}
}

pqLightShaftsViewRefiner::pqLightShaftsViewRefiner(pqView* view)
  : QObject(view)
  , View(view)
  , Proxy(view->getProxy())
{
  this->Timer.setSingleShot(true);
  this->Timer.setInterval(RefineDelayMilliseconds);
  QObject::connect(&this->Timer, &QTimer::timeout, this, &pqLightShaftsViewRefiner::refine);
  this->RenderObserver =
    this->Proxy->AddObserver(vtkCommand::EndEvent, this, &pqLightShaftsViewRefiner::renderEnded);
  this->watchInteractor();
}

pqLightShaftsViewRefiner::~pqLightShaftsViewRefiner()
{
  if (this->Proxy)
  {
    this->Proxy->RemoveObserver(this->RenderObserver);
  }
  if (this->Interactor)
  {
    this->Interactor->RemoveObserver(this->InteractionObservers[0]);
    this->Interactor->RemoveObserver(this->InteractionObservers[1]);
  }
}

void pqLightShaftsViewRefiner::watchInteractor()
{
  auto* viewProxy = vtkSMViewProxy::SafeDownCast(this->Proxy);
  vtkRenderWindowInteractor* interactor = viewProxy ? viewProxy->GetInteractor() : nullptr;
  if (interactor == this->Interactor)
  {
    return;
  }
  // (The widget replaces the proxy's first interactor: follow it.)
  if (this->Interactor)
  {
    this->Interactor->RemoveObserver(this->InteractionObservers[0]);
    this->Interactor->RemoveObserver(this->InteractionObservers[1]);
  }
  this->Interactor = interactor;
  this->Interacting = false;
  if (!interactor)
  {
    return;
  }
  this->InteractionObservers[0] = interactor->AddObserver(
    vtkCommand::StartInteractionEvent, this, &pqLightShaftsViewRefiner::interactionChanged);
  this->InteractionObservers[1] = interactor->AddObserver(
    vtkCommand::EndInteractionEvent, this, &pqLightShaftsViewRefiner::interactionChanged);
}

void pqLightShaftsViewRefiner::interactionChanged(vtkObject*, unsigned long event, void*)
{
  this->Interacting = event == vtkCommand::StartInteractionEvent;
  if (this->Interacting)
  {
    this->Timer.stop();
  }
}

void pqLightShaftsViewRefiner::renderEnded(vtkObject*, unsigned long, void* callData)
{
  this->watchInteractor();
  const bool interactive = callData && *static_cast<int*>(callData) != 0;
  if (interactive || this->Interacting || !this->Proxy)
  {
    this->Timer.stop();
    return;
  }
  // The pass's rule (vtkLightShaftPass::RefinementNeededEvent): estimates were made and the
  // picture has not converged. With Progressive Refinement off no estimates are made.
  const int estimates = FetchInformation(this->Proxy, "RefinementEstimates");
  const bool converged = FetchInformation(this->Proxy, "RefinementConverged") != 0;
  if (estimates > 0 && !converged)
  {
    // While the exact finish runs, its threads need the processor time: look for finished
    // tiles ten times a second.
    const bool finishing = FetchInformation(this->Proxy, "ExactFinishState") == 1;
    this->Timer.setInterval(finishing ? FinishDelayMilliseconds : RefineDelayMilliseconds);
    vtkVLogF(PARAVIEW_LOG_RENDERING_VERBOSITY(),
      "LightShafts: still view refining after %d estimates, rendering again",
      estimates);
    this->Timer.start();
  }
  else if (estimates > 0)
  {
    vtkVLogF(PARAVIEW_LOG_RENDERING_VERBOSITY(),
      "LightShafts: still view converged with %d estimates",
      estimates);
  }
}

void pqLightShaftsViewRefiner::refine()
{
  if (this->View && !this->Interacting)
  {
    this->View->render();
  }
}
