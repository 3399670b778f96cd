#include "vtkLightShaftTranslucentPeel.h"

#include "vtkInformation.h"
#include "vtkLightShaftOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"

#include <algorithm>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLightShaftTranslucentPeel);

vtkLightShaftTranslucentPeel::vtkLightShaftTranslucentPeel() = default;
vtkLightShaftTranslucentPeel::~vtkLightShaftTranslucentPeel() = default;

//------------------------------------------------------------------------------
void vtkLightShaftTranslucentPeel::SetOpaqueDepth(vtkTextureObject* depth, const float rect[4])
{
  this->OpaqueDepth = depth;
  std::copy(rect, rect + 4, this->OpaqueRect);
}

void vtkLightShaftTranslucentPeel::SetPreviousLayer(vtkTextureObject* layer, const float rect[4])
{
  this->PreviousLayer = layer;
  std::copy(rect, rect + 4, this->PreviousRect);
}

//------------------------------------------------------------------------------
void vtkLightShaftTranslucentPeel::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  auto* target = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer());
  if (!target || !this->OpaqueDepth)
  {
    return;
  }
  int size[2] = { 1, 1 };
  target->GetLastSize(size);
  this->TargetSize[0] = static_cast<float>(std::max(size[0], 1));
  this->TargetSize[1] = static_cast<float>(std::max(size[1], 1));

  // Depth writes on for the props' translucent step (the nearest surface is the layer); each
  // prop's own setting, if it had one, is given back after.
  std::vector<std::pair<vtkInformation*, int>> overrides;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    vtkInformation* keys = prop->GetPropertyKeys();
    if (!keys)
    {
      vtkNew<vtkInformation> created;
      prop->SetPropertyKeys(created);
      keys = created;
    }
    const bool had = keys->Has(vtkOpenGLActor::GLDepthMaskOverride()) != 0;
    overrides.emplace_back(keys, had ? keys->Get(vtkOpenGLActor::GLDepthMaskOverride()) : -1);
    keys->Set(vtkOpenGLActor::GLDepthMaskOverride(), 1);
  }

  // The target starts empty (after the camera pass's clear to the renderer's background):
  // everything passes, nothing is stored.
  vtkOpenGLState* ostate = target->GetContext()->GetState();
  ostate->vtkglClearColor(1.0, 1.0, 1.0, 1.0);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDisable(GL_BLEND);

  this->PreRender(s);
  this->OpaqueDepth->Activate();
  if (this->PreviousLayer)
  {
    this->PreviousLayer->Activate();
  }
  this->TranslucentPass->Render(s);
  this->NumberOfRenderedProps = this->TranslucentPass->GetNumberOfRenderedProps();
  if (this->PreviousLayer)
  {
    this->PreviousLayer->Deactivate();
  }
  this->OpaqueDepth->Deactivate();
  this->PostRender(s);

  for (const auto& entry : overrides)
  {
    if (entry.second < 0)
    {
      entry.first->Remove(vtkOpenGLActor::GLDepthMaskOverride());
    }
    else
    {
      entry.first->Set(vtkOpenGLActor::GLDepthMaskOverride(), entry.second);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkLightShaftTranslucentPeel::PostReplaceShaderValues(std::string&,
  std::string&,
  std::string& fragmentShader,
  vtkAbstractMapper*,
  vtkProp*)
{
  // After the mapper's replacements: its colour is written (lighting, texturing) and its
  // transparent fragments are discarded before the peeling hook.
  const bool declared = vtkShaderProgram::Substitute(fragmentShader,
    "//VTK::DepthPeeling::Dec",
    "uniform sampler2D lightShaftOpaqueDepth;\n"
    "uniform sampler2D lightShaftPreviousLayer;\n"
    "uniform vec4 lightShaftOpaqueRect;\n"
    "uniform vec4 lightShaftPreviousRect;\n"
    "uniform vec2 lightShaftTargetSize;\n"
    "uniform int lightShaftPeel;\n");
  // The surface's colour as the mapper computed it before lighting (none: grey, 1 - a); the
  // camera's rule keeps 1 - a of what lies behind, whatever the colour (VTK's blending).
  const bool colored =
    this->Kept == LIGHT && fragmentShader.find("diffuseColor") != std::string::npos;
  const std::string color = colored ? "diffuseColor" : "vec3(0.0)";
  return declared &&
         vtkShaderProgram::Substitute(fragmentShader,
           "//VTK::DepthPeeling::Impl",
           "vec2 lightShaftUV = gl_FragCoord.xy / lightShaftTargetSize;\n"
           "  if (gl_FragCoord.z >= texture(lightShaftOpaqueDepth,\n"
           "        lightShaftOpaqueRect.xy + lightShaftUV * lightShaftOpaqueRect.zw).r ||\n"
           "    (lightShaftPeel != 0 && gl_FragCoord.z <= texture(lightShaftPreviousLayer,\n"
           "        lightShaftPreviousRect.xy + lightShaftUV * lightShaftPreviousRect.zw).a))\n"
           "  {\n"
           "    discard;\n"
           "  }\n"
           "  float lightShaftAlpha = clamp(gl_FragData[0].a, 0.0, 1.0);\n"
           "  gl_FragData[0] = vec4(vec3(1.0) - lightShaftAlpha * (vec3(1.0) - clamp(" +
             color +
             ", 0.0, 1.0)),\n"
             "    gl_FragCoord.z);\n");
}

//------------------------------------------------------------------------------
bool vtkLightShaftTranslucentPeel::SetShaderParameters(vtkShaderProgram* program,
  vtkAbstractMapper*,
  vtkProp*,
  vtkOpenGLVertexArrayObject*)
{
  if (!this->OpaqueDepth)
  {
    return false;
  }
  // With no previous layer its sampler reads the opaque depth (bound, never used).
  vtkTextureObject* previous = this->PreviousLayer ? this->PreviousLayer : this->OpaqueDepth;
  program->SetUniformi("lightShaftOpaqueDepth", this->OpaqueDepth->GetTextureUnit());
  program->SetUniformi("lightShaftPreviousLayer", previous->GetTextureUnit());
  program->SetUniform4f("lightShaftOpaqueRect", this->OpaqueRect);
  program->SetUniform4f("lightShaftPreviousRect", this->PreviousRect);
  program->SetUniform2f("lightShaftTargetSize", this->TargetSize);
  program->SetUniformi("lightShaftPeel", this->PreviousLayer ? 1 : 0);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftTranslucentPeel::ReleaseGraphicsResources(vtkWindow* w)
{
  this->TranslucentPass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}
