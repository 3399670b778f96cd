#include "vtkLightShaftEpipolarMethod.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftEpipolarFS.h"
#include "vtkLightShaftEpipolarMarkFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

using vtkLightShaftResources::TextureKind;

namespace
{
// The stages of vtkLightShaftEpipolarFS.
enum Stage
{
  CoordinatesStage = 0,
  CoarseStage = 1,
  RefineStage = 2,
  FineStage = 3,
  UnwarpStage = 4,
  MarchStage = 5
};
}

//------------------------------------------------------------------------------
vtkLightShaftEpipolarMethod::vtkLightShaftEpipolarMethod(vtkLightShaftSlabDrawer& drawer)
  : Drawer(drawer)
{
  // The stages that fill the epipolar textures draw one slab over the whole of them.
  vtkLightShaftGeometry::SlabFootprint whole;
  whole.Index = 0;
  whole.NearDepth = 0.0; // set per frame
  whole.Hull = { { -1.0, -1.0 }, { 1.0, -1.0 }, { 1.0, 1.0 }, { -1.0, 1.0 } };
  this->WholeTexture.push_back(whole);
}

vtkLightShaftEpipolarMethod::~vtkLightShaftEpipolarMethod() = default;

//------------------------------------------------------------------------------
// No more lines than the target's boundary has pixels, nor samples than two per pixel of its
// diagonal: beyond, they sample the same pixels again.
void vtkLightShaftEpipolarMethod::LinesAndSamples(const vtkLightShaftFrame& frame,
  int& lines,
  int& samples)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int width = frame.Reduced[0];
  const int height = frame.Reduced[1];
  lines = std::min(p.EpipolarLines, 2 * (width + height));
  samples = std::min(p.EpipolarSamples,
    2 * static_cast<int>(std::ceil(std::sqrt(double(width) * width + double(height) * height))));
}

