// vtkLightShaftPass across what changes a window's GL context and framebuffer: sizes at the
// extremes, resizes, a second window (a second context) alive at the same time, releasing the
// pass's resources, and a window destroyed and created again. Written for the headless
// backends (EGL pbuffers, OSMesa buffers; tools/test-headless.sh) and run with the X build too.
// On the sphere-and-floor scene (32 plain slabs, 1024^2 shadow map unless said):
//   1. 160x120: the first frame F0 (in-scatter and RGB pixels), kept;
//   2. 1x1 (512 slabs, 2048^2 shadow map): the one pixel within 1% of the float64 reference
//      vtkLightShaftReference in every channel;
//   3. 256x256, then 4096x4096: the viewport is 4096^2, the in-scatter finite, and its mean
//      within 1% of the 256x256 frame's (the mean in-scatter is an integral over the picture,
//      independent of the resolution up to sampling);
//   4. back to 160x120: F0 again, in-scatter within 1e-6 of its peak and RGB within 1 level;
//   5. a second window with its own scene and pass: F0; the first window rendered again, then
//      after the second is destroyed, then after ReleaseGraphicsResources: F0 each time;
//   6. the first window destroyed and a new one created: F0.
// Every frame without GL error; any error or warning VTK prints fails the test. The figures are
// printed on one line, "contexts: ...", which tools/test-headless.sh reports.
//
// Usage: TestLightShaftContexts [--expect-window <class>]

#include "LightShaftTestScene.h"

#include "vtkLightShaftReference.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace
{
// Stated bounds (see the file's comment).
constexpr double MaximumOnePixelRelativeError = 0.01;
constexpr double MaximumMeanChangeWithResolution = 0.01;
constexpr double MaximumRepeatDifferenceOverPeak = 1e-6;
constexpr int MaximumRepeatPixelDifference = 1;

int Failures = 0;
std::ostringstream Summary;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << std::endl;
    ++Failures;
  }
}

/// A window of its own with the scene, a renderer and a pass.
struct View
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkLightShaftPass> Shafts;

  View(int width, int height)
  {
    this->Window->SetOffScreenRendering(true);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    lightshafts_test::AddSphereAndFloor(this->Renderer);
    this->Shafts->GetMedium()->SetScatteringCoefficient(0.05, 0.045, 0.04);
    this->Shafts->GetMedium()->SetAbsorptionCoefficient(0.01);
    this->SetSampling(32, 1024);
    this->Shafts->JitterOff();
    this->Shafts->SetBlurRadius(0);
    this->Renderer->SetPass(this->Shafts);
  }

  void SetSampling(int slices, int shadowMapSize)
  {
    this->Shafts->SetNumberOfSlices(slices);
    this->Shafts->SetShadowMapSize(shadowMapSize);
  }

  /// Renders at width x height and checks what every frame must be; returns the in-scatter.
  lightshafts_test::Image Render(int width, int height, const std::string& what)
  {
    this->Window->SetSize(width, height);
    const auto start = std::chrono::steady_clock::now();
    this->Window->Render();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << what << ": " << width << "x" << height << " in " << seconds << " s" << std::endl;
    Check(this->Shafts->GetLastFrame()->GetGLErrorCount() == 0, what + ": OpenGL errors");
    const int* viewport = this->Shafts->GetLastFrame()->GetViewportSize();
    Check(viewport[0] == width && viewport[1] == height,
      what + ": viewport " + std::to_string(viewport[0]) + "x" + std::to_string(viewport[1]));
    lightshafts_test::Image image = lightshafts_test::InScatter(this->Shafts);
    Check(image.Width == width && image.Height == height, what + ": in-scatter size");
    Check(image.FiniteAndNonNegative(), what + ": non-finite or negative in-scatter");
    Check(image.Peak() > 0.0, what + ": no in-scattered light");
    return image;
  }

  /// The window's RGB pixels as rendered (re-rendered into the back buffer and read, as
  /// TestLightShaftPass reads them: after a frame the back buffer may have been swapped away).
  std::vector<int> Pixels()
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkDataArray* data = grab->GetOutput()->GetPointData()->GetScalars();
    std::vector<int> pixels(static_cast<size_t>(data->GetNumberOfValues()));
    for (vtkIdType i = 0; i < data->GetNumberOfValues(); ++i)
    {
      pixels[static_cast<size_t>(i)] = static_cast<int>(data->GetComponent(i / 3, i % 3));
    }
    return pixels;
  }
};

