#include "vtkLightShaftResources.h"

#include "vtkLightShaftShaderText.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>

namespace vtkLightShaftResources
{
namespace
{
// Colour attachments the pass ever binds at once (the 8-bit mode's three accumulation buffers).
constexpr unsigned int MaximumColorAttachments = 3;
}

//------------------------------------------------------------------------------
vtkTextureObject* OwnedTexture::Ensure(vtkOpenGLRenderWindow* window,
  TextureKind kind,
  int w,
  int h,
  int samples)
{
  if (this->Object &&
      (this->Kind != kind || this->Object->GetSamples() != static_cast<unsigned int>(samples)))
  {
    this->Release(window);
  }
  if (!this->Object)
  {
    this->Object = vtkSmartPointer<vtkTextureObject>::New();
    this->Object->SetContext(window);
    this->Object->SetSamples(samples);
    this->Object->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Object->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Object->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Object->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Kind = kind;
    switch (kind)
    {
      case TextureKind::RGBA8:
        this->Object->Allocate2D(w, h, 4, VTK_UNSIGNED_CHAR);
        break;
      case TextureKind::RGBA16F:
      case TextureKind::RGBA32F:
        this->Object->SetInternalFormat(kind == TextureKind::RGBA16F ? GL_RGBA16F : GL_RGBA32F);
        this->Object->SetFormat(GL_RGBA);
        this->Object->SetDataType(GL_FLOAT);
        this->Object->Allocate2D(w, h, 4, VTK_FLOAT);
        break;
      case TextureKind::Depth:
        // The depth format VTK 9.1's GPU volume mapper allocates, so that its depth blit from
        // the current target (our scene target) is legal.
        if (window->GetStencilCapable())
        {
          this->Object->AllocateDepthStencil(w, h);
        }
        else
        {
          this->Object->AllocateDepth(w, h, vtkTextureObject::Fixed32);
        }
        break;
      case TextureKind::Depth32F:
        this->Object->AllocateDepth(w, h, vtkTextureObject::Float32);
        break;
    }
  }
  else if (static_cast<int>(this->Object->GetWidth()) != w ||
           static_cast<int>(this->Object->GetHeight()) != h)
  {
    this->Object->Resize(w, h);
  }
  return this->Object;
}

void OwnedTexture::Release(vtkWindow* window)
{
  if (this->Object)
  {
    this->Object->ReleaseGraphicsResources(window);
  }
  this->Object = nullptr;
}

//------------------------------------------------------------------------------
FullScreenPass::FullScreenPass() = default;
FullScreenPass::~FullScreenPass() = default;

vtkShaderProgram* FullScreenPass::Ready(vtkOpenGLRenderWindow* window,
  const char* source,
  const std::vector<std::string>& defines)
{
  const std::string key = vtkLightShaftShaderText::JoinDefines(defines);
  if (!this->Quad || this->Key != key)
  {
    const std::string fragment = vtkLightShaftShaderText::WithFeatures(source, defines);
    this->Quad.reset(new vtkOpenGLQuadHelper(window, nullptr, fragment.c_str(), ""));
    this->Key = key;
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  return (this->Quad->Program && this->Quad->Program->GetCompiled()) ? this->Quad->Program
                                                                     : nullptr;
}

void FullScreenPass::Render()
{
  this->Quad->Render();
}

void FullScreenPass::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
  }
  this->Quad.reset();
  this->Key.clear();
}

//------------------------------------------------------------------------------
vtkOpenGLFramebufferObject* EnsureFramebuffer(
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  vtkOpenGLRenderWindow* window)
{
  if (!framebuffer)
  {
    framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    framebuffer->SetContext(window);
  }
  return framebuffer;
}

void ReleaseFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkWindow* w)
{
  if (framebuffer)
  {
    framebuffer->ReleaseGraphicsResources(w);
  }
  framebuffer = nullptr;
}

//------------------------------------------------------------------------------
void BindTargets(vtkOpenGLFramebufferObject* fbo,
  std::initializer_list<vtkTextureObject*> colors,
  vtkTextureObject* depth,
  int w,
  int h)
{
  fbo->Bind();
  fbo->RemoveColorAttachments(MaximumColorAttachments);
  fbo->RemoveDepthAttachment();
  unsigned int count = 0;
  for (vtkTextureObject* color : colors)
  {
    fbo->AddColorAttachment(count++, color);
  }
  if (depth)
  {
    fbo->AddDepthAttachment(depth);
  }
  if (count > 0)
  {
    fbo->ActivateDrawBuffers(count);
  }
  else
  {
    fbo->DeactivateDrawBuffers();
  }
  fbo->StartNonOrtho(w, h);
  vtkOpenGLState* ostate = fbo->GetContext()->GetState();
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
}

//------------------------------------------------------------------------------
void UploadFloatVolume(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window,
  const float* values,
  int width,
  int height,
  int depth)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetInternalFormat(GL_R32F);
  texture->SetFormat(GL_RED);
  texture->SetDataType(GL_FLOAT);
  texture->Create3DFromRaw(width, height, depth, 1, VTK_FLOAT, const_cast<float*>(values));
}

//------------------------------------------------------------------------------
void UploadMipmapped(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window,
  const std::vector<float>& texels,
  int width,
  int height,
  int components,
  bool repeat)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  const int wrap = repeat ? vtkTextureObject::Repeat : vtkTextureObject::ClampToEdge;
  texture->SetWrapS(wrap);
  texture->SetWrapT(wrap);
  texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetGenerateMipmap(true);
  texture->SetMaxLevel(static_cast<int>(std::log2(std::max(width, height))));
  texture->SetInternalFormat(components == 1 ? GL_R16F : GL_RGB16F);
  texture->SetFormat(components == 1 ? GL_RED : GL_RGB);
  texture->SetDataType(GL_FLOAT);
  texture->Create2DFromRaw(width,
    height,
    components,
    VTK_FLOAT,
    const_cast<void*>(static_cast<const void*>(texels.data())));
  texture->Bind();
  glGenerateMipmap(GL_TEXTURE_2D);
  texture->Deactivate();
}

//------------------------------------------------------------------------------
int TargetSamples()
{
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples <= 1)
  {
    return 0;
  }
  GLint colorSamples = 0;
  GLint depthSamples = 0;
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
  return samples <= std::min(colorSamples, depthSamples) ? samples : 0;
}

//------------------------------------------------------------------------------
bool TargetDepthMatches(vtkTextureObject* depth)
{
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const GLenum attachment = target ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE)
  {
    return false;
  }
  GLint theirs[4] = { 0, 0, 0, 0 };
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &theirs[0]);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &theirs[1]);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &theirs[2]);
  glGetIntegerv(GL_SAMPLES, &theirs[3]);
  GLint ours[4] = { 0, 0, 0, static_cast<GLint>(depth->GetSamples()) };
  depth->Activate();
  glGetTexLevelParameteriv(depth->GetTarget(), 0, GL_TEXTURE_DEPTH_SIZE, &ours[0]);
  glGetTexLevelParameteriv(depth->GetTarget(), 0, GL_TEXTURE_DEPTH_TYPE, &ours[1]);
  glGetTexLevelParameteriv(depth->GetTarget(), 0, GL_TEXTURE_STENCIL_SIZE, &ours[2]);
  depth->Deactivate();
  return std::equal(theirs, theirs + 4, ours);
}
}
