#include "vtkLightShaftInScatter.h"

#include "vtkLightShaftEnums.h"
#include "vtkLightShaftFrame.h"

#include "vtkObject.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

//------------------------------------------------------------------------------
vtkLightShaftInScatter::vtkLightShaftInScatter() = default;
vtkLightShaftInScatter::~vtkLightShaftInScatter() = default;

vtkLightShaftMethod* vtkLightShaftInScatter::GetMethod(int method)
{
  switch (method)
  {
    case vtkLightShaftEnums::RAY_MARCH:
      return &this->RayMarch;
    case vtkLightShaftEnums::RADIAL_BLUR:
      return &this->RadialBlur;
    case vtkLightShaftEnums::ANALYTIC:
      return &this->Analytic;
    case vtkLightShaftEnums::EPIPOLAR:
      return &this->Epipolar;
    case vtkLightShaftEnums::LIGHT_VOLUME:
      return &this->LightVolume;
    default:
      return &this->Slices;
  }
}

//------------------------------------------------------------------------------
bool vtkLightShaftInScatter::RendersField(int method)
{
  return method == vtkLightShaftEnums::SLICES || method == vtkLightShaftEnums::RAY_MARCH ||
         method == vtkLightShaftEnums::EPIPOLAR;
}

//------------------------------------------------------------------------------
// AUTOMATIC takes the exact unshadowed integral when nothing can shadow the light's volume and
// the medium is homogeneous, else the slabs; RAY_MARCH for a medium from data, which the
// methods that cannot render one give way to; LIGHT_VOLUME gives way to RAY_MARCH where it has
// no closed form; ANALYTIC ignores the shadows props could cast. Each reason goes into the
// light's report; a method the user named also says it once, as a warning (one chosen by a
// preset, a target error or the budget gives way silently).
int vtkLightShaftInScatter::ChooseMethod(vtkLightShaftFrame& frame)
{
  const vtkLightShaftParameters& p = frame.Parameters;
  int method = p.Method;
  std::string& fallback = frame.LightStatistics->MethodFallback;
  auto say = [&frame, &fallback](bool& warned, const std::string& why)
  {
    fallback = why;
    if (frame.Parameters.MethodNamed && !warned)
    {
      vtkWarningWithObjectMacro(frame.Owner, "" << why);
      warned = true;
    }
  };
  if (method == vtkLightShaftEnums::AUTOMATIC)
  {
    const bool noise = p.NoiseAmplitude > 0.0;
    method = frame.Density                              ? vtkLightShaftEnums::RAY_MARCH
             : (!frame.Light.ShadowsPossible && !noise) ? vtkLightShaftEnums::ANALYTIC
                                                        : vtkLightShaftEnums::SLICES;
  }
  if (frame.Density && !vtkLightShaftInScatter::RendersField(method))
  {
    say(this->WarnedFieldMethod,
      std::string("A medium from data (MediumDensity) is rendered by SLICES, RAY_MARCH and "
                  "EPIPOLAR: RAY_MARCH computes the shafts instead of method ") +
        vtkLightShaftEnums::MethodName(method) + ".");
    return vtkLightShaftEnums::RAY_MARCH;
  }
  if (method == vtkLightShaftEnums::ANALYTIC && !frame.Light.Casters.empty())
  {
    say(this->WarnedAnalyticShadows,
      "Method ANALYTIC ignores shadows, but " + std::to_string(frame.Light.Casters.size()) +
        " prop(s) reach into the light's volume: use SLICES or AUTOMATIC for shadowed shafts.");
  }
  const bool translucent =
    p.TranslucentLayers > 0 &&
    std::any_of(frame.Light.Casters.begin(),
      frame.Light.Casters.end(),
      [](vtkProp* prop) { return prop->HasTranslucentPolygonalGeometry() != 0; });
  if (method == vtkLightShaftEnums::LIGHT_VOLUME && (frame.Cookie || frame.Noise || translucent))
  {
    // The unshadowed integral up to a crossing is in closed form only without them; its mesh
    // is the opaque casters' shadow.
    say(this->WarnedLightVolumeFeatures,
      std::string("Method LIGHT_VOLUME has no closed form with ") +
        (frame.Cookie   ? "a cookie"
          : frame.Noise ? "density noise"
                        : "translucent casters") +
        ": RAY_MARCH computes the shafts of a light that has one.");
    method = vtkLightShaftEnums::RAY_MARCH;
  }
  return method;
}

