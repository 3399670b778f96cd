#include "vtkLightShaftPass.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkVersionMacros.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkLightShaftBlurFS.h"
#include "vtkLightShaftCommon.h"
#include "vtkLightShaftCompositeFS.h"
#include "vtkLightShaftDepthDownsampleFS.h"
#include "vtkLightShaftDepthResolveFS.h"
#include "vtkLightShaftIntegrand.h"
#include "vtkLightShaftNoise.h"
#include "vtkLightShaftOcclusionFS.h"
#include "vtkLightShaftRadialBlurFS.h"
#include "vtkLightShaftResolveFS.h"
#include "vtkLightShaftSliceFS.h"
#include "vtkLightShaftSliceVS.h"
#include "vtkLightShaftUpsampleFS.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr double MaximumCoefficient = 1.0e6;
constexpr double MaximumExposure = 1.0e6;
constexpr double MaximumAnisotropy = 0.99;
// The bounding pyramid of a cone wider than this is numerically useless; such cones are
// bounded by the view volume instead (the shader still clips to the true cone).
// Relative view-depth difference under which two pixels see "the same surface" (the depth-aware
// blur, gather and upsampling).
constexpr float SameSurfaceTolerance = 0.05f;

constexpr double MaximumBoundingHalfAngle = vtkMath::Pi() * 89.9 / 180.0;

// VTK's key matrices are stored transposed (ready for glUniformMatrix4fv), which is exactly
// glm's column-major layout of the mathematical matrix.
glm::dmat4 FromKeyMatrix(vtkMatrix4x4* key)
{
  return glm::make_mat4(&key->Element[0][0]);
}

// A vtkMatrix4x4 (row-major, mathematical) to glm.
glm::dmat4 FromVTKMatrix(vtkMatrix4x4* m)
{
  return glm::transpose(glm::make_mat4(&m->Element[0][0]));
}

void ToVTKMatrix(const glm::dmat4& m, vtkMatrix4x4* out)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      out->SetElement(row, col, m[col][row]);
    }
  }
}

std::array<float, 16> ToFloatColumnMajor(const glm::dmat4& m)
{
  std::array<float, 16> out;
  const double* p = glm::value_ptr(m);
  std::copy(p, p + 16, out.begin());
  return out;
}

std::array<float, 3> ToFloat3(const glm::dvec3& v)
{
  return { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
}

/**
 * A convex polytope as a list of convex faces, clipped by half-spaces. Used on the CPU to find
 * the part of the view volume lit by the spot's bounding pyramid.
 */
struct ConvexPolytope
{
  std::vector<std::vector<glm::dvec3>> Faces;

  // Keep the part where dot(plane.xyz, p) + plane.w >= 0.
  void Clip(const glm::dvec4& plane)
  {
    const glm::dvec3 n(plane);
    const double scale = glm::length(n);
    if (scale == 0.0)
    {
      return;
    }
    std::vector<std::vector<glm::dvec3>> kept;
    std::vector<glm::dvec3> cut;
    for (const auto& face : this->Faces)
    {
      std::vector<glm::dvec3> out;
      const size_t count = face.size();
      for (size_t i = 0; i < count; ++i)
      {
        const glm::dvec3& a = face[i];
        const glm::dvec3& b = face[(i + 1) % count];
        const double da = (glm::dot(n, a) + plane.w) / scale;
        const double db = (glm::dot(n, b) + plane.w) / scale;
        if (da >= 0.0)
        {
          out.push_back(a);
        }
        if ((da >= 0.0) != (db >= 0.0))
        {
          const glm::dvec3 p = a + (b - a) * (da / (da - db));
          out.push_back(p);
          cut.push_back(p);
        }
      }
      if (out.size() >= 3)
      {
        kept.push_back(std::move(out));
      }
    }
    if (cut.size() >= 3)
    {
      // The cap: the cut points ordered around their centroid in the clipping plane.
      glm::dvec3 centre(0.0);
      for (const auto& p : cut)
      {
        centre += p;
      }
      centre /= static_cast<double>(cut.size());
      const glm::dvec3 axis = n / scale;
      glm::dvec3 u =
        glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
      u = glm::normalize(u);
      const glm::dvec3 v = glm::cross(axis, u);
      std::sort(cut.begin(),
        cut.end(),
        [&](const glm::dvec3& p, const glm::dvec3& q)
        {
          return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
                 std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
        });
      kept.push_back(std::move(cut));
    }
    this->Faces = std::move(kept);
  }

  bool Empty() const { return this->Faces.empty(); }
};

// The part of a convex polygon inside a counter-clockwise convex polygon (Sutherland-Hodgman).
std::vector<glm::dvec2> ClipToConvex(std::vector<glm::dvec2> polygon,
  const std::vector<glm::dvec2>& window)
{
  std::vector<glm::dvec2> next;
  for (size_t e = 0; e < window.size() && !polygon.empty(); ++e)
  {
    const glm::dvec2 a = window[e];
    const glm::dvec2 edge = window[(e + 1) % window.size()] - a;
    auto side = [&](const glm::dvec2& p) { return edge.x * (p.y - a.y) - edge.y * (p.x - a.x); };
    next.clear();
    for (size_t i = 0; i < polygon.size(); ++i)
    {
      const glm::dvec2& p = polygon[i];
      const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
      const double sp = side(p);
      const double sq = side(q);
      if (sp >= 0.0)
      {
        next.push_back(p);
      }
      if ((sp >= 0.0) != (sq >= 0.0))
      {
        next.push_back(p + (q - p) * (sp / (sp - sq)));
      }
    }
    polygon.swap(next);
  }
  return polygon;
}

// 2D convex hull (Andrew's monotone chain), counter-clockwise, no repeated point.
std::vector<glm::dvec2> ConvexHull(std::vector<glm::dvec2> points)
{
  std::sort(points.begin(),
    points.end(),
    [](const glm::dvec2& a, const glm::dvec2& b)
    { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3)
  {
    return points;
  }
  auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
  { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i > 0; --i)
  {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// One slab to draw: its index (for the shader's slab boundaries), its near view depth, and the
// convex hull of its screen footprint (NDC).
struct SlabFootprint
{
  int Index;
  double NearDepth;
  std::vector<glm::dvec2> Hull;
};

// Append the triangles covering `slab` to `vertices` (x, y in NDC, slab index, near depth per
// vertex): the hull as a fan, or with lattice > 0 an n x n lattice over the hull's bounding
// rectangle with each cell clipped to the hull, so that no more fragments are drawn than
// without the lattice.
void AppendSlabTriangles(const SlabFootprint& slab, int lattice, std::vector<float>& vertices)
{
  const std::vector<glm::dvec2>& hull = slab.Hull;
  auto emit = [&](const glm::dvec2& p)
  {
    vertices.insert(vertices.end(),
      { static_cast<float>(p.x),
        static_cast<float>(p.y),
        static_cast<float>(slab.Index),
        static_cast<float>(slab.NearDepth) });
  };
  if (lattice <= 0)
  {
    for (size_t i = 1; i + 1 < hull.size(); ++i)
    {
      emit(hull[0]);
      emit(hull[i]);
      emit(hull[i + 1]);
    }
    return;
  }
  glm::dvec2 low = hull[0];
  glm::dvec2 high = hull[0];
  for (const glm::dvec2& p : hull)
  {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  auto corner = [&](int i, int j)
  { return low + (high - low) * glm::dvec2(double(i) / lattice, double(j) / lattice); };
  // Clip against the hull without its near-coincident vertices: the direction of an edge a
  // rounding error long is noise, and its half-plane would cut a sliver out of the slab.
  const double tiny = 1e-9 * glm::length(high - low);
  std::vector<glm::dvec2> window;
  for (const glm::dvec2& p : hull)
  {
    if (window.empty() || glm::length(p - window.back()) > tiny)
    {
      window.push_back(p);
    }
  }
  while (window.size() > 1 && glm::length(window.front() - window.back()) <= tiny)
  {
    window.pop_back();
  }
  for (int j = 0; j < lattice; ++j)
  {
    for (int i = 0; i < lattice; ++i)
    {
      const std::vector<glm::dvec2> cell = ClipToConvex(
        { corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1) }, window);
      for (size_t c = 1; c + 1 < cell.size(); ++c)
      {
        emit(cell[0]);
        emit(cell[c]);
        emit(cell[c + 1]);
      }
    }
  }
}
} // namespace

namespace
{
/**
 * The scene camera exactly as the mappers see it (VTK's key matrices), in double precision.
 */
struct CameraFrame
{
  glm::dmat4 WorldToView;
  glm::dmat4 ViewToClip;
  glm::dmat4 ClipToView;
};
} // namespace

namespace
{
/**
 * The spotlight as the shaders see it: position and axis in world and view coordinates, and
 * the square light camera whose inscribed cone is the spot cone (shadow map, cookie, noise).
 */
struct LightFrame
{
  glm::dvec3 PositionWC;
  glm::dvec3 AxisWC;
  glm::dvec3 PositionVC;
  glm::dvec3 AxisVC;
  double ConeHalfAngle = 0.0; // radians
  double Near = 0.0;
  double Far = 1.0;
  glm::dmat4 Projection{ 1.0 };
  glm::dmat4 ViewToLightClip{ 1.0 };
  glm::dmat4 WorldToLightClip{ 1.0 };
  double RadiantIntensity[3] = { 0.0, 0.0, 0.0 };
  double Exponent = 1.0;
  double Attenuation[3] = { 1.0, 0.0, 0.0 }; // c0, c1, c2 (all zero is treated as no falloff)
  std::vector<vtkProp*> Casters;             // props whose bounds reach into the light's volume
  bool ShadowsPossible = false;              // casters here, or (distributed) in any process
};

/// Off-screen texture kinds the pass allocates.
enum class TextureKind
{
  RGBA8,
  RGBA16F,
  RGBA32F,
  Depth
};

/**
 * A texture the pass owns, re-allocated only when its kind or size changes.
 */
struct OwnedTexture
{
  vtkSmartPointer<vtkTextureObject> Object;
  TextureKind Kind = TextureKind::RGBA8;

  // `samples` > 0 makes a multisampled texture (GL_TEXTURE_2D_MULTISAMPLE) of that many samples.
  vtkTextureObject* Ensure(vtkOpenGLRenderWindow* window,
    TextureKind kind,
    int w,
    int h,
    int samples = 0)
  {
    if (this->Object && (this->Kind != kind || this->Object->GetSamples() != samples))
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
      }
    }
    else if (static_cast<int>(this->Object->GetWidth()) != w ||
             static_cast<int>(this->Object->GetHeight()) != h)
    {
      this->Object->Resize(w, h);
    }
    return this->Object;
  }

  void Release(vtkWindow* w)
  {
    if (this->Object)
    {
      this->Object->ReleaseGraphicsResources(w);
    }
    this->Object = nullptr;
  }
};

/**
 * The delegate's render of the scene in one frame: colour (and, for a cookie on surfaces, the
 * colour without the spotlight) and depth, multisampled like the target the pass draws into,
 * and the single-sample depth the shafts read (the nearest of each pixel's samples).
 */
struct SceneImage
{
  vtkTextureObject* Color = nullptr;
  vtkTextureObject* ColorUnlit = nullptr;
  vtkTextureObject* Depth = nullptr;
  vtkTextureObject* ShaftDepth = nullptr;
  int Samples = 0;
};

// Lattice cells built and drawn per frame at most (SetLatticeResolution): the cells are clipped
// on the CPU, so their number bounds the frame's CPU time (about 1.5 s for 2^21 cells here:
// README "Behaviour with any scene"); beyond it the lattice resolution is lowered for all slabs.
constexpr long long LatticeCellBudget = 1LL << 21;

// Slab vertices built and drawn in one batch (about 6 MiB of vertex data).
constexpr size_t SlabBatchVertices = 6 * 65536;

// Colour attachments the pass ever binds at once (the 8-bit mode's three accumulation buffers).
constexpr unsigned int MaximumColorAttachments = 3;

// Bind `fbo` with exactly these attachments (any others removed: a target of another size left
// attached would make it incomplete), all of size w x h, drawing into all colour attachments.
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

std::string JoinDefines(const std::vector<std::string>& defines)
{
  std::string features;
  for (const auto& define : defines)
  {
    features += "#define " + define + "\n";
  }
  return features;
}

std::string WithFeatures(const char* source, const std::vector<std::string>& defines)
{
  std::string out = source;
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Features", JoinDefines(defines));
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Common", vtkLightShaftCommon);
  vtkShaderProgram::Substitute(out, "//VTK::LightShaft::Integrand", vtkLightShaftIntegrand);
  return out;
}

/**
 * A full-screen pass, rebuilt only when its feature variant (its #defines) changes; the source
 * is assembled only then.
 */
struct FullScreenPass
{
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Key;

  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window,
    const char* source,
    const std::vector<std::string>& defines = {})
  {
    const std::string key = JoinDefines(defines);
    if (!this->Quad || this->Key != key)
    {
      const std::string fragment = WithFeatures(source, defines);
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

  void Release(vtkWindow* w)
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(w);
    }
    this->Quad.reset();
    this->Key.clear();
  }
};

bool AnyPositive(const double v[3])
{
  return v[0] > 0.0 || v[1] > 0.0 || v[2] > 0.0;
}

// A mipmapped, linearly filtered texture from float texels (1 or 3 components).
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
} // namespace

