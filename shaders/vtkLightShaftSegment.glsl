// Shared by the slab fragment shaders of every method (slices, ray march, analytic): the
// in-scattered radiance of one segment of a pixel's view ray, with the light-space factors
// (shadow map, cookie, noise), and the pixel's lit interval. Features (#defines):
// LIGHTSHAFT_SHADOW, LIGHTSHAFT_COOKIE, LIGHTSHAFT_NOISE, LIGHTSHAFT_LATTICE,
// LIGHTSHAFT_CAMERA_LAYERS (the camera leg through translucent surfaces), LIGHTSHAFT_VOLUME
// (both legs through the scene's vtkVolume), the light's kind;
// code for a feature that is off is not compiled.
//VTK::LightShaft::LightSpace
//VTK::LightShaft::Field
//VTK::LightShaft::Volume

#ifdef LIGHTSHAFT_FIELD
// The optical depth of the view ray from its origin to the start of the segment being
// integrated (in density units: times sigma_t), advanced by lightShaftSegment.
float lightShaftOpticalDepthSoFar = 0.0;
// A share of a split setting's march integrates one piece of each longer span it steps over
// (lightShaftMarch): the span's parts before and after the piece, which it counts at the
// piece's density (0: the piece is its span).
float lightShaftFieldLead = 0.0;
float lightShaftFieldTrail = 0.0;
#endif

#ifdef LIGHTSHAFT_LATTICE
// The smooth factors' mean over this slab, evaluated at the lattice's vertices (Chen, Li and
// Wang) and interpolated; shadow, cookie and noise stay per pixel.
in vec3 latticeSmooth;
#endif

#ifdef LIGHTSHAFT_SHADOW
uniform float shadowBias; // the shadow map's depth tolerance for the shafts
#endif

// integral of dt / (c0 + c1 r + c2 r^2) for x = t + b in [x0, x1], r^2 = h2 + x^2.
float lightShaftAttenuationIntegral(float x0, float x1, float h2)
{
  float c0 = attenuationCoefficients.x;
  float c1 = attenuationCoefficients.y;
  float c2 = attenuationCoefficients.z;
  if (c1 == 0.0)
  {
    if (c2 == 0.0)
    {
      return (x1 - x0) / c0;
    }
    // (atan(s x1) - atan(s x0)) / sqrt(c2 k) with s = sqrt(c2 / k), k = c0 + c2 h^2, written
    // with atan2 so that it stays accurate as k -> 0 (ray through the light).
    float k = c0 + c2 * h2;
    float q = sqrt(c2 * k);
    float num = q * (x1 - x0);
    float den = k + c2 * x0 * x1;
    return (q > 1e-30) ? atan(num, den) / q : (x1 - x0) / den;
  }
  // General case: 4-point Gauss-Legendre in the equiangular variable phi, x = h tan(phi),
  // where dt = r^2 / h dphi keeps the integrand bounded near the light.
  float h = max(sqrt(h2), 1e-6 * max(abs(x0), abs(x1)) + 1e-30);
  float phi0 = atan(x0, h);
  float phi1 = atan(x1, h);
  float half_ = 0.5 * (phi1 - phi0);
  float mid = 0.5 * (phi1 + phi0);
  const vec4 nodes = vec4(-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
  const vec4 weights = vec4(0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451);
  float sum = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    float phi = mid + half_ * nodes[i];
    float r = h / cos(phi);
    sum += weights[i] * (r * r / h) / (c0 + c1 * r + c2 * r * r);
  }
  // (For a piece a few ulps long, float's atan can put phi1 an ulp below phi0: the integral of a
  // positive function is not negative. Measured: -2.9e-15 at a 179-degree view angle.)
  return max(sum * half_, 0.0);
}

// The in-scattered radiance over the piece x in [x0, x1] of the ray originVC + t dirVC, where
// x = t + b is measured from the foot of the perpendicular from the light (squared length h2)
// and the piece lies inside the cone and in front of the surface. Shadow, cookie and noise are
// looked up once, at the piece's (equiangular) midpoint (refining, elsewhere in the piece); a
// medium from data at the midpoint always.
#ifdef LIGHTSHAFT_REFINE
uniform float lookupFraction; // where in a piece (of u) its lookups are; 0.5: the midpoint
#endif