//------------------------------------------------------------------------------
std::vector<vtkProp*> vtkLightShaftInScatter::TranslucentProps(const vtkLightShaftFrame& frame)
{
  std::vector<vtkProp*> translucent;
  for (vtkProp* prop : frame.Props)
  {
    if (prop->HasTranslucentPolygonalGeometry())
    {
      translucent.push_back(prop);
    }
  }
  return translucent;
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatter::Begin(vtkLightShaftFrame& frame)
{
  this->Target.PrepareDepth(frame);
  // The translucent surfaces in front of the opaque scene, as the camera sees them: what lies
  // behind them, shafts included, is dimmed by VTK's blending.
  frame.CameraLayerCount = this->CameraLayers.RenderCamera(frame,
    TranslucentProps(frame),
    frame.Scene.ShaftDepth,
    frame.Parameters.CameraLayers,
    frame.Renderer->GetActiveCamera());
  frame.CameraLayers = frame.CameraLayerCount > 0 ? this->CameraLayers.GetTexture() : nullptr;
  frame.Statistics.CameraLayers = frame.CameraLayerCount;
  frame.Statistics.CameraLayerBytes = this->CameraLayers.GetBytes();
  this->TargetCleared = false;
  this->TargetHolds = false;
  this->Pending = nullptr;
}

void vtkLightShaftInScatter::ClearTarget(vtkLightShaftFrame& frame, vtkLightShaftMethod* method)
{
  int buffers = 1;
  const vtkLightShaftResources::TextureKind kind =
    method->AccumulationKind(frame.Parameters, buffers);
  this->Target.Clear(frame, buffers, kind);
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatter::Add(vtkLightShaftFrame& frame, int method)
{
  vtkLightShaftMethod* computing = this->GetMethod(method);
  const bool direct = computing->AddsIntoTarget(frame);
  const vtkLightShaftGeometry::LitVolume lit =
    vtkLightShaftGeometry::ComputeLitVolume(frame.Light, frame.Camera);
  if (lit.Empty() || !frame.Light.Model.Radiates())
  {
    return; // the light's volume is outside the view, or the light is dark: nothing to do
  }
  if (this->Pending)
  {
    // The previous light's result lives in a buffer this light may write: sum it first.
    this->Target.AddToSum(frame, this->Pending);
    this->Pending = nullptr;
    this->TargetCleared = false;
  }
  if (!direct && this->TargetHolds)
  {
    // The lights added into the target so far go into the sum before it is cleared.
    this->Target.AddToSum(frame, this->Target.GetAccumulation(0));
    this->TargetHolds = false;
  }
  if (!direct || !this->TargetCleared)
  {
    // A light that does not add into the target computes into a cleared one; the first light
    // that does clears it once for all of them.
    this->ClearTarget(frame, computing);
    this->TargetCleared = direct;
  }
  vtkLightShaftLightStatistics& stats = *frame.LightStatistics;
  stats.Method = method;
  if (frame.Statistics.SliceDepthRange[1] <= frame.Statistics.SliceDepthRange[0])
  {
    frame.Statistics.SliceDepthRange[0] = lit.Nearest;
    frame.Statistics.SliceDepthRange[1] = lit.Deepest;
  }
  // Image pieces: the methods that compute each pixel on its own draw the piece's rows only.
  const bool perPixel = method == vtkLightShaftEnums::SLICES ||
                        method == vtkLightShaftEnums::RAY_MARCH ||
                        method == vtkLightShaftEnums::ANALYTIC;
  frame.ComputeRows = (perPixel && frame.Parameters.ImagePieces > 1) ? &frame.PieceRows : nullptr;
  vtkTextureObject* computed = computing->Render(frame, lit, this->Target);
  frame.ComputeRows = nullptr;
  if (frame.ShaderMethod)
  {
    this->ShaderMethod = frame.ShaderMethod;
    stats.ShaderVariant = frame.ShaderMethod->GetShaderVariant();
  }
  if (!computed)
  {
    return;
  }
  if (direct)
  {
    this->TargetHolds = true;
  }
  else
  {
    this->Pending = computed; // summed when another light comes (one light: never copied)
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkLightShaftInScatter::Sum(vtkLightShaftFrame& frame, bool& computed)
{
  vtkTextureObject* lights = nullptr;
  if (this->Pending && !this->Target.GetSum() && !this->TargetHolds)
  {
    lights = this->Pending; // one light's own result
  }
  else
  {
    if (this->Pending)
    {
      this->Target.AddToSum(frame, this->Pending);
    }
    if (this->Target.GetSum() && this->TargetHolds)
    {
      this->Target.AddToSum(frame, this->Target.GetAccumulation(0));
    }
    lights = this->Target.GetSum();
    if (!lights && this->TargetHolds)
    {
      lights = this->Target.GetAccumulation(0);
    }
  }
  this->Pending = nullptr;
  computed = lights != nullptr;
  if (!computed)
  {
    if (!this->TargetCleared)
    {
      this->ClearTarget(frame, &this->Slices); // zeros
    }
    return this->Target.GetAccumulation(0);
  }
  return lights;
}

vtkTextureObject* vtkLightShaftInScatter::PostProcess(vtkLightShaftFrame& frame,
  vtkTextureObject* lights)
{
  return this->Post.Render(frame, lights, this->Target.GetDepth(), frame.Scene.ShaftDepth);
}

//------------------------------------------------------------------------------
void vtkLightShaftInScatter::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Target.ReleaseGraphicsResources(window);
  this->Slabs.ReleaseGraphicsResources(window);
  const std::initializer_list<vtkLightShaftMethod*> methods = { &this->Slices,
    &this->RayMarch,
    &this->RadialBlur,
    &this->Analytic,
    &this->Epipolar,
    &this->LightVolume };
  for (vtkLightShaftMethod* method : methods)
  {
    method->ReleaseGraphicsResources(window);
  }
  this->Post.ReleaseGraphicsResources(window);
  this->CameraLayers.ReleaseGraphicsResources(window);
  this->ShaderMethod = nullptr;
}
