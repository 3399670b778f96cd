#include "vtkLightShaftLightVolumeMethod.h"

#include "vtkLightShaftFrame.h"
#include "vtkLightShaftInScatterTarget.h"
#include "vtkLightShaftShadowMap.h"
#include "vtkLightShaftSlabDrawer.h"

#include "vtkLightShaftOpenGL.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkLightShaftGeometryBudget.h"
#include "vtkLightShaftLightVolumeFS.h"
#include "vtkLightShaftLightVolumeVS.h"

#include <algorithm>
#include <cmath>

using vtkLightShaftResources::TextureKind;

//------------------------------------------------------------------------------
vtkLightShaftLightVolumeMethod::vtkLightShaftLightVolumeMethod(vtkLightShaftSlabDrawer& drawer)
  : Drawer(drawer)
{
}

vtkLightShaftLightVolumeMethod::~vtkLightShaftLightVolumeMethod() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftLightVolumeMethod::Render(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkLightShaftInScatterTarget& target)
{
  this->Footprints = vtkLightShaftGeometry::ComputeSlabFootprints(lit, frame.Camera, 1, false);
  if (this->Footprints.empty())
  {
    return nullptr;
  }
  vtkTextureObject* shadowMap = frame.ShadowMap->Ready(frame);
  // The integrand without lookups (G is unshadowed); the map is read by the mesh only.
  vtkLightShaftShaders::Variant variant =
    vtkLightShaftShaders::IntegrandVariant(this->GetName(), nullptr, frame, false);
  variant.Feature(shadowMap != nullptr, "LIGHTSHAFT_SHADOW_VOLUME", "shadow-volume");
  variant.Description += FloatAccumulation(frame.Parameters);
  if (shadowMap && !this->DrawCrossings(frame, lit, shadowMap, variant, target))
  {
    return nullptr;
  }

  vtkLightShaftShaders::Variant resolve = variant;
  resolve.Defines.emplace_back("LIGHTSHAFT_LIGHT_VOLUME_STAGE 1");
  vtkShaderProgram* program = this->ReadySlabProgram(frame, vtkLightShaftLightVolumeFS, resolve);
  if (!program)
  {
    return nullptr;
  }
  program->SetUniformf("maximumSigmaT", static_cast<float>(frame.Medium.MaximumSigmaT()));
  vtkTextureObject* crossings = shadowMap ? this->Crossings.Object.Get() : nullptr;
  if (crossings)
  {
    crossings->Activate();
    program->SetUniformi("lightVolumeCrossings", crossings->GetTextureUnit());
  }
  target.Bind();
  vtkLightShaftSlabDrawer::Slabs slabs =
    vtkLightShaftSlabDrawer::Slabs::Over(lit, this->Footprints, target.GetDepth());
  this->Drawer.Draw(frame, program, slabs);
  if (crossings)
  {
    crossings->Deactivate();
  }
  frame.LightStatistics->SlicesDrawn = static_cast<int>(this->Footprints.size());
  return target.GetAccumulation(0);
}

//------------------------------------------------------------------------------
// LightVolumeResolution, or fewer cells where a refining view's frame would draw more than
// vtkLightShaftGeometry::FrameLightVolumeCellAllowance (SplitLongFrames), said once.
int vtkLightShaftLightVolumeMethod::CellsWithinAllowance(vtkLightShaftFrame& frame, int faces)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  const int requested = p.LightVolumeResolution;
  if (!p.ProgressiveRefinement || !p.SplitLongFrames)
  {
    return requested;
  }
  const long long pixels = static_cast<long long>(frame.Reduced[0]) * frame.Reduced[1];
  const int affordable =
    vtkLightShaftGeometry::AffordableLightVolume(requested, faces, frame.RadiatingLights, pixels);
  // (One flag per kind of light: point lights' cube faces afford fewer cells than spots'.)
  bool& warned = faces > 1 ? this->WarnedCubeAllowance : this->WarnedAllowance;
  if (SayReduction(affordable != requested, warned))
  {
    vtkWarningWithObjectMacro(frame.Owner,
      "LightVolumeResolution " << requested << " would draw "
                               << static_cast<long long>(requested) * requested * faces *
                                    frame.RadiatingLights
                               << " mesh cells over " << pixels
                               << " in-scatter pixels in a frame, more than a refining view's "
                                  "frame allows (SplitLongFrames)"
                               << SharedBy(frame) << ": using " << affordable
                               << " (vtkLightShaftFrameReport::GetLightVolumeResolution).");
  }
  return affordable;
}

