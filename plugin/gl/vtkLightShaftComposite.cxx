#include "vtkLightShaftComposite.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShaders.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftCompositeFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
// Whether the pass paints a background behind the scene image's uncovered part (1 - alpha):
// asked (PaintBackground: a compositor renders the scene over a transparent background and
// blends the background in after the pass, as ParaView's IceT does on several processes), so
// that the medium dims it as it dims a background the renderer cleared to.
bool PaintsBackground(const vtkLightShaftFrame& frame)
{
  return frame.Parameters.PaintBackground && frame.Parameters.PaintedBackground &&
         !frame.Renderer->Transparent();
}

// The background as a renderer clearing the scene's target would leave it: 8-bit targets hold
// it rounded to a level.
std::array<float, 3> ClearedBackground(const double* background, bool highRange)
{
  std::array<float, 3> color;
  for (int c = 0; c < 3; ++c)
  {
    const double value = std::min(std::max(background[c], 0.0), 1.0);
    color[c] = static_cast<float>(highRange ? value : std::round(value * 255.0) / 255.0);
  }
  return color;
}
}

//------------------------------------------------------------------------------
vtkLightShaftComposite::vtkLightShaftComposite() = default;
vtkLightShaftComposite::~vtkLightShaftComposite() = default;

//------------------------------------------------------------------------------
void vtkLightShaftComposite::Render(vtkLightShaftFrame& frame, vtkTextureObject* inScatter)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  const vtkLightShaftSceneImage& scene = frame.Scene;
  const int w = frame.Size[0];
  const int h = frame.Size[1];
  const bool attenuate = frame.Parameters.AttenuateScene && frame.Medium.Extinguishes();
  vtkTextureObject* correction = scene.SurfaceCorrection;
  const bool multisample = scene.Samples > 0;
  // The scene's depth goes to the target unchanged, so that later passes, overlays and depth
  // queries (vtkRenderer::GetZ) see the surfaces as without the pass: copied when the target's
  // depth has the same format, else written by the shader.
  const bool copyDepth = vtkLightShaftResources::TargetDepthMatches(scene.Depth);
  std::vector<std::string> defines;
  if (attenuate)
  {
    defines.emplace_back("LIGHTSHAFT_ATTENUATE");
    if (frame.Density)
    {
      defines.emplace_back("LIGHTSHAFT_FIELD");
    }
  }
  if (correction)
  {
    defines.emplace_back("LIGHTSHAFT_SURFACE_CORRECTION");
  }
  if (multisample)
  {
    defines.emplace_back("LIGHTSHAFT_MULTISAMPLE");
  }
  if (!copyDepth)
  {
    defines.emplace_back("LIGHTSHAFT_WRITE_DEPTH");
  }
  const bool background = PaintsBackground(frame);
  if (background)
  {
    defines.emplace_back("LIGHTSHAFT_BACKGROUND");
  }
  vtkShaderProgram* program = this->Pass.Ready(frame.Window, vtkLightShaftCompositeFS, defines);
  if (!program)
  {
    vtkErrorWithObjectMacro(frame.Owner, "Could not build the light-shaft composite shader.");
    return;
  }

  // Multisampled scene textures are read per sample (their uniforms have a "Samples" suffix).
  const std::string suffix = multisample ? "Samples" : "";
  std::vector<vtkTextureObject*> active = { scene.Color, scene.Depth, inScatter };
  for (vtkTextureObject* t : active)
  {
    t->Activate();
  }
  program->SetUniformi(("sceneColor" + suffix).c_str(), scene.Color->GetTextureUnit());
  program->SetUniformi(("sceneDepth" + suffix).c_str(), scene.Depth->GetTextureUnit());
  program->SetUniformi("inScatter", inScatter->GetTextureUnit());
  program->SetUniformf("exposure", static_cast<float>(frame.Parameters.Exposure));
  if (background)
  {
    program->SetUniform3f(
      "background", ClearedBackground(frame.Parameters.PaintedBackground, scene.HighRange).data());
  }
  if (attenuate)
  {
    vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, w, h);
    program->SetUniform3f("sigmaT", frame.Medium.SigmaT);
    if (frame.Density)
    {
      vtkLightShaftShaders::SetDensityUniforms(program, frame); // (activates its texture)
      active.push_back(frame.Density);
    }
  }
  if (correction)
  {
    correction->Activate();
    active.push_back(correction);
    program->SetUniformi(("surfaceCorrection" + suffix).c_str(), correction->GetTextureUnit());
  }

  // Write colour (and depth), per sample when the scene is multisampled (the shader reads
  // gl_SampleID).
  if (multisample)
  {
    ostate->vtkglEnable(GL_MULTISAMPLE);
  }
  if (copyDepth)
  {
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }
  else
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
  }
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (frame.Renderer->Transparent())
  {
    // A layer over other renderers: the scene target is premultiplied (cleared to 0 alpha).
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  this->Pass.Render();
  for (auto it = active.rbegin(); it != active.rend(); ++it)
  {
    (*it)->Deactivate();
  }
  if (copyDepth)
  {
    ostate->PushReadFramebufferBinding();
    scene.Framebuffer->Bind(GL_READ_FRAMEBUFFER);
    ostate->vtkglDepthMask(GL_TRUE);
    const int* origin = frame.Origin;
    ostate->vtkglBlitFramebuffer(0,
      0,
      w,
      h,
      origin[0],
      origin[1],
      origin[0] + w,
      origin[1] + h,
      GL_DEPTH_BUFFER_BIT,
      GL_NEAREST);
    ostate->PopReadFramebufferBinding();
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftComposite::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Pass.Release(window);
}