long long vtkLightShaftEpipolarMethod::MarchedRays(const vtkLightShaftFrame& frame)
{
  int lines;
  int samples;
  LinesAndSamples(frame, lines, samples);
  return static_cast<long long>(lines) * samples +
         static_cast<long long>(frame.Reduced[0]) * frame.Reduced[1];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftEpipolarMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  vtkTextureObject* shadowMap = nullptr;
  vtkLightShaftShaders::Variant variant;
  if (!this->PrepareMarch(frame, lit, nullptr, this->Footprints, shadowMap, variant))
  {
    return nullptr;
  }

  // The lines through the light's image over the in-scatter target.
  const int width = frame.Reduced[0];
  const int height = frame.Reduced[1];
  int lines;
  int samples;
  LinesAndSamples(frame, lines, samples);
  const vtkLightShaftEpipolarGeometry::Layout layout = vtkLightShaftEpipolarGeometry::ComputeLayout(
    vtkLightShaftEpipolarGeometry::ComputeEpipole(frame.Light, frame.Camera, width, height),
    width,
    height,
    lines,
    samples);
  const int step = std::max(1, std::min(p.EpipolarStep, layout.Samples - 1));
  const int columns = (layout.Samples - 1 + step - 1) / step + 1;
  // Marched at most: every sample of every line (coarse and refined) and every pixel the
  // samples miss.
  const int steps = this->StepsWithinBudget(frame,
    static_cast<long long>(layout.Lines) * layout.Samples + static_cast<long long>(width) * height);
  this->UploadEnds(frame, layout);

  vtkOpenGLRenderWindow* window = frame.Window;
  vtkTextureObject* textures[] = { this->Ends.Object,
    this->Coordinates.Ensure(window, TextureKind::RGBA32F, layout.Samples, layout.Lines),
    // (A split setting's share adds the columns its shares decide by: stage 2.)
    this->Coarse.Ensure(window,
      TextureKind::RGBA32F,
      frame.RefinementSplit > 1 ? 2 * columns : columns,
      layout.Lines),
    this->Refined.Ensure(window, TextureKind::RGBA32F, layout.Samples, layout.Lines),
    this->Fine.Ensure(window, TextureKind::RGBA32F, layout.Samples, layout.Lines),
    this->Marked.Ensure(window, TextureKind::RGBA8, width, height) };
  const char* samplers[] = { "epipolarEnds",
    "epipolarCoordinates",
    "epipolarCoarse",
    "epipolarRefined",
    "epipolarFine",
    "epipolarMarked" };
  // Every stage's inputs stay bound for all of them: a stage never samples its own output.
  for (vtkTextureObject* texture : textures)
  {
    texture->Activate();
  }
  // Drawn at the lit range's near depth: a view depth of 0 projects to an infinite depth with a
  // perspective camera, which a GPU may clip the whole draw for.
  this->WholeTexture[0].NearDepth = lit.Nearest;
  vtkLightShaftSlabDrawer::Slabs slabs =
    vtkLightShaftSlabDrawer::Slabs::Over(lit, this->WholeTexture, target.GetDepth());
  slabs.ShadowMap = shadowMap;
  slabs.ShadowBias = shadowMap ? frame.LightStatistics->ShadowBias : 0.0;
  bool drawn = true;
  for (int stage = CoordinatesStage; stage <= MarchStage && drawn; ++stage)
  {
    if (stage == MarchStage)
    {
      this->MarkForMarch(frame, textures[5]);
    }
    vtkShaderProgram* program = this->ReadyStage(frame, stage, variant);
    drawn = program != nullptr;
    if (!drawn)
    {
      break;
    }
    SetLayoutUniforms(program, layout, step);
    program->SetUniformi("epipolarColumns", columns);
    program->SetUniformi("numberOfSteps", steps);
    program->SetUniformf("samplingRotation", static_cast<float>(frame.SamplingRotation));
    program->SetUniformi("sampleShare", frame.RefinementSplit);
    program->SetUniformi("samplePart", frame.SamplePart);
    for (int i = 0; i < 6; ++i)
    {
      program->SetUniformi(samplers[i], textures[i]->GetTextureUnit());
    }
    if (stage < UnwarpStage)
    {
      this->DrawStage(frame, program, textures[stage + 1], slabs);
      continue;
    }
    // The pixels of the lit volume's footprint, into the target: interpolated, marking those
    // with no sample on their surface (a second output, cleared first), then those marched.
    slabs.Footprints = &this->Footprints;
    if (stage == UnwarpStage)
    {
      target.BindWith(textures[5]);
      const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
      glClearBufferfv(GL_COLOR, 1, zero);
    }
    else
    {
      // Only the marked pixels pass the depth test (MarkForMarch); the march stage checks the
      // scene's depth itself.
      vtkLightShaftResources::BindTargets(
        this->Framebuffer, { target.GetAccumulation(0) }, this->MarkDepth.Object, width, height);
    }
    this->Drawer.Draw(frame, program, slabs);
  }
  for (vtkTextureObject* texture : textures)
  {
    texture->Deactivate();
  }
  frame.LightStatistics->SlicesDrawn = static_cast<int>(this->Footprints.size());
  return drawn ? target.GetAccumulation(0) : nullptr;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLightShaftEpipolarMethod::ReadyStage(vtkLightShaftFrame& frame,
  int stage,
  const vtkLightShaftShaders::Variant& variant)
{
  vtkLightShaftShaders::Variant staged = variant;
  staged.Defines.push_back("LIGHTSHAFT_EPIPOLAR_STAGE " + std::to_string(stage));
  if (stage == MarchStage)
  {
    // The last stage's variant is the one the frame reports.
    return this->ReadySlabProgram(frame, vtkLightShaftEpipolarFS, staged);
  }
  return vtkLightShaftMethod::ReadySlabProgram(
    frame, this->StagePrograms[stage], vtkLightShaftEpipolarFS, staged);
}

//------------------------------------------------------------------------------
void vtkLightShaftEpipolarMethod::MarkForMarch(vtkLightShaftFrame& frame, vtkTextureObject* marked)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const int width = static_cast<int>(marked->GetWidth());
  const int height = static_cast<int>(marked->GetHeight());
  vtkTextureObject* depth = this->MarkDepth.Ensure(window, TextureKind::Depth32F, width, height);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window), {}, depth, width, height);
  vtkShaderProgram* program = this->Mark.Ready(window, vtkLightShaftEpipolarMarkFS);
  if (!program)
  {
    return;
  }
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  program->SetUniformi("marked", marked->GetTextureUnit());
  this->Mark.Render();
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ++frame.Statistics.PostPasses;
}