/**
 * Everything the pass holds besides its parameters: GL objects (owned by smart pointers, freed
 * by ReleaseGraphicsResources), the light choice, and the shader variants that were built.
 */
class vtkLightShaftPass::Internals
{
public:
  vtkSmartPointer<vtkLight> Light;
  vtkWeakPointer<vtkLight> LastUsedLight;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkCallbackCommand> WindowDeleted;
  unsigned long WindowDeletedTag = 0;
  bool WarnedNoLight = false;
  bool WarnedCookie = false;
  bool WarnedNoise = false;
  bool WarnedAnalyticShadows = false;
  bool WarnedLatticeBudget = false;
  bool EightBitThisFrame = false;
  vtkTextureObject* ShadowMapEventTexture = nullptr;

  vtkSmartPointer<vtkTexture> Cookie;
  vtkSmartPointer<vtkTexture> NoiseImage;

  // Used when no delegate is set: renders like VTK's default pipeline, or with the opaque step
  // shadowed by vtkShadowMapPass (ShadowSurfaces).
  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  vtkNew<vtkRenderStepsPass> ShadowedDelegate;
  vtkNew<vtkShadowMapPass> SurfaceShadows;

  // Shadow map: the opaque step rendered from the light's camera.
  vtkNew<vtkCameraPass> ShadowCameraPass;
  vtkNew<vtkOpaquePass> ShadowOpaquePass;
  vtkNew<vtkCamera> LightCamera;

  // Targets. Full resolution: the scene (lit, and unlit for cookies on surfaces) and its depth,
  // multisampled like the pass's own target, the nearest-sample depth when they are, the final
  // in-scatter. Reduced resolution (DownsampleFactor): the accumulation buffers, a depth for
  // the slabs and its copy for the depth test, blur buffers.
  OwnedTexture SceneColor;
  OwnedTexture SceneColorUnlit;
  OwnedTexture SceneDepth;
  OwnedTexture ResolvedDepth;
  OwnedTexture ReducedDepth;
  OwnedTexture SlabDepthTest;
  OwnedTexture Accumulation[3];
  OwnedTexture Resolved;
  OwnedTexture BlurTemporary;
  OwnedTexture Blurred;
  OwnedTexture Upsampled;
  OwnedTexture ShadowMap;
  OwnedTexture OcclusionMask;
  OwnedTexture GuardDepth;
  OwnedTexture RadialOutput;
  OwnedTexture GatherTemporary;
  OwnedTexture Gathered;
  vtkSmartPointer<vtkTextureObject> CookieTexture;
  vtkMTimeType CookieUploadTime = 0;
  vtkSmartPointer<vtkTextureObject> NoiseTexture;
  vtkMTimeType NoiseUploadTime = 0;
  bool NoiseIsGenerated = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> SceneFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> AccumulationFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> WorkFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ShadowFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> GuardFramebuffer;
  vtkNew<vtkCamera> GuardCamera;

  // The light camera of the last shadow map (GetLastShadowMap).
  glm::dmat4 LastWorldToLightClip{ 1.0 };

  // The last frame's L_in (full resolution) when InScatterValid.
  vtkTextureObject* FinalInScatter = nullptr;
  bool InScatterValid = false;

  // Slab program: owned by the window's shader cache; rebuilt when its source (variant)
  // changes.
  vtkShaderProgram* SliceProgram = nullptr;
  std::string SliceSource;
  std::string SliceKey;
  std::string SliceVariant;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> SliceArray;
  vtkSmartPointer<vtkOpenGLBufferObject> SliceBuffer;
  vtkShaderProgram* SliceArrayProgram = nullptr;
  std::vector<SlabFootprint> SlabFootprints;
  std::vector<float> SliceVertices;

  FullScreenPass Composite;
  FullScreenPass DepthResolve;
  FullScreenPass DepthDownsample;
  FullScreenPass Resolve;
  FullScreenPass Blur;
  FullScreenPass Upsample;
  FullScreenPass Occlusion;
  FullScreenPass RadialBlur;

  // Track the window whose context holds our GL objects. When it goes away first, free them
  // while its context still exists (at DeleteEvent the window is still whole).
  void Track(vtkOpenGLRenderWindow* window)
  {
    if (this->Window == window)
    {
      return;
    }
    this->Untrack();
    this->Window = window;
    this->WindowDeleted->SetClientData(this);
    this->WindowDeleted->SetCallback(
      [](vtkObject* caller, unsigned long, void* clientData, void*)
      {
        auto* self = static_cast<Internals*>(clientData);
        auto* dying = static_cast<vtkOpenGLRenderWindow*>(caller);
        dying->MakeCurrent();
        self->ReleaseOwnResources(dying);
        self->Window = nullptr;
        self->WindowDeletedTag = 0;
      });
    this->WindowDeletedTag = window->AddObserver(vtkCommand::DeleteEvent, this->WindowDeleted);
  }

  void Untrack()
  {
    if (this->Window && this->WindowDeletedTag)
    {
      this->Window->RemoveObserver(this->WindowDeletedTag);
    }
    this->WindowDeletedTag = 0;
    this->Window = nullptr;
  }

  // VTK 9.1's shadow-map baker gives its light cameras the renderer's aspect ratio, so on a
  // non-square viewport the surface shadows come out squeezed. Its cameras persist between
  // frames: pin their aspect to the square shadow map's. Returns true when a camera had to be
  // fixed (its shadow map, baked this frame, was wrong).
  bool FixSurfaceShadowCameras()
  {
    bool fixed = false;
    if (auto* cameras = this->SurfaceShadows->GetShadowMapBakerPass()->GetLightCameras())
    {
      for (auto& camera : *cameras)
      {
        if (camera &&
            (!camera->GetUseExplicitAspectRatio() || camera->GetExplicitAspectRatio() != 1.0))
        {
          camera->SetExplicitAspectRatio(1.0);
          camera->SetUseExplicitAspectRatio(true);
          fixed = true;
        }
      }
    }
    return fixed;
  }

  // Render `delegate` with `render`; with the shadowed delegate, make sure its shadow maps were
  // baked with square cameras (re-render once when they were not).
  void RenderDelegate(vtkLightShaftPass& self,
    vtkRenderPass* delegate,
    const vtkRenderState* s,
    const std::function<void()>& render)
  {
    const bool shadowed = delegate == this->ShadowedDelegate.Get();
    if (shadowed)
    {
      this->FixSurfaceShadowCameras();
    }
    render();
    if (shadowed && this->FixSurfaceShadowCameras())
    {
      s->GetRenderer()->GetLights()->Modified(); // make the baker bake again
      render();
    }
    self.NumberOfRenderedProps += delegate->GetNumberOfRenderedProps();
  }

  void ReleaseOwnResources(vtkWindow* w)
  {
    for (OwnedTexture* t : { &this->SceneColor,
           &this->SceneColorUnlit,
           &this->SceneDepth,
           &this->ResolvedDepth,
           &this->ReducedDepth,
           &this->SlabDepthTest,
           &this->Accumulation[0],
           &this->Accumulation[1],
           &this->Accumulation[2],
           &this->Resolved,
           &this->BlurTemporary,
           &this->Blurred,
           &this->Upsampled,
           &this->ShadowMap,
           &this->OcclusionMask,
           &this->GuardDepth,
           &this->RadialOutput,
           &this->GatherTemporary,
           &this->Gathered })
    {
      t->Release(w);
    }
    for (auto* t : { &this->CookieTexture, &this->NoiseTexture })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(w);
      }
      *t = nullptr;
    }
    this->CookieUploadTime = 0;
    this->NoiseUploadTime = 0;
    for (auto* f : { &this->SceneFramebuffer,
           &this->AccumulationFramebuffer,
           &this->WorkFramebuffer,
           &this->ShadowFramebuffer,
           &this->GuardFramebuffer })
    {
      if (*f)
      {
        (*f)->ReleaseGraphicsResources(w);
      }
      *f = nullptr;
    }
    if (this->SliceArray)
    {
      this->SliceArray->ReleaseGraphicsResources();
    }
    if (this->SliceBuffer)
    {
      this->SliceBuffer->ReleaseGraphicsResources();
    }
    this->SliceArray = nullptr;
    this->SliceBuffer = nullptr;
    this->SliceProgram = nullptr;
    this->SliceArrayProgram = nullptr;
    this->SliceSource.clear();
    this->SliceKey.clear();
    for (FullScreenPass* p : { &this->Composite,
           &this->DepthResolve,
           &this->DepthDownsample,
           &this->Resolve,
           &this->Blur,
           &this->Upsample,
           &this->Occlusion,
           &this->RadialBlur })
    {
      p->Release(w);
    }
    this->FinalInScatter = nullptr;
    this->InScatterValid = false;
  }

  // Bind the work framebuffer with `color` (and optionally `depth`) as its only attachments.
  void BindWork(vtkTextureObject* color, vtkTextureObject* depth, int w, int h)
  {
    if (color)
    {
      BindTargets(this->WorkFramebuffer, { color }, depth, w, h);
    }
    else
    {
      BindTargets(this->WorkFramebuffer, {}, depth, w, h);
    }
  }

  bool ComputeLightFrame(vtkLightShaftPass& self,
    vtkRenderer* ren,
    vtkLight* light,
    const CameraFrame& camera,
    LightFrame& frame);
  SceneImage RenderScene(vtkLightShaftPass& self,
    const vtkRenderState* s,
    vtkRenderPass* delegate,
    vtkLight* light,
    bool twice,
    int samples,
    int w,
    int h);
  vtkTextureObject* ResolveDepth(vtkTextureObject* depthSamples, int samples, int w, int h);
  void RenderInScatter(vtkLightShaftPass& self,
    const vtkRenderState* s,
    LightFrame& light,
    const CameraFrame& camera,
    const SceneImage& scene,
    bool cookie,
    int w,
    int h);
  bool RenderShadowMap(vtkLightShaftPass& self, const vtkRenderState* s, LightFrame& frame);
  void RenderCasters(vtkLightShaftPass& self,
    const vtkRenderState* s,
    LightFrame& frame,
    vtkCamera* camera,
    vtkSmartPointer<vtkOpenGLFramebufferObject>& target,
    vtkTextureObject* depth);
  vtkShaderProgram* ReadySliceProgram(vtkLightShaftPass& self,
    int method,
    bool shadows,
    bool cookie,
    bool noise);
  bool ReadyCookie(vtkLightShaftPass& self);
  vtkLight* ChooseLight(vtkLightShaftPass& self, vtkRenderer* ren);
  int LatticeWithinBudget(vtkLightShaftPass& self, int slabs);
  bool ReadyNoise(vtkLightShaftPass& self);
  // Two passes of the blur shader (x, then y): a Gaussian of `radius`, or with boxWidth > 0
  // the interleaved-sampling gather. Counts its passes in LastNumberOfPostPasses.
  vtkTextureObject* SeparableFilter(vtkLightShaftPass& self,
    vtkTextureObject* source,
    OwnedTexture& temporary,
    OwnedTexture& output,
    const CameraFrame& camera,
    vtkTextureObject* slabDepth,
    int radius,
    int boxWidth,
    int lw,
    int lh);
  vtkTextureObject* Gather(vtkLightShaftPass& self,
    vtkTextureObject* source,
    const CameraFrame& camera,
    vtkTextureObject* slabDepth,
    int lw,
    int lh);
  vtkTextureObject* RenderRadialBlur(vtkLightShaftPass& self,
    const vtkRenderState* s,
    const CameraFrame& camera,
    LightFrame& light,
    vtkTextureObject* slabDepth,
    int lw,
    int lh);
  void PostProcess(vtkLightShaftPass& self,
    vtkTextureObject* current,
    const CameraFrame& camera,
    vtkTextureObject* slabDepth,
    vtkTextureObject* fullDepth,
    int w,
    int h,
    int lw,
    int lh);
  void RenderComposite(vtkLightShaftPass& self,
    vtkRenderer* ren,
    const CameraFrame& camera,
    const LightFrame* light,
    const SceneImage& scene,
    bool cookieSurfaces,
    const int viewport[4]);
};

vtkStandardNewMacro(vtkLightShaftPass);

//------------------------------------------------------------------------------
vtkLightShaftPass::vtkLightShaftPass()
  : Impl(new Internals)
{
  this->Impl->ShadowCameraPass->SetDelegatePass(this->Impl->ShadowOpaquePass);

  // Shadowed opaque step: bake the lights' shadow maps, then render the opaque props with them.
  vtkNew<vtkRenderPassCollection> shadowedOpaque;
  shadowedOpaque->AddItem(this->Impl->SurfaceShadows->GetShadowMapBakerPass());
  shadowedOpaque->AddItem(this->Impl->SurfaceShadows);
  vtkNew<vtkSequencePass> shadowedSequence;
  shadowedSequence->SetPasses(shadowedOpaque);
  this->Impl->ShadowedDelegate->SetOpaquePass(shadowedSequence);
}

