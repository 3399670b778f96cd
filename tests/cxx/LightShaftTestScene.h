// What the C++ accuracy and context tests share: the sphere-and-floor scene of
// TestLightShaftPass, a record of every error and warning VTK prints, the pass's in-scatter and
// the reference's output as numbers, and the error measures of tests/python (relative RMS over
// the pixels the light reaches, energy).

#ifndef LightShaftTestScene_h
#define LightShaftTestScene_h

#include "vtkActor.h"           // For the scene's props
#include "vtkCallbackCommand.h" // For observing VTK's output window
#include "vtkCamera.h"          // For the scene's view
#include "vtkDataArray.h"       // For reading images as numbers
#include "vtkImageData.h"       // For the in-scatter and the reference's output
#include "vtkLight.h"           // For the scene's spotlight
#include "vtkLightShaftPass.h"  // For the pass under test
#include "vtkNew.h"             // For vtkNew
#include "vtkOutputWindow.h"    // For the messages VTK prints
#include "vtkPlaneSource.h"     // For the floor
#include "vtkPointData.h"       // For the images' arrays
#include "vtkPolyDataMapper.h"  // For the props' mappers
#include "vtkProperty.h"        // For the sphere's colour
#include "vtkRenderWindow.h"    // For the window's class name
#include "vtkRenderer.h"        // For the renderer the scene goes into
#include "vtkSphereSource.h"    // For the occluding sphere

#include <algorithm> // For std::max
#include <cmath>     // For std::sqrt, std::isfinite
#include <iostream>  // For std::cerr
#include <string>    // For std::string
#include <vector>    // For std::vector

namespace lightshafts_test
{
/// Every error and warning VTK prints through its output window, from construction on.
class MessageLog
{
public:
  MessageLog()
  {
    this->Recorder->SetCallback(&MessageLog::Record);
    this->Recorder->SetClientData(this);
    vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::ErrorEvent, this->Recorder);
    vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::WarningEvent, this->Recorder);
  }
  ~MessageLog() { vtkOutputWindow::GetInstance()->RemoveObserver(this->Recorder); }
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;

  /// Prints the messages recorded and returns how many there were.
  size_t Report() const
  {
    for (const std::string& message : this->Messages)
    {
      std::cerr << "unexpected VTK message: " << message << std::endl;
    }
    return this->Messages.size();
  }

private:
  static void Record(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<MessageLog*>(clientData)
      ->Messages.emplace_back(callData ? static_cast<const char*>(callData) : "");
  }

  vtkNew<vtkCallbackCommand> Recorder;
  std::vector<std::string> Messages;
};

/// The scene of TestLightShaftPass: a sphere over a floor under a spotlight aiming down, seen
/// from the front; the sphere shadows part of the beam.
inline void AddSphereAndFloor(vtkRenderer* renderer)
{
  renderer->SetBackground(0.02, 0.02, 0.05);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 1.5, 0.0);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(128);
  sphere->SetPhiResolution(128);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(0.9, 0.5, 0.3);
  renderer->AddActor(sphereActor);

  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-6.0, 0.0, -6.0);
  floor->SetPoint1(-6.0, 0.0, 6.0);
  floor->SetPoint2(6.0, 0.0, -6.0);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floor->GetOutputPort());
  vtkNew<vtkActor> floorActor;
  floorActor->SetMapper(floorMapper);
  renderer->AddActor(floorActor);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(0.5, 6.0, 0.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetConeAngle(30.0);
  renderer->AddLight(light);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 3.0, 12.0);
  camera->SetFocalPoint(0.0, 2.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

/// An RGB image as doubles, row 0 at the bottom (the in-scatter's and the reference's layout).
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Values; // Width * Height * 3

  bool Empty() const { return this->Values.empty(); }
  double Peak() const
  {
    double peak = 0.0;
    for (double v : this->Values)
    {
      peak = std::max(peak, v);
    }
    return peak;
  }
  double Sum() const
  {
    double sum = 0.0;
    for (double v : this->Values)
    {
      sum += v;
    }
    return sum;
  }
  /// True when every value is finite and >= 0.
  bool FiniteAndNonNegative() const
  {
    for (double v : this->Values)
    {
      if (!std::isfinite(v) || v < 0.0)
      {
        return false;
      }
    }
    return true;
  }
};

