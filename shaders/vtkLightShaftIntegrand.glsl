// Shared by the slab vertex and fragment shaders: the light, the medium, and the smooth factors
// of the integrand (phase, spot, extinction), all in view coordinates (VC). The light's kind
// (LIGHTSHAFT_POINT, LIGHTSHAFT_DIRECTIONAL, else a spot) decides r, the direction the light
// travels and whether there is a spot factor.

//VTK::LightShaft::LightKind

uniform float spotExponent;
uniform vec3 attenuationCoefficients; // c0, c1, c2 (a directional light: 1, 0, 0)
uniform vec3 lightRadiantIntensity;   // intensity * colour
uniform vec3 sigmaS;
uniform vec3 sigmaT;

#ifdef LIGHTSHAFT_PHASE_HG
uniform float anisotropy;
#endif

const float PI = 3.14159265358979;

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

// The length scale of the equiangular variable u = atan(x / H) for a ray at distance h from the
// light: H^2 = h^2 + c0 / c2, so that A dt = du / (c2 H) is uniform in u when c1 = 0 (for pure
// inverse-square, H = h); h alone when c2 = 0. Kept away from 0 relative to the lit part
// [x0, x1].
float lightShaftAngleScale(float h2, float x0, float x1)
{
  float c2 = attenuationCoefficients.z;
  float scale2 = h2 + ((c2 > 0.0) ? attenuationCoefficients.x / c2 : 0.0);
  return max(sqrt(scale2), 1e-6 * max(abs(x0), abs(x1)) + 1e-30);
}

// The point of the ray originVC + t dirVC at integration variable u (x = t + b = u for constant
// A, h tan(u) for falling A), its light distance r, and the sine of its scattering angle.
// Returns the smooth factor there: phase * spot * exp(-sigma_t (r + t)) (phase * spot with a
// density field, whose extinction lightShaftSegment applies).
vec3 lightShaftNode(vec3 originVC, vec3 dirVC, float b, float h, bool constantA, float u,
  out vec3 pointVC, out float r, out float sinTheta)
{
  float x = constantA ? u : h * tan(u);
  float t = x - b;
  pointVC = originVC + t * dirVC;
  r = lightShaftLightDistance(pointVC);
  vec3 lightDir = lightShaftLightDirection(pointVC, r);
#if defined(LIGHTSHAFT_POINT) || defined(LIGHTSHAFT_DIRECTIONAL)
  float spot = 1.0;
#else
  float cosAxis = max(dot(lightDir, lightAxisVC), 0.0);
  float spot = (spotExponent == 0.0) ? 1.0 : pow(cosAxis, spotExponent);
#endif
  float cosTheta = -dot(dirVC, lightDir);
  sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
#ifdef LIGHTSHAFT_FIELD
  // (A medium from data: the extinction is the segment's, from the field: lightShaftSegment.)
  return vec3(lightShaftPhase(cosTheta) * spot);
#else
  return lightShaftPhase(cosTheta) * spot * exp(-sigmaT * (r + t));
#endif
}

// The A-weighted mean of the smooth factors over u in [u0, u1], with 3-point Gauss-Legendre in
// t (constant A) or in the equiangular angle phi, x = h tan(phi) (falling A; h from
// lightShaftAngleScale), where those factors stay smooth even when the ray passes close to the
// light. Also returns the middle
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
    // Relative weight of this node in the A-weighted mean: A dt/dphi with dt/dphi =
    // (h^2 + x^2) / h = (r^2 + c0 / c2) / h (lightShaftAngleScale; h cancels).
    float c2 = attenuationCoefficients.z;
    float a = constantA ? 1.0 :
      (r * r + ((c2 > 0.0) ? attenuationCoefficients.x / c2 : 0.0)) /
        (attenuationCoefficients.x + r * (attenuationCoefficients.y + c2 * r));
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