//------------------------------------------------------------------------------
vtkLightShaftPass::~vtkLightShaftPass()
{
  // Free our GL objects even when nobody called ReleaseGraphicsResources (the window may still
  // be alive while the pass goes away).
  if (vtkOpenGLRenderWindow* window = this->Impl->Window)
  {
    window->MakeCurrent();
    this->Impl->ReleaseOwnResources(window);
  }
  this->Impl->Untrack();
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Impl->DefaultDelegate->ReleaseGraphicsResources(w);
  this->Impl->ShadowedDelegate->ReleaseGraphicsResources(w);
  this->Impl->ShadowCameraPass->ReleaseGraphicsResources(w);
  this->Impl->ReleaseOwnResources(w);
}

//------------------------------------------------------------------------------
// Parameters.
namespace
{
// Setters refuse NaN and infinities: report the parameter and keep the previous value.
bool RefuseNonFinite(vtkObject* self, const char* parameter, std::initializer_list<double> values)
{
  if (std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
  {
    return false;
  }
  vtkErrorWithObjectMacro(
    self, << parameter << ": non-finite value refused; the previous value is kept.");
  return true;
}

// Clamp `values` into [low, high] and store them in `target`; Modified() when they changed.
void SetClamped(vtkObject* self,
  const char* parameter,
  double* target,
  std::initializer_list<double> values,
  double low,
  double high)
{
  if (RefuseNonFinite(self, parameter, values))
  {
    return;
  }
  bool changed = false;
  size_t i = 0;
  for (double value : values)
  {
    const double clamped = vtkMath::ClampValue(value, low, high);
    changed = changed || target[i] != clamped;
    target[i++] = clamped;
  }
  if (changed)
  {
    self->Modified();
  }
}
} // namespace

void vtkLightShaftPass::SetScatteringCoefficient(double r, double g, double b)
{
  SetClamped(this,
    "ScatteringCoefficient",
    this->ScatteringCoefficient,
    { r, g, b },
    0.0,
    MaximumCoefficient);
}

void vtkLightShaftPass::SetScatteringCoefficient(const double rgb[3])
{
  this->SetScatteringCoefficient(rgb[0], rgb[1], rgb[2]);
}

void vtkLightShaftPass::SetScatteringCoefficient(double grey)
{
  this->SetScatteringCoefficient(grey, grey, grey);
}

void vtkLightShaftPass::SetAbsorptionCoefficient(double r, double g, double b)
{
  SetClamped(this,
    "AbsorptionCoefficient",
    this->AbsorptionCoefficient,
    { r, g, b },
    0.0,
    MaximumCoefficient);
}

void vtkLightShaftPass::SetAbsorptionCoefficient(const double rgb[3])
{
  this->SetAbsorptionCoefficient(rgb[0], rgb[1], rgb[2]);
}

void vtkLightShaftPass::SetAbsorptionCoefficient(double grey)
{
  this->SetAbsorptionCoefficient(grey, grey, grey);
}

void vtkLightShaftPass::SetAnisotropy(double g)
{
  SetClamped(this, "Anisotropy", &this->Anisotropy, { g }, -MaximumAnisotropy, MaximumAnisotropy);
}

void vtkLightShaftPass::SetExposure(double exposure)
{
  SetClamped(this, "Exposure", &this->Exposure, { exposure }, 0.0, MaximumExposure);
}

void vtkLightShaftPass::SetNoiseAmplitude(double amplitude)
{
  SetClamped(this, "NoiseAmplitude", &this->NoiseAmplitude, { amplitude }, 0.0, 1.0);
}

void vtkLightShaftPass::SetNoiseScale(double scale)
{
  SetClamped(this, "NoiseScale", &this->NoiseScale, { scale }, 0.01, 1000.0);
}

void vtkLightShaftPass::SetNoiseVelocity1(double u, double v)
{
  SetClamped(this, "NoiseVelocity1", this->NoiseVelocity1, { u, v }, -1e3, 1e3);
}

void vtkLightShaftPass::SetNoiseVelocity2(double u, double v)
{
  SetClamped(this, "NoiseVelocity2", this->NoiseVelocity2, { u, v }, -1e3, 1e3);
}

void vtkLightShaftPass::SetTime(double time)
{
  SetClamped(this,
    "Time",
    &this->Time,
    { time },
    -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max());
}

void vtkLightShaftPass::SetRadialGuardBand(double extent)
{
  SetClamped(this, "RadialGuardBand", &this->RadialGuardBand, { extent }, 1.0, 4.0);
}

void vtkLightShaftPass::SetDecay(double decay)
{
  SetClamped(this, "Decay", &this->Decay, { decay }, 0.0, 1.0);
}

void vtkLightShaftPass::SetDensity(double density)
{
  SetClamped(this, "Density", &this->Density, { density }, 0.0, 1.0);
}

void vtkLightShaftPass::SetWeight(double weight)
{
  SetClamped(this, "Weight", &this->Weight, { weight }, 0.0, 1.0);
}

const char* vtkLightShaftPass::GetMethodName(int method)
{
  switch (method)
  {
    case SLICES:
      return "slices";
    case RAY_MARCH:
      return "ray-march";
    case RADIAL_BLUR:
      return "radial-blur";
    case ANALYTIC:
      return "analytic";
    case AUTOMATIC:
      return "automatic";
    default:
      return "none";
  }
}

namespace
{
void ApplyQuality(vtkLightShaftPass* pass,
  int slices,
  int shadowMap,
  bool jitter,
  int blur,
  int downsample)
{
  pass->SetAutomaticSliceCount(false);
  pass->SetNumberOfSlices(slices);
  pass->SetShadowMapSize(shadowMap);
  pass->SetJitter(jitter);
  pass->SetBlurRadius(blur);
  pass->SetDownsampleFactor(downsample);
  pass->SetAccumulationPrecision(vtkLightShaftPass::ACCUMULATE_FLOAT32);
}
}

void vtkLightShaftPass::SetQualityToDraft()
{
  ApplyQuality(this, 32, 512, true, 2, 2);
}

void vtkLightShaftPass::SetQualityToInteractive()
{
  ApplyQuality(this, 64, 1024, true, 2, 1);
}

void vtkLightShaftPass::SetQualityToFinal()
{
  ApplyQuality(this, 512, 2048, false, 0, 1);
}

void vtkLightShaftPass::SetDownsampleFactor(int factor)
{
  factor = factor >= 4 ? 4 : (factor >= 2 ? 2 : 1);
  if (factor != this->DownsampleFactor)
  {
    this->DownsampleFactor = factor;
    this->Modified();
  }
}

void vtkLightShaftPass::SetLight(vtkLight* light)
{
  if (this->Impl->Light != light)
  {
    this->Impl->Light = light;
    this->Impl->WarnedNoLight = false;
    this->Modified();
  }
}

vtkLight* vtkLightShaftPass::GetLight()
{
  return this->Impl->Light;
}

vtkLight* vtkLightShaftPass::GetLastUsedLight()
{
  return this->Impl->LastUsedLight;
}

void vtkLightShaftPass::SetCookie(vtkTexture* cookie)
{
  if (this->Impl->Cookie != cookie)
  {
    this->Impl->Cookie = cookie;
    this->Impl->CookieUploadTime = 0;
    this->Impl->WarnedCookie = false;
    this->Modified();
  }
}

vtkTexture* vtkLightShaftPass::GetCookie()
{
  return this->Impl->Cookie;
}

void vtkLightShaftPass::SetNoiseTexture(vtkTexture* noise)
{
  if (this->Impl->NoiseImage != noise)
  {
    this->Impl->NoiseImage = noise;
    this->Impl->NoiseUploadTime = 0;
    this->Impl->WarnedNoise = false;
    this->Modified();
  }
}

vtkTexture* vtkLightShaftPass::GetNoiseTexture()
{
  return this->Impl->NoiseImage;
}

vtkTextureObject* vtkLightShaftPass::GetShadowMapTexture()
{
  return this->Impl->ShadowMapEventTexture;
}

void vtkLightShaftPass::SetShadowCasterBounds(const double bounds[6])
{
  if (RefuseNonFinite(this,
        "ShadowCasterBounds",
        { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] }))
  {
    return;
  }
  if (!this->UseShadowCasterBounds || !std::equal(bounds, bounds + 6, this->ShadowCasterBounds))
  {
    std::copy(bounds, bounds + 6, this->ShadowCasterBounds);
    this->UseShadowCasterBounds = true;
    this->Modified();
  }
}

void vtkLightShaftPass::UnsetShadowCasterBounds()
{
  if (this->UseShadowCasterBounds)
  {
    this->UseShadowCasterBounds = false;
    this->Modified();
  }
}

bool vtkLightShaftPass::GetShadowCasterBounds(double bounds[6])
{
  std::copy(this->ShadowCasterBounds, this->ShadowCasterBounds + 6, bounds);
  return this->UseShadowCasterBounds;
}

const char* vtkLightShaftPass::GetLastShaderVariant()
{
  return this->Impl->SliceVariant.c_str();
}

const char* vtkLightShaftPass::GetLastSliceShaderSource()
{
  return this->Impl->SliceSource.c_str();
}

