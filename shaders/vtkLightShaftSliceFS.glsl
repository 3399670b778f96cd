//VTK::System::Dec
//VTK::Output::Dec

// One slab of the pixel's view ray: integrates the in-scattered radiance
//   sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t (r + t)) dt
// over the part of the slab that lies inside the spot cone and in front of the scene surface.
// A(r) = 1 / (c0 + c1 r + c2 r^2) is integrated in closed form (c1 = 0) or by Gauss-Legendre
// in the equiangular variable; the remaining factors are evaluated at the segment's
// equiangular midpoint (the arithmetic midpoint when A is constant).

flat in vec2 slabDepths;

//VTK::LightShaft::Common

uniform vec3 lightPositionVC;
uniform vec3 lightAxisVC;      // unit spot direction
uniform float cosConeAngle;    // cos of the cone half-angle
uniform float spotExponent;
uniform vec3 attenuationCoefficients; // c0, c1, c2
uniform vec3 lightRadiantIntensity;   // intensity * colour
uniform vec3 sigmaS;
uniform vec3 sigmaT;

//VTK::LightShaft::PhaseDec

//VTK::LightShaft::ShadowDec

const float PI = 3.14159265358979;

// The parameter interval of the line m + t dir (m relative to the apex) inside the spot cone's forward nappe.
// The nappe is convex (half-angle < 90 degrees), so the intersection is one interval.
bool lightShaftConeInterval(vec3 m, vec3 dir, out float t0, out float t1)
{
  float c2 = cosConeAngle * cosConeAngle;
  float da = dot(dir, lightAxisVC);
  float ma = dot(m, lightAxisVC);
  float lo = -3.0e38;
  float hi = 3.0e38;
  // Forward half-space: (m + t dir) . axis >= 0.
  if (abs(da) > 1e-12)
  {
    float tPlane = -ma / da;
    if (da > 0.0)
    {
      lo = tPlane;
    }
    else
    {
      hi = tPlane;
    }
  }
  else if (ma < 0.0)
  {
    return false;
  }
  // Double cone: A t^2 + B t + C >= 0.
  float qa = da * da - c2;
  float qb = 2.0 * (da * ma - c2 * dot(dir, m));
  float qc = ma * ma - c2 * dot(m, m);
  if (abs(qa) < 1e-7)
  {
    if (abs(qb) > 1e-30)
    {
      float tLine = -qc / qb;
      if (qb > 0.0)
      {
        lo = max(lo, tLine);
      }
      else
      {
        hi = min(hi, tLine);
      }
    }
    else if (qc < 0.0)
    {
      return false;
    }
  }
  else
  {
    float disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0)
    {
      if (qa < 0.0)
      {
        return false;
      }
    }
    else
    {
      float q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      float rootA = q / qa;
      float rootB = (q != 0.0) ? qc / q : rootA;
      float tIn = min(rootA, rootB);
      float tOut = max(rootA, rootB);
      if (qa < 0.0)
      {
        lo = max(lo, tIn);
        hi = min(hi, tOut);
      }
      else
      {
        // Outside [tIn, tOut]: keep the piece on the forward nappe's side.
        bool before = lo <= tIn;
        bool after = hi >= tOut;
        if (before && !after)
        {
          hi = min(hi, tIn);
        }
        else if (after && !before)
        {
          lo = max(lo, tOut);
        }
        else if (!before && !after)
        {
          return false;
        }
        else if (ma + 0.5 * (lo + tIn) * da >= 0.0 && tIn - lo >= hi - tOut)
        {
          hi = min(hi, tIn);
        }
        else
        {
          lo = max(lo, tOut);
        }
      }
    }
  }
  t0 = lo;
  t1 = hi;
  return t1 > t0;
}

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
  return sum * half_;
}

void main()
{
  vec3 originVC;
  vec3 dirVC;
  vec2 ndc;
  lightShaftViewRay(gl_FragCoord.xy, originVC, dirVC, ndc);

  // The slab [near, far] in view depth, as ray parameters; cut at the scene surface.
  float tPerDepth = -1.0 / dirVC.z;
  float ta = slabDepths.x * tPerDepth;
  float tb = slabDepths.y * tPerDepth;
  float depth = texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  tb = min(tb, lightShaftSurfaceDistance(ndc, depth, dirVC));

  // Work relative to the foot of the perpendicular from the light to the ray, x = t + b:
  // the cone quadratic then has coefficients of the size of h, not of the eye-light distance,
  // which keeps rays passing next to the apex accurate in float.
  vec3 m = originVC - lightPositionVC;
  float b = dot(m, dirVC);
  vec3 foot = m - b * dirVC;
  float h2 = dot(foot, foot);
  float coneIn;
  float coneOut;
  if (!lightShaftConeInterval(foot, dirVC, coneIn, coneOut))
  {
    discard;
  }
  float x0 = max(ta + b, coneIn);
  float x1 = min(tb + b, coneOut);
  if (x1 <= x0)
  {
    discard;
  }

  // Product rule: the exact integral of A(r) over the segment times the A-weighted mean of the
  // smooth factors (phase, spot, extinction), the mean taken with 3-point Gauss-Legendre in
  // t (constant A) or in the equiangular angle phi, x = h tan(phi) (falling A), where those
  // factors are smooth even when the ray passes close to the light.
  float weight = lightShaftAttenuationIntegral(x0, x1, h2);
  bool constantA = attenuationCoefficients.y == 0.0 && attenuationCoefficients.z == 0.0;
  float h = max(sqrt(h2), 1e-6 * max(abs(x0), abs(x1)) + 1e-30);
  float u0 = constantA ? x0 : atan(x0, h);
  float u1 = constantA ? x1 : atan(x1, h);
  float uMid = 0.5 * (u0 + u1);
  float uHalf = 0.5 * (u1 - u0);
  const vec3 nodes = vec3(-0.7745966692, 0.0, 0.7745966692);
  const vec3 nodeWeights = vec3(0.5555555556, 0.8888888889, 0.5555555556);
  vec3 smoothSum = vec3(0.0);
  float weightSum = 0.0;
  vec3 sampleVC = originVC;
  for (int i = 0; i < 3; ++i)
  {
    float u = uMid + uHalf * nodes[i];
    float x = constantA ? u : h * tan(u);
    float t = x - b;
    vec3 pointVC = originVC + t * dirVC;
    vec3 toPoint = pointVC - lightPositionVC;
    float r = length(toPoint);
    vec3 lightDir = toPoint / max(r, 1e-30);
    float cosAxis = max(dot(lightDir, lightAxisVC), 0.0);
    float spot = (spotExponent == 0.0) ? 1.0 : pow(cosAxis, spotExponent);
    float cosTheta = -dot(dirVC, lightDir);
    float phase;
    //VTK::LightShaft::PhaseImpl
    // Relative weight of this node in the A-weighted mean (dt/dphi = r^2 / h, h cancels).
    float a = constantA ? 1.0 :
      r * r / (attenuationCoefficients.x + r * (attenuationCoefficients.y +
        attenuationCoefficients.z * r));
    smoothSum += nodeWeights[i] * a * phase * spot * exp(-sigmaT * (r + t));
    weightSum += nodeWeights[i] * a;
    if (i == 1)
    {
      sampleVC = pointVC;
    }
  }

  // Visibility once per segment, at its (equiangular) midpoint.
  float visibility = 1.0;
  //VTK::LightShaft::ShadowImpl

  vec3 radiance = sigmaS * lightRadiantIntensity * (weight * visibility / max(weightSum, 1e-30)) *
    smoothSum;
  gl_FragData[0] = vec4(radiance, 0.0);
}