//------------------------------------------------------------------------------
bool vtkLightShaftLightVolumeMethod::DrawCrossings(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkTextureObject* shadowMap,
  const vtkLightShaftShaders::Variant& variant,
  vtkLightShaftInScatterTarget& target)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkLightShaftShaders::Variant crossing = variant;
  crossing.Defines.emplace_back("LIGHTSHAFT_LIGHT_VOLUME_STAGE 0");
  vtkShaderProgram* program = this->CrossingProgram.Ready(
    window, vtkLightShaftLightVolumeVS, vtkLightShaftLightVolumeFS, crossing);
  if (!program)
  {
    vtkErrorWithObjectMacro(frame.Owner, "Could not build the light-volume shader.");
    return false;
  }

  // The mesh: as many cells across a face as the map has texels at most.
  const bool point = frame.Light.Model.Kind == vtkLightShaftModel::LightKind::Point;
  const int texels = static_cast<int>(point ? shadowMap->GetHeight() / 2 : shadowMap->GetWidth());
  const int cells = this->CellsWithinAllowance(frame, point ? 6 : 1);
  this->UploadGrid(std::max(1, std::min(cells, texels)));
  int& recorded = frame.Statistics.LightVolumeResolution;
  recorded = recorded > 0 ? std::min(recorded, this->GridCells) : this->GridCells;
  this->SetMeshUniforms(frame, lit, program, shadowMap, target.GetDepth(), texels);

  const int width = frame.Reduced[0];
  const int height = frame.Reduced[1];
  vtkTextureObject* crossings = this->Crossings.Ensure(window, TextureKind::RGBA32F, width, height);
  vtkLightShaftResources::BindTargets(
    vtkLightShaftResources::EnsureFramebuffer(this->Framebuffer, window),
    { crossings },
    nullptr,
    width,
    height);
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  // Every crossing in front of the lit range's start counts, however far: a perspective
  // camera's projection gets its near plane in front of that start and its far plane at
  // infinity (SetMeshUniforms); a parallel one's depth is clamped (w = 1: nothing behind the
  // eye to clip). Those before the start have G = 0.
  const GLboolean depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP);
  if (!frame.Camera.Perspective)
  {
    glEnable(GL_DEPTH_CLAMP);
  }
  this->DrawMesh(frame, program, point, texels);
  if (!depthClampWasOn)
  {
    glDisable(GL_DEPTH_CLAMP);
  }
  ostate->vtkglDisable(GL_BLEND);
  target.GetDepth()->Deactivate();
  shadowMap->Deactivate();
  ++frame.Statistics.PostPasses;
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftLightVolumeMethod::SetMeshUniforms(vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit,
  vtkShaderProgram* program,
  vtkTextureObject* shadowMap,
  vtkTextureObject* depth,
  int texels)
{
  const int width = frame.Reduced[0];
  vtkLightShaftShaders::SetViewUniforms(program, frame.Camera, width, frame.Reduced[1]);
  vtkLightShaftShaders::SetIntegrandUniforms(program, frame);
  vtkLightShaftShaders::SetLightSpaceUniforms(program, frame, width, shadowMap);
  depth->Activate();
  program->SetUniformi("sceneDepth", depth->GetTextureUnit());
  program->SetUniformf("slabStart", static_cast<float>(lit.Nearest));
  program->SetUniformf("slabEnd", static_cast<float>(lit.Deepest));
  program->SetUniformf("maximumSigmaT", static_cast<float>(frame.Medium.MaximumSigmaT()));
  program->SetUniformi("lightVolumeCells", this->GridCells);
  program->SetUniformi("shadowTexels", texels);
  program->SetUniformf("shadowBias", static_cast<float>(frame.LightStatistics->ShadowBias));
  program->SetUniformf("lightVolumeFar", static_cast<float>(FarCapDepth(frame, lit)));
  // A perspective camera's projection with its near plane at half the lit range's nearest
  // depth (the medium in front of the camera's own near plane is lit too: crossings there
  // count) and its far plane at infinity.
  glm::dmat4 meshProjection = frame.Camera.ViewToClip;
  if (frame.Camera.Perspective)
  {
    meshProjection[2][2] = -1.0;
    meshProjection[3][2] = -lit.Nearest;
  }
  program->SetUniformMatrix4x4(
    "meshClipFromVC", vtkLightShaftGeometry::ToFloatColumnMajor(meshProjection).data());
}

