#include "vtkLightShaftExactFinish.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkLightShaftReferenceJob.h"
#include "vtkLightShaftReferenceScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMapper.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"

#include "vtkLightShaftExactFinishFS.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <numeric>
#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

using vtkLightShaftResources::TextureKind;

namespace
{
/// Tiles of this many pixels a side: a few milliseconds of a worker each.
constexpr int TileSide = 32;

/// The calling thread takes only the processor time others leave (Linux: SCHED_IDLE); where
/// the system has no such class it keeps its priority.
void YieldToRendering()
{
#if defined(__linux__) && defined(SCHED_IDLE)
  sched_param parameters{};
  parameters.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_IDLE, &parameters);
#endif
}

/// Back to the normal class, so that a worker told to stop is scheduled at once even where
/// other processes keep the processors busy (at the idle class it could wait for seconds).
/// Unprivileged processes may be refused (RLIMIT_NICE): the worker then stops at its pace.
void Expedite(std::thread& worker)
{
#if defined(__linux__) && defined(SCHED_IDLE)
  sched_param parameters{};
  parameters.sched_priority = 0;
  pthread_setschedparam(worker.native_handle(), SCHED_OTHER, &parameters);
#else
  (void)worker;
#endif
}
}

/// What the workers share with the render thread.
struct vtkLightShaftExactFinish::Work
{
  vtkLightShaftReferenceJob Job;
  std::vector<Tile> Tiles;
  std::atomic<int> Next{ 0 };
  std::atomic<bool> Cancel{ false };
  /// Pixels whose integration the reference's evaluation bound ended (their error estimate
  /// then above the tolerance).
  std::atomic<long long> ExhaustedPixels{ 0 };
  /// Set while the render thread renders a frame: the workers wait, so that the frame has the
  /// processors (and their caches) to itself.
  std::atomic<bool> Held{ false };
  std::mutex HoldMutex;
  std::condition_variable Resumed;

  void WaitWhileHeld()
  {
    if (this->Held)
    {
      // At most a second: a frame that long is no interactive frame, and the finish goes on
      // where no window event lets it (the hold is then dropped until the next frame).
      std::unique_lock<std::mutex> lock(this->HoldMutex);
      if (!this->Resumed.wait_for(
            lock, std::chrono::seconds(1), [this]() { return !this->Held || this->Cancel; }))
      {
        this->Held = false;
      }
    }
  }
  void SetHeld(bool held)
  {
    {
      std::lock_guard<std::mutex> lock(this->HoldMutex);
      this->Held = held;
    }
    if (!held)
    {
      this->Resumed.notify_all();
    }
  }
  std::mutex Mutex;
  /// The finished tiles' RGBA texels (alpha 1), the picture's rows, float: allocated by the
  /// render thread before the workers start, written by them tile by tile, uploaded from
  /// there. No memory passes between the threads: the render thread never frees what a worker
  /// allocated, which would wait for that worker's malloc arena, held by a thread that runs
  /// only when rendering leaves it time.
  std::vector<float> Texels;
  int Width = 0;
  /// Tiles finished and not yet shown (capacity reserved for all: no allocation).
  std::vector<int> Done;

  void Run()
  {
    YieldToRendering();
    std::vector<double> rgb;
    for (;;)
    {
      const int index = this->Next++;
      if (this->Cancel || index >= static_cast<int>(this->Tiles.size()))
      {
        return;
      }
      const Tile& tile = this->Tiles[index];
      rgb.assign(3 * static_cast<size_t>(tile.W) * tile.H, 0.0);
      for (int row = 0; row < tile.H; ++row)
      {
        this->WaitWhileHeld();
        if (this->Cancel)
        {
          return; // a change of the view
        }
        const vtkIdType first = vtkIdType(tile.Y + row) * this->Job.GetWidth() + tile.X;
        // The cancel request is watched inside each pixel: Stop() waits milliseconds, however
        // slow a pixel is, and the tile in flight is dropped.
        const vtkLightShaftReferenceJob::Tally tally = this->Job.Integrate(
          first, first + tile.W, rgb.data() + 3 * size_t(row) * tile.W, nullptr, &this->Cancel);
        if (tally.Cancelled)
        {
          return;
        }
        this->ExhaustedPixels += tally.ExhaustedPixels;
      }
      for (int row = 0; row < tile.H; ++row)
      {
        float* out = this->Texels.data() + 4 * (size_t(tile.Y + row) * this->Width + tile.X);
        for (int x = 0; x < tile.W; ++x)
        {
          for (int c = 0; c < 3; ++c)
          {
            out[4 * x + c] = static_cast<float>(rgb[3 * (size_t(row) * tile.W + x) + c]);
          }
          out[4 * x + 3] = 1.0f;
        }
      }
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Done.push_back(index);
    }
  }
};

