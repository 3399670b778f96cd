//VTK::System::Dec
//VTK::Output::Dec

// SLICES: one fragment of slab slabIndex integrates the pixel's view ray over the slab (its
// view-depth interval), cut at the cone and the scene surface. Features (#defines):
// LIGHTSHAFT_PHASE_HG / _RAYLEIGH (else isotropic), LIGHTSHAFT_SHADOW, LIGHTSHAFT_COOKIE,
// LIGHTSHAFT_NOISE, LIGHTSHAFT_LATTICE, LIGHTSHAFT_JITTER, LIGHTSHAFT_ACCUMULATE_8BIT,
// LIGHTSHAFT_FIELD (and _FIELD_SHADOW).
//VTK::LightShaft::Features

flat in float slabIndex;

// Slab k spans view depths [slabStart + k * slabThickness, + slabThickness], within
// [slabStart, slabEnd]; with jitter each pixel shifts the boundaries by its own fraction.
uniform float slabStart;
uniform float slabEnd;
uniform float slabThickness;
uniform float lastSlab;
uniform float samplingRotation; // in [0, 1): progressive refinement's shift of the offsets
uniform float sampleWeight; // the slabs each drawn slab stands for (a split setting's share)

#ifdef LIGHTSHAFT_ACCUMULATE_8BIT
uniform float accumulationScale; // Exposure: the talk's buffers hold displayed values
#endif

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
//VTK::LightShaft::Segment

void main()
{
  float slabOffset = 0.0;
#ifdef LIGHTSHAFT_JITTER
  // 4x4 ordered (Bayer) offsets: neighbouring pixels sample between each other's boundaries.
  ivec2 cell = ivec2(gl_FragCoord.xy) & 3;
  const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0,
    9.0, 15.0, 7.0, 13.0, 5.0);
  // Refinement's estimates shift every pixel's offset by the same fraction of a slab (0:
  // unchanged), so that each pixel's boundaries visit the whole slab over the estimates.
  slabOffset = fract((bayer[cell.y * 4 + cell.x] + 0.5) / 16.0 + samplingRotation) - 1.0;
#endif
  // Neighbouring slabs compute their shared boundary with the same expression: no gap.
  float nearDepth =
    clamp(slabStart + (slabIndex + slabOffset) * slabThickness, slabStart, slabEnd);
  float farDepth = (slabIndex == lastSlab) ? slabEnd :
    clamp(slabStart + (slabIndex + 1.0 + slabOffset) * slabThickness, slabStart, slabEnd);
  LightShaftRay ray;
  if (!lightShaftLitInterval(nearDepth, farDepth, ray))
  {
    discard;
  }
#ifdef LIGHTSHAFT_FIELD
  // A medium from data: the view ray's extinction up to this slab (each slab is its own
  // fragment: no running sum as RAY_MARCH's), the light leg's in lightShaftSegment.
  lightShaftOpticalDepthSoFar =
    lightShaftOpticalDepth(ray.originVC, ray.originVC + (ray.x0 - ray.b) * ray.dirVC);
#endif
  vec3 radiance =
    sampleWeight * lightShaftSegment(ray.originVC, ray.dirVC, ray.b, ray.h2, ray.x0, ray.x1);

#ifdef LIGHTSHAFT_ACCUMULATE_8BIT
  // The talk's trick: slab k adds into channel k mod 4 (one RGBA8 buffer per colour).
  int channel = int(mod(slabIndex + 4.0, 4.0));
  vec4 mask = vec4(equal(ivec4(channel), ivec4(0, 1, 2, 3)));
  vec3 displayed = accumulationScale * radiance;
  gl_FragData[0] = displayed.r * mask;
  gl_FragData[1] = displayed.g * mask;
  gl_FragData[2] = displayed.b * mask;
#else
  gl_FragData[0] = vec4(radiance, 0.0);
#endif
}
