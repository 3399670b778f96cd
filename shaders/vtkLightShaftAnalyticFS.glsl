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
  vec3 originVC;
  vec3 dirVC;
  float b;
  float h2;
  float x0;
  float x1;
  if (!lightShaftLitInterval(slabStart, slabEnd, originVC, dirVC, b, h2, x0, x1))
  {
    discard;
  }
  bool constantA = attenuationCoefficients.y == 0.0 && attenuationCoefficients.z == 0.0;
  float h = max(sqrt(h2), 1e-6 * max(abs(x0), abs(x1)) + 1e-30);
  float u0 = constantA ? x0 : atan(x0, h);
  float u1 = constantA ? x1 : atan(x1, h);
  vec3 radiance = vec3(0.0);

  // 3-point Gauss-Legendre per piece (lightShaftSegment), with enough pieces that the
  // extinction across a piece stays below ~0.5 (float precision for the smooth factors).
  int pieces = clamp(max(analyticPieces, int(ceil(2.0 * maximumSigmaT * (x1 - x0)))), 1, 64);
  float xa = x0;
  for (int j = 1; j <= pieces; ++j)
  {
    float xb = (j == pieces) ? x1 :
      lightShaftPieceBoundary(u0, u1, float(j) / float(pieces), h, constantA);
    radiance += lightShaftSegment(originVC, dirVC, b, h2, xa, xb);
    xa = xb;
  }
  // Alpha: the light distance at the lit interval's (equiangular) middle, which the radial
  // blur compares its occluders with.
  float xMiddle = lightShaftPieceBoundary(u0, u1, 0.5, h, constantA);
  gl_FragData[0] = vec4(radiance, sqrt(h2 + xMiddle * xMiddle));
}
