// Image-regression and basic C++ API test of vtkLightShaftPass: renders the sphere-and-floor
// scene offscreen, checks the in-scatter readback, compares the frame with a baseline PNG,
// renders a frame with every method and selects through the pass with VTK's hardware
// selector. Any error or warning VTK prints (but the one documented warning the test meets)
// fails the test.
//
// Usage: TestLightShaftPass <baseline.png> [--update]
//   --update writes the baseline instead of comparing (then check the image by eye).

#include "LightShaftTestScene.h" // For the sphere-and-floor scene
#include "vtkLightShaftPass.h"

#include "vtkCallbackCommand.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Explicit thresholds: the mean absolute difference over all channels, and the fraction of
// pixels allowed to differ by more than 8 levels in some channel (driver rounding, sphere
// silhouettes).
constexpr double MaximumMeanAbsoluteDifference = 1.0;
constexpr double MaximumFractionOfDifferentPixels = 0.005;

int Fail(const std::string& message)
{
  std::cerr << "FAIL: " << message << std::endl;
  return EXIT_FAILURE;
}

// Every error and warning VTK prints through its output window.
struct MessageLog
{
  std::vector<std::string> Unexpected;
  std::string Expected; // a substring of the one message the test means to meet

  static void Record(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* log = static_cast<MessageLog*>(clientData);
    const std::string text = callData ? static_cast<const char*>(callData) : "";
    if (log->Expected.empty() || text.find(log->Expected) == std::string::npos)
    {
      log->Unexpected.push_back(text);
    }
  }
};
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    return Fail("usage: TestLightShaftPass <baseline.png> [--update]");
  }
  const std::string baseline = argv[1];
  const bool update = argc > 2 && std::strcmp(argv[2], "--update") == 0;

  MessageLog messages;
  vtkNew<vtkCallbackCommand> recorder;
  recorder->SetCallback(MessageLog::Record);
  recorder->SetClientData(&messages);
  vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::ErrorEvent, recorder);
  vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::WarningEvent, recorder);

  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(true);
  window->SetMultiSamples(0);
  window->SetSize(320, 240);
  window->AddRenderer(renderer);
  lightshafts_test::AddSphereAndFloor(renderer);

  vtkNew<vtkLightShaftPass> shafts;
  shafts->GetMedium()->SetScatteringCoefficient(0.05, 0.045, 0.04);
  shafts->GetMedium()->SetAbsorptionCoefficient(0.01);
  shafts->SetExposure(40.0);
  shafts->SetNumberOfSlices(256);
  shafts->SetShadowMapSize(1024);
  shafts->JitterOff();
  shafts->SetBlurRadius(0);
  renderer->SetPass(shafts);
  window->Render();

  if (shafts->GetLastFrame()->GetGLErrorCount() != 0)
  {
    return Fail("OpenGL errors during the frame");
  }
  if (shafts->GetLastFrame()->GetNumberOfSlicesDrawn() != 256 ||
      !shafts->GetLastFrame()->GetShadowMapRendered())
  {
    return Fail("expected 256 slabs and a shadow map");
  }
  vtkNew<vtkImageData> radiance;
  if (!shafts->GetInScatteredRadiance(radiance))
  {
    return Fail("no in-scatter readback");
  }
  int dims[3];
  radiance->GetDimensions(dims);
  auto* values = vtkFloatArray::SafeDownCast(radiance->GetPointData()->GetScalars());
  if (dims[0] != 320 || dims[1] != 240 || !values || values->GetNumberOfComponents() != 3)
  {
    return Fail("in-scatter readback has the wrong layout");
  }
  double peak = 0.0;
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    const double v = values->GetValue(i);
    if (!std::isfinite(v) || v < 0.0)
    {
      return Fail("non-finite or negative in-scattered radiance");
    }
    peak = std::max(peak, v);
  }
  if (!(peak > 0.0))
  {
    return Fail("no in-scattered light");
  }

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* frame = grab->GetOutput();

  if (update)
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(baseline.c_str());
    writer->SetInputData(frame);
    writer->Write();
    std::cout << "baseline written: " << baseline << std::endl;
    return EXIT_SUCCESS;
  }

  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(baseline.c_str()))
  {
    return Fail("cannot read baseline " + baseline + " (run with --update to create it)");
  }
  reader->SetFileName(baseline.c_str());
  reader->Update();
  vtkImageData* expected = reader->GetOutput();
  int expectedDims[3];
  expected->GetDimensions(expectedDims);
  if (expectedDims[0] != 320 || expectedDims[1] != 240 ||
      expected->GetNumberOfScalarComponents() < 3)
  {
    return Fail("baseline has the wrong size");
  }
  auto* a = vtkUnsignedCharArray::SafeDownCast(frame->GetPointData()->GetScalars());
  auto* b = vtkUnsignedCharArray::SafeDownCast(expected->GetPointData()->GetScalars());
  const int ca = a->GetNumberOfComponents();
  const int cb = b->GetNumberOfComponents();
  double sum = 0.0;
  vtkIdType different = 0;
  const vtkIdType pixels = 320 * 240;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int d = std::abs(static_cast<int>(a->GetValue(p * ca + c)) - b->GetValue(p * cb + c));
      sum += d;
      worst = std::max(worst, d);
    }
    different += worst > 8 ? 1 : 0;
  }
  const double mean = sum / (3.0 * pixels);
  const double fraction = static_cast<double>(different) / pixels;
  std::cout << "mean absolute difference " << mean << " (limit " << MaximumMeanAbsoluteDifference
            << "), pixels differing by > 8: " << 100.0 * fraction << "% (limit "
            << 100.0 * MaximumFractionOfDifferentPixels << "%)" << std::endl;
  if (mean > MaximumMeanAbsoluteDifference || fraction > MaximumFractionOfDifferentPixels)
  {
    vtkNew<vtkPNGWriter> writer;
    const std::string actual = baseline.substr(0, baseline.size() - 4) + ".actual.png";
    writer->SetFileName(actual.c_str());
    writer->SetInputData(frame);
    writer->Write();
    return Fail("image differs from the baseline; this frame: " + actual);
  }

  // Every other method, a frame each, with the lattice and the interleaved march too (what
  // tools/memcheck.sh runs under valgrind): no GL error, in-scattered light. ANALYTIC warns
  // (documented) that it ignores the sphere's shadow.
  messages.Expected = "Method ANALYTIC ignores shadows";
  shafts->SetLatticeResolution(8);
  for (int method : { vtkLightShaftPass::SLICES,
         vtkLightShaftPass::RAY_MARCH,
         vtkLightShaftPass::RADIAL_BLUR,
         vtkLightShaftPass::ANALYTIC,
         vtkLightShaftPass::AUTOMATIC })
  {
    shafts->SetMethod(method);
    window->Render();
    vtkNew<vtkImageData> methodRadiance;
    if (shafts->GetLastFrame()->GetGLErrorCount() != 0 ||
        !shafts->GetInScatteredRadiance(methodRadiance) ||
        methodRadiance->GetPointData()->GetScalars()->GetRange(0)[1] <= 0.0)
    {
      return Fail(std::string("method ") + vtkLightShaftPass::GetMethodName(method) +
                  ": GL errors or no in-scattered light");
    }
  }

  // Hardware selection through the pass: both props, as without it; then the shafts again.
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetArea(0, 0, 319, 239);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  if (!selection || selection->GetNumberOfNodes() != 2 || !shafts->GetLastFrame()->GetPlainScene())
  {
    return Fail("hardware selection through the pass did not find the sphere and the floor");
  }
  window->Render();
  if (shafts->GetLastFrame()->GetPlainScene() || shafts->GetLastFrame()->GetMethod() < 0)
  {
    return Fail("no shafts in the frame after the selection");
  }

  for (const std::string& message : messages.Unexpected)
  {
    std::cerr << "unexpected VTK message: " << message << std::endl;
  }
  if (!messages.Unexpected.empty())
  {
    return Fail("VTK printed errors or warnings");
  }
  return EXIT_SUCCESS;
}
