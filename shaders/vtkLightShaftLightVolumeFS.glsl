//VTK::System::Dec
//VTK::Output::Dec

// LIGHT_VOLUME (Billeter, Sintorn and Assarsson 2010). With G(x) the unshadowed in-scatter
// from where a pixel's lit interval [x0, x1] starts to x (clamped to it), the shadowed part of
// the interval is the sum, over the points where the ray crosses the shadow volume's surface,
// of +G where it leaves the volume and -G where it enters, plus G(x1) if x1 is in shadow.
// Stages (LIGHTSHAFT_LIGHT_VOLUME_STAGE):
// 0. each crossing of the shadow volume's mesh (vtkLightShaftLightVolumeVS), added up: +-G(x)
//    in RGB for crossings inside the lit interval, +-1 in alpha for those beyond it. The alpha
//    sum is whether x1 is in shadow, an integer exact in float: the G(x1) terms of the
//    crossings beyond x1 (most of them, behind the surface) never enter the float sum, where
//    they would cancel each other only to rounding.
// 1. the resolve, over the lit volume's footprint: G(x1) (1 - shadowed at x1) - RGB.
// Without casters (no LIGHTSHAFT_SHADOW_VOLUME) stage 1 alone gives the unshadowed integral.
// Features (#defines): LIGHTSHAFT_PHASE_HG / _RAYLEIGH (else isotropic), the light's kind.
//VTK::LightShaft::Features

uniform float slabStart; // the lit depth range
uniform float slabEnd;
uniform float maximumSigmaT; // largest extinction coefficient (more pieces in thick media)

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
//VTK::LightShaft::Segment

// G(xEnd): the unshadowed in-scatter over [ray.x0, xEnd], in pieces as ANALYTIC integrates,
// as many as the extinction and the direction's change along it ask for.
vec3 lightVolumeUnshadowed(LightShaftRay ray, float xEnd)
{
  ray.x1 = xEnd;
  // Pieces: enough that the extinction across one stays below ~0.5, and (the phase and spot
  // factors vary with the direction from the light) that one spans at most 0.4 rad of it, less
  // for a spot whose exponent narrows its beam (cos^e falls to half within 1.2 / sqrt(e)).
  float pieces = 2.0 * maximumSigmaT * (ray.x1 - ray.x0);
#ifndef LIGHTSHAFT_DIRECTIONAL
  float h = lightShaftAngleScale(ray.h2, ray.x0, ray.x1);
  float span = 0.4;
#ifndef LIGHTSHAFT_POINT
  span /= 1.0 + sqrt(spotExponent);
#endif
  pieces = max(pieces, abs(atan(ray.x1, h) - atan(ray.x0, h)) / span);
#endif
  return lightShaftPieces(ray, clamp(int(ceil(pieces)), 1, 64));
}

#if LIGHTSHAFT_LIGHT_VOLUME_STAGE == 0
in vec3 crossingVC;

void main()
{
  float depth = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  LightShaftRay ray;
  if (!lightShaftLitIntervalAt(gl_FragCoord.xy, depth, slabStart, slabEnd, ray))
  {
    discard;
  }
  float x = dot(crossingVC - ray.originVC, ray.dirVC) + ray.b;
  if (x <= ray.x0)
  {
    discard; // G = 0
  }
  float leaving = gl_FrontFacing ? -1.0 : 1.0;
  gl_FragData[0] =
    (x >= ray.x1) ? vec4(0.0, 0.0, 0.0, leaving) : vec4(leaving * lightVolumeUnshadowed(ray, x), 0.0);
}
#else
#ifdef LIGHTSHAFT_SHADOW_VOLUME
uniform sampler2D lightVolumeCrossings;
#endif

void main()
{
  LightShaftRay ray;
  if (!lightShaftLitInterval(slabStart, slabEnd, ray))
  {
    discard;
  }
  vec3 radiance = lightVolumeUnshadowed(ray, ray.x1);
#ifdef LIGHTSHAFT_SHADOW_VOLUME
  vec4 crossings = texelFetch(lightVolumeCrossings, ivec2(gl_FragCoord.xy), 0);
  float shadowedAtEnd = clamp(round(crossings.a), 0.0, 1.0);
  radiance = max((1.0 - shadowedAtEnd) * radiance - crossings.rgb, vec3(0.0));
#endif
  gl_FragData[0] = vec4(radiance, 0.0);
}
#endif
