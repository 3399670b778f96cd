#include "vtkLightShaftRendererStep.h"

#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"

vtkStandardNewMacro(vtkLightShaftRendererStep);

vtkLightShaftRendererStep::vtkLightShaftRendererStep() = default;
vtkLightShaftRendererStep::~vtkLightShaftRendererStep() = default;

//------------------------------------------------------------------------------
void vtkLightShaftRendererStep::SetStage(Stage stage, vtkLightShaftRendererStep* translucent)
{
  this->Step = stage;
  this->Translucent = translucent;
}

//------------------------------------------------------------------------------
void vtkLightShaftRendererStep::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (this->Step == OPAQUE)
  {
    this->RenderOpaque(s);
    return;
  }
  if (this->Step == TRANSLUCENT)
  {
    this->RenderTranslucent(s);
    return;
  }
  if (this->Translucent && this->Translucent->GetPeeledVolumes())
  {
    return; // the translucent step's dual depth peeling drew them, as VTK's render does
  }
  this->PlainVolumes->Render(s);
  this->NumberOfRenderedProps = this->PlainVolumes->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkLightShaftRendererStep::RenderOpaque(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  if (s->GetRequiredKeys())
  {
    this->PlainOpaque->Render(s);
    this->NumberOfRenderedProps = this->PlainOpaque->GetNumberOfRenderedProps();
  }
  else if (renderer->GetUseShadows())
  {
    if (!this->Shadows)
    {
      this->Shadows = vtkSmartPointer<vtkShadowMapPass>::New();
    }
    this->Shadows->GetShadowMapBakerPass()->Render(s);
    this->Shadows->Render(s);
    this->NumberOfRenderedProps = this->Shadows->GetNumberOfRenderedProps();
  }
  else
  {
    const int before = renderer->GetNumberOfPropsRendered();
    renderer->DeviceRenderOpaqueGeometry(s->GetFrameBuffer());
    this->NumberOfRenderedProps = renderer->GetNumberOfPropsRendered() - before;
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftRendererStep::RenderTranslucent(const vtkRenderState* s)
{
  this->PeeledVolumes = false;
  if (s->GetRenderer()->GetUseShadows() && !s->GetRequiredKeys())
  {
    return; // VTK's render with shadows draws the opaque geometry only
  }
  if (s->GetRequiredKeys())
  {
    this->PlainTranslucent->Render(s);
    this->NumberOfRenderedProps = this->PlainTranslucent->GetNumberOfRenderedProps();
    return;
  }
  // As VTK's render: nothing at all (not even the compositing of an empty layer) without
  // translucent geometry.
  bool translucent = false;
  for (int i = 0; i < s->GetPropArrayCount() && !translucent; ++i)
  {
    translucent = s->GetPropArray()[i]->HasTranslucentPolygonalGeometry() != 0;
  }
  if (!translucent)
  {
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  const int before = renderer->GetNumberOfPropsRendered();
  renderer->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  this->NumberOfRenderedProps = renderer->GetNumberOfPropsRendered() - before;
  this->PeeledVolumes =
    renderer->GetLastRenderingUsedDepthPeeling() && renderer->GetUseDepthPeelingForVolumes();
}

//------------------------------------------------------------------------------
void vtkLightShaftRendererStep::ReleaseGraphicsResources(vtkWindow* window)
{
  this->PlainOpaque->ReleaseGraphicsResources(window);
  this->PlainTranslucent->ReleaseGraphicsResources(window);
  this->PlainVolumes->ReleaseGraphicsResources(window);
  if (this->Shadows)
  {
    this->Shadows->ReleaseGraphicsResources(window);
  }
}