//------------------------------------------------------------------------------
void vtkLightShaftLightVolumeMethod::DrawMesh(vtkLightShaftFrame& frame,
  vtkShaderProgram* program,
  bool point,
  int texels)
{
  this->VertexArray->Bind();
  this->Indices->Bind();
  const int faces = point ? 6 : 1;
  for (int face = 0; face < faces; ++face)
  {
    const glm::dmat4& lightClipFromVC =
      point ? frame.Light.Views[face].ViewToClip : frame.Light.ViewToLightClip;
    program->SetUniformMatrix4x4("vcFromLightClip",
      vtkLightShaftGeometry::ToFloatColumnMajor(glm::inverse(lightClipFromVC)).data());
    const int origin[2] = { point ? (face % 3) * texels : 0, point ? (face / 3) * texels : 0 };
    program->SetUniform2i("shadowFaceOrigin", origin);
    // In batches as the slab drawer's, each finished before the next: llvmpipe would
    // otherwise hold all of a fine mesh's binned triangles at once.
    const int batch = static_cast<int>(vtkLightShaftSlabDrawer::SlabBatchVertices);
    for (int first = 0; first < this->IndexCount; first += batch)
    {
      const int count = std::min(batch, this->IndexCount - first);
      glDrawElements(GL_TRIANGLES,
        count,
        GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(static_cast<size_t>(first) * sizeof(unsigned int)));
      if (this->IndexCount > batch && (first + count < this->IndexCount || face + 1 < faces))
      {
        glFinish();
      }
    }
  }
  this->Indices->Release();
  this->VertexArray->Release();
}

//------------------------------------------------------------------------------
void vtkLightShaftLightVolumeMethod::UploadGrid(int cells)
{
  if (this->VertexArray && cells == this->GridCells)
  {
    return;
  }
  const unsigned int side = static_cast<unsigned int>(cells) + 4;
  auto at = [side](unsigned int column, unsigned int row) { return row * side + column; };
  std::vector<unsigned int> indices;
  indices.reserve(6 * (side - 1) * (side - 1) + 12 * (side - 1));
  // Counter-clockwise in the light's (x, y): facing the light.
  for (unsigned int row = 0; row + 1 < side; ++row)
  {
    for (unsigned int column = 0; column + 1 < side; ++column)
    {
      const unsigned int quad[4] = {
        at(column, row), at(column + 1, row), at(column + 1, row + 1), at(column, row + 1)
      };
      indices.insert(indices.end(), { quad[0], quad[1], quad[2], quad[0], quad[2], quad[3] });
    }
  }
  // The far cap: a fan from its centre (the last vertex) over the ring, which it walks against
  // the grid's own (counter-clockwise) walk of it: facing away from the light.
  std::vector<unsigned int> ring;
  for (unsigned int c = 0; c + 1 < side; ++c)
  {
    ring.push_back(at(c, 0));
  }
  for (unsigned int r = 0; r + 1 < side; ++r)
  {
    ring.push_back(at(side - 1, r));
  }
  for (unsigned int c = side - 1; c > 0; --c)
  {
    ring.push_back(at(c, side - 1));
  }
  for (unsigned int r = side - 1; r > 0; --r)
  {
    ring.push_back(at(0, r));
  }
  const unsigned int centre = side * side;
  for (size_t k = 0; k < ring.size(); ++k)
  {
    indices.insert(indices.end(), { centre, ring[(k + 1) % ring.size()], ring[k] });
  }

  if (!this->VertexArray)
  {
    this->VertexArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Indices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Indices->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  this->VertexArray->Bind();
  this->Indices->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
  this->VertexArray->Release();
  this->GridCells = cells;
  this->IndexCount = static_cast<int>(indices.size());
}

//------------------------------------------------------------------------------
double vtkLightShaftLightVolumeMethod::FarCapDepth(const vtkLightShaftFrame& frame,
  const vtkLightShaftGeometry::LitVolume& lit)
{
  const vtkLightShaftGeometry::LightFrame& light = frame.Light;
  const bool directional = light.Model.Kind == vtkLightShaftModel::LightKind::Directional;
  double deepest = light.Far;
  for (const std::vector<glm::dvec3>& face : lit.Polytope.Faces)
  {
    for (const glm::dvec3& corner : face)
    {
      // An upper bound of the light depth (axial distance <= distance).
      const glm::dvec3 fromLight = corner - light.PositionVC;
      deepest =
        std::max(deepest, directional ? glm::dot(fromLight, light.AxisVC) : glm::length(fromLight));
    }
  }
  return 2.0 * deepest;
}

//------------------------------------------------------------------------------
void vtkLightShaftLightVolumeMethod::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SlabProgram.Release();
  this->CrossingProgram.Release();
  this->Crossings.Release(window);
  vtkLightShaftResources::ReleaseFramebuffer(this->Framebuffer, window);
  if (this->VertexArray)
  {
    this->VertexArray->ReleaseGraphicsResources();
    this->Indices->ReleaseGraphicsResources();
  }
  this->VertexArray = nullptr;
  this->Indices = nullptr;
  this->GridCells = 0;
  this->IndexCount = 0;
}
