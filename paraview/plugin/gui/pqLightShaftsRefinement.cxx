#include "pqLightShaftsRefinement.h"

#include "pqLightShaftsViewRefiner.h"

#include <pqApplicationCore.h>
#include <pqServerManagerModel.h>
#include <pqView.h>
#include <vtkSMProxy.h>

#include <cstring>

namespace
{
// The view proxy the refiner serves (LightShafts.xml).
const char* const LightShaftsViewName = "LightShaftsRenderView";
}

pqLightShaftsRefinement::pqLightShaftsRefinement(QObject* parent)
  : QObject(parent)
{
}

pqLightShaftsRefinement::~pqLightShaftsRefinement() = default;

void pqLightShaftsRefinement::startup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::viewAdded, this, &pqLightShaftsRefinement::watch);
  // A plugin loaded into a running session: its light-shaft views already exist.
  for (pqView* view : model->findItems<pqView*>())
  {
    this->watch(view);
  }
}

void pqLightShaftsRefinement::shutdown()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::disconnect(model, nullptr, this, nullptr);
}

void pqLightShaftsRefinement::watch(pqView* view)
{
  vtkSMProxy* proxy = view ? view->getProxy() : nullptr;
  if (!proxy || !proxy->GetXMLName() || std::strcmp(proxy->GetXMLName(), LightShaftsViewName) != 0)
  {
    return;
  }
  if (!view->findChild<pqLightShaftsViewRefiner*>(QString(), Qt::FindDirectChildrenOnly))
  {
    new pqLightShaftsViewRefiner(view);
  }
}
