#include "vtkLightShaftPass.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
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
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkLightShaftCommon.h"
#include "vtkLightShaftCompositeFS.h"
#include "vtkLightShaftSliceFS.h"
#include "vtkLightShaftSliceVS.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double MaximumCoefficient = 1.0e6;
constexpr double MaximumExposure = 1.0e6;
constexpr double MaximumAnisotropy = 0.99;
// The bounding pyramid of a cone wider than this is numerically useless; such cones are
// bounded by the view volume instead (the shader still clips to the true cone).
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

  // Used when no delegate is set: renders like VTK's default pipeline, or with the opaque step
  // shadowed by vtkShadowMapPass (ShadowSurfaces).
  vtkNew<vtkRenderStepsPass> DefaultDelegate;
  vtkNew<vtkRenderStepsPass> ShadowedDelegate;
  vtkNew<vtkShadowMapPass> SurfaceShadows;

  // Shadow map: the opaque step rendered from the light's camera.
  vtkNew<vtkCameraPass> ShadowCameraPass;
  vtkNew<vtkOpaquePass> ShadowOpaquePass;
  vtkNew<vtkCamera> LightCamera;

  vtkSmartPointer<vtkOpenGLFramebufferObject> SceneFramebuffer;
  vtkSmartPointer<vtkTextureObject> SceneColor;
  vtkSmartPointer<vtkTextureObject> SceneDepth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> InScatterFramebuffer;
  vtkSmartPointer<vtkTextureObject> InScatter;
  // A copy of the scene depth for the in-scatter target: the hardware depth test then culls
  // slab fragments that start behind the surface before they are shaded.
  vtkSmartPointer<vtkTextureObject> InScatterDepth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ShadowFramebuffer;
  vtkSmartPointer<vtkTextureObject> ShadowMap;

  // Slice program: owned by the window's shader cache; rebuilt when its variant changes.
  vtkShaderProgram* SliceProgram = nullptr;
  int SliceVariantPhase = -1;
  bool SliceVariantShadow = false;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> SliceArray;
  vtkSmartPointer<vtkOpenGLBufferObject> SliceBuffer;
  std::vector<float> SliceVertices;

  std::unique_ptr<vtkOpenGLQuadHelper> Composite;
  bool CompositeVariantAttenuate = false;

  // Whether the in-scatter target holds the last frame's L_in.
  bool InScatterValid = false;
  vtkShaderProgram* SliceArrayProgram = nullptr;

  void AllocateTargets(vtkOpenGLRenderWindow* renWin, int w, int h);
  void RenderScene(vtkLightShaftPass& self,
    const vtkRenderState* s,
    vtkRenderPass* delegate,
    int w,
    int h);
  void RenderInScatter(vtkLightShaftPass& self,
    const vtkRenderState* s,
    vtkLight* light,
    const CameraFrame& camera,
    int w,
    int h);
  bool RenderShadowMap(vtkLightShaftPass& self,
    const vtkRenderState* s,
    const glm::dvec3& lightWC,
    const glm::dvec3& axisWC,
    double coneHalfAngle,
    const glm::dmat4& worldToView,
    glm::dmat4& viewToLightClip,
    double lightDepthRange[2]);
  vtkShaderProgram* ReadySliceProgram(vtkLightShaftPass& self, bool shadows);
  void RenderComposite(vtkLightShaftPass& self,
    vtkRenderer* ren,
    const CameraFrame& camera,
    int w,
    int h);

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

  // Render `delegate` with state `s`; with the shadowed delegate, make sure its shadow maps were
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
    for (vtkTextureObject* t : { this->SceneColor.Get(),
           this->SceneDepth.Get(),
           this->InScatter.Get(),
           this->ShadowMap.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(w);
      }
    }
    for (vtkOpenGLFramebufferObject* f : { this->SceneFramebuffer.Get(),
           this->InScatterFramebuffer.Get(),
           this->ShadowFramebuffer.Get() })
    {
      if (f)
      {
        f->ReleaseGraphicsResources(w);
      }
    }
    if (this->SliceArray)
    {
      this->SliceArray->ReleaseGraphicsResources();
    }
    if (this->SliceBuffer)
    {
      this->SliceBuffer->ReleaseGraphicsResources();
    }
    if (this->Composite)
    {
      this->Composite->ReleaseGraphicsResources(w);
    }
    this->SceneColor = nullptr;
    this->SceneDepth = nullptr;
    this->InScatter = nullptr;
    this->InScatterDepth = nullptr;
    this->ShadowMap = nullptr;
    this->SceneFramebuffer = nullptr;
    this->InScatterFramebuffer = nullptr;
    this->ShadowFramebuffer = nullptr;
    this->SliceArray = nullptr;
    this->SliceBuffer = nullptr;
    this->Composite.reset();
    this->SliceProgram = nullptr;
    this->SliceArrayProgram = nullptr;
    this->SliceVariantPhase = -1;
    this->InScatterValid = false;
  }
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