struct FirstFrame
{
  lightshafts_test::Image InScatter;
  std::vector<int> Pixels;
};

/// Checks that `view`'s 160x120 frame is the first frame again.
void CheckSameAsFirst(View& view, const FirstFrame& first, const std::string& what)
{
  const lightshafts_test::Image image = view.Render(160, 120, what);
  const double difference =
    lightshafts_test::MaximumDifference(image, first.InScatter) / first.InScatter.Peak();
  const std::vector<int> pixels = view.Pixels();
  int pixelDifference = pixels.size() == first.Pixels.size() ? 0 : 256;
  for (size_t i = 0; pixelDifference < 256 && i < pixels.size(); ++i)
  {
    pixelDifference = std::max(pixelDifference, std::abs(pixels[i] - first.Pixels[i]));
  }
  Summary << "; " << what << ": " << difference << " of the peak, " << pixelDifference
          << " level(s)";
  Check(difference <= MaximumRepeatDifferenceOverPeak,
    what + ": in-scatter differs from the first frame by " + std::to_string(difference));
  Check(pixelDifference <= MaximumRepeatPixelDifference,
    what + ": pixels differ from the first frame by " + std::to_string(pixelDifference));
}

double Mean(const lightshafts_test::Image& image)
{
  return image.Sum() / static_cast<double>(image.Values.size());
}
}

int main(int argc, char* argv[])
{
  lightshafts_test::MessageLog messages;
  FirstFrame first;
  {
    auto a = std::make_unique<View>(160, 120);
    if (!lightshafts_test::CheckWindowClass(a->Window, argc, argv))
    {
      return EXIT_FAILURE;
    }
    Summary << "contexts: window " << a->Window->GetClassName();

    // 1. The first frame.
    first.InScatter = a->Render(160, 120, "first frame");
    first.Pixels = a->Pixels();

    // 2. One pixel, against the reference.
    a->SetSampling(512, 2048);
    const lightshafts_test::Image one = a->Render(1, 1, "1x1");
    vtkNew<vtkLightShaftReference> reference;
    reference->SetRenderer(a->Renderer);
    reference->SetLightShaftPass(a->Shafts);
    reference->Update();
    const lightshafts_test::Image expected =
      lightshafts_test::ToImage(reference->GetOutput(), "InScatteredRadiance");
    double worst = INFINITY;
    if (expected.Width == 1 && expected.Height == 1 && one.Width == 1 && expected.Peak() > 0.0)
    {
      worst = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(one.Values[c] - expected.Values[c]) / expected.Values[c]);
      }
    }
    Summary << "; 1x1 relative error " << worst;
    Check(worst <= MaximumOnePixelRelativeError, "1x1: relative error against the reference");
    a->SetSampling(32, 1024);

    // 3. 256x256 and 4096x4096: the same mean.
    const double mean256 = Mean(a->Render(256, 256, "256x256"));
    const double mean4096 = Mean(a->Render(4096, 4096, "4096x4096"));
    const double change = std::abs(mean4096 / mean256 - 1.0);
    Summary << "; 4096x4096 mean over 256x256 mean - 1: " << mean4096 / mean256 - 1.0;
    Check(change <= MaximumMeanChangeWithResolution,
      "4096x4096: mean in-scatter differs from 256x256's by " + std::to_string(change));

    // 4. Back to the first size.
    CheckSameAsFirst(*a, first, "resized back");

    // 5. A second context alive at the same time, then gone; the pass's resources released.
    {
      View b(160, 120);
      CheckSameAsFirst(b, first, "second window");
      CheckSameAsFirst(*a, first, "first window again");
    }
    CheckSameAsFirst(*a, first, "second window destroyed");
    a->Shafts->ReleaseGraphicsResources(a->Window);
    CheckSameAsFirst(*a, first, "after ReleaseGraphicsResources");
  }
  // 6. A new window after the first one was destroyed.
  {
    View c(160, 120);
    CheckSameAsFirst(c, first, "new window");
  }

  Check(messages.Report() == 0, "VTK printed errors or warnings");
  std::cout << Summary.str() << std::endl;
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
