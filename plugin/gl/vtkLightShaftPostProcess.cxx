#include "vtkLightShaftPostProcess.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShaders.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftUpsampleFS.h"

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftPostProcess::vtkLightShaftPostProcess() = default;
vtkLightShaftPostProcess::~vtkLightShaftPostProcess() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPostProcess::Render(vtkLightShaftFrame& frame,
  vtkTextureObject* inScatter,
  vtkTextureObject* reducedDepth,
  vtkTextureObject* fullDepth)
{
  vtkTextureObject* current = inScatter;
  if (frame.Parameters.BlurRadius > 0 && !frame.Unfiltered)
  {
    current = this->Blur.Apply(frame, current, reducedDepth, frame.Parameters.BlurRadius, 0);
  }
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  if (frame.Reduced[0] == w && frame.Reduced[1] == h)
  {
    return current;
  }
  vtkTextureObject* upsampled = this->Upsampled.Ensure(frame.Window, TextureKind::RGBA32F, w, h);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { upsampled },
    nullptr,
    w,
    h);
  vtkShaderProgram* program = this->Upsample.Ready(frame.Window, vtkLightShaftUpsampleFS);
  if (!program)
  {
    return upsampled;
  }
  current->Activate();
  reducedDepth->Activate();
  fullDepth->Activate();
  program->SetUniformi("reduced", current->GetTextureUnit());
  program->SetUniformi("reducedDepth", reducedDepth->GetTextureUnit());
  program->SetUniformi("fullDepth", fullDepth->GetTextureUnit());
  vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, w, h);
  const float fullSize[2] = { static_cast<float>(w), static_cast<float>(h) };
  program->SetUniform2f("fullSize", fullSize);
  program->SetUniformf("depthTolerance", vtkLightShaftSeparableFilter::SameSurfaceTolerance);
  this->Upsample.Render();
  ++frame.Statistics.PostPasses;
  fullDepth->Deactivate();
  reducedDepth->Deactivate();
  current->Deactivate();
  return upsampled;
}

//------------------------------------------------------------------------------
void vtkLightShaftPostProcess::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Blur.ReleaseGraphicsResources(window);
  this->Upsample.Release(window);
  this->Upsampled.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
