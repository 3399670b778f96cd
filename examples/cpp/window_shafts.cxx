// Light shafts through a window, from C++: a spotlight behind a wall with a four-pane window,
// rendered offscreen to a PNG.
//
//   window_shafts [output.png]     (default window_shafts.png; needs an X server: xvfb-run -a)

#include "vtkLightShaftPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <array>
#include <iostream>

namespace
{
void AddBox(vtkRenderer* renderer, std::array<double, 3> centre, std::array<double, 3> size)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(centre.data());
  cube->SetXLength(size[0]);
  cube->SetYLength(size[1]);
  cube->SetZLength(size[2]);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.55, 0.45, 0.35);
  renderer->AddActor(actor);
}
}

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "window_shafts.png";

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.01, 0.01, 0.02);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(true);
  window->SetMultiSamples(0);
  window->SetSize(960, 540);
  window->AddRenderer(renderer);

  // Floor, and a wall at x = -3 with a window split into four panes by a cross of bars.
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-8.0, 0.0, -8.0);
  floor->SetPoint1(-8.0, 0.0, 8.0);
  floor->SetPoint2(8.0, 0.0, -8.0);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floor->GetOutputPort());
  vtkNew<vtkActor> floorActor;
  floorActor->SetMapper(floorMapper);
  floorActor->GetProperty()->SetColor(0.75, 0.7, 0.65);
  renderer->AddActor(floorActor);
  AddBox(renderer, { -3.0, 0.75, 0.0 }, { 0.2, 1.5, 9.0 });
  AddBox(renderer, { -3.0, 6.25, 0.0 }, { 0.2, 2.5, 9.0 });
  AddBox(renderer, { -3.0, 3.25, -3.0 }, { 0.2, 3.5, 3.0 });
  AddBox(renderer, { -3.0, 3.25, 3.0 }, { 0.2, 3.5, 3.0 });
  AddBox(renderer, { -3.0, 3.25, 0.0 }, { 0.2, 3.5, 0.25 });
  AddBox(renderer, { -3.0, 3.25, 0.0 }, { 0.2, 0.25, 3.0 });

  // The spotlight outside (VTK's conventions: cone angle is the half-angle in degrees).
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(true);
  sun->SetPosition(-9.0, 8.0, 1.0);
  sun->SetFocalPoint(0.5, 0.0, -0.5);
  sun->SetConeAngle(22.0);
  sun->SetColor(1.0, 0.93, 0.8);
  renderer->AddLight(sun);
  vtkNew<vtkLight> fill; // dim headlight: the room is not pitch black; it makes no shafts
  fill->SetLightTypeToHeadlight();
  fill->SetIntensity(0.12);
  renderer->AddLight(fill);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(7.0, 2.2, 8.0);
  camera->SetFocalPoint(-3.0, 3.0, -1.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkLightShaftPass> shafts;
  shafts->GetMedium()->SetScatteringCoefficient(0.05, 0.047, 0.043); // per world unit
  shafts->GetMedium()->SetAbsorptionCoefficient(0.005);
  shafts->GetMedium()->SetPhaseFunctionToHenyeyGreenstein();
  shafts->GetMedium()->SetAnisotropy(0.3);
  shafts->SetExposure(45.0);
  shafts->SetNumberOfSlices(192);
  shafts->SetShadowMapSize(2048);
  shafts->ShadowSurfacesOn();
  renderer->SetPass(shafts);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(output);
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::cout << "wrote " << output << " (" << shafts->GetLastFrame()->GetNumberOfSlicesDrawn()
            << " slices)" << std::endl;
  return shafts->GetLastFrame()->GetGLErrorCount() == 0 ? 0 : 1;
}
