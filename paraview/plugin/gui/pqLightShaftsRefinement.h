/**
 * @class   pqLightShaftsRefinement
 * @brief   ParaView GUI: still light-shaft views keep rendering until their shafts converge.
 *
 * The plugin's auto-start piece (loaded by the Qt client only; pvpython and pvbatch never
 * create it). vtkLightShaftPass refines a still view by one estimate per render (the view's
 * Progressive Refinement property), and the client must ask for those renders. This object
 * gives every "Render View (Light Shafts)" of the session a pqLightShaftsViewRefiner, which
 * does, and pauses while the user interacts.
 *
 * @sa pqLightShaftsViewRefiner vtkPVLightShaftsView
 */

#ifndef pqLightShaftsRefinement_h
#define pqLightShaftsRefinement_h

#include <QObject> // For the base class

class pqView;

class pqLightShaftsRefinement : public QObject
{
  Q_OBJECT

public:
  explicit pqLightShaftsRefinement(QObject* parent = nullptr);
  ~pqLightShaftsRefinement() override;

  /// Called by ParaView when the plugin loads: watch the views there are and will be.
  void startup();
  /// Called by ParaView when the application ends.
  void shutdown();

private Q_SLOTS:
  /// A view of the session appeared: light-shaft views get a refiner (owned by the view).
  void watch(pqView* view);

private:
  Q_DISABLE_COPY(pqLightShaftsRefinement)
};

#endif
