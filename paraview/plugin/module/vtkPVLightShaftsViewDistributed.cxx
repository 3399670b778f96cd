// vtkPVLightShaftsView on several processes: what each process does before it renders, and its
// side of the pass's exchanges (the properties' side is vtkPVLightShaftsView.cxx).
#include "vtkPVLightShaftsView.h"
#include "vtkPVLightShaftsViewInternals.h"

#include "vtkCollection.h"
#include "vtkLightShaftFrameReport.h"
#include "vtkMultiProcessController.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPVSession.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkProcessModule.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSMSession.h"
#include "vtkVolume.h"

namespace
{
vtkMultiProcessController* DistributedController()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return (controller && controller->GetNumberOfProcesses() > 1) ? controller : nullptr;
}

// A client whose render server runs on several processes: a picture rendered there is
// composited by IceT, which turns the renderer's FXAA off, and antialiased by this process's
// synchronizer when it shows the picture (with the renderer's FXAA setting).
bool ClientOfCompositingServer()
{
  vtkProcessModule* module = vtkProcessModule::GetProcessModule();
  if (!module || module->GetProcessType() != vtkProcessModule::PROCESS_CLIENT)
  {
    return false;
  }
  vtkSMSession* session = vtkSMSession::SafeDownCast(module->GetActiveSession());
  return session && session->GetNumberOfProcesses(vtkPVSession::RENDER_SERVER) > 1;
}
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  vtkMultiProcessController* controller = DistributedController();
  // With its image-processing slot filled, ParaView 5.11 antialiases twice: its FXAA pass runs
  // around the slot, and the renderer's own FXAA inside the scene's default pass. Keep the
  // outer one (it sees the final picture, shafts included) and turn the renderer's off for
  // this render (restored at its end), so the medium off gives a RenderView's picture. On
  // several processes (IceT composites the image) the outer one does not run (measured: the
  // pictures lose their antialiasing): the renderer's stays, for the synchronizer that shows the
  // composited picture, as on a client showing the picture of a server on several processes.
  vtkRenderer* renderer = this->GetRenderer();
  const bool remote = interactive ? this->GetUseDistributedRenderingForLODRender()
                                  : this->GetUseDistributedRenderingForRender();
  if (this->SynchronizedRenderers->GetImageProcessingPass() &&
      this->SynchronizedRenderers->GetUseFXAA() && renderer->GetUseFXAA() && !controller &&
      !(remote && ClientOfCompositingServer()))
  {
    renderer->SetUseFXAA(false);
    this->Impl->RestoreRendererFXAA = true;
  }
  this->UpdateVolumes(controller);
  vtkLightShaftPass* shafts = this->Impl->Shafts;
  // Rendering for compositing (IceT's processes, or a pvserver's picture for its client), the
  // image is made over a transparent background and the renderer's flat background blended in
  // after the pass (the renderer's is black while it renders): the pass paints it where the
  // medium must dim it. A gradient or textured background is left to the compositor.
  const bool composited = controller || remote;
  shafts->SetPaintBackground(
    composited && !renderer->GetGradientBackground() && !renderer->GetTexturedBackground());
  shafts->SetPaintedBackground(
    renderer->GetBackground()[0], renderer->GetBackground()[1], renderer->GetBackground()[2]);
  if (this->Impl->FitMedium && !this->Impl->FitAsked)
  {
    // Asked now, after ParaView pushed the properties' defaults; the user's values given
    // again after the request, so that they win.
    shafts->FitMediumToSceneOn();
    this->Impl->GiveMedium(true);
    this->Impl->FitAsked = true;
  }
  // The processes divide the in-scatter's rows (SLICES, RAY_MARCH, ANALYTIC): each computes
  // its piece on the processes' composited depth, and process 0 gathers them (Exchange).
  const bool divide = controller && this->DivideShaftWork;
  shafts->SetImagePiece(
    divide ? controller->GetLocalProcessId() : 0, divide ? controller->GetNumberOfProcesses() : 1);
  this->Impl->Exchange.BeginFrame();
  // With a volume or a translucent surface IceT composites in order, colour only (it has no
  // composited depth to give back; asked, it says so with an error): the processes' depths are
  // then combined by the exchange, as they are for image pieces.
  const bool ordered = controller && this->GetUseOrderedCompositing();
  this->SynchronizedRenderers->SetUseDepthBuffer(!ordered);
  this->Impl->ShareSceneDepth = divide || ordered;
  this->Impl->OrderedCompositing = ordered;
  // The exact finish integrates on each process's idle threads and completes when they are
  // done: the processes would not take the same path in the same render.
  if (controller && this->Impl->ExactFinish && !this->Impl->WarnedExactFinish)
  {
    vtkWarningMacro("Exact Finish is not distributed: it is off while the view renders on "
                    << controller->GetNumberOfProcesses() << " processes.");
    this->Impl->WarnedExactFinish = true;
  }
  shafts->SetExactFinish(this->Impl->ExactFinish && !controller);
  if (this->DistributedShadowMap && controller && this->GeometryBounds.IsValid())
  {
    // GeometryBounds holds the union over the processes (vtkPVRenderView reduces it).
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    shafts->SetShadowCasterBounds(bounds);
  }
  else
  {
    shafts->UnsetShadowCasterBounds();
  }
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::Exchange(unsigned long event, void* data)
{
  vtkMultiProcessController* controller = DistributedController();
  vtkPVLightShaftsExchange& exchange = this->Impl->Exchange;
  vtkLightShaftPass* shafts = this->Impl->Shafts;
  if (event == vtkLightShaftPass::FrameTimedEvent)
  {
    exchange.AgreeOnTimes(static_cast<double*>(data), controller);
  }
  else if (event == vtkLightShaftPass::ShadowMapReuseEvent)
  {
    // Kept only where every process's map is unchanged (then the combined map still holds);
    // alone, or not combining, a map is as reusable as the pass finds it.
    exchange.AgreeOnReuse(
      static_cast<int*>(data), this->DistributedShadowMap ? controller : nullptr);
  }
  else if (event == vtkLightShaftPass::ShadowMapRenderedEvent && this->DistributedShadowMap)
  {
    exchange.CombineShadowMaps(shafts, controller);
  }
  else if (event == vtkLightShaftPass::SceneDepthReadyEvent && this->Impl->ShareSceneDepth)
  {
    exchange.ShareSceneDepth(shafts,
      controller,
      this->Impl->OrderedCompositing ? this->GetRenderer() : nullptr,
      vtkOpenGLRenderWindow::SafeDownCast(this->GetRenderWindow()));
  }
  else if (event == vtkLightShaftPass::InScatterPieceEvent)
  {
    exchange.GatherInScatter(
      shafts, controller, vtkOpenGLRenderWindow::SafeDownCast(this->GetRenderWindow()));
  }
}