//VTK::LightShaft::CameraLayers

vec3 lightShaftSegment(vec3 originVC, vec3 dirVC, float b, float h2, float x0, float x1)
{
  // Product rule: the exact integral of A(r) over the segment times the A-weighted mean of the
  // smooth factors (phase, spot, extinction; lightShaftSmoothMean).
  float weight = lightShaftAttenuationIntegral(x0, x1, h2);
  bool constantA = attenuationCoefficients.y == 0.0 && attenuationCoefficients.z == 0.0;
  float h = lightShaftAngleScale(h2, x0, x1);
  float u0 = constantA ? x0 : atan(x0, h);
  float u1 = constantA ? x1 : atan(x1, h);
  vec3 sampleVC;
  float sampleR;
  float sampleSinTheta;
#ifdef LIGHTSHAFT_LATTICE
  vec3 smoothMean = latticeSmooth;
  lightShaftNode(originVC, dirVC, b, h, constantA, 0.5 * (u0 + u1), sampleVC, sampleR,
    sampleSinTheta);
#else
  vec3 smoothMean = lightShaftSmoothMean(originVC, dirVC, b, h, constantA, u0, u1, sampleVC,
    sampleR, sampleSinTheta);
#endif
#ifdef LIGHTSHAFT_FIELD
  // A medium from data is sampled at the midpoint in every estimate: its density is smooth
  // within a piece, where the midpoint rule is of second order and a lookup off the centre of
  // first (a dense plume's second estimate was then three times as far from the reference as
  // its first); refinement's shifted pieces move the midpoints.
  vec3 fieldVC = sampleVC;
  float fieldR = sampleR;
#endif
#ifdef LIGHTSHAFT_REFINE
  // Progressive refinement: each estimate looks up at another point of the piece (uniform in
  // u, where A dt is), so that the estimates' mean averages the shadow over the piece.
  lightShaftNode(originVC, dirVC, b, h, constantA, mix(u0, u1, lookupFraction), sampleVC,
    sampleR, sampleSinTheta);
#endif

  // Per-segment light-space factors, once, at the (equiangular) midpoint.
  float visibility = 1.0;
  vec3 modulation = vec3(1.0);
#ifdef LIGHTSHAFT_LIGHT_SPACE
  // The sample stands for a pixel-wide, segment-long footprint: its size in light-square widths
  // picks the mip level, so cookie and noise are pre-filtered instead of aliasing.
  float pieceLength = x1 - x0;
  float footprint = max(pixelFootprint.x * (-sampleVC.z) + pixelFootprint.y,
    pieceLength * sampleSinTheta);
  float footprintInSquares =
    footprint / max(lightSquareWidth.x * sampleR + lightSquareWidth.y, 1e-30);
#endif
#ifdef LIGHTSHAFT_SHADOW
  visibility = lightShaftVisibility(sampleVC, sampleR, shadowBias);
#endif
#ifdef LIGHTSHAFT_TRANSLUCENT
  modulation *= lightShaftTranslucency(sampleVC, sampleR, shadowBias);
#endif
#ifdef LIGHTSHAFT_CAMERA_LAYERS
  modulation *= lightShaftCameraLeg(b, x0, x1);
#endif
#ifdef LIGHTSHAFT_VOLUME
  modulation *= lightShaftVolumeLegs(originVC, dirVC, b, x0, x1, sampleVC);
#endif
#ifdef LIGHTSHAFT_COOKIE
  modulation *= lightShaftCookie(sampleVC, footprintInSquares);
#endif
#ifdef LIGHTSHAFT_NOISE
  modulation *= lightShaftNoiseDensity(sampleVC, footprintInSquares);
#endif

#ifdef LIGHTSHAFT_FIELD
  // A medium from data: sigma_s and sigma_t scale with the density at the sample; the
  // extinction is that of the view ray up to it (the depth so far plus half this segment's)
  // and of the light leg (to the light, or back to a directional light's plane).
  float density = lightShaftDensity(fieldVC);
  float segmentDepth = density * (x1 - x0);
  float lightLeg = lightShaftFieldLightLeg(fieldVC, fieldR);
  float depth =
    lightShaftOpticalDepthSoFar + density * lightShaftFieldLead + 0.5 * segmentDepth + lightLeg;
  lightShaftOpticalDepthSoFar +=
    segmentDepth + density * (lightShaftFieldLead + lightShaftFieldTrail);
  smoothMean *= density * exp(-sigmaT * depth);
#endif
  return sigmaS * lightRadiantIntensity * modulation * (weight * visibility) * smoothMean;
}