//------------------------------------------------------------------------------
void vtkLightShaftEpipolarMethod::DrawStage(vtkLightShaftFrame& frame,
  vtkShaderProgram* program,
  vtkTextureObject* output,
  const vtkLightShaftSlabDrawer::Slabs& slabs)
{
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, frame.Window),
    { output },
    nullptr,
    static_cast<int>(output->GetWidth()),
    static_cast<int>(output->GetHeight()));
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  this->Drawer.Draw(frame, program, slabs);
  ++frame.Statistics.PostPasses;
}

//------------------------------------------------------------------------------
void vtkLightShaftEpipolarMethod::UploadEnds(vtkLightShaftFrame& frame,
  const vtkLightShaftEpipolarGeometry::Layout& layout)
{
  this->EndTexels.resize(4 * static_cast<size_t>(layout.Lines));
  for (int i = 0; i < layout.Lines; ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      this->EndTexels[4 * i + k] = static_cast<float>(layout.Ends[i][k]);
    }
  }
  vtkTextureObject* ends = this->Ends.Ensure(frame.Window, TextureKind::RGBA32F, layout.Lines, 1);
  ends->Bind();
  glTexSubImage2D(
    GL_TEXTURE_2D, 0, 0, 0, layout.Lines, 1, GL_RGBA, GL_FLOAT, this->EndTexels.data());
  ends->Deactivate();
}

//------------------------------------------------------------------------------
void vtkLightShaftEpipolarMethod::SetLayoutUniforms(vtkShaderProgram* program,
  const vtkLightShaftEpipolarGeometry::Layout& layout,
  int step)
{
  using Shape = vtkLightShaftEpipolarGeometry::Layout::Shape;
  const int form = layout.Form == Shape::Radial ? 0 : (layout.Form == Shape::Fan ? 1 : 2);
  auto vec2 = [](const glm::dvec2& v) {
    return std::array<float, 2>{ static_cast<float>(v.x), static_cast<float>(v.y) };
  };
  program->SetUniformi("epipolarLines", layout.Lines);
  program->SetUniformi("epipolarSamples", layout.Samples);
  program->SetUniformi("epipolarStep", step);
  program->SetUniformi("epipolarForm", form);
  program->SetUniform2f("epipolarOrigin", vec2(layout.Origin).data());
  program->SetUniform2f("epipolarAxis", vec2(layout.Axis).data());
  program->SetUniform2f("epipolarNormal", vec2(layout.Normal).data());
  program->SetUniformf("epipolarStart", static_cast<float>(layout.Start));
  program->SetUniformf("epipolarSpan", static_cast<float>(layout.Span));
}

//------------------------------------------------------------------------------
void vtkLightShaftEpipolarMethod::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SlabProgram.Release();
  for (vtkLightShaftShaders::Program& program : this->StagePrograms)
  {
    program.Release();
  }
  for (auto* texture :
    { &this->Ends, &this->Coordinates, &this->Coarse, &this->Refined, &this->Fine, &this->Marked })
  {
    texture->Release(window);
  }
  this->MarkDepth.Release(window);
  this->Mark.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
}