//------------------------------------------------------------------------------
vtkLightShaftExactFinish::vtkLightShaftExactFinish() = default;

vtkLightShaftExactFinish::~vtkLightShaftExactFinish()
{
  this->Stop();
}

//------------------------------------------------------------------------------
std::string vtkLightShaftExactFinish::Unmodelled(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const double* center = camera->GetWindowCenter();
  if (camera->GetUseOffAxisProjection() || center[0] != 0.0 || center[1] != 0.0 ||
      camera->GetUserTransform() || camera->GetUserViewTransform() ||
      camera->GetUseExplicitProjectionTransformMatrix())
  {
    return "the camera's projection (off-axis, a window centre or a user transform)";
  }
  vtkCollectionSimpleIterator it;
  renderer->GetViewProps()->InitTraversal(it);
  while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(it))
  {
    if (!prop->GetVisibility() || !vtkProp3D::SafeDownCast(prop) || vtkVolume::SafeDownCast(prop))
    {
      continue; // overlays are not in the medium; the reference models a volume
    }
    auto* actor = vtkActor::SafeDownCast(prop);
    bool polygonal = false;
    const std::vector<vtkPolyData*> pieces =
      actor ? vtkLightShaftReferenceScene::Surfaces(actor, polygonal) : std::vector<vtkPolyData*>();
    if (!polygonal)
    {
      return std::string("a ") + prop->GetClassName() + " without polygonal input";
    }
    if (pieces.empty())
    {
      continue; // draws nothing
    }
    const bool lines = std::any_of(pieces.begin(),
      pieces.end(),
      [](vtkPolyData* piece)
      { return piece->GetNumberOfVerts() > 0 || piece->GetNumberOfLines() > 0; });
    if (actor->GetProperty()->GetOpacity() > 0.0 &&
        (actor->GetProperty()->GetRepresentation() != VTK_SURFACE || lines))
    {
      return "an actor drawn with points or lines";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
void vtkLightShaftExactFinish::Check(vtkRenderer* renderer)
{
  if (this->Current == State::Off)
  {
    this->Problem = Unmodelled(renderer);
    this->Current = this->Problem.empty() ? State::Off : State::Unsupported;
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftExactFinish::Start(vtkLightShaftFrame& frame,
  const vtkLightShaftReferenceInput& input,
  vtkTextureObject* estimate)
{
  if (this->Current != State::Off)
  {
    return;
  }
  this->Check(frame.Renderer);
  if (this->Current != State::Off)
  {
    return;
  }
  auto work = std::make_shared<Work>();
  this->Problem = work->Job.Prepare(frame.Renderer,
    input,
    frame.Owner,
    frame.Size[0],
    frame.Size[1],
    vtkLightShaftReferenceJob::Options());
  if (!this->Problem.empty())
  {
    this->Current = State::Failed;
    return;
  }
  this->Size[0] = frame.Size[0];
  this->Size[1] = frame.Size[1];
  this->OrderTiles(frame, estimate);
  work->Tiles = this->Tiles;
  work->Width = this->Size[0];
  work->Texels.assign(4 * size_t(this->Size[0]) * this->Size[1], 0.0f);
  work->Done.reserve(this->Tiles.size());

  // Nothing exact yet: alpha 0 everywhere.
  vtkTextureObject* exact =
    this->Exact.Ensure(frame.Window, TextureKind::RGBA32F, this->Size[0], this->Size[1]);
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { exact },
    nullptr,
    this->Size[0],
    this->Size[1]);
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  ostate->PopFramebufferBindings();

  this->Shared = work;
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  for (unsigned i = 0; i < threads; ++i)
  {
    this->Workers.emplace_back([work]() { work->Run(); });
  }
  this->Current = State::Running;
}

//------------------------------------------------------------------------------
// The tiles, brightest first: the error of a picture is mostly where its in-scatter is
// large (the relative RMS weighs each pixel by its square).
void vtkLightShaftExactFinish::OrderTiles(vtkLightShaftFrame& frame, vtkTextureObject* estimate)
{
  const int w = this->Size[0];
  const int h = this->Size[1];
  const int columns = (w + TileSide - 1) / TileSide;
  const int rows = (h + TileSide - 1) / TileSide;
  std::vector<Tile> tiles;
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const int x = i * TileSide;
      const int y = j * TileSide;
      tiles.push_back({ x, y, std::min(TileSide, w - x), std::min(TileSide, h - y) });
    }
  }
  std::vector<double> weight(tiles.size(), 0.0);
  if (estimate && static_cast<int>(estimate->GetWidth()) == w &&
      static_cast<int>(estimate->GetHeight()) == h)
  {
    // Every RowStride-th row is enough to rank the tiles, and costs that share of a full
    // read-back (the frame that starts the finish stays a cheap one).
    constexpr int RowStride = 8;
    std::vector<float> row(4 * static_cast<size_t>(w));
    vtkOpenGLState* ostate = frame.Window->GetState();
    ostate->PushFramebufferBindings();
    vtkLightShaftResources::BindTargets(
      vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
      { estimate },
      nullptr,
      w,
      h);
    this->Framebuffer->ActivateReadBuffer(0);
    GLint packAlignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int y = RowStride / 2; y < h; y += RowStride)
    {
      glReadPixels(0, y, w, 1, GL_RGBA, GL_FLOAT, row.data());
      for (int x = 0; x < w; ++x)
      {
        const float* p = &row[4 * size_t(x)];
        const double luminance = (double(p[0]) + p[1] + p[2]) / 3.0;
        weight[size_t(y / TileSide) * columns + x / TileSide] += luminance * luminance;
      }
    }
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
    ostate->PopFramebufferBindings();
  }
  std::vector<size_t> order(tiles.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return weight[a] > weight[b]; });
  this->Tiles.clear();
  for (size_t index : order)
  {
    this->Tiles.push_back(tiles[index]);
  }
}

