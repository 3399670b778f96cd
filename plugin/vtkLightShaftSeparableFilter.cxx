#include "vtkLightShaftSeparableFilter.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShaders.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftBlurFS.h"

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftSeparableFilter::vtkLightShaftSeparableFilter() = default;
vtkLightShaftSeparableFilter::~vtkLightShaftSeparableFilter() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftSeparableFilter::Apply(vtkLightShaftFrame& frame,
  vtkTextureObject* source,
  vtkTextureObject* depth,
  int radius,
  int boxWidth)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program = this->Pass.Ready(window, vtkLightShaftBlurFS);
  if (!program)
  {
    return source;
  }
  const int lw = frame.Reduced[0];
  const int lh = frame.Reduced[1];
  vtkOpenGLFramebufferObject* fbo =
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window);
  vtkTextureObject* sources[2] = { source,
    this->Temporary.Ensure(window, TextureKind::RGBA32F, lw, lh) };
  vtkTextureObject* outputs[2] = { sources[1],
    this->Output.Ensure(window, TextureKind::RGBA32F, lw, lh) };
  const int directions[2][2] = { { 1, 0 }, { 0, 1 } };
  for (int pass = 0; pass < 2; ++pass)
  {
    vtkLightShaftResources::BindTargets(fbo, { outputs[pass] }, nullptr, lw, lh);
    window->GetShaderCache()->ReadyShaderProgram(program);
    sources[pass]->Activate();
    depth->Activate();
    program->SetUniformi("source", sources[pass]->GetTextureUnit());
    program->SetUniformi("sceneDepth", depth->GetTextureUnit());
    vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, lw, lh);
    program->SetUniform2i("direction", directions[pass]);
    program->SetUniformi("radius", radius);
    program->SetUniformi("boxWidth", boxWidth);
    program->SetUniformf("depthTolerance", SameSurfaceTolerance);
    this->Pass.Render();
    depth->Deactivate();
    sources[pass]->Deactivate();
    ++frame.Statistics.PostPasses;
  }
  return outputs[1];
}

//------------------------------------------------------------------------------
void vtkLightShaftSeparableFilter::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Pass.Release(window);
  this->Temporary.Release(window);
  this->Output.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