// Where the pieces of [x0, x1] start and end: uniform in x (constant A) or in the equiangular
// angle (falling A: the pieces shorten towards the light, where the integrand changes fastest).
float lightShaftPieceBoundary(float u0, float u1, float fraction, float h, bool constantA)
{
  float u = mix(u0, u1, clamp(fraction, 0.0, 1.0));
  return constantA ? u : h * tan(u);
}

// A pixel's view ray (origin, unit direction) and its lit part: x in [x0, x1], measured from
// the foot of the perpendicular from the light (b: that foot's ray parameter, h2: its squared
// distance to the light). Working relative to the foot keeps the cone quadratic's
// coefficients of the size of h, not of the eye-light distance: rays passing next to the apex
// stay accurate in float. A directional light has no apex: x = t (b = 0).
struct LightShaftRay
{
  vec3 originVC;
  vec3 dirVC;
  float b;
  float h2;
  float x0;
  float x1;
};

// The ray through `fragCoord` (target pixels) and the part of it between the view depths
// [nearDepth, farDepth] that the light reaches (lightShaftLightInterval) in front of the
// surface whose depth-buffer value is `depth`; false when that part is empty.
bool lightShaftLitIntervalAt(vec2 fragCoord, float depth, float nearDepth, float farDepth,
  out LightShaftRay ray)
{
  vec2 ndc;
  lightShaftViewRay(fragCoord, ray.originVC, ray.dirVC, ndc);
#ifdef LIGHTSHAFT_CAMERA_LAYERS
  lightShaftReadCameraLayers(ndc, ray.dirVC);
#endif
  float tPerDepth = -1.0 / ray.dirVC.z;
  float ta = nearDepth * tPerDepth;
  float tb = farDepth * tPerDepth;
  tb = min(tb, lightShaftSurfaceDistance(ndc, depth, ray.dirVC));
  vec3 foot;
  lightShaftRayFoot(ray.originVC, ray.dirVC, ray.b, foot);
  ray.h2 = dot(foot, foot);
  float litIn;
  float litOut;
  if (!lightShaftLightInterval(foot, ray.dirVC, litIn, litOut))
  {
    return false;
  }
  ray.x0 = max(ta + ray.b, litIn);
  ray.x1 = min(tb + ray.b, litOut);
#ifdef LIGHTSHAFT_VOLUME
  lightShaftVolumeStart(ray.originVC, ray.dirVC, ray.b, ray.x0);
#endif
  return ray.x1 > ray.x0;
}

// The pixel's ray and its lit part in front of the scene surface (lightShaftLitIntervalAt).
bool lightShaftLitInterval(float nearDepth, float farDepth, out LightShaftRay ray)
{
  float depth = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  return lightShaftLitIntervalAt(gl_FragCoord.xy, depth, nearDepth, farDepth, ray);
}

// The integration variable over a lit part [x0, x1]: u = x when A is constant, else the
// equiangular angle u = atan(x / h) (h from lightShaftAngleScale), from u0 to u1.
struct LightShaftVariable
{
  bool constantA;
  float h;
  float u0;
  float u1;
};

LightShaftVariable lightShaftVariable(LightShaftRay ray)
{
  LightShaftVariable v;
  v.constantA = attenuationCoefficients.y == 0.0 && attenuationCoefficients.z == 0.0;
  v.h = lightShaftAngleScale(ray.h2, ray.x0, ray.x1);
  v.u0 = v.constantA ? ray.x0 : atan(ray.x0, v.h);
  v.u1 = v.constantA ? ray.x1 : atan(ray.x1, v.h);
  return v;
}