double vtkPVLightShaftsView::GetLastBytesExchanged()
{
  return this->Impl->Exchange.GetBytes() + this->Impl->VolumeGather.GetBytes() +
         this->Impl->TranslucentGather.GetBytes();
}

int vtkPVLightShaftsView::GetLastImagePieceRows()
{
  return this->Impl->Shafts->GetLastFrame()->GetImagePieceRows();
}

double vtkPVLightShaftsView::GetLastInScatterFragments()
{
  return static_cast<double>(this->Impl->Shafts->GetLastFrame()->GetInScatterFragments());
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsView::SetMediumDensityConnection(vtkAlgorithmOutput* output)
{
  if (DistributedController())
  {
    // Each process computes its piece of the source; the pass sees the whole image. (No
    // source: the gather lets go of the last one.)
    this->Impl->FieldGather->SetInputConnection(output);
    output = output ? this->Impl->FieldGather->GetOutputPort() : nullptr;
  }
  this->Impl->DensityConnection = output;
  if (!this->MediumFromVolume)
  {
    this->Impl->Shafts->GetMedium()->SetDensityFieldConnection(output);
  }
}

//------------------------------------------------------------------------------
// The renderer's first visible volume dims the shafts, or with MediumFromVolume is the medium
// (the volume representations' props change as their data and visibility do: chosen at each
// render). Under MPI each process's volume draws its piece: the pass models the whole image,
// gathered, in its place.
void vtkPVLightShaftsView::UpdateVolumes(vtkMultiProcessController* controller)
{
  vtkVolume* chosen = nullptr;
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = this->GetRenderer()->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (volume && volume->GetVisibility())
    {
      chosen = volume;
      break;
    }
  }
  vtkLightShaftMedium* medium = this->Impl->Shafts->GetMedium();
  // (With the shafts off nothing is gathered: the pass does not run. LightShafts is the same on
  // every process, so they all skip the same collective calls.)
  if (controller && this->LightShafts)
  {
    this->Impl->TranslucentGather.Update(this->GetRenderer(), controller);
    vtkVolume* whole =
      this->Impl->VolumeGather.Update(chosen, controller, medium->GetFieldResolution());
    chosen = whole ? whole : chosen;
  }
  if (!this->MediumFromVolume)
  {
    return;
  }
  if (chosen)
  {
    medium->SetDensityVolume(chosen);
  }
  else if (medium->GetDensityVolume())
  {
    medium->SetDensityFieldConnection(nullptr); // (no volume: the homogeneous medium)
  }
}
