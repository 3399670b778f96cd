// Tests of LightShafts::Core's float64 reference without OpenGL (linked without it, run without
// a display): the reference job captures a renderer's scene (no render window) with a medium
// and lights given as data (vtkLightShaftReferenceInput), and integrates every pixel:
//   - the closed forms and the adaptive quadrature agree;
//   - in-scatter is linear over lights (two lights' job is the sum of each light's);
//   - a medium that does not scatter gives exactly zero;
//   - an opaque occluder in the beam takes light away, and only in the beam's shadow.
//
// Usage: TestLightShaftReferenceCore

#include "vtkLightShaftMedium.h"
#include "vtkLightShaftReferenceInput.h"
#include "vtkLightShaftReferenceJob.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures;
  }
}

// A polygonal mapper for a scene without GL (vtkPolyDataMapper::New needs the OpenGL module's
// factory): the reference reads its input, nothing draws it.
class DataOnlyMapper : public vtkPolyDataMapper
{
public:
  static DataOnlyMapper* New();
  vtkTypeMacro(DataOnlyMapper, vtkPolyDataMapper);
  void RenderPiece(vtkRenderer*, vtkActor*) override {}
};
vtkStandardNewMacro(DataOnlyMapper);

constexpr int Size = 24;

// A spotlight above the origin, pointing down, its cone across the view.
vtkNew<vtkLight> MakeSpot(double x)
{
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetPosition(x, 4.0, 0.0);
  light->SetFocalPoint(x, 0.0, 0.0);
  light->SetConeAngle(25.0);
  light->SetIntensity(1.0);
  // Inverse-square falloff and a flat cone: where nothing shadows, the closed forms hold.
  light->SetAttenuationValues(0.0, 0.0, 1.0);
  light->SetExponent(0.0);
  return light;
}

// A box of polygons (an actor of the scene, drawn by nothing) centred at `centre`.
void AddBox(vtkRenderer* renderer, const double centre[3], const double lengths[3])
{
  vtkNew<vtkCubeSource> box;
  box->SetCenter(centre[0], centre[1], centre[2]);
  box->SetXLength(lengths[0]);
  box->SetYLength(lengths[1]);
  box->SetZLength(lengths[2]);
  vtkNew<DataOnlyMapper> mapper;
  mapper->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

// The in-scatter of every pixel (3 doubles each) of `renderer`'s view with `lights`.
std::vector<double> Integrate(vtkRenderer* renderer,
  vtkLightShaftMedium* medium,
  const std::vector<vtkLight*>& lights,
  bool closedForms)
{
  vtkLightShaftReferenceInput input;
  input.Lights = lights;
  input.Medium = medium;
  vtkLightShaftReferenceJob::Options options;
  options.UseClosedForms = closedForms;
  vtkLightShaftReferenceJob job;
  const std::string problem = job.Prepare(renderer, input, nullptr, Size, Size, options);
  Check(problem.empty(), "the job is prepared (" + problem + ")");
  Check(job.GetNumberOfLights() == static_cast<int>(lights.size()), "every light is captured");
  std::vector<double> radiance(3 * Size * Size, 0.0);
  const vtkLightShaftReferenceJob::Tally tally =
    job.Integrate(0, Size * Size, radiance.data(), nullptr);
  Check(!tally.Cancelled && tally.ExhaustedPixels == 0, "every pixel converges");
  const bool scatters = medium->GetScatteringCoefficient()[0] > 0.0;
  Check((tally.ClosedFormPixels > 0) == (closedForms && scatters),
    closedForms ? "closed forms integrate unshadowed rays" : "the quadrature integrates all");
  Check(std::all_of(
          radiance.begin(), radiance.end(), [](double v) { return std::isfinite(v) && v >= 0.0; }),
    "the in-scatter is finite and not negative");
  return radiance;
}

double Peak(const std::vector<double>& image)
{
  return *std::max_element(image.begin(), image.end());
}

double Sum(const std::vector<double>& image)
{
  double sum = 0.0;
  for (double v : image)
  {
    sum += v;
  }
  return sum;
}

// The largest difference between two images, relative to the first one's peak.
double Difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    largest = std::max(largest, std::abs(a[i] - b[i]));
  }
  return largest / std::max(Peak(a), 1e-300);
}
}

int main()
{
  vtkNew<vtkRenderer> renderer; // no render window: nothing here needs GL
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 1.0, 12.0);
  camera->SetFocalPoint(0.0, 1.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(1.0, 30.0);

  // A block off to the side, behind the beams: the scene whose box the medium fills (the view
  // rays end at its backdrop), out of both lights' cones, so that it shadows nothing.
  const double floorCentre[3] = { 7.0, -0.5, -5.0 };
  const double floorLengths[3] = { 1.0, 1.0, 1.0 };
  AddBox(renderer, floorCentre, floorLengths);

  vtkNew<vtkLightShaftMedium> medium;
  medium->SetScatteringCoefficient(0.1);
  medium->SetAbsorptionCoefficient(0.02);
  vtkNew<vtkLight> left = MakeSpot(-1.0);
  vtkNew<vtkLight> right = MakeSpot(1.5);

  // Closed forms and quadrature.
  const std::vector<double> closed = Integrate(renderer, medium, { left }, true);
  const std::vector<double> quadrature = Integrate(renderer, medium, { left }, false);
  Check(Peak(closed) > 0.0, "the beam scatters light towards the camera");
  const double formsDifference = Difference(closed, quadrature);
  Check(formsDifference < 1e-9,
    "closed forms and quadrature agree (" + std::to_string(formsDifference) + " of the peak)");

  // Linearity over lights.
  const std::vector<double> second = Integrate(renderer, medium, { right }, true);
  const std::vector<double> both = Integrate(renderer, medium, { left, right }, true);
  std::vector<double> sum(closed.size());
  for (size_t i = 0; i < sum.size(); ++i)
  {
    sum[i] = closed[i] + second[i];
  }
  const double linearity = Difference(sum, both);
  Check(linearity < 1e-12,
    "two lights give the sum of each (" + std::to_string(linearity) + " of the peak)");

  // No scattering: exactly nothing.
  vtkNew<vtkLightShaftMedium> clear;
  clear->SetScatteringCoefficient(0.0);
  clear->SetAbsorptionCoefficient(0.05);
  Check(Peak(Integrate(renderer, clear, { left }, true)) == 0.0,
    "a medium that does not scatter adds nothing");

  // An opaque slab across the left beam, below the light: less in-scatter, none added.
  const double slabCentre[3] = { -1.0, 2.5, 0.0 };
  const double slabLengths[3] = { 1.2, 0.1, 1.2 };
  AddBox(renderer, slabCentre, slabLengths);
  const std::vector<double> shadowed = Integrate(renderer, medium, { left }, true);
  Check(Sum(shadowed) < 0.9 * Sum(closed), "the occluder takes light from the beam");
  Check(Peak(shadowed) > 0.0, "light above the occluder still scatters");
  bool added = false;
  for (size_t i = 0; i < closed.size(); ++i)
  {
    added = added || shadowed[i] > closed[i] * (1.0 + 1e-9) + 1e-300;
  }
  Check(!added, "the occluder adds no light to any pixel");

  if (Failures == 0)
  {
    std::cout << "reference without GL: closed forms vs quadrature " << formsDifference
              << ", linearity " << linearity << " of the peak; all checks passed\n";
  }
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
