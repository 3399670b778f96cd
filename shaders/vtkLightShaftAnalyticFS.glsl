//VTK::System::Dec
//VTK::Output::Dec

// ANALYTIC (and RADIAL_BLUR's unshadowed base): one slab spans the lit depth range; nothing
// occludes, so the integrand is smooth over each pixel's whole lit interval, integrated in
// pieces fine enough for float precision. Features (#defines): LIGHTSHAFT_ANALYTIC,
// LIGHTSHAFT_PHASE_HG / _RAYLEIGH (else isotropic), LIGHTSHAFT_COOKIE, LIGHTSHAFT_NOISE.
//VTK::LightShaft::Features

uniform float slabStart; // the lit depth range
uniform float slabEnd;
uniform int analyticPieces;  // pieces of the lit interval at least
uniform float maximumSigmaT; // largest extinction coefficient (more pieces in thick media)

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
//VTK::LightShaft::Segment

void main()
{
  LightShaftRay ray;
  if (!lightShaftLitInterval(slabStart, slabEnd, ray))
  {
    discard;
  }
  // 3-point Gauss-Legendre per piece (lightShaftSegment), with enough pieces that the
  // extinction across a piece stays below ~0.5 (float precision for the smooth factors).
  int pieces =
    clamp(max(analyticPieces, int(ceil(2.0 * maximumSigmaT * (ray.x1 - ray.x0)))), 1, 64);
  vec3 radiance = lightShaftPieces(ray, pieces);
  // Alpha: the light distance at the lit interval's (equiangular) middle, which the radial
  // blur compares its occluders with.
  LightShaftVariable u = lightShaftVariable(ray);
  float xMiddle = lightShaftPieceBoundary(u.u0, u.u1, 0.5, u.h, u.constantA);
  gl_FragData[0] = vec4(radiance, sqrt(ray.h2 + xMiddle * xMiddle));
}