// Both medium coefficients: refuse non-finite values, clamp each channel to [0, max].
void SetCoefficient(vtkObject* self,
  const char* parameter,
  double coefficient[3],
  double r,
  double g,
  double b)
{
  if (RefuseNonFinite(self, parameter, { r, g, b }))
  {
    return;
  }
  const double v[3] = { vtkMath::ClampValue(r, 0.0, MaximumCoefficient),
    vtkMath::ClampValue(g, 0.0, MaximumCoefficient),
    vtkMath::ClampValue(b, 0.0, MaximumCoefficient) };
  if (!std::equal(v, v + 3, coefficient))
  {
    std::copy(v, v + 3, coefficient);
    self->Modified();
  }
}
} // namespace

void vtkLightShaftPass::SetScatteringCoefficient(double r, double g, double b)
{
  SetCoefficient(this, "ScatteringCoefficient", this->ScatteringCoefficient, r, g, b);
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
  SetCoefficient(this, "AbsorptionCoefficient", this->AbsorptionCoefficient, r, g, b);
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
  if (RefuseNonFinite(this, "Anisotropy", { g }))
  {
    return;
  }
  g = vtkMath::ClampValue(g, -MaximumAnisotropy, MaximumAnisotropy);
  if (g != this->Anisotropy)
  {
    this->Anisotropy = g;
    this->Modified();
  }
}

