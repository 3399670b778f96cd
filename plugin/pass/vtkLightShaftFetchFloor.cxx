#include "vtkLightShaftFetchFloor.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftFetchFloorFS.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkLightShaftFetchFloor);

double vtkLightShaftFetchFloor::Measure(vtkRenderWindow* window,
  int width,
  int height,
  int fetchesPerPixel,
  int frames)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!renWin || width < 1 || height < 1 || frames < 1)
  {
    vtkErrorMacro("Measure needs an OpenGL render window, a size and at least one frame.");
    return -1.0;
  }
  fetchesPerPixel = std::max(0, std::min(fetchesPerPixel, 100000));
  renWin->MakeCurrent();
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->PushFramebufferBindings();
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);

  auto makeTexture = [&]()
  {
    auto texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(renWin);
    texture->SetInternalFormat(GL_RGBA32F);
    texture->SetFormat(GL_RGBA);
    texture->SetDataType(GL_FLOAT);
    texture->Allocate2D(width, height, 4, VTK_FLOAT);
    return texture;
  };
  vtkSmartPointer<vtkTextureObject> source = makeTexture();
  vtkSmartPointer<vtkTextureObject> target = makeTexture();
  auto framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  framebuffer->SetContext(renWin);
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, target);
  framebuffer->ActivateDrawBuffer(0);
  framebuffer->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);

  double median = -1.0;
  {
    std::unique_ptr<vtkOpenGLQuadHelper> quad(
      new vtkOpenGLQuadHelper(renWin, nullptr, vtkLightShaftFetchFloorFS, ""));
    if (quad->Program && quad->Program->GetCompiled())
    {
      source->Activate();
      quad->Program->SetUniformi("source", source->GetTextureUnit());
      quad->Program->SetUniformi("fetches", fetchesPerPixel);
      std::vector<double> samples;
      for (int frame = -1; frame < frames; ++frame)
      {
        const auto start = std::chrono::steady_clock::now();
        quad->Render();
        glFinish();
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        if (frame >= 0)
        {
          samples.push_back(elapsed.count());
        }
      }
      source->Deactivate();
      std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
      median = samples[samples.size() / 2];
    }
    else
    {
      vtkErrorMacro("Could not build the fetch-floor shader.");
    }
    quad->ReleaseGraphicsResources(renWin);
  }
  framebuffer->ReleaseGraphicsResources(renWin);
  source->ReleaseGraphicsResources(renWin);
  target->ReleaseGraphicsResources(renWin);
  ostate->PopFramebufferBindings();
  return median;
}

void vtkLightShaftFetchFloor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
