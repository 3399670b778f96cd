// Shared by the slab vertex and fragment shaders: the light, the medium, and the smooth factors
// of the integrand (phase, spot, extinction), all in view coordinates (VC).

uniform vec3 lightPositionVC;
uniform vec3 lightAxisVC;      // unit spot direction
uniform float cosConeAngle;    // cos of the cone half-angle
uniform float spotExponent;
uniform vec3 attenuationCoefficients; // c0, c1, c2
uniform vec3 lightRadiantIntensity;   // intensity * colour
uniform vec3 sigmaS;
uniform vec3 sigmaT;

#ifdef LIGHTSHAFT_PHASE_HG
uniform float anisotropy;
#endif

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

float lightShaftPhase(float cosTheta)
{
#if defined(LIGHTSHAFT_PHASE_HG)
  float hgDenominator = 1.0 + anisotropy * anisotropy - 2.0 * anisotropy * cosTheta;
  return (1.0 - anisotropy * anisotropy) / (4.0 * PI * hgDenominator * sqrt(hgDenominator));
#elif defined(LIGHTSHAFT_PHASE_RAYLEIGH)
  return 3.0 / (16.0 * PI) * (1.0 + cosTheta * cosTheta);
#else
  return 1.0 / (4.0 * PI);
#endif
}

// The point of the ray originVC + t dirVC at integration variable u (x = t + b = u for constant
// A, h tan(u) for falling A), its distance to the light, and the sine of its scattering angle.
// Returns the smooth factor there: phase * spot * exp(-sigma_t (r + t)).
vec3 lightShaftNode(vec3 originVC, vec3 dirVC, float b, float h, bool constantA, float u,
  out vec3 pointVC, out float r, out float sinTheta)
{
  float x = constantA ? u : h * tan(u);
  float t = x - b;
  pointVC = originVC + t * dirVC;
  vec3 toPoint = pointVC - lightPositionVC;
  r = length(toPoint);
  vec3 lightDir = toPoint / max(r, 1e-30);
  float cosAxis = max(dot(lightDir, lightAxisVC), 0.0);
  float spot = (spotExponent == 0.0) ? 1.0 : pow(cosAxis, spotExponent);
  float cosTheta = -dot(dirVC, lightDir);
  sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  return lightShaftPhase(cosTheta) * spot * exp(-sigmaT * (r + t));
}

// The A-weighted mean of the smooth factors over u in [u0, u1], with 3-point Gauss-Legendre in
// t (constant A) or in the equiangular angle phi, x = h tan(phi) (falling A), where those
// factors stay smooth even when the ray passes close to the light. Also returns the middle
// node (the segment's equiangular midpoint).
vec3 lightShaftSmoothMean(vec3 originVC, vec3 dirVC, float b, float h, bool constantA, float u0,
  float u1, out vec3 middleVC, out float middleR, out float middleSinTheta)
{
  float uMid = 0.5 * (u0 + u1);
  float uHalf = 0.5 * (u1 - u0);
  const vec3 nodes = vec3(-0.7745966692, 0.0, 0.7745966692);
  const vec3 nodeWeights = vec3(0.5555555556, 0.8888888889, 0.5555555556);
  vec3 smoothSum = vec3(0.0);
  float weightSum = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    vec3 pointVC;
    float r;
    float sinTheta;
    vec3 factors =
      lightShaftNode(originVC, dirVC, b, h, constantA, uMid + uHalf * nodes[i], pointVC, r,
        sinTheta);
    // Relative weight of this node in the A-weighted mean (dt/dphi = r^2 / h, h cancels).
    float a = constantA ? 1.0 :
      r * r / (attenuationCoefficients.x + r * (attenuationCoefficients.y +
        attenuationCoefficients.z * r));
    smoothSum += nodeWeights[i] * a * factors;
    weightSum += nodeWeights[i] * a;
    if (i == 1)
    {
      middleVC = pointVC;
      middleR = r;
      middleSinTheta = sinTheta;
    }
  }
  return smoothSum / max(weightSum, 1e-30);
}