void vtkLightShaftPass::SetExposure(double exposure)
{
  if (RefuseNonFinite(this, "Exposure", { exposure }))
  {
    return;
  }
  exposure = vtkMath::ClampValue(exposure, 0.0, MaximumExposure);
  if (exposure != this->Exposure)
  {
    this->Exposure = exposure;
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

//------------------------------------------------------------------------------
namespace
{
bool IsSpotLight(vtkLight* light)
{
  return light->GetPositional() && light->GetConeAngle() < 90.0;
}

} // namespace

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
  this->LastSliceDepthRange[0] = this->LastSliceDepthRange[1] = 0.0;
  impl.InScatterValid = false;

  vtkRenderer* ren = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro("vtkLightShaftPass needs an OpenGL render window.");
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
    impl.SurfaceShadows->GetShadowMapBakerPass()->SetResolution(this->ShadowMapSize);
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

  // Find the light (warn once when there is none).
  vtkLight* light = impl.Light;
  if (light && !IsSpotLight(light))
  {
    if (!impl.WarnedNoLight)
    {
      vtkWarningMacro("The light given to SetLight is not a spotlight (positional, cone angle "
                      "< 90 degrees): rendering the scene without shafts.");
      impl.WarnedNoLight = true;
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
    if (!light && !impl.WarnedNoLight)
    {
      vtkWarningMacro("No spotlight in the renderer (a switched-on positional light with cone "
                      "angle < 90 degrees): rendering the scene without shafts.");
      impl.WarnedNoLight = true;
    }
  }
  if (light)
  {
    impl.WarnedNoLight = false;
  }
  impl.LastUsedLight = light;

  const bool hasMedium = std::any_of(this->ScatteringCoefficient,
                           this->ScatteringCoefficient + 3,
                           [](double v) { return v > 0.0; }) ||
                         std::any_of(this->AbsorptionCoefficient,
                           this->AbsorptionCoefficient + 3,
                           [](double v) { return v > 0.0; });

  if (!light || !hasMedium || w < 1 || h < 1)
  {
    // Nothing to add: the delegate's image, untouched.
    impl.RenderDelegate(*this, delegate, s, [&]() { delegate->Render(s); });
    vtkOpenGLCheckErrorMacro("failed after pass-through render");
    return;
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

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);

  impl.AllocateTargets(renWin, w, h);

  // The 2D overlay step of a vtkRenderStepsPass is held back and drawn after compositing so
  // that text and scalar bars stay on top, unfogged.
  auto* steps = vtkRenderStepsPass::SafeDownCast(delegate);
  vtkSmartPointer<vtkRenderPass> overlay = steps ? steps->GetOverlayPass() : nullptr;
  if (overlay)
  {
    steps->SetOverlayPass(nullptr);
  }

  ostate->PushFramebufferBindings();
  impl.RenderScene(*this, s, delegate, w, h);
  if (overlay)
  {
    steps->SetOverlayPass(overlay);
  }
  impl.RenderInScatter(*this, s, light, camera, w, h);
  ostate->PopFramebufferBindings();

  ostate->vtkglViewport(x, y, w, h);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(x, y, w, h);
  impl.RenderComposite(*this, ren, camera, w, h);

  if (overlay)
  {
    overlay->Render(s);
    this->NumberOfRenderedProps += overlay->GetNumberOfRenderedProps();
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::AllocateTargets(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  Internals& impl = *this;
  auto makeTexture = [renWin]()
  {
    auto t = vtkSmartPointer<vtkTextureObject>::New();
    t->SetContext(renWin);
    t->SetWrapS(vtkTextureObject::ClampToEdge);
    t->SetWrapT(vtkTextureObject::ClampToEdge);
    t->SetMinificationFilter(vtkTextureObject::Nearest);
    t->SetMagnificationFilter(vtkTextureObject::Nearest);
    return t;
  };
  auto makeFramebuffer = [renWin]()
  {
    auto f = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    f->SetContext(renWin);
    return f;
  };
  if (!impl.SceneColor)
  {
    impl.SceneColor = makeTexture();
    impl.SceneColor->Allocate2D(w, h, 4, VTK_UNSIGNED_CHAR);
    // The depth format VTK 9.1's GPU volume mapper allocates, so that its depth blit from the
    // current target (our scene target) is legal.
    for (auto* depth : { &impl.SceneDepth, &impl.InScatterDepth })
    {
      *depth = makeTexture();
      if (renWin->GetStencilCapable())
      {
        (*depth)->AllocateDepthStencil(w, h);
      }
      else
      {
        (*depth)->AllocateDepth(w, h, vtkTextureObject::Fixed32);
      }
    }
    impl.InScatter = makeTexture();
    impl.InScatter->SetInternalFormat(GL_RGBA32F);
    impl.InScatter->SetFormat(GL_RGBA);
    impl.InScatter->SetDataType(GL_FLOAT);
    impl.InScatter->Allocate2D(w, h, 4, VTK_FLOAT);
    impl.SceneFramebuffer = makeFramebuffer();
    impl.InScatterFramebuffer = makeFramebuffer();
  }
  else if (static_cast<int>(impl.SceneColor->GetWidth()) != w ||
           static_cast<int>(impl.SceneColor->GetHeight()) != h)
  {
    impl.SceneColor->Resize(w, h);
    impl.SceneDepth->Resize(w, h);
    impl.InScatter->Resize(w, h);
    impl.InScatterDepth->Resize(w, h);
  }
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::RenderScene(vtkLightShaftPass& self,
  const vtkRenderState* s,
  vtkRenderPass* delegate,
  int w,
  int h)
{
  Internals& impl = *this;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLState* ostate = impl.Window->GetState();

  impl.SceneFramebuffer->Bind();
  impl.SceneFramebuffer->AddColorAttachment(0, impl.SceneColor);
  impl.SceneFramebuffer->ActivateDrawBuffer(0);
  impl.SceneFramebuffer->AddDepthAttachment(impl.SceneDepth);
  impl.SceneFramebuffer->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  // Renderers that do not erase (layers) would otherwise see the previous frame.
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglClearDepth(1.0);

  vtkRenderState sceneState(ren);
  sceneState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  sceneState.SetFrameBuffer(impl.SceneFramebuffer);
  this->RenderDelegate(self,
    delegate,
    s,
    [&]()
    {
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      ostate->vtkglEnable(GL_DEPTH_TEST);
      delegate->Render(&sceneState);
    });
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::Internals::RenderInScatter(vtkLightShaftPass& self,
  const vtkRenderState* s,
  vtkLight* light,
  const CameraFrame& camera,
  int w,
  int h)
{
  Internals& impl = *this;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = impl.Window;
  vtkOpenGLState* ostate = renWin->GetState();

  // Clear L_in; it stays zero when nothing scatters.
  impl.InScatterFramebuffer->Bind();
  impl.InScatterFramebuffer->AddColorAttachment(0, impl.InScatter);
  impl.InScatterFramebuffer->ActivateDrawBuffer(0);
  impl.InScatterFramebuffer->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  impl.InScatterValid = true;

  const double* color = light->GetDiffuseColor();
  const double intensity = light->GetIntensity();
  const double radiantIntensity[3] = {
    intensity * color[0], intensity * color[1], intensity * color[2]
  };
  const bool scatters =
    light->GetSwitch() &&
    std::any_of(self.ScatteringCoefficient,
      self.ScatteringCoefficient + 3,
      [](double v) { return v > 0.0; }) &&
    std::any_of(radiantIntensity, radiantIntensity + 3, [](double v) { return v > 0.0; });
  if (!scatters)
  {
    return;
  }

  const glm::dmat4& worldToView = camera.WorldToView;
  const glm::dmat4& viewToClip = camera.ViewToClip;
  const glm::dmat4& clipToView = camera.ClipToView;

  // The light, in world and view coordinates.
  const glm::dvec3 lightWC = glm::make_vec3(light->GetTransformedPosition());
  glm::dvec3 axisWC = glm::make_vec3(light->GetTransformedFocalPoint()) - lightWC;
  if (glm::length(axisWC) == 0.0)
  {
    axisWC = glm::dvec3(0.0, 0.0, -1.0);
  }
  axisWC = glm::normalize(axisWC);
  const glm::dvec3 lightVC = glm::dvec3(worldToView * glm::dvec4(lightWC, 1.0));
  const glm::dvec3 axisVC = glm::normalize(glm::dvec3(worldToView * glm::dvec4(axisWC, 0.0)));
  const double coneHalfAngle = vtkMath::RadiansFromDegrees(light->GetConeAngle());

  // The view volume from the camera plane to the far plane, as a polytope's vertices and the
  // clip-space half-spaces that bound it.
  double farthest = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double sx = (corner & 1) ? 1.0 : -1.0;
    const double sy = (corner & 2) ? 1.0 : -1.0;
    glm::dvec4 nearPoint = clipToView * glm::dvec4(sx, sy, -1.0, 1.0);
    glm::dvec4 farPoint = clipToView * glm::dvec4(sx, sy, 1.0, 1.0);
    const glm::dvec3 n3 = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 f3 = glm::dvec3(farPoint) / farPoint.w;
    const glm::dvec3 dir = f3 - n3;
    const glm::dvec3 start = n3 - dir * (n3.z / dir.z);
    farthest = std::max({ farthest, glm::length(start - lightVC), glm::length(f3 - lightVC) });
  }

  // The light's bounding pyramid (apex at the light, base beyond everything the view can see).
  const double boundingHalfAngle = std::min(coneHalfAngle, MaximumBoundingHalfAngle);
  const double reach = std::max(farthest, 1e-30);
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
  const double farDepth = [&]()
  {
    const glm::dvec4 p = clipToView * glm::dvec4(0.0, 0.0, 1.0, 1.0);
    return -p.z / p.w;
  }();
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

  // Slabs: for each, the screen footprint of the lit polytope between its two depths.
  const int slices = self.NumberOfSlices;
  const double thickness = (deepest - nearest) / slices;
  std::vector<float>& vertices = impl.SliceVertices;
  vertices.clear();
  std::vector<glm::dvec2> footprint;
  int drawn = 0;
  for (int k = 0; k < slices; ++k)
  {
    const double za = nearest + k * thickness;
    const double zb = (k + 1 == slices) ? deepest : za + thickness;
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
    const std::vector<glm::dvec2> hull = ConvexHull(footprint);
    if (hull.size() < 3)
    {
      continue;
    }
    ++drawn;
    for (size_t i = 1; i + 1 < hull.size(); ++i)
    {
      for (const glm::dvec2& p : { hull[0], hull[i], hull[i + 1] })
      {
        vertices.insert(vertices.end(),
          { static_cast<float>(p.x),
            static_cast<float>(p.y),
            static_cast<float>(za),
            static_cast<float>(zb) });
      }
    }
  }
  if (vertices.empty())
  {
    return;
  }

  // Shadow map of the opaque geometry, seen from the light.
  glm::dmat4 viewToLightClip(1.0);
  double lightDepthRange[2] = { 0.0, 0.0 };
  const bool shadows = impl.RenderShadowMap(
    self, s, lightWC, axisWC, coneHalfAngle, worldToView, viewToLightClip, lightDepthRange);

  // Re-bind the in-scatter target (the shadow pass used its own) with a copy of the scene depth.
  impl.InScatterFramebuffer->Bind();
  impl.InScatterFramebuffer->AddDepthAttachment(impl.InScatterDepth);
  impl.InScatterFramebuffer->ActivateDrawBuffer(0);
  impl.SceneFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  ostate->vtkglBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  impl.InScatterFramebuffer->Bind();
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);

  vtkShaderProgram* program = impl.ReadySliceProgram(self, shadows);
  if (!program)
  {
    return;
  }

  // Each slab is drawn at its near depth: the depth test drops it where it starts behind the
  // surface. Depth clamping keeps slabs in front of the near plane (eye inside the light).
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDepthMask(GL_FALSE);
  const GLboolean depthClampWasOn = glIsEnabled(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_CLAMP);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  auto invProjection = ToFloatColumnMajor(clipToView);
  program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
  const float targetSize[2] = { static_cast<float>(w), static_cast<float>(h) };
  program->SetUniform2f("targetSize", targetSize);
  // Row 2 and row 3 of the projection: a view depth's NDC z, for the slabs' depth test.
  const float depthProjection[4] = { static_cast<float>(viewToClip[2][2]),
    static_cast<float>(viewToClip[3][2]),
    static_cast<float>(viewToClip[2][3]),
    static_cast<float>(viewToClip[3][3]) };
  program->SetUniform4f("depthProjection", depthProjection);
  impl.SceneDepth->Activate();
  program->SetUniformi("sceneDepth", impl.SceneDepth->GetTextureUnit());
  program->SetUniform3f("lightPositionVC", ToFloat3(lightVC).data());
  program->SetUniform3f("lightAxisVC", ToFloat3(axisVC).data());
  program->SetUniformf("cosConeAngle", static_cast<float>(std::cos(coneHalfAngle)));
  program->SetUniformf("spotExponent", static_cast<float>(light->GetExponent()));
  double attenuation[3];
  light->GetAttenuationValues(attenuation);
  if (attenuation[0] <= 0.0 && attenuation[1] <= 0.0 && attenuation[2] <= 0.0)
  {
    attenuation[0] = 1.0; // VTK's lighting would divide by zero; treat as no falloff.
  }
  program->SetUniform3f("attenuationCoefficients", attenuation);
  program->SetUniform3f("lightRadiantIntensity", radiantIntensity);
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
  if (shadows)
  {
    impl.ShadowMap->Activate();
    program->SetUniformi("shadowMap", impl.ShadowMap->GetTextureUnit());
    auto lightMatrix = ToFloatColumnMajor(viewToLightClip);
    program->SetUniformMatrix4x4("lightClipFromVC", lightMatrix.data());
    const float depthRange[2] = { static_cast<float>(lightDepthRange[0]),
      static_cast<float>(lightDepthRange[1]) };
    program->SetUniform2f("lightDepthRange", depthRange);
    // Two texels' worth of relative depth: a sample this close behind a caster's front face is
    // inside the caster, where no view ray goes.
    const double texelAngle = 2.0 * std::tan(std::min(coneHalfAngle, MaximumBoundingHalfAngle)) /
                              impl.ShadowMap->GetWidth();
    program->SetUniformf("shadowBias", static_cast<float>(2.0 * texelAngle + 1e-4));
  }

  impl.SliceBuffer->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer);
  if (impl.SliceArrayProgram != program)
  {
    impl.SliceArray->ShaderProgramChanged();
  }
  impl.SliceArray->Bind();
  if (impl.SliceArrayProgram != program)
  {
    impl.SliceArray->AddAttributeArray(
      program, impl.SliceBuffer, "sliceVertex", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    impl.SliceArrayProgram = program;
  }
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size() / 4));
  impl.SliceArray->Release();

  impl.SceneDepth->Deactivate();
  if (shadows)
  {
    impl.ShadowMap->Deactivate();
  }
  self.LastNumberOfSlicesDrawn = drawn;
}

//------------------------------------------------------------------------------
bool vtkLightShaftPass::Internals::RenderShadowMap(vtkLightShaftPass& self,
  const vtkRenderState* s,
  const glm::dvec3& lightWC,
  const glm::dvec3& axisWC,
  double coneHalfAngle,
  const glm::dmat4& worldToView,
  glm::dmat4& viewToLightClip,
  double lightDepthRange[2])
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkOpenGLState* ostate = renWin->GetState();

  // Every visible prop casts, including those culled from the camera's view.
  std::vector<vtkProp*> casters;
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility())
    {
      casters.push_back(prop);
    }
  }
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  if (casters.empty() || !vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }

  // Depth range of the scene along the light's axis.
  double nearest = std::numeric_limits<double>::max();
  double deepest = -std::numeric_limits<double>::max();
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec3 p(
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
    const double depth = glm::dot(p - lightWC, axisWC);
    nearest = std::min(nearest, depth);
    deepest = std::max(deepest, depth);
  }
  if (deepest <= 0.0)
  {
    return false; // Everything is behind the light: nothing can shadow the cone.
  }
  const double farPlane = deepest * 1.001;
  const double nearPlane = std::max(nearest * 0.999, farPlane * 1e-4);
  lightDepthRange[0] = nearPlane;
  lightDepthRange[1] = farPlane;

  // The light's camera: a square frustum whose inscribed cone is the spot cone.
  const double halfAngle = std::min(coneHalfAngle, MaximumBoundingHalfAngle);
  const glm::dmat4 projection = glm::perspective(2.0 * halfAngle, 1.0, nearPlane, farPlane);
  const glm::dvec3 up =
    std::abs(axisWC.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  vtkCamera* lightCamera = this->LightCamera;
  lightCamera->SetPosition(lightWC.x, lightWC.y, lightWC.z);
  lightCamera->SetFocalPoint(lightWC.x + axisWC.x, lightWC.y + axisWC.y, lightWC.z + axisWC.z);
  lightCamera->SetViewUp(up.x, up.y, up.z);
  vtkNew<vtkMatrix4x4> explicitProjection;
  ToVTKMatrix(projection, explicitProjection);
  lightCamera->SetExplicitProjectionTransformMatrix(explicitProjection);
  lightCamera->SetUseExplicitProjectionTransformMatrix(true);
  const glm::dmat4 lightView = FromVTKMatrix(lightCamera->GetViewTransformMatrix());
  viewToLightClip = projection * lightView * glm::inverse(worldToView);

  // Target.
  const int size = std::min(self.ShadowMapSize, vtkTextureObject::GetMaximumTextureSize(renWin));
  if (!this->ShadowMap)
  {
    this->ShadowMap = vtkSmartPointer<vtkTextureObject>::New();
    this->ShadowMap->SetContext(renWin);
    this->ShadowMap->SetWrapS(vtkTextureObject::ClampToEdge);
    this->ShadowMap->SetWrapT(vtkTextureObject::ClampToEdge);
    this->ShadowMap->SetMinificationFilter(vtkTextureObject::Nearest);
    this->ShadowMap->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->ShadowMap->AllocateDepth(size, size, vtkTextureObject::Float32);
    this->ShadowFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->ShadowFramebuffer->SetContext(renWin);
  }
  else if (static_cast<int>(this->ShadowMap->GetWidth()) != size)
  {
    this->ShadowMap->Resize(size, size);
  }
  this->ShadowFramebuffer->Bind();
  this->ShadowFramebuffer->AddDepthAttachment(this->ShadowMap);
  this->ShadowFramebuffer->StartNonOrtho(size, size);
  this->ShadowFramebuffer->DeactivateDrawBuffers();
  ostate->vtkglViewport(0, 0, size, size);
  ostate->vtkglScissor(0, 0, size, size);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);

  vtkRenderState shadowState(ren);
  shadowState.SetPropArrayAndCount(casters.data(), static_cast<int>(casters.size()));
  shadowState.SetFrameBuffer(this->ShadowFramebuffer);

  // Render the opaque step with the light's camera, as vtkShadowMapBakerPass does.
  vtkCamera* sceneCamera = ren->GetActiveCamera();
  sceneCamera->Register(&self);
  const vtkTypeBool automaticLights = ren->GetAutomaticLightCreation();
  ren->SetAutomaticLightCreation(false);
  ren->SetActiveCamera(lightCamera);
  this->ShadowCameraPass->Render(&shadowState);
  ren->SetActiveCamera(sceneCamera);
  ren->SetAutomaticLightCreation(automaticLights);
  sceneCamera->UnRegister(&self);

  self.LastShadowMapRendered = true;
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkLightShaftPass::Internals::ReadySliceProgram(vtkLightShaftPass& self,
  bool shadows)
{
  vtkOpenGLShaderCache* cache = this->Window->GetShaderCache();
  if (this->SliceProgram && this->SliceVariantPhase == self.PhaseFunction &&
      this->SliceVariantShadow == shadows)
  {
    return cache->ReadyShaderProgram(this->SliceProgram);
  }

  // Build the variant: only the phase function and shadow lookup in use are compiled in.
  std::string fragment = vtkLightShaftSliceFS;
  vtkShaderProgram::Substitute(fragment, "//VTK::LightShaft::Common", vtkLightShaftCommon);
  switch (self.PhaseFunction)
  {
    case HENYEY_GREENSTEIN:
      vtkShaderProgram::Substitute(
        fragment, "//VTK::LightShaft::PhaseDec", "uniform float anisotropy;");
      vtkShaderProgram::Substitute(fragment,
        "//VTK::LightShaft::PhaseImpl",
        "float hgDenominator = 1.0 + anisotropy * anisotropy - 2.0 * anisotropy * cosTheta;\n"
        "  phase = (1.0 - anisotropy * anisotropy) /\n"
        "    (4.0 * PI * hgDenominator * sqrt(hgDenominator));");
      break;
    case RAYLEIGH:
      vtkShaderProgram::Substitute(fragment,
        "//VTK::LightShaft::PhaseImpl",
        "phase = 3.0 / (16.0 * PI) * (1.0 + cosTheta * cosTheta);");
      break;
    default:
      vtkShaderProgram::Substitute(
        fragment, "//VTK::LightShaft::PhaseImpl", "phase = 1.0 / (4.0 * PI);");
      break;
  }
  if (shadows)
  {
    vtkShaderProgram::Substitute(fragment,
      "//VTK::LightShaft::ShadowDec",
      "uniform sampler2D shadowMap;\n"
      "uniform mat4 lightClipFromVC;  // VC -> the light camera's clip coordinates\n"
      "uniform vec2 lightDepthRange;  // near, far of the light camera\n"
      "uniform float shadowBias;      // relative depth tolerance");
    vtkShaderProgram::Substitute(fragment,
      "//VTK::LightShaft::ShadowImpl",
      "vec4 lightClip = lightClipFromVC * vec4(sampleVC, 1.0);\n"
      "  if (lightClip.w > 0.0)\n"
      "  {\n"
      "    vec2 lightNDC = lightClip.xy / lightClip.w;\n"
      "    if (all(lessThanEqual(abs(lightNDC), vec2(1.0))))\n"
      "    {\n"
      "      float stored = texture(shadowMap, 0.5 * lightNDC + 0.5).r;\n"
      "      if (stored < 1.0)\n"
      "      {\n"
      "        float n = lightDepthRange.x;\n"
      "        float f = lightDepthRange.y;\n"
      "        float casterDepth = 2.0 * n * f / ((f + n) - (2.0 * stored - 1.0) * (f - n));\n"
      "        visibility = (lightClip.w > casterDepth * (1.0 + shadowBias)) ? 0.0 : 1.0;\n"
      "      }\n"
      "    }\n"
      "  }");
  }
  this->SliceProgram = cache->ReadyShaderProgram(vtkLightShaftSliceVS, fragment.c_str(), "");
  if (!this->SliceProgram || !this->SliceProgram->GetCompiled())
  {
    vtkErrorWithObjectMacro(&self, "Could not build the light-shaft slice shader.");
    this->SliceProgram = nullptr;
    return nullptr;
  }
  this->SliceVariantPhase = self.PhaseFunction;
  this->SliceVariantShadow = shadows;
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
void vtkLightShaftPass::Internals::RenderComposite(vtkLightShaftPass& self,
  vtkRenderer* ren,
  const CameraFrame& camera,
  int w,
  int h)
{
  vtkOpenGLRenderWindow* renWin = this->Window;
  vtkOpenGLState* ostate = renWin->GetState();
  double sigmaT[3];
  for (int c = 0; c < 3; ++c)
  {
    sigmaT[c] = self.ScatteringCoefficient[c] + self.AbsorptionCoefficient[c];
  }
  const bool attenuate =
    self.AttenuateScene && std::any_of(sigmaT, sigmaT + 3, [](double v) { return v > 0.0; });

  if (!this->Composite || this->CompositeVariantAttenuate != attenuate)
  {
    std::string fragment = vtkLightShaftCompositeFS;
    vtkShaderProgram::Substitute(fragment, "//VTK::LightShaft::Common", vtkLightShaftCommon);
    if (attenuate)
    {
      vtkShaderProgram::Substitute(fragment,
        "//VTK::LightShaft::Attenuate",
        "vec3 originVC;\n"
        "  vec3 dirVC;\n"
        "  vec2 ndc;\n"
        "  lightShaftViewRay(vec2(pixel) + 0.5, originVC, dirVC, ndc);\n"
        "  color.rgb *= exp(-sigmaT * lightShaftSurfaceDistance(ndc, depth, dirVC));");
    }
    this->Composite.reset(new vtkOpenGLQuadHelper(renWin, nullptr, fragment.c_str(), ""));
    this->CompositeVariantAttenuate = attenuate;
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Composite->Program);
  }
  vtkShaderProgram* program = this->Composite->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorWithObjectMacro(&self, "Could not build the light-shaft composite shader.");
    return;
  }

  this->SceneColor->Activate();
  this->SceneDepth->Activate();
  this->InScatter->Activate();
  program->SetUniformi("sceneColor", this->SceneColor->GetTextureUnit());
  program->SetUniformi("sceneDepth", this->SceneDepth->GetTextureUnit());
  program->SetUniformi("inScatter", this->InScatter->GetTextureUnit());
  program->SetUniformf("exposure", static_cast<float>(self.Exposure));
  if (attenuate)
  {
    program->SetUniform3f("sigmaT", sigmaT);
    auto invProjection = ToFloatColumnMajor(camera.ClipToView);
    program->SetUniformMatrix4x4("invProjectionDCVC", invProjection.data());
    const float targetSize[2] = { static_cast<float>(w), static_cast<float>(h) };
    program->SetUniform2f("targetSize", targetSize);
  }

  // Write colour and the scene's depth, so later passes and overlays see the surfaces.
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
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
  this->Composite->Render();

  this->InScatter->Deactivate();
  this->SceneDepth->Deactivate();
  this->SceneColor->Deactivate();
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
  if (impl.InScatterValid && impl.InScatterFramebuffer)
  {
    impl.Window->MakeCurrent();
    vtkOpenGLState* ostate = impl.Window->GetState();
    ostate->PushReadFramebufferBinding();
    impl.InScatterFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    impl.InScatterFramebuffer->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, radiance->GetPointer(0));
    ostate->PopReadFramebufferBinding();
    vtkOpenGLCheckErrorMacro("failed after reading the in-scattered radiance");
  }
  out->GetPointData()->SetScalars(radiance);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightShaftPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto print3 = [&os](const char* name, const double* v)
  { os << name << ": (" << v[0] << ", " << v[1] << ", " << v[2] << ")\n"; };
  os << indent << "Light: " << this->Impl->Light.Get() << "\n";
  os << indent;
  print3("ScatteringCoefficient", this->ScatteringCoefficient);
  os << indent;
  print3("AbsorptionCoefficient", this->AbsorptionCoefficient);
  os << indent << "PhaseFunction: " << this->PhaseFunction << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "AttenuateScene: " << this->AttenuateScene << "\n";
  os << indent << "ShadowSurfaces: " << this->ShadowSurfaces << "\n";
  os << indent << "NumberOfSlices: " << this->NumberOfSlices << "\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "LastNumberOfSlicesDrawn: " << this->LastNumberOfSlicesDrawn << "\n";
  os << indent << "LastShadowMapRendered: " << this->LastShadowMapRendered << "\n";
}
