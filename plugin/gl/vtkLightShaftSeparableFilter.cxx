#include "vtkLightShaftSeparableFilter.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShaders.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftBlurFS.h"

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftSeparableFilter::vtkLightShaftSeparableFilter() = default;
vtkLightShaftSeparableFilter::~vtkLightShaftSeparableFilter() = default;

//------------------------------------------------------------------------------
vtkLightShaftSeparableFilter::Kernel vtkLightShaftSeparableFilter::Kernel::Blur(int radius)
{
  Kernel kernel;
  kernel.Sigma = std::max(0.5 * radius, 0.5);
  kernel.Radius = radius;
  return kernel;
}

vtkLightShaftSeparableFilter::Kernel vtkLightShaftSeparableFilter::Kernel::Gather(int width)
{
  Kernel kernel;
  kernel.BoxWidth = width;
  return kernel;
}

vtkLightShaftSeparableFilter::Kernel vtkLightShaftSeparableFilter::Kernel::Gaussian(double sigma)
{
  Kernel kernel;
  kernel.Sigma = sigma;
  kernel.Radius = std::max(1, static_cast<int>(std::ceil(2.0 * sigma)));
  return kernel;
}

// As the shader weighs its taps (before the depth test leaves some out).
std::vector<double> vtkLightShaftSeparableFilter::Kernel::Weights() const
{
  std::vector<double> weights;
  if (this->BoxWidth > 0)
  {
    const int half = this->BoxWidth / 2;
    const bool halfEnds = this->BoxWidth % 2 == 0;
    for (int i = -half; i <= half; ++i)
    {
      weights.push_back(halfEnds && std::abs(i) == half ? 0.5 : 1.0);
    }
    return weights;
  }
  const float sigma = static_cast<float>(this->Sigma);
  for (int i = -this->Radius; i <= this->Radius; ++i)
  {
    weights.push_back(std::exp(-0.5 * i * i / (double(sigma) * sigma)));
  }
  return weights;
}

//------------------------------------------------------------------------------
double vtkLightShaftSeparableFilter::EffectiveSamples(const std::vector<double>& weights)
{
  double sum = 0.0;
  double squares = 0.0;
  for (double w : weights)
  {
    sum += w;
    squares += w * w;
  }
  return squares > 0.0 ? sum * sum / squares : 1.0;
}

std::vector<double> vtkLightShaftSeparableFilter::Convolve(const std::vector<double>& a,
  const std::vector<double>& b)
{
  if (a.empty() || b.empty())
  {
    return a.empty() ? b : a;
  }
  std::vector<double> c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    for (std::size_t j = 0; j < b.size(); ++j)
    {
      c[i + j] += a[i] * b[j];
    }
  }
  return c;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftSeparableFilter::Apply(vtkLightShaftFrame& frame,
  vtkTextureObject* source,
  vtkTextureObject* depth,
  int radius,
  int boxWidth)
{
  const Kernel kernel = boxWidth > 0 ? Kernel::Gather(boxWidth) : Kernel::Blur(radius);
  return this->Apply(frame, source, depth, kernel, frame.Reduced[0], frame.Reduced[1]);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftSeparableFilter::Apply(vtkLightShaftFrame& frame,
  vtkTextureObject* source,
  vtkTextureObject* depth,
  const Kernel& kernel,
  int width,
  int height)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program = this->Pass.Ready(window, vtkLightShaftBlurFS);
  if (!program)
  {
    return source;
  }
  vtkOpenGLFramebufferObject* fbo =
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window);
  vtkTextureObject* sources[2] = { source,
    this->Temporary.Ensure(window, TextureKind::RGBA32F, width, height) };
  vtkTextureObject* outputs[2] = { sources[1],
    this->Output.Ensure(window, TextureKind::RGBA32F, width, height) };
  const int directions[2][2] = { { 1, 0 }, { 0, 1 } };
  for (int pass = 0; pass < 2; ++pass)
  {
    vtkLightShaftResources::BindTargets(fbo, { outputs[pass] }, nullptr, width, height);
    window->GetShaderCache()->ReadyShaderProgram(program);
    sources[pass]->Activate();
    depth->Activate();
    program->SetUniformi("source", sources[pass]->GetTextureUnit());
    program->SetUniformi("sceneDepth", depth->GetTextureUnit());
    vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, width, height);
    program->SetUniform2i("direction", directions[pass]);
    program->SetUniformi("radius", kernel.Radius);
    program->SetUniformf("sigma", static_cast<float>(kernel.Sigma));
    program->SetUniformi("boxWidth", kernel.BoxWidth);
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