//------------------------------------------------------------------------------
double vtkLightShaftExactFinish::Stop()
{
  const auto start = std::chrono::steady_clock::now();
  const bool running = !this->Workers.empty();
  if (this->Shared)
  {
    this->Shared->Cancel = true;
    this->Shared->SetHeld(false);
  }
  for (std::thread& worker : this->Workers)
  {
    Expedite(worker);
  }
  for (std::thread& worker : this->Workers)
  {
    worker.join();
  }
  this->Workers.clear();
  this->Shared.reset();
  this->Tiles.clear();
  this->Shown = 0;
  this->FinishedPixels = 0;
  this->Exhausted = 0;
  this->MixedValid = false;
  this->MixedEstimate = nullptr;
  this->Current = State::Off;
  this->Problem.clear();
  return running ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                 : 0.0;
}

//------------------------------------------------------------------------------
// The tiles finished since the last frame into the exact texture (alpha 1 marks them), and
// into `shown` too when given.
void vtkLightShaftExactFinish::Upload(vtkLightShaftFrame& frame, vtkTextureObject* shown)
{
  {
    // Never wait for a worker: one holding the lock may have been set aside for rendering
    // (it runs at idle priority); its tiles come with a later frame.
    std::unique_lock<std::mutex> lock(this->Shared->Mutex, std::try_to_lock);
    if (!lock.owns_lock())
    {
      return;
    }
    this->Finished.assign(this->Shared->Done.begin(), this->Shared->Done.end());
    this->Shared->Done.clear();
  }
  if (this->Finished.empty())
  {
    return;
  }
  vtkTextureObject* exact =
    this->Exact.Ensure(frame.Window, TextureKind::RGBA32F, this->Size[0], this->Size[1]);
  GLint unpackAlignment = 4;
  GLint unpackRowLength = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &unpackRowLength);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, this->Size[0]);
  for (vtkTextureObject* texture : { exact, shown })
  {
    if (!texture)
    {
      continue;
    }
    texture->Bind();
    for (int index : this->Finished)
    {
      const Tile& tile = this->Tiles[index];
      const float* texels =
        this->Shared->Texels.data() + 4 * (size_t(tile.Y) * this->Size[0] + tile.X);
      glTexSubImage2D(GL_TEXTURE_2D, 0, tile.X, tile.Y, tile.W, tile.H, GL_RGBA, GL_FLOAT, texels);
    }
  }
  for (int index : this->Finished)
  {
    this->FinishedPixels += static_cast<long long>(this->Tiles[index].W) * this->Tiles[index].H;
  }
  this->Shown += static_cast<int>(this->Finished.size());
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, unpackRowLength);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftExactFinish::Apply(vtkLightShaftFrame& frame,
  vtkTextureObject* estimate,
  bool estimateChanged)
{
  if (!this->IsActive() || frame.Size[0] != this->Size[0] || frame.Size[1] != this->Size[1])
  {
    return estimate;
  }
  // The same estimate as the last mix: the new tiles go straight into the mixed picture, and
  // the frame costs their upload only (no pass over the picture).
  const bool incremental =
    !estimateChanged && this->MixedValid && estimate == this->MixedEstimate && this->Mixed.Object;
  if (this->Current == State::Running)
  {
    this->Upload(frame, incremental ? this->Mixed.Object.GetPointer() : nullptr);
    if (this->Shown == static_cast<int>(this->Tiles.size()))
    {
      for (std::thread& worker : this->Workers)
      {
        worker.join(); // they have no tile left: they are returning
      }
      this->Workers.clear();
      this->Exhausted = this->Shared->ExhaustedPixels;
      this->Shared.reset();
      this->Current = State::Complete;
    }
  }
  if (this->Current == State::Complete)
  {
    return this->Exact.Object;
  }
  if (this->Shown == 0 || !estimate || static_cast<int>(estimate->GetWidth()) != this->Size[0] ||
      static_cast<int>(estimate->GetHeight()) != this->Size[1])
  {
    return estimate;
  }
  if (incremental)
  {
    return this->Mixed.Object;
  }
  vtkTextureObject* mixed =
    this->Mixed.Ensure(frame.Window, TextureKind::RGBA32F, this->Size[0], this->Size[1]);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { mixed },
    nullptr,
    this->Size[0],
    this->Size[1]);
  // Whatever the scene's render left on (the caller restores it).
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkShaderProgram* program = this->Mix.Ready(frame.Window, vtkLightShaftExactFinishFS);
  if (!program)
  {
    return estimate;
  }
  vtkTextureObject* exact = this->Exact.Object;
  estimate->Activate();
  exact->Activate();
  program->SetUniformi("estimate", estimate->GetTextureUnit());
  program->SetUniformi("exact", exact->GetTextureUnit());
  this->Mix.Render();
  ++frame.Statistics.PostPasses;
  exact->Deactivate();
  estimate->Deactivate();
  this->MixedValid = true;
  this->MixedEstimate = estimate;
  return mixed;
}

//------------------------------------------------------------------------------
void vtkLightShaftExactFinish::Hold(bool held)
{
  if (this->Shared)
  {
    this->Shared->SetHeld(held);
  }
}

//------------------------------------------------------------------------------
long long vtkLightShaftExactFinish::GetExhaustedPixels() const
{
  return this->Shared ? this->Shared->ExhaustedPixels.load() : this->Exhausted;
}

//------------------------------------------------------------------------------
double vtkLightShaftExactFinish::GetFinishedFraction() const
{
  const double pixels = double(this->Size[0]) * this->Size[1];
  return this->Current == State::Complete ? 1.0
         : pixels > 0.0                   ? double(this->FinishedPixels) / pixels
                                          : 0.0;
}

//------------------------------------------------------------------------------
void vtkLightShaftExactFinish::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Stop();
  this->Exact.Release(window);
  this->Mixed.Release(window);
  this->Mix.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