// Boundary j of the ray's lit part marched in `steps` pieces (shorter towards the light when A
// falls off), shifted by `offset` of a piece: piece j spans [boundary j - 1, boundary j].
float lightShaftMarchBoundary(LightShaftRay ray, LightShaftVariable u, int j, int steps,
  float offset)
{
  if (j < 0)
  {
    return ray.x0;
  }
  if (j >= steps)
  {
    return ray.x1;
  }
  float x = lightShaftPieceBoundary(u.u0, u.u1, (float(j) + offset) / float(steps), u.h,
    u.constantA);
  return clamp(x, ray.x0, ray.x1);
}

// The ray's lit part marched in `steps` segments, one shadow-map lookup each; the boundaries
// shifted by `offset` of a step (1: none; the interleaved sampling of RAY_MARCH). Step j spans
// [j - 1 + offset, j + offset] steps, clamped. A split setting's share (`share` > 1) integrates
// steps part, part + share, ... only, each standing for the `share` steps of its span (times
// share): a group of shares, part 0 to share - 1, adds up to the whole march, piece for piece.
vec3 lightShaftMarch(LightShaftRay ray, int steps, float offset, int share, int part)
{
  LightShaftVariable u = lightShaftVariable(ray);
#ifdef LIGHTSHAFT_FIELD
  // The view ray's extinction before its lit part (the unlit medium still dims it).
  lightShaftOpticalDepthSoFar = lightShaftOpticalDepth(
    ray.originVC, ray.originVC + (ray.x0 - ray.b) * ray.dirVC);
#endif
  vec3 radiance = vec3(0.0);
  float xa = ray.x0; // (a share's pieces are not adjacent: each starts at its own boundary)
#ifdef LIGHTSHAFT_FIELD
  float spanStart = ray.x0;
#endif
  for (int first = 0; first <= steps; first += share)
  {
    int j = first + part;
    if (share > 1)
    {
      xa = lightShaftMarchBoundary(ray, u, j - 1, steps, offset);
    }
    float xb = j <= steps ? lightShaftMarchBoundary(ray, u, j, steps, offset) : xa;
#ifdef LIGHTSHAFT_FIELD
    if (share > 1)
    {
      // The span's medium before and after the piece, at the piece's density; an empty piece's
      // span still dims what lies behind it, at the density where it starts.
      float spanEnd = lightShaftMarchBoundary(ray, u, first + share - 1, steps, offset);
      if (xb > xa)
      {
        lightShaftFieldLead = xa - spanStart;
        lightShaftFieldTrail = spanEnd - xb;
      }
      else
      {
        lightShaftOpticalDepthSoFar += (spanEnd - spanStart) *
          lightShaftDensity(ray.originVC + (spanStart - ray.b) * ray.dirVC);
      }
      spanStart = spanEnd;
    }
#endif
    if (xb > xa)
    {
      radiance += lightShaftSegment(ray.originVC, ray.dirVC, ray.b, ray.h2, xa, xb);
    }
    xa = max(xa, xb); // (float's tan may step back an ulp: no piece is integrated twice)
  }
#ifdef LIGHTSHAFT_FIELD
  lightShaftFieldLead = 0.0;
  lightShaftFieldTrail = 0.0;
#endif
  return radiance * float(share);
}

// The ray's lit part integrated in `pieces` pieces (lightShaftSegment each, with the lookups
// the variant has; shorter towards the light when A falls off): ANALYTIC's integral, and
// LIGHT_VOLUME's up to a crossing.
vec3 lightShaftPieces(LightShaftRay ray, int pieces)
{
  LightShaftVariable u = lightShaftVariable(ray);
  vec3 radiance = vec3(0.0);
  float xa = ray.x0;
  for (int j = 1; j <= pieces; ++j)
  {
    float xb = (j == pieces) ? ray.x1 :
      lightShaftPieceBoundary(u.u0, u.u1, float(j) / float(pieces), u.h, u.constantA);
    radiance += lightShaftSegment(ray.originVC, ray.dirVC, ray.b, ray.h2, xa, xb);
    xa = xb;
  }
  return radiance;
}
