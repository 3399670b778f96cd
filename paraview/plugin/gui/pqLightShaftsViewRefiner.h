/**
 * @class   pqLightShaftsViewRefiner
 * @brief   Renders one light-shaft view again while its still picture refines.
 *
 * After each still render of its view, the refiner reads the view's information properties
 * RefinementEstimates and RefinementConverged (what vtkLightShaftPass reported, gathered from
 * the server in client-server sessions too). While the shafts are refining, it asks for one
 * more render, through a short timer so that the event loop answers the user first. Renders
 * during interaction (the interactor between StartInteractionEvent and EndInteractionEvent,
 * or any interactive render) cancel the request; the still render ParaView makes when the
 * interaction ends starts refining again. Each decision is logged at ParaView's rendering
 * verbosity (PARAVIEW_LOG_RENDERING_VERBOSITY=INFO shows them).
 *
 * Owned by its pqView (a child QObject): it ends with the view.
 *
 * @sa pqLightShaftsRefinement
 */

#ifndef pqLightShaftsViewRefiner_h
#define pqLightShaftsViewRefiner_h

#include <QObject>  // For the base class
#include <QPointer> // For the view, which can go first
#include <QTimer>   // For the delayed render

#include <vtkWeakPointer.h> // For the observed proxy and interactor, which can go first

class pqView;
class vtkObject;
class vtkRenderWindowInteractor;
class vtkSMProxy;

class pqLightShaftsViewRefiner : public QObject
{
  Q_OBJECT

public:
  explicit pqLightShaftsViewRefiner(pqView* view);
  ~pqLightShaftsViewRefiner() override;

  /// Milliseconds from a still render that left the shafts refining to the next render.
  static constexpr int RefineDelayMilliseconds = 10;
  /// The same while the exact finish runs: its worker threads need the processor time.
  static constexpr int FinishDelayMilliseconds = 100;

private:
  /// The view proxy's EndEvent: its call data says whether the render was interactive.
  void renderEnded(vtkObject* caller, unsigned long event, void* callData);
  /// The interactor's StartInteractionEvent and EndInteractionEvent.
  void interactionChanged(vtkObject* caller, unsigned long event, void* callData);
  /// Observe the view's interactor (the widget's, which replaces the proxy's first one).
  void watchInteractor();
  /// The timer's end: render again unless the user has started interacting since.
  void refine();

  QPointer<pqView> View;
  QTimer Timer;
  vtkWeakPointer<vtkSMProxy> Proxy;
  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  unsigned long RenderObserver = 0;
  unsigned long InteractionObservers[2] = { 0, 0 };
  bool Interacting = false;

  Q_DISABLE_COPY(pqLightShaftsViewRefiner)
};

#endif
