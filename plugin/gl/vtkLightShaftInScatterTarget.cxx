#include "vtkLightShaftInScatterTarget.h"

#include "vtkLightShaftFrame.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftAddFS.h"
#include "vtkLightShaftDepthDownsampleFS.h"

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftInScatterTarget::vtkLightShaftInScatterTarget() = default;
vtkLightShaftInScatterTarget::~vtkLightShaftInScatterTarget() = default;

vtkTextureObject* vtkLightShaftInScatterTarget::GetDepth()
{
  return this->Depth;
}

vtkTextureObject* vtkLightShaftInScatterTarget::GetAccumulation(int index)
{
  return this->Accumulation[index].Object;
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatterTarget::PrepareDepth(vtkLightShaftFrame& frame)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int factor = frame.Parameters.DownsampleFactor;
  const int lw = frame.Reduced[0];
  const int lh = frame.Reduced[1];
  this->Size[0] = lw;
  this->Size[1] = lh;
  this->Summed = false;
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // The depth the shafts read: the scene's, or at reduced resolution the nearest of each block.
  this->Depth = frame.Scene.ShaftDepth;
  if (factor > 1)
  {
    this->Depth = this->ReducedDepth.Ensure(window, TextureKind::Depth, lw, lh);
    vtkLightShaftResources::BindTargets(
      vtkLightShaftResources::EnsureFramebuffer(this->DepthFramebuffer, window),
      {},
      this->Depth,
      lw,
      lh);
    if (vtkShaderProgram* program =
          this->DepthDownsample.Ready(window, vtkLightShaftDepthDownsampleFS))
    {
      ostate->vtkglEnable(GL_DEPTH_TEST);
      ostate->vtkglDepthFunc(GL_ALWAYS);
      ostate->vtkglDepthMask(GL_TRUE);
      frame.Scene.ShaftDepth->Activate();
      program->SetUniformi("fullDepth", frame.Scene.ShaftDepth->GetTextureUnit());
      program->SetUniformi("factor", factor);
      const float reducedSize[2] = { static_cast<float>(lw), static_cast<float>(lh) };
      program->SetUniform2f("reducedSize", reducedSize);
      this->DepthDownsample.Render();
      frame.Scene.ShaftDepth->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatterTarget::Clear(vtkLightShaftFrame& frame,
  int buffers,
  vtkLightShaftResources::TextureKind kind)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int lw = this->Size[0];
  const int lh = this->Size[1];
  this->Buffers = buffers;
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // The accumulation buffer(s), and the copy of the depth for the depth test.
  this->DepthTest.Ensure(window, TextureKind::Depth, lw, lh);
  for (int i = 0; i < buffers; ++i)
  {
    this->Accumulation[i].Ensure(window, kind, lw, lh);
  }
  vtkOpenGLFramebufferObject* depthTarget =
    vtkLightShaftResources::EnsureFramebuffer(this->DepthFramebuffer, window);
  vtkLightShaftResources::BindTargets(depthTarget, {}, this->Depth, lw, lh);
  this->Bind();
  depthTarget->Bind(GL_READ_FRAMEBUFFER);
  ostate->vtkglBlitFramebuffer(0, 0, lw, lh, 0, 0, lw, lh, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  this->AccumulationFramebuffer->Bind();
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatterTarget::AddToSum(vtkLightShaftFrame& frame, vtkTextureObject* inScatter)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  const int lw = this->Size[0];
  const int lh = this->Size[1];
  vtkTextureObject* sum = this->Sum.Ensure(window, TextureKind::RGBA32F, lw, lh);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->SumFramebuffer, window),
    { sum },
    nullptr,
    lw,
    lh);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (!this->Summed)
  {
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->Summed = true;
  }
  if (vtkShaderProgram* program = this->Add.Ready(window, vtkLightShaftAddFS))
  {
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    inScatter->Activate();
    program->SetUniformi("source", inScatter->GetTextureUnit());
    this->Add.Render();
    inScatter->Deactivate();
    ostate->vtkglDisable(GL_BLEND);
  }
  ++frame.Statistics.PostPasses;
}

vtkTextureObject* vtkLightShaftInScatterTarget::GetSum()
{
  return this->Summed ? this->Sum.Object.Get() : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatterTarget::Bind()
{
  this->BindWith(nullptr);
}

void vtkLightShaftInScatterTarget::BindWith(vtkTextureObject* extra)
{
  vtkOpenGLFramebufferObject* fbo = this->AccumulationFramebuffer;
  if (!fbo)
  {
    fbo = vtkLightShaftResources::EnsureFramebuffer(
      this->AccumulationFramebuffer, this->DepthTest.Object->GetContext());
  }
  const int lw = this->Size[0];
  const int lh = this->Size[1];
  vtkTextureObject* depthTest = this->DepthTest.Object;
  if (this->Buffers == 3)
  {
    vtkLightShaftResources::BindTargets(fbo,
      { this->Accumulation[0].Object, this->Accumulation[1].Object, this->Accumulation[2].Object },
      depthTest,
      lw,
      lh);
  }
  else if (extra)
  {
    vtkLightShaftResources::BindTargets(
      fbo, { this->Accumulation[0].Object, extra }, depthTest, lw, lh);
  }
  else
  {
    vtkLightShaftResources::BindTargets(fbo, { this->Accumulation[0].Object }, depthTest, lw, lh);
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatterTarget::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* texture : { &this->ReducedDepth,
         &this->Sum,
         &this->DepthTest,
         &this->Accumulation[0],
         &this->Accumulation[1],
         &this->Accumulation[2] })
  {
    texture->Release(window);
  }
  vtkLightShaftResources::ReleaseFramebuffer(this->AccumulationFramebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->DepthFramebuffer, window);
  vtkLightShaftResources::ReleaseFramebuffer(this->SumFramebuffer, window);
  this->DepthDownsample.Release(window);
  this->Add.Release(window);
  this->Summed = false;
  this->Depth = nullptr;
}
