#include "vtkPVLightShaftsExchange.h"

#include "vtkLightShaftGeometry.h"
#include "vtkLightShaftResources.h"

#include "vtkCameraPass.h"
#include "vtkCollection.h"
#include "vtkCommunicator.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkLightShaftPass.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <vector>

namespace
{
// The rows of an image piece, counted.
int RowCount(const std::vector<vtkLightShaftGeometry::RowBlock>& rows)
{
  int count = 0;
  for (const vtkLightShaftGeometry::RowBlock& block : rows)
  {
    count += block.End - block.First;
  }
  return count;
}

// A 2D depth texture's values as float into `values` (resized), and back.
void ReadDepth(vtkTextureObject* texture, std::vector<float>& values)
{
  values.resize(static_cast<size_t>(texture->GetWidth()) * texture->GetHeight());
  texture->Bind();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, values.data());
  texture->Deactivate();
}

void WriteDepth(vtkTextureObject* texture, const std::vector<float>& values)
{
  texture->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D,
    0,
    0,
    0,
    static_cast<GLsizei>(texture->GetWidth()),
    static_cast<GLsizei>(texture->GetHeight()),
    GL_DEPTH_COMPONENT,
    GL_FLOAT,
    values.data());
  texture->Deactivate();
}
}

//------------------------------------------------------------------------------
vtkPVLightShaftsExchange::vtkPVLightShaftsExchange() = default;
vtkPVLightShaftsExchange::~vtkPVLightShaftsExchange() = default;

