#include "vtkLightShaftSlabDrawer.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftShaders.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkLightShaftSlabDrawer::vtkLightShaftSlabDrawer() = default;
vtkLightShaftSlabDrawer::~vtkLightShaftSlabDrawer() = default;

//------------------------------------------------------------------------------
vtkLightShaftSlabDrawer::Slabs vtkLightShaftSlabDrawer::Slabs::Over(
  const vtkLightShaftGeometry::LitVolume& lit,
  const std::vector<vtkLightShaftGeometry::SlabFootprint>& footprints,
  vtkTextureObject* depth,
  int count)
{
  Slabs slabs;
  slabs.Footprints = &footprints;
  slabs.Start = lit.Nearest;
  slabs.End = lit.Deepest;
  slabs.Thickness = (lit.Deepest - lit.Nearest) / count;
  slabs.LastSlab = count - 1;
  slabs.Depth = depth;
  return slabs;
}

//------------------------------------------------------------------------------
void vtkLightShaftSlabDrawer::SetUniforms(vtkLightShaftFrame& frame,
  vtkShaderProgram* program,
  const Slabs& slabs)
{
  const glm::dmat4& viewToClip = frame.Camera.ViewToClip;
  const int lw = frame.Reduced[0];
  const int lh = frame.Reduced[1];
  vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, lw, lh);
  // Row 2 and row 3 of the projection: a view depth's NDC z, for the slabs' depth test.
  const float depthProjection[4] = { static_cast<float>(viewToClip[2][2]),
    static_cast<float>(viewToClip[3][2]),
    static_cast<float>(viewToClip[2][3]),
    static_cast<float>(viewToClip[3][3]) };
  program->SetUniform4f("depthProjection", depthProjection);
  program->SetUniformf("slabStart", static_cast<float>(slabs.Start));
  program->SetUniformf("slabEnd", static_cast<float>(slabs.End));
  program->SetUniformf("slabThickness", static_cast<float>(slabs.Thickness));
  program->SetUniformf("lastSlab", static_cast<float>(slabs.LastSlab));
  if (slabs.Lattice > 0)
  {
    program->SetUniformf("latticeSlabShift", static_cast<float>(slabs.LatticeShift));
  }
  slabs.Depth->Activate();
  program->SetUniformi("sceneDepth", slabs.Depth->GetTextureUnit());
  vtkLightShaftShaders::SetIntegrandUniforms(program, frame);
  if (slabs.ShadowMap || frame.Cookie || frame.Noise)
  {
    vtkLightShaftShaders::SetLightSpaceUniforms(program, frame, lw, slabs.ShadowMap);
  }
  if (slabs.ShadowMap)
  {
    program->SetUniformf("shadowBias", static_cast<float>(slabs.ShadowBias));
  }
  if (frame.Cookie)
  {
    vtkLightShaftShaders::SetCookieUniforms(program, frame.Cookie, frame.Light.Model);
  }
  if (frame.Noise)
  {
    const vtkLightShaftParameters& p = frame.Parameters;
    frame.Noise->Activate();
    program->SetUniformi("noiseTexture", frame.Noise->GetTextureUnit());
    program->SetUniformf("noiseSize", static_cast<float>(frame.Noise->GetWidth()));
    program->SetUniformf("noiseAmplitude", static_cast<float>(p.NoiseAmplitude));
    program->SetUniformf("noiseScale", static_cast<float>(p.NoiseScale));
    const float shift[4] = { static_cast<float>(p.NoiseShift[0]),
      static_cast<float>(p.NoiseShift[1]),
      static_cast<float>(p.NoiseShift[2]),
      static_cast<float>(p.NoiseShift[3]) };
    program->SetUniform4f("noiseShift", shift);
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftSlabDrawer::DrawBatch(vtkShaderProgram* program,
  bool more,
  vtkLightShaftFrame& frame)
{
  std::vector<float>& vertices = this->Vertices;
  if (vertices.empty())
  {
    return;
  }
  if (!this->VertexArray)
  {
    this->VertexArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Buffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->VertexArrayProgram = nullptr;
  }
  this->Buffer->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer);
  if (this->VertexArrayProgram != program)
  {
    this->VertexArray->ShaderProgramChanged();
  }
  this->VertexArray->Bind();
  if (this->VertexArrayProgram != program)
  {
    this->VertexArray->AddAttributeArray(
      program, this->Buffer, "sliceVertex", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    this->VertexArrayProgram = program;
  }
  this->DrawRows(static_cast<int>(vertices.size() / 4), frame);
  this->VertexArray->Release();
  if (more)
  {
    glFinish();
  }
  ++frame.Statistics.SlabBatches;
  vertices.clear();
}

//------------------------------------------------------------------------------
void vtkLightShaftSlabDrawer::DrawRows(int vertices, const vtkLightShaftFrame& frame)
{
  if (!this->Rows)
  {
    glDrawArrays(GL_TRIANGLES, 0, vertices);
    return;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  for (const vtkLightShaftGeometry::RowBlock& block : *this->Rows)
  {
    ostate->vtkglScissor(0, block.First, frame.Reduced[0], block.End - block.First);
    glDrawArrays(GL_TRIANGLES, 0, vertices);
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftSlabDrawer::Draw(vtkLightShaftFrame& frame,
  vtkShaderProgram* program,
  const Slabs& slabs)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  // Each slab is drawn at the near depth of its footprint: the depth test drops it where it
  // starts behind the surface. Depth clamping keeps slabs in front of the near plane, and those
  // beyond the far plane (up to the backdrop) at its depth, where nothing drawn is 1 too (the
  // test passes them: a slab starting at a surface adds nothing, its fragments cut there).
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);
  ostate->vtkglDepthMask(GL_FALSE);
  const GLboolean depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_CLAMP);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  this->SetUniforms(frame, program, slabs);
  // An image piece's rows: a scissor per block, and the fragments that pass counted (the share
  // of the frame's in-scatter this process computes).
  this->Rows = slabs.Rows;
  GLuint fragments = 0;
  GLboolean scissorWasOn = GL_FALSE;
  if (this->Rows)
  {
    scissorWasOn = glIsEnabled(GL_SCISSOR_TEST);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    glGenQueries(1, &fragments);
    glBeginQuery(GL_SAMPLES_PASSED, fragments);
  }

  this->Vertices.clear();
  for (const vtkLightShaftGeometry::SlabFootprint& slab : *slabs.Footprints)
  {
    vtkLightShaftGeometry::AppendSlabTriangles(slab, slabs.Lattice, this->Vertices);
    if (this->Vertices.size() / 4 >= SlabBatchVertices)
    {
      this->DrawBatch(program, true, frame);
    }
  }
  this->DrawBatch(program, false, frame);
  if (this->Rows)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 passed = 0;
    glGetQueryObjectui64v(fragments, GL_QUERY_RESULT, &passed);
    glDeleteQueries(1, &fragments);
    long long& counted = frame.Statistics.InScatterFragments;
    counted = std::max(counted, 0LL) + static_cast<long long>(passed);
    ostate->vtkglScissor(0, 0, frame.Reduced[0], frame.Reduced[1]);
    if (!scissorWasOn)
    {
      ostate->vtkglDisable(GL_SCISSOR_TEST);
    }
    this->Rows = nullptr;
  }

  slabs.Depth->Deactivate();
  for (vtkTextureObject* t : { slabs.ShadowMap,
         frame.Translucency,
         frame.CameraLayers,
         frame.Volume,
         frame.VolumeShadow,
         frame.Cookie,
         frame.Noise,
         frame.Density,
         frame.FieldShadow })
  {
    if (t)
    {
      t->Deactivate();
    }
  }
  if (!depthClampWasOn)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
}

//------------------------------------------------------------------------------
void vtkLightShaftSlabDrawer::ReleaseGraphicsResources(vtkWindow*)
{
  if (this->VertexArray)
  {
    this->VertexArray->ReleaseGraphicsResources();
  }
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources();
  }
  this->VertexArray = nullptr;
  this->Buffer = nullptr;
  this->VertexArrayProgram = nullptr;
}
