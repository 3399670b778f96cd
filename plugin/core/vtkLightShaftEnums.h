/**
 * @file   vtkLightShaftEnums.h
 * @brief  The values every layer shares: the methods, the accumulation precisions, the events
 *         the pass invokes and the methods' names (private, not installed).
 *
 * The bottom of the include graph: the components and the models compare a frame's values with
 * these, and none includes vtkLightShaftPass.h for them. The pass keeps its public enums (the
 * wrappers read them there), equal to these by static_assert (vtkLightShaftPass.cxx).
 */
#ifndef vtkLightShaftEnums_h
#define vtkLightShaftEnums_h

#include "vtkCommand.h" // For vtkCommand::UserEvent

namespace vtkLightShaftEnums
{
/// How the in-scattered radiance is computed (vtkLightShaftPass::MethodType).
enum Method
{
  SLICES = 0,
  RAY_MARCH = 1,
  RADIAL_BLUR = 2,
  ANALYTIC = 3,
  AUTOMATIC = 4,
  EPIPOLAR = 5,
  LIGHT_VOLUME = 6
};

/// The buffer the slabs add up in (vtkLightShaftPass::AccumulationPrecisionType).
enum AccumulationPrecision
{
  ACCUMULATE_FLOAT32 = 0,
  ACCUMULATE_FLOAT16 = 1,
  ACCUMULATE_8BIT = 2
};

/// The events the pass invokes (vtkLightShaftPass::EventIds).
enum Event
{
  ShadowMapRenderedEvent = vtkCommand::UserEvent + 4301,
  RefinementNeededEvent = vtkCommand::UserEvent + 4302,
  SceneDepthReadyEvent = vtkCommand::UserEvent + 4303,
  InScatterPieceEvent = vtkCommand::UserEvent + 4304,
  ShadowMapReuseEvent = vtkCommand::UserEvent + 4305,
  FrameTimedEvent = vtkCommand::UserEvent + 4306
};

/// A method's name ("slices", "ray-march", ...; "none" for any other value).
inline const char* MethodName(int method)
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
    case EPIPOLAR:
      return "epipolar";
    case LIGHT_VOLUME:
      return "light-volume";
    default:
      return "none";
  }
}
}

#endif