//------------------------------------------------------------------------------
namespace
{
bool IsSpotLight(vtkLight* light)
{
  return light->GetPositional() && light->GetConeAngle() < 90.0;
}

// Renders that need the scene exactly as without the pass: a hardware selector's (VTK's
// picking and selection draw ids, not colours); those of an enclosing pass that renders the
// props itself, with its own shaders (a vtkOpenGLRenderPass such as a shadow-map baker or a
// value pass marks the props while it renders) or by their information keys; and those into
// a target that takes no colour (depth only).
bool NeedsPlainScene(const vtkRenderState* s)
{
  if (s->GetRenderer()->GetSelector() != nullptr || s->GetRequiredKeys() != nullptr)
  {
    return true;
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkInformation* keys = s->GetPropArray()[i]->GetPropertyKeys();
    if (keys && keys->Length(vtkOpenGLRenderPass::RenderPasses()) > 0)
    {
      return true;
    }
  }
  GLint drawBuffer = GL_NONE;
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
  return drawBuffer == GL_NONE;
}

// The scene exactly as the renderer would draw it without `pass`. For a hardware selector
// that is the renderer's own pass-less render, which hands the props (or the pick list) to
// the selector: render passes draw colours, not ids. Returns the number of props rendered.
int RenderPlainScene(vtkRenderPass* pass, vtkRenderPass* delegate, const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  if (ren->GetSelector() && ren->GetPass() == pass)
  {
    vtkSmartPointer<vtkRenderPass> keep = pass; // the renderer may hold the only reference
    ren->SetPass(nullptr);
    ren->DeviceRender();
    ren->SetPass(pass);
    return ren->GetNumberOfPropsRendered();
  }
  // Nested in another pass: what that pass would have drawn without this one.
  delegate->Render(s);
  return delegate->GetNumberOfRenderedProps();
}

// Whether the bound draw framebuffer's depth has the format and samples of `depth`, so that a
// blit copies it bit for bit.
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

// Samples per pixel of the target the pass draws into (the window's multisampled render
// framebuffer, or an outer pass's target), 0 when it is not multisampled. The scene is then
// rendered with as many samples, so that it keeps its antialiasing; where multisampled
// textures cannot have that many, it is rendered single-sampled.
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
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Render(const vtkRenderState* s)
{
  // Errors left by others are not ours: drain them, then count what this frame raises.
  for (int guard = 0; guard < 64 && glGetError() != GL_NO_ERROR; ++guard)
  {
  }
  this->RenderFrame(s);
  this->LastGLErrorCount = 0;
  std::string names;
  for (GLenum error = glGetError(); error != GL_NO_ERROR && this->LastGLErrorCount < 64;
       error = glGetError())
  {
    ++this->LastGLErrorCount;
    names += std::string(names.empty() ? "" : ", ") + vtkOpenGLStrError(error);
  }
  if (this->LastGLErrorCount > 0)
  {
    vtkErrorMacro("OpenGL errors during the frame: " << names);
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::RenderFrame(const vtkRenderState* s)
{
  Internals& impl = *this->Impl;

  this->NumberOfRenderedProps = 0;
  this->LastNumberOfSlicesDrawn = 0;
  this->LastShadowMapRendered = false;
  this->LastNumberOfShadowCasters = 0;
  this->LastNumberOfSceneRenders = 0;
  this->LastMethod = -1;
  this->LastNumberOfPostPasses = 0;
  this->LastRadialGuardBand = 0.0;
  this->LastLatticeResolution = 0;
  this->LastNumberOfSlabBatches = 0;
  this->LastMultiSamples = 0;
  this->LastPlainScene = false;
  this->LastSliceDepthRange[0] = this->LastSliceDepthRange[1] = 0.0;
  impl.InScatterValid = false;
  impl.FinalInScatter = nullptr;

  vtkRenderer* ren = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro("vtkLightShaftPass needs an OpenGL render window.");
    return;
  }
  if (NeedsPlainScene(s))
  {
    this->NumberOfRenderedProps = RenderPlainScene(this,
      this->DelegatePass ? this->DelegatePass : static_cast<vtkRenderPass*>(impl.DefaultDelegate),
      s);
    this->LastNumberOfSceneRenders = 1;
    this->LastPlainScene = true;
    return;
  }
  if (impl.Window != renWin)
  {
    // Objects made in another window's context cannot be used here.
    if (impl.Window)
    {
      impl.Window->MakeCurrent();
      impl.ReleaseOwnResources(impl.Window);
      renWin->MakeCurrent();
    }
    impl.Track(renWin);
  }
  vtkRenderPass* delegate = this->DelegatePass;
  if (!delegate && this->ShadowSurfaces)
  {
    // VTK's baker does not check the size against the GL's limit: the pass does.
    impl.SurfaceShadows->GetShadowMapBakerPass()->SetResolution(
      std::min(this->ShadowMapSize, vtkTextureObject::GetMaximumTextureSize(renWin)));
    delegate = impl.ShadowedDelegate;
  }
  else if (!delegate)
  {
    delegate = impl.DefaultDelegate;
  }

  int x = 0;
  int y = 0;
  int w = 0;
  int h = 0;
  if (vtkFrameBufferObjectBase* target = s->GetFrameBuffer())
  {
    target->GetLastSize(w, h);
  }
  else
  {
    ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  }
  this->LastViewportSize[0] = std::max(w, 0);
  this->LastViewportSize[1] = std::max(h, 0);

  vtkLight* light = impl.ChooseLight(*this, ren);

  const bool hasMedium =
    AnyPositive(this->ScatteringCoefficient) || AnyPositive(this->AbsorptionCoefficient);
  if (!light || !hasMedium || w < 1 || h < 1)
  {
    // Nothing to add: the delegate's image, untouched.
    impl.RenderDelegate(*this, delegate, s, [&]() { delegate->Render(s); });
    this->LastNumberOfSceneRenders = 1;
    return;
  }

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable multisampleSaver(ostate, GL_MULTISAMPLE);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);

  if (!impl.SceneFramebuffer)
  {
    for (auto* f : { &impl.SceneFramebuffer, &impl.AccumulationFramebuffer, &impl.WorkFramebuffer })
    {
      *f = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      (*f)->SetContext(renWin);
    }
  }
  // The scene is rendered with the samples of the target it is composited into.
  const int samples = TargetSamples();
  this->LastMultiSamples = samples;

  // The one decision whether this frame has a cookie: it shapes the shafts and, rendering the
  // scene a second time without the spotlight, the light on surfaces.
  const bool cookie = impl.Cookie && impl.ReadyCookie(*this);

  // The 2D overlay step of a vtkRenderStepsPass is held back and drawn after compositing so
  // that text and scalar bars stay on top, unfogged.
  auto* steps = vtkRenderStepsPass::SafeDownCast(delegate);
  vtkSmartPointer<vtkRenderPass> overlay = steps ? steps->GetOverlayPass() : nullptr;
  if (overlay)
  {
    steps->SetOverlayPass(nullptr);
  }

  ostate->PushFramebufferBindings();
  const SceneImage scene = impl.RenderScene(*this, s, delegate, light, cookie, samples, w, h);
  if (overlay)
  {
    steps->SetOverlayPass(overlay);
  }

  // Scene camera, exactly as the mappers see it.
  CameraFrame camera;
  {
    auto* glCamera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
    vtkMatrix4x4* wcvc = nullptr;
    vtkMatrix4x4* vcdc = nullptr;
    vtkMatrix4x4* wcdc = nullptr;
    vtkMatrix3x3* normals = nullptr;
    glCamera->GetKeyMatrices(ren, wcvc, normals, vcdc, wcdc);
    camera.WorldToView = FromKeyMatrix(wcvc);
    camera.ViewToClip = FromKeyMatrix(vcdc);
    camera.ClipToView = glm::inverse(camera.ViewToClip);
  }
  LightFrame lightFrame;
  const bool lightFrameValid = impl.ComputeLightFrame(*this, ren, light, camera, lightFrame);
  impl.RenderInScatter(*this, s, lightFrame, camera, scene, cookie, w, h);
  ostate->PopFramebufferBindings();

  ostate->vtkglViewport(x, y, w, h);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(x, y, w, h);
  const int viewport[4] = { x, y, w, h };
  impl.RenderComposite(*this,
    ren,
    camera,
    lightFrameValid ? &lightFrame : nullptr,
    scene,
    cookie && lightFrameValid,
    viewport);

  if (overlay)
  {
    overlay->Render(s);
    this->NumberOfRenderedProps += overlay->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
// The scattering light: the one set, or the renderer's first switched-on spotlight; nullptr
// (one warning until a light is found again) when there is none.
vtkLight* vtkLightShaftPass::Internals::ChooseLight(vtkLightShaftPass& self, vtkRenderer* ren)
{
  vtkLight* light = this->Light;
  if (light && !IsSpotLight(light))
  {
    if (!this->WarnedNoLight)
    {
      vtkWarningWithObjectMacro(&self,
        "The light given to SetLight is not a spotlight (positional, cone angle "
        "< 90 degrees): rendering the scene without shafts.");
      this->WarnedNoLight = true;
    }
    light = nullptr;
  }
  else if (!light)
  {
    vtkLightCollection* lights = ren->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* candidate = lights->GetNextLight(it))
    {
      if (candidate->GetSwitch() && IsSpotLight(candidate))
      {
        light = candidate;
        break;
      }
    }
    if (!light && !this->WarnedNoLight)
    {
      vtkWarningWithObjectMacro(&self,
        "No spotlight in the renderer (a switched-on positional light with cone "
        "angle < 90 degrees): rendering the scene without shafts.");
      this->WarnedNoLight = true;
    }
  }
  if (light)
  {
    this->WarnedNoLight = false;
  }
  this->LastUsedLight = light;
  return light;
}

//------------------------------------------------------------------------------
SceneImage vtkLightShaftPass::Internals::RenderScene(vtkLightShaftPass& self,
  const vtkRenderState* s,
  vtkRenderPass* delegate,
  vtkLight* light,
  bool twice,
  int samples,
  int w,
  int h)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLState* ostate = this->Window->GetState();
  SceneImage scene;
  scene.Samples = samples;
  scene.Color = this->SceneColor.Ensure(this->Window, TextureKind::RGBA8, w, h, samples);
  scene.Depth = this->SceneDepth.Ensure(this->Window, TextureKind::Depth, w, h, samples);
  if (twice)
  {
    scene.ColorUnlit =
      this->SceneColorUnlit.Ensure(this->Window, TextureKind::RGBA8, w, h, samples);
  }

  vtkRenderState sceneState(ren);
  sceneState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  sceneState.SetFrameBuffer(this->SceneFramebuffer);
  auto renderInto = [&](vtkTextureObject* target)
  {
    BindTargets(this->SceneFramebuffer, { target }, scene.Depth, w, h);
    // Renderers that do not erase (layers) would otherwise see the previous frame.
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClearDepth(1.0);
    this->RenderDelegate(self,
      delegate,
      s,
      [&]()
      {
        ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        ostate->vtkglEnable(GL_DEPTH_TEST);
        delegate->Render(&sceneState);
      });
    ++self.LastNumberOfSceneRenders;
  };
  if (twice)
  {
    // Without the spotlight: the composite puts its light back through the cookie. (Zero
    // intensity rather than switching it off: with no light on, VTK would add a headlight.)
    const double intensity = light->GetIntensity();
    light->SetIntensity(0.0);
    renderInto(scene.ColorUnlit);
    light->SetIntensity(intensity);
  }
  renderInto(scene.Color);
  scene.ShaftDepth = samples > 0 ? this->ResolveDepth(scene.Depth, samples, w, h) : scene.Depth;
  return scene;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPass::Internals::ResolveDepth(vtkTextureObject* depthSamples,
  int samples,
  int w,
  int h)
{
  vtkTextureObject* resolved = this->ResolvedDepth.Ensure(this->Window, TextureKind::Depth, w, h);
  this->BindWork(nullptr, resolved, w, h);
  vtkOpenGLState* ostate = this->Window->GetState();
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  if (vtkShaderProgram* program =
        this->DepthResolve.Ready(this->Window, vtkLightShaftDepthResolveFS))
  {
    depthSamples->Activate();
    program->SetUniformi("sceneDepthSamples", depthSamples->GetTextureUnit());
    program->SetUniformi("sampleCount", samples);
    this->DepthResolve.Quad->Render();
    depthSamples->Deactivate();
  }
  else
  {
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }
  return resolved;
}

//------------------------------------------------------------------------------
namespace
{
// The farthest point of the view volume (camera plane to far plane) from `pointVC`.
double FarthestViewPoint(const glm::dmat4& clipToView, const glm::dvec3& pointVC)
{
  double farthest = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double sx = (corner & 1) ? 1.0 : -1.0;
    const double sy = (corner & 2) ? 1.0 : -1.0;
    const glm::dvec4 nearPoint = clipToView * glm::dvec4(sx, sy, -1.0, 1.0);
    const glm::dvec4 farPoint = clipToView * glm::dvec4(sx, sy, 1.0, 1.0);
    const glm::dvec3 n3 = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 f3 = glm::dvec3(farPoint) / farPoint.w;
    const glm::dvec3 dir = f3 - n3;
    const glm::dvec3 start = n3 - dir * (n3.z / dir.z);
    farthest = std::max({ farthest, glm::length(start - pointVC), glm::length(f3 - pointVC) });
  }
  return farthest;
}

// Extend [nearest, deepest] by the depths along `axis` (from `apex`) of a box's eight corners.
void ExtendDepthRange(const double bounds[6],
  const glm::dvec3& apex,
  const glm::dvec3& axis,
  double& nearest,
  double& deepest)
{
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec3 p(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
    const double depth = glm::dot(p - apex, axis);
    nearest = std::min(nearest, depth);
    deepest = std::max(deepest, depth);
  }
}

// Whether an axis-aligned box can reach into the light's bounding pyramid (apex, unit axis a,
// unit u, v across it, half-angle with tangent `tangent`): false when all its corners are
// outside one of the pyramid's planes.
bool BoxReachesPyramid(const double bounds[6],
  const glm::dvec3& apex,
  const glm::dvec3& a,
  const glm::dvec3& u,
  const glm::dvec3& v,
  double tangent)
{
  const glm::dvec3 sides[4] = { u, -u, v, -v };
  auto outside = [&](const std::function<double(const glm::dvec3&)>& f)
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::dvec3 p(
        bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
      if (f(p - apex) >= 0.0)
      {
        return false;
      }
    }
    return true;
  };
  if (outside([&](const glm::dvec3& d) { return glm::dot(d, a); }))
  {
    return false;
  }
  for (const glm::dvec3& side : sides)
  {
    if (outside([&](const glm::dvec3& d) { return tangent * glm::dot(d, a) - glm::dot(d, side); }))
    {
      return false;
    }
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
bool vtkLightShaftPass::Internals::ComputeLightFrame(vtkLightShaftPass& self,
  vtkRenderer* ren,
  vtkLight* light,
  const CameraFrame& camera,
  LightFrame& frame)
{
  frame.PositionWC = glm::make_vec3(light->GetTransformedPosition());
  glm::dvec3 axis = glm::make_vec3(light->GetTransformedFocalPoint()) - frame.PositionWC;
  frame.AxisWC = glm::length(axis) > 0.0 ? glm::normalize(axis) : glm::dvec3(0.0, 0.0, -1.0);
  frame.PositionVC = glm::dvec3(camera.WorldToView * glm::dvec4(frame.PositionWC, 1.0));
  frame.AxisVC = glm::normalize(glm::dvec3(camera.WorldToView * glm::dvec4(frame.AxisWC, 0.0)));
  frame.ConeHalfAngle = vtkMath::RadiansFromDegrees(light->GetConeAngle());
  frame.Exponent = light->GetExponent();
  light->GetAttenuationValues(frame.Attenuation);
  if (frame.Attenuation[0] <= 0.0 && frame.Attenuation[1] <= 0.0 && frame.Attenuation[2] <= 0.0)
  {
    frame.Attenuation[0] = 1.0; // VTK's lighting would divide by zero; treat as no falloff.
  }
  const double* color = light->GetDiffuseColor();
  for (int c = 0; c < 3; ++c)
  {
    frame.RadiantIntensity[c] = light->GetSwitch() ? light->GetIntensity() * color[c] : 0.0;
  }

  // Casters: visible props (culled from the camera's view or not) whose bounds reach into the
  // light's bounding pyramid; only they can shadow the shafts.
  const double halfAngle = std::min(frame.ConeHalfAngle, MaximumBoundingHalfAngle);
  const double tangent = std::tan(halfAngle);
  const glm::dvec3 up =
    std::abs(frame.AxisWC.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 u = glm::normalize(glm::cross(frame.AxisWC, up));
  const glm::dvec3 v = glm::cross(u, frame.AxisWC);
  frame.Casters.clear();
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const double* bounds = prop->GetVisibility() ? prop->GetBounds() : nullptr;
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds) ||
        !BoxReachesPyramid(bounds, frame.PositionWC, frame.AxisWC, u, v, tangent))
    {
      continue;
    }
    frame.Casters.push_back(prop);
    ExtendDepthRange(bounds, frame.PositionWC, frame.AxisWC, nearest, deepest);
  }
  self.LastNumberOfShadowCasters = static_cast<int>(frame.Casters.size());
  frame.ShadowsPossible = !frame.Casters.empty();
  if (self.UseShadowCasterBounds)
  {
    // Distributed: every process uses the global casters' bounds, and so the same light camera.
    const double* bounds = self.ShadowCasterBounds;
    nearest = std::numeric_limits<double>::max();
    deepest = 0.0;
    frame.ShadowsPossible =
      vtkMath::AreBoundsInitialized(bounds) &&
      BoxReachesPyramid(bounds, frame.PositionWC, frame.AxisWC, u, v, tangent);
    if (frame.ShadowsPossible)
    {
      ExtendDepthRange(bounds, frame.PositionWC, frame.AxisWC, nearest, deepest);
    }
  }

  // The light camera's depth range: the casters' (tight: best shadow-map precision), else as
  // far as the view volume reaches.
  if (deepest <= 0.0)
  {
    deepest = std::max(FarthestViewPoint(camera.ClipToView, frame.PositionVC), 1e-30);
    nearest = 0.0;
  }
  frame.Far = deepest * 1.001;
  frame.Near = std::max(nearest * 0.999, frame.Far * 1e-4);
  frame.Projection = glm::perspective(2.0 * halfAngle, 1.0, frame.Near, frame.Far);

  vtkCamera* lightCamera = this->LightCamera;
  lightCamera->SetPosition(frame.PositionWC.x, frame.PositionWC.y, frame.PositionWC.z);
  lightCamera->SetFocalPoint(frame.PositionWC.x + frame.AxisWC.x,
    frame.PositionWC.y + frame.AxisWC.y,
    frame.PositionWC.z + frame.AxisWC.z);
  lightCamera->SetViewUp(up.x, up.y, up.z);
  vtkNew<vtkMatrix4x4> explicitProjection;
  ToVTKMatrix(frame.Projection, explicitProjection);
  lightCamera->SetExplicitProjectionTransformMatrix(explicitProjection);
  lightCamera->SetUseExplicitProjectionTransformMatrix(true);
  const glm::dmat4 lightView = FromVTKMatrix(lightCamera->GetViewTransformMatrix());
  frame.WorldToLightClip = frame.Projection * lightView;
  frame.ViewToLightClip = frame.WorldToLightClip * glm::inverse(camera.WorldToView);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::RenderCasters(vtkLightShaftPass& self,
  const vtkRenderState* s,
  LightFrame& frame,
  vtkCamera* camera,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& target,
  vtkTextureObject* depth)
{
  // A depth-only target, cleared, with the depth test of an opaque step.
  if (!target)
  {
    target = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    target->SetContext(this->Window);
  }
  const int w = static_cast<int>(depth->GetWidth());
  const int h = static_cast<int>(depth->GetHeight());
  vtkOpenGLState* ostate = this->Window->GetState();
  target->Bind();
  target->AddDepthAttachment(depth);
  target->StartNonOrtho(w, h);
  target->DeactivateDrawBuffers();
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);

  vtkRenderer* ren = s->GetRenderer();
  vtkRenderState casterState(ren);
  casterState.SetPropArrayAndCount(frame.Casters.data(), static_cast<int>(frame.Casters.size()));
  casterState.SetFrameBuffer(target);

  // Render the opaque step of the casters with another camera, as vtkShadowMapBakerPass does.
  vtkCamera* sceneCamera = ren->GetActiveCamera();
  sceneCamera->Register(&self);
  const vtkTypeBool automaticLights = ren->GetAutomaticLightCreation();
  ren->SetAutomaticLightCreation(false);
  ren->SetActiveCamera(camera);
  this->ShadowCameraPass->Render(&casterState);
  ren->SetActiveCamera(sceneCamera);
  ren->SetAutomaticLightCreation(automaticLights);
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  // The casters' step set the shaders' lighting uniforms in the other camera's frame and
  // stamped them with its MTime; vtkOpenGLRenderer::UpdateLightingUniforms only sets them again
  // when the active camera (or the lights) changed after that stamp. Seen with VTK 9.2
  // (ParaView 5.11): a still scene camera kept the light camera's lighting from the second
  // frame on.
  sceneCamera->Modified();
#endif
  sceneCamera->UnRegister(&self);
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::Internals::RenderShadowMap(vtkLightShaftPass& self,
  const vtkRenderState* s,
  LightFrame& frame)
{
  if (!frame.ShadowsPossible)
  {
    return false; // nothing can shadow the light's volume
  }
  vtkOpenGLRenderWindow* renWin = this->Window;
  const int size = std::min(self.ShadowMapSize, vtkTextureObject::GetMaximumTextureSize(renWin));
  vtkTextureObject* map = this->ShadowMap.Object;
  if (!map || static_cast<int>(map->GetWidth()) != size)
  {
    // Float depth: the best precision for the light's (perspective) depth.
    this->ShadowMap.Release(renWin);
    this->ShadowMap.Object = vtkSmartPointer<vtkTextureObject>::New();
    map = this->ShadowMap.Object;
    map->SetContext(renWin);
    map->SetWrapS(vtkTextureObject::ClampToEdge);
    map->SetWrapT(vtkTextureObject::ClampToEdge);
    map->SetMinificationFilter(vtkTextureObject::Nearest);
    map->SetMagnificationFilter(vtkTextureObject::Nearest);
    map->AllocateDepth(size, size, vtkTextureObject::Float32);
  }
  this->RenderCasters(self, s, frame, this->LightCamera, this->ShadowFramebuffer, map);

  // Observers may read and rewrite the map now (distributed processes combine theirs).
  this->ShadowMapEventTexture = map;
  self.InvokeEvent(ShadowMapRenderedEvent);
  this->ShadowMapEventTexture = nullptr;

  self.LastShadowMapRendered = true;
  self.LastLightDepthRange[0] = frame.Near;
  self.LastLightDepthRange[1] = frame.Far;
  this->LastWorldToLightClip = frame.WorldToLightClip;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::Internals::ReadyCookie(vtkLightShaftPass& self)
{
  vtkTexture* cookie = this->Cookie;
  if (cookie->GetNumberOfInputPorts() > 0 && cookie->GetNumberOfInputConnections(0) > 0)
  {
    cookie->GetInputAlgorithm()->Update();
  }
  vtkDataObject* input = cookie->GetInputDataObject(0, 0);
  const vtkMTimeType time = std::max(cookie->GetMTime(), input ? input->GetMTime() : 0);
  if (this->CookieTexture && time <= this->CookieUploadTime)
  {
    return true;
  }
  std::vector<float> rgb;
  int width = 0;
  int height = 0;
  if (!vtkLightShaftImageToRGB(cookie, rgb, width, height))
  {
    // No cookie this frame: drop the texture of an earlier image so that nothing uses it.
    if (this->CookieTexture)
    {
      this->CookieTexture->ReleaseGraphicsResources(this->Window);
      this->CookieTexture = nullptr;
    }
    this->CookieUploadTime = 0;
    if (!this->WarnedCookie)
    {
      vtkWarningWithObjectMacro(&self, "The cookie texture has no image: no cookie is applied.");
      this->WarnedCookie = true;
    }
    return false;
  }
  UploadMipmapped(this->CookieTexture, this->Window, rgb, width, height, 3, false);
  this->CookieUploadTime = time;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::Internals::ReadyNoise(vtkLightShaftPass& self)
{
  if (this->NoiseImage)
  {
    vtkDataObject* input = this->NoiseImage->GetInputDataObject(0, 0);
    const vtkMTimeType time = std::max(this->NoiseImage->GetMTime(), input ? input->GetMTime() : 0);
    if (this->NoiseTexture && !this->NoiseIsGenerated && time <= this->NoiseUploadTime)
    {
      return true;
    }
    std::vector<float> rgb;
    int width = 0;
    int height = 0;
    if (vtkLightShaftImageToRGB(this->NoiseImage, rgb, width, height))
    {
      std::vector<float> texels(static_cast<size_t>(width) * height);
      for (size_t i = 0; i < texels.size(); ++i)
      {
        texels[i] = rgb[3 * i];
      }
      vtkLightShaftNormalizeNoise(texels);
      UploadMipmapped(this->NoiseTexture, this->Window, texels, width, height, 1, true);
      this->NoiseUploadTime = time;
      this->NoiseIsGenerated = false;
      return true;
    }
    if (!this->WarnedNoise)
    {
      vtkWarningWithObjectMacro(
        &self, "The noise texture has no image: using the generated noise.");
      this->WarnedNoise = true;
    }
  }
  if (!this->NoiseTexture || !this->NoiseIsGenerated)
  {
    constexpr int size = 256;
    UploadMipmapped(this->NoiseTexture,
      this->Window,
      vtkLightShaftTileableNoise(size, 5, 2004u),
      size,
      size,
      1,
      true);
    this->NoiseIsGenerated = true;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLightShaftPass::Internals::LatticeWithinBudget(vtkLightShaftPass& self, int slabs)
{
  const int requested = self.LatticeResolution;
  if (requested <= 0)
  {
    return 0;
  }
  const int affordable = std::max(
    1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(LatticeCellBudget) / slabs))));
  if (requested <= affordable)
  {
    this->WarnedLatticeBudget = false;
    return requested;
  }
  if (!this->WarnedLatticeBudget)
  {
    vtkWarningWithObjectMacro(&self,
      "LatticeResolution " << requested << " over " << slabs << " slabs would be "
                           << static_cast<long long>(requested) * requested * slabs
                           << " lattice cells in a frame, more than the " << LatticeCellBudget
                           << " allowed: using a lattice of " << affordable
                           << " (GetLastLatticeResolution).");
    this->WarnedLatticeBudget = true;
  }
  return affordable;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLightShaftPass::Internals::ReadySliceProgram(vtkLightShaftPass& self,
  int method,
  bool shadows,
  bool cookie,
  bool noise)
{
  std::vector<std::string> defines;
  std::string variant = std::string("method=") + vtkLightShaftPass::GetMethodName(method) + " ";
  if (method == RAY_MARCH)
  {
    defines.emplace_back("LIGHTSHAFT_RAY_MARCH");
  }
  else if (method == ANALYTIC || method == RADIAL_BLUR)
  {
    defines.emplace_back("LIGHTSHAFT_ANALYTIC");
  }
  switch (self.PhaseFunction)
  {
    case HENYEY_GREENSTEIN:
      defines.emplace_back("LIGHTSHAFT_PHASE_HG");
      variant += "phase=henyey-greenstein";
      break;
    case RAYLEIGH:
      defines.emplace_back("LIGHTSHAFT_PHASE_RAYLEIGH");
      variant += "phase=rayleigh";
      break;
    default:
      variant += "phase=isotropic";
      break;
  }
  auto feature = [&](bool on, const char* define, const char* name)
  {
    if (on)
    {
      defines.emplace_back(define);
      variant += std::string(" ") + name;
    }
  };
  feature(shadows, "LIGHTSHAFT_SHADOW", "shadow");
  feature(cookie, "LIGHTSHAFT_COOKIE", "cookie");
  feature(noise, "LIGHTSHAFT_NOISE", "noise");
  feature(method == SLICES && self.Jitter, "LIGHTSHAFT_JITTER", "jitter");
  feature(method == SLICES && self.LatticeResolution > 0, "LIGHTSHAFT_LATTICE", "lattice");
  if (this->EightBitThisFrame)
  {
    defines.emplace_back("LIGHTSHAFT_ACCUMULATE_8BIT");
  }
  const char* accumulation[] = { " accumulate=float32", " accumulate=float16", " accumulate=8bit" };
  variant +=
    accumulation[(self.AccumulationPrecision == ACCUMULATE_8BIT && !this->EightBitThisFrame)
                   ? ACCUMULATE_FLOAT32
                   : self.AccumulationPrecision];
  this->SliceVariant = variant;
  vtkOpenGLShaderCache* cache = this->Window->GetShaderCache();
  const std::string key = JoinDefines(defines);
  if (this->SliceProgram && key == this->SliceKey)
  {
    return cache->ReadyShaderProgram(this->SliceProgram);
  }
  const std::string fragment = WithFeatures(vtkLightShaftSliceFS, defines);
  const std::string vertex = WithFeatures(vtkLightShaftSliceVS, defines);
  this->SliceProgram = cache->ReadyShaderProgram(vertex.c_str(), fragment.c_str(), "");
  this->SliceSource = fragment;
  this->SliceKey = key;
  if (!this->SliceProgram || !this->SliceProgram->GetCompiled())
  {
    vtkErrorWithObjectMacro(&self, "Could not build the light-shaft slice shader.");
    this->SliceProgram = nullptr;
    this->SliceSource.clear();
    this->SliceKey.clear();
    return nullptr;
  }
  if (!this->SliceArray)
  {
    this->SliceArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->SliceBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->SliceBuffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  }
  this->SliceArrayProgram = nullptr; // attributes are bound to the new program on first draw
  return this->SliceProgram;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::RenderInScatter(vtkLightShaftPass& self,
  const vtkRenderState* s,
  LightFrame& light,
  const CameraFrame& camera,
  const SceneImage& scene,
  bool cookie,
  int w,
  int h)
{
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkOpenGLState* ostate = renWin->GetState();
  // The method: AUTOMATIC takes the exact unshadowed integral when nothing can shadow the
  // light's volume and the medium is homogeneous, else the slabs.
  const bool noiseOn = self.NoiseAmplitude > 0.0;
  int method = self.Method;
  if (method == AUTOMATIC)
  {
    method = (!light.ShadowsPossible && !noiseOn) ? ANALYTIC : SLICES;
  }
  if (method == ANALYTIC && !light.Casters.empty() && !this->WarnedAnalyticShadows)
  {
    vtkWarningWithObjectMacro(&self,
      "Method ANALYTIC ignores shadows, but "
        << light.Casters.size()
        << " prop(s) reach into the light's volume: use SLICES or AUTOMATIC for shadowed shafts.");
    this->WarnedAnalyticShadows = true;
  }
  const bool slabs = method == SLICES;
  const int factor = self.DownsampleFactor;
  const int lw = (w + factor - 1) / factor;
  const int lh = (h + factor - 1) / factor;
  // The four-channel 8-bit trick is a slab technique; the other methods add up in float.
  const bool eightBit = slabs && self.AccumulationPrecision == ACCUMULATE_8BIT;
  this->EightBitThisFrame = eightBit;
  const TextureKind accumulationKind =
    eightBit ? TextureKind::RGBA8
             : (self.AccumulationPrecision == ACCUMULATE_FLOAT16 ? TextureKind::RGBA16F
                                                                 : TextureKind::RGBA32F);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // The depth the slabs read: the scene's, or at reduced resolution the nearest of each block.
  vtkTextureObject* slabDepth = scene.ShaftDepth;
  if (factor > 1)
  {
    slabDepth = this->ReducedDepth.Ensure(renWin, TextureKind::Depth, lw, lh);
    this->BindWork(nullptr, slabDepth, lw, lh);
    if (vtkShaderProgram* program =
          this->DepthDownsample.Ready(renWin, vtkLightShaftDepthDownsampleFS))
    {
      ostate->vtkglEnable(GL_DEPTH_TEST);
      ostate->vtkglDepthFunc(GL_ALWAYS);
      ostate->vtkglDepthMask(GL_TRUE);
      scene.ShaftDepth->Activate();
      program->SetUniformi("fullDepth", scene.ShaftDepth->GetTextureUnit());
      program->SetUniformi("factor", factor);
      const float reducedSize[2] = { static_cast<float>(lw), static_cast<float>(lh) };
      program->SetUniform2f("reducedSize", reducedSize);
      this->DepthDownsample.Quad->Render();
      scene.ShaftDepth->Deactivate();
    }
  }

  // Accumulation target(s), cleared, with a copy of the slab depth for the depth test (the
  // slabs sample the slab depth, so it cannot be their depth target too).
  vtkTextureObject* depthTest = this->SlabDepthTest.Ensure(renWin, TextureKind::Depth, lw, lh);
  const unsigned int targets = eightBit ? 3 : 1;
  for (unsigned int i = 0; i < targets; ++i)
  {
    this->Accumulation[i].Ensure(renWin, accumulationKind, lw, lh);
  }
  auto bindAccumulation = [&]()
  {
    vtkOpenGLFramebufferObject* fbo = this->AccumulationFramebuffer;
    if (eightBit)
    {
      BindTargets(fbo,
        { this->Accumulation[0].Object,
          this->Accumulation[1].Object,
          this->Accumulation[2].Object },
        depthTest,
        lw,
        lh);
    }
    else
    {
      BindTargets(fbo, { this->Accumulation[0].Object }, depthTest, lw, lh);
    }
  };
  this->BindWork(nullptr, slabDepth, lw, lh);
  bindAccumulation();
  this->WorkFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  ostate->vtkglBlitFramebuffer(0, 0, lw, lh, 0, 0, lw, lh, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  this->AccumulationFramebuffer->Bind();
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  this->FinalInScatter = this->Accumulation[0].Object;

  const bool scatters =
    AnyPositive(self.ScatteringCoefficient) && AnyPositive(light.RadiantIntensity);
  if (!scatters)
  {
    return;
  }

  const glm::dmat4& viewToClip = camera.ViewToClip;
  const glm::dmat4& clipToView = camera.ClipToView;
  const glm::dvec3& lightVC = light.PositionVC;
  const glm::dvec3& axisVC = light.AxisVC;
  const double coneHalfAngle = light.ConeHalfAngle;

  // The light's bounding pyramid (apex at the light, base beyond everything the view can see).
  const double boundingHalfAngle = std::min(coneHalfAngle, MaximumBoundingHalfAngle);
  const double reach = std::max(FarthestViewPoint(clipToView, lightVC), 1e-30);
  const double halfSide = reach * std::tan(boundingHalfAngle);
  glm::dvec3 u = glm::cross(
    axisVC, std::abs(axisVC.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0));
  u = glm::normalize(u);
  const glm::dvec3 v = glm::cross(axisVC, u);
  const glm::dvec3 baseCentre = lightVC + reach * axisVC;
  const std::array<glm::dvec3, 4> base = { baseCentre + halfSide * (u + v),
    baseCentre + halfSide * (-u + v),
    baseCentre + halfSide * (-u - v),
    baseCentre + halfSide * (u - v) };
  ConvexPolytope lit;
  lit.Faces.push_back({ base[3], base[2], base[1], base[0] });
  for (int i = 0; i < 4; ++i)
  {
    lit.Faces.push_back({ lightVC, base[i], base[(i + 1) % 4] });
  }

  // Clip it to the view volume: the four sides, the far plane, and a depth just in front of
  // the camera plane (slabs must project).
  const glm::dmat4 clipT = glm::transpose(viewToClip); // rows of the projection as columns
  const glm::dvec4 row0 = clipT[0];
  const glm::dvec4 row1 = clipT[1];
  const glm::dvec4 row2 = clipT[2];
  const glm::dvec4 row3 = clipT[3];
  const glm::dvec4 farPoint = clipToView * glm::dvec4(0.0, 0.0, 1.0, 1.0);
  const double farDepth = -farPoint.z / farPoint.w;
  const double minimumDepth = farDepth * 1e-7;
  for (const glm::dvec4& plane : { row3 + row0,
         row3 - row0,
         row3 + row1,
         row3 - row1,
         row3 - row2,
         glm::dvec4(0.0, 0.0, -1.0, -minimumDepth) })
  {
    lit.Clip(plane);
  }
  if (lit.Empty())
  {
    return; // The light volume is outside the view: nothing to do.
  }
  double nearest = std::numeric_limits<double>::max();
  double deepest = 0.0;
  for (const auto& face : lit.Faces)
  {
    for (const auto& p : face)
    {
      nearest = std::min(nearest, -p.z);
      deepest = std::max(deepest, -p.z);
    }
  }
  nearest = std::max(nearest, minimumDepth);
  if (!(deepest > nearest))
  {
    return;
  }
  self.LastSliceDepthRange[0] = nearest;
  self.LastSliceDepthRange[1] = deepest;

  self.LastMethod = method;
  const bool jitter = slabs && self.Jitter;

  // How many slabs: fixed, or (automatic) as many slabs of thickness far / maximum as the lit
  // depth range needs. The per-pixel methods draw one slab over the whole lit range.
  int slices = slabs ? self.NumberOfSlices : 1;
  if (slabs && self.AutomaticSliceCount)
  {
    const double spacing = farDepth / self.MaximumNumberOfSlices;
    slices = static_cast<int>(std::ceil((deepest - nearest) / spacing - 1e-9));
    slices = std::max(1, std::min(slices, self.MaximumNumberOfSlices));
  }
  const double thickness = (deepest - nearest) / slices;
  // With jitter a pixel's slab k spans [k - 1 + o, k + o] thicknesses (o in (0, 1)): one more
  // slab, and footprints covering two thicknesses.
  const int drawnSlabs = jitter ? slices + 1 : slices;

  // Slabs: for each, the screen footprint of the lit polytope between its two depths.
  std::vector<SlabFootprint>& footprints = this->SlabFootprints;
  footprints.clear();
  std::vector<glm::dvec2> footprint;
  for (int k = 0; k < drawnSlabs; ++k)
  {
    const double za = std::max(nearest, nearest + (jitter ? k - 1 : k) * thickness);
    const double zb = std::min(deepest, nearest + (k + 1) * thickness);
    footprint.clear();
    auto addPoint = [&](const glm::dvec3& p)
    {
      const glm::dvec4 c = viewToClip * glm::dvec4(p, 1.0);
      footprint.emplace_back(c.x / c.w, c.y / c.w);
    };
    for (const auto& face : lit.Faces)
    {
      const size_t count = face.size();
      for (size_t i = 0; i < count; ++i)
      {
        const glm::dvec3& a = face[i];
        const glm::dvec3& b = face[(i + 1) % count];
        const double da = -a.z;
        const double db = -b.z;
        if (da >= za && da <= zb)
        {
          addPoint(a);
        }
        for (double plane : { za, zb })
        {
          if ((da - plane) * (db - plane) < 0.0)
          {
            addPoint(a + (b - a) * ((plane - da) / (db - da)));
          }
        }
      }
    }
    std::vector<glm::dvec2> hull = ConvexHull(footprint);
    if (hull.size() >= 3)
    {
      footprints.push_back({ k, za, std::move(hull) });
    }
  }
  if (footprints.empty())
  {
    return;
  }
  // Each slab is drawn as its footprint, or as a lattice of n x n cells over it when the smooth
  // factors are evaluated per lattice vertex (n within the frame's cell budget).
  const int lattice =
    slabs ? this->LatticeWithinBudget(self, static_cast<int>(footprints.size())) : 0;
  self.LastLatticeResolution = lattice;

  // Shadow map of the casters, seen from the light (skipped when nothing can shadow).
  // Only the slabs and the march look up a shadow map.
  const bool shadows =
    (method == SLICES || method == RAY_MARCH) && this->RenderShadowMap(self, s, light);
  const bool noise = noiseOn && this->ReadyNoise(self);
  vtkShaderProgram* program = this->ReadySliceProgram(self, method, shadows, cookie, noise);
  if (!program)
  {
    return;
  }
  bindAccumulation();

  // Each slab is drawn at the near depth of its footprint: the depth test drops it where it
  // starts behind the surface. Depth clamping keeps slabs in front of the near plane.
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDepthMask(GL_FALSE);
  const GLboolean depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_CLAMP);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);

  auto invProjection = ToFloatColumnMajor(clipToView);
  program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
  const float targetSize[2] = { static_cast<float>(lw), static_cast<float>(lh) };
  program->SetUniform2f("targetSize", targetSize);
  // Row 2 and row 3 of the projection: a view depth's NDC z, for the slabs' depth test.
  const float depthProjection[4] = { static_cast<float>(viewToClip[2][2]),
    static_cast<float>(viewToClip[3][2]),
    static_cast<float>(viewToClip[2][3]),
    static_cast<float>(viewToClip[3][3]) };
  program->SetUniform4f("depthProjection", depthProjection);
  program->SetUniformf("slabStart", static_cast<float>(nearest));
  program->SetUniformf("slabEnd", static_cast<float>(deepest));
  program->SetUniformf("slabThickness", static_cast<float>(thickness));
  program->SetUniformf("lastSlab", static_cast<float>(drawnSlabs - 1));
  if (lattice > 0)
  {
    program->SetUniformf("latticeSlabShift", jitter ? -0.5f : 0.0f);
  }
  slabDepth->Activate();
  program->SetUniformi("sceneDepth", slabDepth->GetTextureUnit());
  program->SetUniform3f("lightPositionVC", ToFloat3(lightVC).data());
  program->SetUniform3f("lightAxisVC", ToFloat3(axisVC).data());
  program->SetUniformf("cosConeAngle", static_cast<float>(std::cos(coneHalfAngle)));
  program->SetUniformf("spotExponent", static_cast<float>(light.Exponent));
  program->SetUniform3f("attenuationCoefficients", light.Attenuation);
  program->SetUniform3f("lightRadiantIntensity", light.RadiantIntensity);
  program->SetUniform3f("sigmaS", self.ScatteringCoefficient);
  double sigmaT[3];
  for (int c = 0; c < 3; ++c)
  {
    sigmaT[c] = self.ScatteringCoefficient[c] + self.AbsorptionCoefficient[c];
  }
  program->SetUniform3f("sigmaT", sigmaT);
  if (self.PhaseFunction == HENYEY_GREENSTEIN)
  {
    program->SetUniformf("anisotropy", static_cast<float>(self.Anisotropy));
  }
  if (shadows || cookie || noise)
  {
    auto lightMatrix = ToFloatColumnMajor(light.ViewToLightClip);
    program->SetUniformMatrix4x4("lightClipFromVC", lightMatrix.data());
    const bool perspective = viewToClip[2][3] != 0.0;
    const float pixel = static_cast<float>(2.0 / (lw * viewToClip[0][0]));
    const float pixelFootprint[2] = { perspective ? pixel : 0.0f, perspective ? 0.0f : pixel };
    program->SetUniform2f("pixelFootprint", pixelFootprint);
    program->SetUniformf("lightTexelAngle", static_cast<float>(2.0 * std::tan(boundingHalfAngle)));
  }
  if (shadows)
  {
    this->ShadowMap.Object->Activate();
    program->SetUniformi("shadowMap", this->ShadowMap.Object->GetTextureUnit());
    const float depthRange[2] = { static_cast<float>(light.Near), static_cast<float>(light.Far) };
    program->SetUniform2f("lightDepthRange", depthRange);
    // Two texels' worth of relative depth: a sample this close behind a caster's front face is
    // inside the caster, where no view ray goes.
    const double texelAngle =
      2.0 * std::tan(boundingHalfAngle) / this->ShadowMap.Object->GetWidth();
    self.LastShadowBias = static_cast<float>(2.0 * texelAngle + 1e-4);
    program->SetUniformf("shadowBias", static_cast<float>(self.LastShadowBias));
  }
  if (cookie)
  {
    this->CookieTexture->Activate();
    program->SetUniformi("cookieTexture", this->CookieTexture->GetTextureUnit());
    program->SetUniformf("cookieSize",
      static_cast<float>(
        std::max(this->CookieTexture->GetWidth(), this->CookieTexture->GetHeight())));
  }
  if (noise)
  {
    this->NoiseTexture->Activate();
    program->SetUniformi("noiseTexture", this->NoiseTexture->GetTextureUnit());
    program->SetUniformf("noiseSize", static_cast<float>(this->NoiseTexture->GetWidth()));
    program->SetUniformf("noiseAmplitude", static_cast<float>(self.NoiseAmplitude));
    program->SetUniformf("noiseScale", static_cast<float>(self.NoiseScale));
    // Scroll offsets at Time, wrapped to one tile in double precision (large times stay exact).
    auto wrap = [](double value) { return static_cast<float>(value - std::floor(value)); };
    const float shift[4] = { wrap(self.NoiseVelocity1[0] * self.Time),
      wrap(self.NoiseVelocity1[1] * self.Time),
      wrap(self.NoiseVelocity2[0] * self.Time + 0.37),
      wrap(self.NoiseVelocity2[1] * self.Time + 0.61) };
    program->SetUniform4f("noiseShift", shift);
  }
  if (method == RAY_MARCH)
  {
    program->SetUniformi("numberOfSteps", self.NumberOfSteps);
    program->SetUniformi("interleaveSize", self.InterleaveSize);
  }
  else if (method == ANALYTIC || method == RADIAL_BLUR)
  {
    // One piece is exact (closed-form A) when the other factors are constant along the ray;
    // cookie and noise vary across the light's square: 16 pieces sample them.
    const bool constantFactors = self.PhaseFunction == ISOTROPIC && light.Exponent == 0.0 &&
                                 !AnyPositive(sigmaT) && !cookie && !noise;
    program->SetUniformi("analyticPieces", constantFactors ? 1 : ((cookie || noise) ? 16 : 4));
    program->SetUniformf(
      "maximumSigmaT", static_cast<float>(std::max({ sigmaT[0], sigmaT[1], sigmaT[2] })));
  }
  if (eightBit)
  {
    program->SetUniformf(
      "accumulationScale", static_cast<float>(self.Exposure > 0.0 ? self.Exposure : 1.0));
  }

  // The slabs' triangles are built and drawn in batches of about SlabBatchVertices, so that the
  // vertex memory stays bounded and no single draw holds the GPU for the whole frame. Before
  // the next batch the driver finishes this one: drivers that queue the whole frame's triangles
  // (llvmpipe) would otherwise hold them all (measured: 0.9 GiB instead of 0.2 GiB at 2^21
  // lattice cells).
  std::vector<float>& vertices = this->SliceVertices;
  vertices.clear();
  auto drawBatch = [&](bool more)
  {
    if (vertices.empty())
    {
      return;
    }
    this->SliceBuffer->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer);
    if (this->SliceArrayProgram != program)
    {
      this->SliceArray->ShaderProgramChanged();
    }
    this->SliceArray->Bind();
    if (this->SliceArrayProgram != program)
    {
      this->SliceArray->AddAttributeArray(
        program, this->SliceBuffer, "sliceVertex", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
      this->SliceArrayProgram = program;
    }
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size() / 4));
    this->SliceArray->Release();
    if (more)
    {
      glFinish();
    }
    ++self.LastNumberOfSlabBatches;
    vertices.clear();
  };
  for (const SlabFootprint& slab : footprints)
  {
    AppendSlabTriangles(slab, lattice, vertices);
    if (vertices.size() / 4 >= SlabBatchVertices)
    {
      drawBatch(true);
    }
  }
  drawBatch(false);

  slabDepth->Deactivate();
  for (vtkTextureObject* t : { shadows ? this->ShadowMap.Object.Get() : nullptr,
         cookie ? this->CookieTexture.Get() : nullptr,
         noise ? this->NoiseTexture.Get() : nullptr })
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
  self.LastNumberOfSlicesDrawn = static_cast<int>(footprints.size());

  vtkTextureObject* current = this->Accumulation[0].Object;
  if (method == RADIAL_BLUR)
  {
    current = this->RenderRadialBlur(self, s, camera, light, slabDepth, lw, lh);
  }
  if (method == RAY_MARCH && self.InterleaveSize > 1)
  {
    current = this->Gather(self, current, camera, slabDepth, lw, lh);
  }
  this->PostProcess(self, current, camera, slabDepth, scene.ShaftDepth, w, h, lw, lh);
  this->InScatterValid = true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPass::Internals::Gather(vtkLightShaftPass& self,
  vtkTextureObject* source,
  const CameraFrame& camera,
  vtkTextureObject* slabDepth,
  int lw,
  int lh)
{
  // Interleaved sampling's gather: two separable passes, each an unweighted, depth-aware mean
  // over InterleaveSize consecutive pixels (the blur shader's box mode).
  return this->SeparableFilter(self,
    source,
    this->GatherTemporary,
    this->Gathered,
    camera,
    slabDepth,
    0,
    self.InterleaveSize,
    lw,
    lh);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPass::Internals::SeparableFilter(vtkLightShaftPass& self,
  vtkTextureObject* source,
  OwnedTexture& temporary,
  OwnedTexture& output,
  const CameraFrame& camera,
  vtkTextureObject* slabDepth,
  int radius,
  int boxWidth,
  int lw,
  int lh)
{
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkShaderProgram* program = this->Blur.Ready(renWin, vtkLightShaftBlurFS);
  if (!program)
  {
    return source;
  }
  vtkTextureObject* sources[2] = { source, temporary.Ensure(renWin, TextureKind::RGBA32F, lw, lh) };
  vtkTextureObject* outputs[2] = { sources[1],
    output.Ensure(renWin, TextureKind::RGBA32F, lw, lh) };
  auto invProjection = ToFloatColumnMajor(camera.ClipToView);
  const float targetSize[2] = { static_cast<float>(lw), static_cast<float>(lh) };
  const int directions[2][2] = { { 1, 0 }, { 0, 1 } };
  for (int pass = 0; pass < 2; ++pass)
  {
    this->BindWork(outputs[pass], nullptr, lw, lh);
    renWin->GetShaderCache()->ReadyShaderProgram(program);
    sources[pass]->Activate();
    slabDepth->Activate();
    program->SetUniformi("source", sources[pass]->GetTextureUnit());
    program->SetUniformi("sceneDepth", slabDepth->GetTextureUnit());
    program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
    program->SetUniform2f("targetSize", targetSize);
    program->SetUniform2i("direction", directions[pass]);
    program->SetUniformi("radius", radius);
    program->SetUniformi("boxWidth", boxWidth);
    program->SetUniformf("depthTolerance", SameSurfaceTolerance);
    this->Blur.Quad->Render();
    slabDepth->Deactivate();
    sources[pass]->Deactivate();
    ++self.LastNumberOfPostPasses;
  }
  return outputs[1];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftPass::Internals::RenderRadialBlur(vtkLightShaftPass& self,
  const vtkRenderState* s,
  const CameraFrame& camera,
  LightFrame& light,
  vtkTextureObject* slabDepth,
  int lw,
  int lh)
{
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkTextureObject* unshadowed = this->Accumulation[0].Object;
  // Nothing reaches into the light's volume: nothing to blur, the unshadowed integral is exact.
  if (!light.ShadowsPossible || self.Weight <= 0.0)
  {
    return unshadowed;
  }

  // Where the light projects, and how much to trust it: the blur fades out as the light nears
  // the camera plane (its projection runs off to infinity, then mirrors behind the camera).
  const glm::dvec4 lightClip = camera.ViewToClip * glm::dvec4(light.PositionVC, 1.0);
  const bool perspective = camera.ViewToClip[2][3] != 0.0;
  double fade = 1.0;
  float lightUV[2] = { 0.5f, 0.5f };
  if (perspective)
  {
    const double inFront = -light.PositionVC.z / std::max(glm::length(light.PositionVC), 1e-30);
    fade = vtkMath::ClampValue(inFront / 0.1, 0.0, 1.0);
  }
  if (fade <= 0.0 || !(std::abs(lightClip.w) > 0.0))
  {
    return unshadowed;
  }
  for (int i = 0; i < 2; ++i)
  {
    // Clamped far outside the screen: the walk is cut at the screen's edge anyway.
    lightUV[i] =
      static_cast<float>(vtkMath::ClampValue(0.5 * lightClip[i] / lightClip.w + 0.5, -1e6, 1e6));
  }

  // Occlusion pre-pass at half the in-scatter resolution, over a guard band RadialGuardBand
  // times the screen's extent: the casters' depth is rendered again with the scene camera's
  // frustum widened about its axis (same view, projection scaled by 1 / g in x and y), so that
  // occluders off the screen still cut the shafts on it. Cameras with an explicit projection or
  // an off-centre window keep the screen's own depth (g = 1).
  vtkRenderer* ren = s->GetRenderer();
  vtkCamera* sceneCamera = ren->GetActiveCamera();
  double guard = self.RadialGuardBand;
  const double* windowCenter = sceneCamera->GetWindowCenter();
  if (sceneCamera->GetUseExplicitProjectionTransformMatrix() || windowCenter[0] != 0.0 ||
      windowCenter[1] != 0.0 || sceneCamera->GetUseOffAxisProjection())
  {
    guard = 1.0;
  }
  if (perspective &&
      std::tan(vtkMath::RadiansFromDegrees(sceneCamera->GetViewAngle()) / 2.0) * guard > 57.0)
  {
    guard = std::max(1.0,
      57.0 / std::tan(vtkMath::RadiansFromDegrees(sceneCamera->GetViewAngle()) /
                      2.0)); // keep it below 178 degrees
  }
  const int mw = std::max(1, static_cast<int>(std::lround(0.5 * lw * guard)));
  const int mh = std::max(1, static_cast<int>(std::lround(0.5 * lh * guard)));
  vtkTextureObject* occluderDepth = slabDepth;
  glm::dmat4 occluderClipToView = camera.ClipToView;
  if (guard > 1.0)
  {
    vtkCamera* guardCamera = this->GuardCamera;
    guardCamera->DeepCopy(sceneCamera);
    if (sceneCamera->GetParallelProjection())
    {
      guardCamera->SetParallelScale(sceneCamera->GetParallelScale() * guard);
    }
    else
    {
      const double halfAngle = vtkMath::RadiansFromDegrees(sceneCamera->GetViewAngle()) / 2.0;
      guardCamera->SetViewAngle(
        vtkMath::DegreesFromRadians(2.0 * std::atan(std::tan(halfAngle) * guard)));
    }
    occluderDepth = this->GuardDepth.Ensure(this->Window, TextureKind::Depth, mw, mh);
    this->RenderCasters(self, s, light, guardCamera, this->GuardFramebuffer, occluderDepth);
    this->Window->GetState()->vtkglDisable(GL_DEPTH_TEST);
    // The same view; x and y of the projection scaled by 1 / g.
    const glm::dmat4 scale = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / guard, 1.0 / guard, 1.0));
    occluderClipToView = glm::inverse(scale * camera.ViewToClip);
    ++self.LastNumberOfPostPasses;
  }
  self.LastRadialGuardBand = guard;
  auto invProjection = ToFloatColumnMajor(occluderClipToView);
  vtkTextureObject* mask = this->OcclusionMask.Ensure(renWin, TextureKind::RGBA32F, mw, mh);
  this->BindWork(mask, nullptr, mw, mh);
  if (vtkShaderProgram* program = this->Occlusion.Ready(renWin, vtkLightShaftOcclusionFS))
  {
    occluderDepth->Activate();
    program->SetUniformi("sceneDepth", occluderDepth->GetTextureUnit());
    program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
    const float size[2] = { static_cast<float>(mw), static_cast<float>(mh) };
    program->SetUniform2f("targetSize", size);
    program->SetUniform3f("lightPositionVC", ToFloat3(light.PositionVC).data());
    program->SetUniform3f("lightAxisVC", ToFloat3(light.AxisVC).data());
    program->SetUniformf("cosConeAngle", static_cast<float>(std::cos(light.ConeHalfAngle)));
    this->Occlusion.Quad->Render();
    occluderDepth->Deactivate();
  }
  else
  {
    return unshadowed;
  }

  vtkTextureObject* output = this->RadialOutput.Ensure(renWin, TextureKind::RGBA32F, lw, lh);
  this->BindWork(output, nullptr, lw, lh);
  vtkShaderProgram* program = this->RadialBlur.Ready(renWin, vtkLightShaftRadialBlurFS);
  if (!program)
  {
    return unshadowed;
  }
  unshadowed->Activate();
  mask->Activate();
  program->SetUniformi("unshadowed", unshadowed->GetTextureUnit());
  program->SetUniformi("occlusion", mask->GetTextureUnit());
  program->SetUniform2f("lightUV", lightUV);
  program->SetUniformf("fade", static_cast<float>(fade));
  program->SetUniformi("samples", self.RadialSamples);
  program->SetUniformf("decay", static_cast<float>(self.Decay));
  program->SetUniformf("weight", static_cast<float>(self.Weight));
  program->SetUniformf("density", static_cast<float>(self.Density));
  program->SetUniformi("stochastic", self.RadialJitter ? 1 : 0);
  program->SetUniformf("guardBand", static_cast<float>(guard));
  this->RadialBlur.Quad->Render();
  mask->Deactivate();
  unshadowed->Deactivate();
  self.LastNumberOfPostPasses += 2;
  return output;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::PostProcess(vtkLightShaftPass& self,
  vtkTextureObject* current,
  const CameraFrame& camera,
  vtkTextureObject* slabDepth,
  vtkTextureObject* fullDepth,
  int w,
  int h,
  int lw,
  int lh)
{
  vtkOpenGLRenderWindow* renWin = this->Window;
  auto invProjection = ToFloatColumnMajor(camera.ClipToView);

  if (this->EightBitThisFrame)
  {
    vtkTextureObject* resolved = this->Resolved.Ensure(renWin, TextureKind::RGBA32F, lw, lh);
    this->BindWork(resolved, nullptr, lw, lh);
    if (vtkShaderProgram* program = this->Resolve.Ready(renWin, vtkLightShaftResolveFS))
    {
      const char* names[3] = { "accumulatedRed", "accumulatedGreen", "accumulatedBlue" };
      for (int c = 0; c < 3; ++c)
      {
        this->Accumulation[c].Object->Activate();
        program->SetUniformi(names[c], this->Accumulation[c].Object->GetTextureUnit());
      }
      program->SetUniformf(
        "inverseScale", static_cast<float>(1.0 / (self.Exposure > 0.0 ? self.Exposure : 1.0)));
      this->Resolve.Quad->Render();
      for (int c = 0; c < 3; ++c)
      {
        this->Accumulation[c].Object->Deactivate();
      }
    }
    current = resolved;
  }

  if (self.BlurRadius > 0)
  {
    current = this->SeparableFilter(self,
      current,
      this->BlurTemporary,
      this->Blurred,
      camera,
      slabDepth,
      self.BlurRadius,
      0,
      lw,
      lh);
  }

  if (lw != w || lh != h)
  {
    vtkTextureObject* upsampled = this->Upsampled.Ensure(renWin, TextureKind::RGBA32F, w, h);
    this->BindWork(upsampled, nullptr, w, h);
    if (vtkShaderProgram* program = this->Upsample.Ready(renWin, vtkLightShaftUpsampleFS))
    {
      current->Activate();
      slabDepth->Activate();
      fullDepth->Activate();
      program->SetUniformi("reduced", current->GetTextureUnit());
      program->SetUniformi("reducedDepth", slabDepth->GetTextureUnit());
      program->SetUniformi("fullDepth", fullDepth->GetTextureUnit());
      program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
      const float fullSize[2] = { static_cast<float>(w), static_cast<float>(h) };
      program->SetUniform2f("fullSize", fullSize);
      program->SetUniformf("depthTolerance", SameSurfaceTolerance);
      this->Upsample.Quad->Render();
      ++self.LastNumberOfPostPasses;
      fullDepth->Deactivate();
      slabDepth->Deactivate();
      current->Deactivate();
    }
    current = upsampled;
  }
  this->FinalInScatter = current;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::RenderComposite(vtkLightShaftPass& self,
  vtkRenderer* ren,
  const CameraFrame& camera,
  const LightFrame* light,
  const SceneImage& scene,
  bool cookieSurfaces,
  const int viewport[4])
{
  const int w = viewport[2];
  const int h = viewport[3];
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkOpenGLState* ostate = renWin->GetState();
  double sigmaT[3];
  for (int c = 0; c < 3; ++c)
  {
    sigmaT[c] = self.ScatteringCoefficient[c] + self.AbsorptionCoefficient[c];
  }
  const bool attenuate = self.AttenuateScene && AnyPositive(sigmaT);
  std::vector<std::string> defines;
  if (attenuate)
  {
    defines.emplace_back("LIGHTSHAFT_ATTENUATE");
  }
  if (cookieSurfaces)
  {
    defines.emplace_back("LIGHTSHAFT_COOKIE_SURFACES");
  }
  const bool multisample = scene.Samples > 0;
  if (multisample)
  {
    defines.emplace_back("LIGHTSHAFT_MULTISAMPLE");
  }
  // The scene's depth goes to the target unchanged, so that later passes, overlays and depth
  // queries (vtkRenderer::GetZ) see the surfaces as without the pass: copied when the target's
  // depth has the same format, else written by the shader.
  const bool copyDepth = TargetDepthMatches(scene.Depth);
  if (!copyDepth)
  {
    defines.emplace_back("LIGHTSHAFT_WRITE_DEPTH");
  }
  vtkShaderProgram* program = this->Composite.Ready(renWin, vtkLightShaftCompositeFS, defines);
  if (!program)
  {
    vtkErrorWithObjectMacro(&self, "Could not build the light-shaft composite shader.");
    return;
  }

  // Multisampled scene textures are read per sample (their uniforms have a "Samples" suffix).
  const std::string suffix = multisample ? "Samples" : "";
  vtkTextureObject* inScatter = this->FinalInScatter;
  std::vector<vtkTextureObject*> active = { scene.Color, scene.Depth, inScatter };
  for (vtkTextureObject* t : active)
  {
    t->Activate();
  }
  program->SetUniformi(("sceneColor" + suffix).c_str(), scene.Color->GetTextureUnit());
  program->SetUniformi(("sceneDepth" + suffix).c_str(), scene.Depth->GetTextureUnit());
  program->SetUniformi("inScatter", inScatter->GetTextureUnit());
  program->SetUniformf("exposure", static_cast<float>(self.Exposure));
  auto invProjection = ToFloatColumnMajor(camera.ClipToView);
  const float targetSize[2] = { static_cast<float>(w), static_cast<float>(h) };
  if (attenuate || cookieSurfaces)
  {
    program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
    program->SetUniform2f("targetSize", targetSize);
  }
  if (attenuate)
  {
    program->SetUniform3f("sigmaT", sigmaT);
  }
  if (cookieSurfaces)
  {
    vtkTextureObject* unlit = scene.ColorUnlit;
    unlit->Activate();
    this->CookieTexture->Activate();
    active.push_back(unlit);
    active.push_back(this->CookieTexture);
    program->SetUniformi(("sceneColorUnlit" + suffix).c_str(), unlit->GetTextureUnit());
    program->SetUniformi("cookieTexture", this->CookieTexture->GetTextureUnit());
    program->SetUniformf("cookieSize",
      static_cast<float>(
        std::max(this->CookieTexture->GetWidth(), this->CookieTexture->GetHeight())));
    auto lightMatrix = ToFloatColumnMajor(light->ViewToLightClip);
    program->SetUniformMatrix4x4("lightClipFromVC", lightMatrix.data());
    program->SetUniform3f("lightPositionVC", ToFloat3(light->PositionVC).data());
    const bool perspective = camera.ViewToClip[2][3] != 0.0;
    const float pixel = static_cast<float>(2.0 / (w * camera.ViewToClip[0][0]));
    const float pixelFootprint[2] = { perspective ? pixel : 0.0f, perspective ? 0.0f : pixel };
    program->SetUniform2f("pixelFootprint", pixelFootprint);
    program->SetUniformf("lightTexelAngle",
      static_cast<float>(2.0 * std::tan(std::min(light->ConeHalfAngle, MaximumBoundingHalfAngle))));
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
  if (ren->Transparent())
  {
    // A layer over other renderers: the scene target is premultiplied (cleared to 0 alpha).
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  this->Composite.Quad->Render();
  for (auto it = active.rbegin(); it != active.rend(); ++it)
  {
    (*it)->Deactivate();
  }
  if (copyDepth)
  {
    ostate->PushReadFramebufferBinding();
    this->SceneFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglBlitFramebuffer(0,
      0,
      w,
      h,
      viewport[0],
      viewport[1],
      viewport[0] + w,
      viewport[1] + h,
      GL_DEPTH_BUFFER_BIT,
      GL_NEAREST);
    ostate->PopReadFramebufferBinding();
  }
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::GetInScatteredRadiance(vtkImageData* out)
{
  if (!out)
  {
    vtkErrorMacro("GetInScatteredRadiance: the output image is nullptr.");
    return false;
  }
  out->Initialize();
  Internals& impl = *this->Impl;
  const int w = this->LastViewportSize[0];
  const int h = this->LastViewportSize[1];
  if (!impl.Window || w < 1 || h < 1)
  {
    vtkErrorMacro("GetInScatteredRadiance: nothing has been rendered yet.");
    return false;
  }
  out->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("InScatteredRadiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  radiance->Fill(0.0);
  vtkTextureObject* final = impl.FinalInScatter;
  if (impl.InScatterValid && final && static_cast<int>(final->GetWidth()) == w &&
      static_cast<int>(final->GetHeight()) == h)
  {
    impl.Window->MakeCurrent();
    vtkOpenGLState* ostate = impl.Window->GetState();
    ostate->PushFramebufferBindings();
    impl.BindWork(final, nullptr, w, h);
    impl.WorkFramebuffer->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, radiance->GetPointer(0));
    ostate->PopFramebufferBindings();
  }
  out->GetPointData()->SetScalars(radiance);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::GetLastShadowMap(vtkImageData* depths, vtkMatrix4x4* worldToLightClip)
{
  Internals& impl = *this->Impl;
  vtkTextureObject* map = impl.ShadowMap.Object;
  if (!depths || !worldToLightClip || !this->LastShadowMapRendered || !impl.Window || !map ||
      !impl.ShadowFramebuffer)
  {
    return false;
  }
  const int size = static_cast<int>(map->GetWidth());
  depths->Initialize();
  depths->SetDimensions(size, size, 1);
  vtkNew<vtkFloatArray> values;
  values->SetName("Depth");
  values->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  impl.Window->MakeCurrent();
  vtkOpenGLState* ostate = impl.Window->GetState();
  ostate->PushFramebufferBindings();
  impl.ShadowFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, values->GetPointer(0));
  ostate->PopFramebufferBindings();
  depths->GetPointData()->SetScalars(values);
  ToVTKMatrix(impl.LastWorldToLightClip, worldToLightClip);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto print = [&os, indent](const char* name, const double* v, int n)
  {
    os << indent << name << ": (";
    for (int i = 0; i < n; ++i)
    {
      os << (i ? ", " : "") << v[i];
    }
    os << ")\n";
  };
  os << indent << "Light: " << this->Impl->Light.Get() << "\n";
  print("ScatteringCoefficient", this->ScatteringCoefficient, 3);
  print("AbsorptionCoefficient", this->AbsorptionCoefficient, 3);
  os << indent << "PhaseFunction: " << this->PhaseFunction << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "AttenuateScene: " << this->AttenuateScene << "\n";
  os << indent << "ShadowSurfaces: " << this->ShadowSurfaces << "\n";
  os << indent << "NumberOfSlices: " << this->NumberOfSlices << "\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "Cookie: " << this->Impl->Cookie.Get() << "\n";
  os << indent << "NoiseAmplitude: " << this->NoiseAmplitude << "\n";
  os << indent << "NoiseScale: " << this->NoiseScale << "\n";
  print("NoiseVelocity1", this->NoiseVelocity1, 2);
  print("NoiseVelocity2", this->NoiseVelocity2, 2);
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "NoiseTexture: " << this->Impl->NoiseImage.Get() << "\n";
  os << indent << "AutomaticSliceCount: " << this->AutomaticSliceCount << "\n";
  os << indent << "MaximumNumberOfSlices: " << this->MaximumNumberOfSlices << "\n";
  os << indent << "Jitter: " << this->Jitter << "\n";
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "LatticeResolution: " << this->LatticeResolution << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "InterleaveSize: " << this->InterleaveSize << "\n";
  os << indent << "RadialSamples: " << this->RadialSamples << "\n";
  os << indent << "Decay: " << this->Decay << "\n";
  os << indent << "Density: " << this->Density << "\n";
  os << indent << "Weight: " << this->Weight << "\n";
  os << indent << "RadialJitter: " << this->RadialJitter << "\n";
  os << indent << "RadialGuardBand: " << this->RadialGuardBand << "\n";
  os << indent << "LastMethod: " << GetMethodName(this->LastMethod) << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << "\n";
  os << indent << "DownsampleFactor: " << this->DownsampleFactor << "\n";
  os << indent << "AccumulationPrecision: " << this->AccumulationPrecision << "\n";
  os << indent << "LastNumberOfSlicesDrawn: " << this->LastNumberOfSlicesDrawn << "\n";
  os << indent << "LastShadowMapRendered: " << this->LastShadowMapRendered << "\n";
  os << indent << "LastShaderVariant: " << this->Impl->SliceVariant << "\n";
}