//------------------------------------------------------------------------------
void vtkPVLightShaftsExchange::AgreeOnReuse(int* reuse, vtkMultiProcessController* controller)
{
  if (!reuse || !controller)
  {
    return;
  }
  int mine = *reuse;
  controller->AllReduce(&mine, reuse, 1, vtkCommunicator::MIN_OP);
  this->Bytes += 2.0 * sizeof(int);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsExchange::AgreeOnTimes(double* seconds, vtkMultiProcessController* controller)
{
  if (!seconds || !controller)
  {
    return;
  }
  const double mine[2] = { seconds[0], seconds[1] };
  controller->AllReduce(mine, seconds, 2, vtkCommunicator::MAX_OP);
  this->Bytes += 4.0 * sizeof(double);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsExchange::CombineShadowMaps(vtkLightShaftPass* pass,
  vtkMultiProcessController* controller)
{
  vtkTextureObject* map = pass->GetShadowMapTexture();
  if (!controller || !map)
  {
    return;
  }
  // Every process renders a map with the same light camera (SetShadowCasterBounds), so the
  // minimum depth per texel is the nearest occluder of any process.
  ReadDepth(map, this->Local);
  this->Combined.resize(this->Local.size());
  controller->AllReduce(this->Local.data(),
    this->Combined.data(),
    static_cast<vtkIdType>(this->Local.size()),
    vtkCommunicator::MIN_OP);
  WriteDepth(map, this->Combined);
  this->Bytes += 2.0 * sizeof(float) * this->Local.size(); // (an all-reduce: sent and received)
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsExchange::ShareSceneDepth(vtkLightShaftPass* pass,
  vtkMultiProcessController* controller,
  vtkRenderer* opaque,
  vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* depth = pass->GetSceneDepthTexture();
  if (!controller || !depth)
  {
    return;
  }
  std::vector<float>& values = this->Local;
  if (!opaque || !window)
  {
    // IceT composites depth on process 0 only: process 0 gives it to the others.
    const bool root = controller->GetLocalProcessId() == 0;
    if (root)
    {
      ReadDepth(depth, values);
    }
    else
    {
      values.resize(static_cast<size_t>(depth->GetWidth()) * depth->GetHeight());
    }
    controller->Broadcast(values.data(), static_cast<vtkIdType>(values.size()), 0);
    if (!root)
    {
      WriteDepth(depth, values);
    }
    this->Bytes +=
      sizeof(float) * values.size() * (root ? controller->GetNumberOfProcesses() - 1 : 1);
    return;
  }
  // IceT composites in order (volumes, translucent surfaces): colour only, and process 0 is
  // left no depth of its own. Each process renders its opaque props' depth again; the nearest
  // surface of any process is the minimum.
  this->RenderOpaqueDepth(opaque, window, depth->GetWidth(), depth->GetHeight());
  this->Combined.resize(values.size());
  controller->AllReduce(values.data(),
    this->Combined.data(),
    static_cast<vtkIdType>(values.size()),
    vtkCommunicator::MIN_OP);
  WriteDepth(depth, this->Combined);
  this->Bytes += 2.0 * sizeof(float) * values.size();
}

//------------------------------------------------------------------------------
// The depth of `renderer`'s visible opaque props from its camera, `width` x `height`, into Local.
void vtkPVLightShaftsExchange::RenderOpaqueDepth(vtkRenderer* renderer,
  vtkOpenGLRenderWindow* window,
  int width,
  int height)
{
  std::vector<vtkProp*> props;
  vtkCollectionSimpleIterator it;
  vtkPropCollection* all = renderer->GetViewProps();
  all->InitTraversal(it);
  while (vtkProp* prop = all->GetNextProp(it))
  {
    if (prop->GetVisibility())
    {
      props.push_back(prop);
    }
  }
  vtkOpenGLState* ostate = window->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  ostate->PushFramebufferBindings();
  vtkNew<vtkTextureObject> depth;
  depth->SetContext(window);
  depth->AllocateDepth(width, height, vtkTextureObject::Float32);
  vtkNew<vtkOpenGLFramebufferObject> framebuffer;
  framebuffer->SetContext(window);
  vtkLightShaftResources::BindTargets(framebuffer, {}, depth, width, height);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  vtkRenderState state(renderer);
  state.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  state.SetFrameBuffer(framebuffer);
  this->CameraPass->SetDelegatePass(this->OpaquePass);
  this->CameraPass->Render(&state);
  ostate->PopFramebufferBindings();
  ReadDepth(depth, this->Local);
  framebuffer->ReleaseGraphicsResources(window);
  depth->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkPVLightShaftsExchange::GatherInScatter(vtkLightShaftPass* pass,
  vtkMultiProcessController* controller,
  vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* inScatter = pass->GetInScatterPieceTexture();
  if (!controller || !inScatter || !window)
  {
    return;
  }
  const int width = static_cast<int>(inScatter->GetWidth());
  const int height = static_cast<int>(inScatter->GetHeight());
  const int pieces = controller->GetNumberOfProcesses();
  const int rank = controller->GetLocalProcessId();
  const vtkIdType rowValues = 4 * static_cast<vtkIdType>(width);
  // Each process's rows, by the pass's rule, and where they go in process 0's buffer.
  std::vector<std::vector<vtkLightShaftGeometry::RowBlock>> rows(pieces);
  std::vector<vtkIdType> lengths(pieces);
  std::vector<vtkIdType> offsets(pieces);
  vtkIdType total = 0;
  for (int p = 0; p < pieces; ++p)
  {
    rows[p] = vtkLightShaftGeometry::ImagePieceRows(p, pieces, height);
    lengths[p] = RowCount(rows[p]) * rowValues;
    offsets[p] = total;
    total += lengths[p];
  }

  // This process's rows, read through a framebuffer (a block at a time).
  vtkOpenGLState* ostate = window->GetState();
  std::vector<float>& mine = this->Local;
  mine.resize(static_cast<size_t>(lengths[rank]));
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    ostate->PushFramebufferBindings();
    vtkNew<vtkOpenGLFramebufferObject> framebuffer;
    framebuffer->SetContext(window);
    framebuffer->Bind();
    framebuffer->AddColorAttachment(0, inScatter);
    framebuffer->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    float* out = mine.data();
    for (const vtkLightShaftGeometry::RowBlock& block : rows[rank])
    {
      const int count = block.End - block.First;
      glReadPixels(0, block.First, width, count, GL_RGBA, GL_FLOAT, out);
      out += count * rowValues;
    }
    framebuffer->RemoveColorAttachment(0);
    ostate->PopFramebufferBindings();
    framebuffer->ReleaseGraphicsResources(window);
  }
  std::vector<float>& gathered = this->Combined;
  gathered.resize(rank == 0 ? static_cast<size_t>(total) : 0);
  controller->GatherV(
    mine.data(), gathered.data(), lengths[rank], lengths.data(), offsets.data(), 0);
  this->Bytes += sizeof(float) * (rank == 0 ? total - lengths[0] : lengths[rank]);
  if (rank != 0)
  {
    return;
  }
  // The other processes' rows into process 0's in-scatter.
  inScatter->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int p = 1; p < pieces; ++p)
  {
    const float* in = gathered.data() + offsets[p];
    for (const vtkLightShaftGeometry::RowBlock& block : rows[p])
    {
      const int count = block.End - block.First;
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, block.First, width, count, GL_RGBA, GL_FLOAT, in);
      in += count * rowValues;
    }
  }
  inScatter->Deactivate();
}