/// The 3-component array `name` of `data` (its scalars when `name` is null); empty when absent.
inline Image ToImage(vtkImageData* data, const char* name = nullptr)
{
  Image image;
  vtkDataArray* array =
    name ? data->GetPointData()->GetArray(name) : data->GetPointData()->GetScalars();
  int dims[3];
  data->GetDimensions(dims);
  if (!array || array->GetNumberOfComponents() != 3 ||
      array->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    return image;
  }
  image.Width = dims[0];
  image.Height = dims[1];
  image.Values.resize(static_cast<size_t>(array->GetNumberOfValues()));
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    image.Values[static_cast<size_t>(i)] = array->GetComponent(i / 3, static_cast<int>(i % 3));
  }
  return image;
}

/// The pass's last in-scattered radiance (empty when it has none).
inline Image InScatter(vtkLightShaftPass* shafts)
{
  vtkNew<vtkImageData> data;
  if (!shafts->GetInScatteredRadiance(data))
  {
    return Image();
  }
  return ToImage(data);
}

/// ||image - reference|| / ||reference|| over the pixels whose reference luminance (mean of
/// the channels) exceeds `threshold` times its maximum, as tests/python's relative_rms_error.
/// Returns infinity when the sizes differ or no pixel qualifies.
inline double RelativeRmsError(const Image& image, const Image& reference, double threshold = 0.01)
{
  if (image.Width != reference.Width || image.Height != reference.Height || reference.Empty())
  {
    return INFINITY;
  }
  const size_t pixels = reference.Values.size() / 3;
  double peak = 0.0;
  for (size_t p = 0; p < pixels; ++p)
  {
    const double* r = &reference.Values[3 * p];
    peak = std::max(peak, (r[0] + r[1] + r[2]) / 3.0);
  }
  double difference = 0.0;
  double norm = 0.0;
  for (size_t p = 0; p < pixels; ++p)
  {
    const double* r = &reference.Values[3 * p];
    if ((r[0] + r[1] + r[2]) / 3.0 <= threshold * peak)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double d = image.Values[3 * p + c] - r[c];
      difference += d * d;
      norm += r[c] * r[c];
    }
  }
  return norm > 0.0 ? std::sqrt(difference / norm) : INFINITY;
}

/// |sum(image) - sum(reference)| / sum(reference).
inline double EnergyError(const Image& image, const Image& reference)
{
  const double total = reference.Sum();
  return total > 0.0 ? std::abs(image.Sum() - total) / total : INFINITY;
}

/// The largest |image - reference| over all values (infinity when the sizes differ).
inline double MaximumDifference(const Image& image, const Image& reference)
{
  if (image.Width != reference.Width || image.Height != reference.Height)
  {
    return INFINITY;
  }
  double largest = 0.0;
  for (size_t i = 0; i < image.Values.size(); ++i)
  {
    largest = std::max(largest, std::abs(image.Values[i] - reference.Values[i]));
  }
  return largest;
}

/// Checks the window's class against `--expect-window <class>` when given (the headless tests
/// prove which backend rendered: vtkEGLRenderWindow, vtkOSOpenGLRenderWindow); prints it.
inline bool CheckWindowClass(vtkRenderWindow* window, int argc, char* argv[])
{
  const std::string actual = window->GetClassName();
  std::cout << "render window: " << actual << std::endl;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "--expect-window" && actual != argv[i + 1])
    {
      std::cerr << "FAIL: render window is " << actual << ", expected " << argv[i + 1] << std::endl;
      return false;
    }
  }
  return true;
}
}

#endif
