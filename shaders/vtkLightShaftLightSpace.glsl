// Shared by the slab fragment shaders and the surface-light pass: what a light does at a point
// besides the smooth factors, looked up in the light's own space: its shadow map's visibility,
// its cookie, and the density noise projected from it. Features (#defines): LIGHTSHAFT_SHADOW
// (with LIGHTSHAFT_TRANSLUCENT: the translucent casters' layers too), LIGHTSHAFT_COOKIE,
// LIGHTSHAFT_NOISE; the light's kind (LIGHTSHAFT_POINT,
// LIGHTSHAFT_DIRECTIONAL, else a spot); LIGHTSHAFT_SHADOW_VOLUME: only the map and its depths
// (LIGHT_VOLUME's mesh). Code for a feature that is off is not compiled.
#ifndef LIGHTSHAFT_LIGHT_SPACE_CHUNK
#define LIGHTSHAFT_LIGHT_SPACE_CHUNK

//VTK::LightShaft::LightKind

#if defined(LIGHTSHAFT_SHADOW) || defined(LIGHTSHAFT_COOKIE) || defined(LIGHTSHAFT_NOISE)
#define LIGHTSHAFT_LIGHT_SPACE
#endif

#ifdef LIGHTSHAFT_LIGHT_SPACE
uniform vec2 pixelFootprint;   // a pixel's width at view depth z: x * z + y (view units)
uniform vec2 lightSquareWidth; // the light's square's width at light distance r: x * r + y
#endif

#if defined(LIGHTSHAFT_COOKIE) || (defined(LIGHTSHAFT_NOISE) && !defined(LIGHTSHAFT_POINT))
uniform mat4 lightSquareFromVC; // VC -> the light's square as clip coordinates
// Where pointVC falls on the light's square, (0, 0) to (1, 1) across it (outside for a spot
// outside its square, repeating for a directional light's plane).
vec2 lightShaftSquareUV(vec3 pointVC)
{
  vec4 square = lightSquareFromVC * vec4(pointVC, 1.0);
  return 0.5 * square.xy / max(square.w, 1e-30) + 0.5;
}
#endif

#if defined(LIGHTSHAFT_POINT) && (defined(LIGHTSHAFT_SHADOW) || defined(LIGHTSHAFT_NOISE))
uniform mat3 worldFromVC; // the rotation from view to world coordinates
#endif

#if defined(LIGHTSHAFT_SHADOW) || defined(LIGHTSHAFT_SHADOW_VOLUME)
uniform sampler2D shadowMap;
uniform vec2 lightDepthRange; // near, far of the light camera(s)

// The distance along a perspective light camera's axis of a stored depth.
float lightShaftCasterDepth(float stored)
{
  float n = lightDepthRange.x;
  float f = lightDepthRange.y;
#ifdef LIGHTSHAFT_DIRECTIONAL
  return mix(n, f, stored); // orthographic: depth is linear
#else
  return 2.0 * n * f / ((f + n) - (2.0 * stored - 1.0) * (f - n));
#endif
}
#endif

#ifdef LIGHTSHAFT_SHADOW
#ifdef LIGHTSHAFT_POINT
uniform mat4 faceClipFromVC[6]; // VC -> each cube face's clip coordinates (+X -X +Y -Y +Z -Z)
uniform float shadowFaceSize;   // texels across a face (the atlas is 3 x 2 faces)
#else
uniform mat4 lightClipFromVC; // VC -> the light camera's clip coordinates
#endif

// Where pointVC (at light distance r) falls in the light's map: `uv` across the map (a point
// light's 3 x 2 atlas of cube faces: the texel nearest the direction, kept inside its face, so
// no seams between faces) and `w`, the depth the stored depths are compared with. False where
// the map does not reach (outside a spot's or directional light's square, behind a spot).
bool lightShaftMapPoint(vec3 pointVC, float r, out vec2 uv, out float w)
{
#if defined(LIGHTSHAFT_POINT)
  vec3 d = worldFromVC * (pointVC - lightPositionVC);
  vec3 a = abs(d);
  int face = (a.x >= a.y && a.x >= a.z) ? (d.x >= 0.0 ? 0 : 1) :
    ((a.y >= a.z) ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5));
  vec4 lightClip = faceClipFromVC[face] * vec4(pointVC, 1.0);
  vec2 faceUV = 0.5 * lightClip.xy / max(lightClip.w, 1e-30) + 0.5;
  float inset = 0.5 / shadowFaceSize;
  faceUV = clamp(faceUV, vec2(inset), vec2(1.0 - inset));
  uv = (vec2(float(face - 3 * (face / 3)), float(face / 3)) + faceUV) / vec2(3.0, 2.0);
  w = lightClip.w;
  return true;
#elif defined(LIGHTSHAFT_DIRECTIONAL)
  vec4 lightClip = lightClipFromVC * vec4(pointVC, 1.0);
  uv = 0.5 * lightClip.xy + 0.5;
  w = r;
  return all(lessThanEqual(abs(lightClip.xy), vec2(1.0)));
#else
  vec4 lightClip = lightClipFromVC * vec4(pointVC, 1.0);
  vec2 lightNDC = lightClip.xy / max(lightClip.w, 1e-30);
  uv = 0.5 * lightNDC + 0.5;
  w = lightClip.w;
  return lightClip.w > 0.0 && all(lessThanEqual(abs(lightNDC), vec2(1.0)));
#endif
}

// Whether depth w lies behind the stored depth (1: nothing stored), beyond the tolerance
// `bias`: relative (spot, point) or in world units (directional).
bool lightShaftBehind(float stored, float w, float bias)
{
#ifdef LIGHTSHAFT_DIRECTIONAL
  return stored < 1.0 && w > lightShaftCasterDepth(stored) + bias;
#else
  return stored < 1.0 && w > lightShaftCasterDepth(stored) * (1.0 + bias);
#endif
}

// 1 where pointVC (at light distance r) sees the light past the shadow map's casters, else 0.
float lightShaftVisibility(vec3 pointVC, float r, float bias)
{
  vec2 uv;
  float w;
  if (lightShaftMapPoint(pointVC, r, uv, w) &&
    lightShaftBehind(texture(shadowMap, uv).r, w, bias))
  {
    return 0.0;
  }
  return 1.0;
}

#ifdef LIGHTSHAFT_TRANSLUCENT
uniform sampler2D translucentLayers; // the layers side by side: rgb transmittance, a depth
uniform int translucentLayerCount;
uniform float translucentBiasScale; // the map's texels per layer texel (> 1: coarser layers)

// The light that reaches pointVC through the translucent casters' surfaces in front of it,
// per channel: the product of the transmittance of each layer (nearest first) that it lies
// behind. (Opaque casters: lightShaftVisibility.)
vec3 lightShaftTranslucency(vec3 pointVC, float r, float bias)
{
  vec2 uv;
  float w;
  vec3 transmittance = vec3(1.0);
  if (lightShaftMapPoint(pointVC, r, uv, w))
  {
    float layers = float(translucentLayerCount);
    for (int k = 0; k < translucentLayerCount; ++k)
    {
      vec4 layer = texture(translucentLayers, vec2((uv.x + float(k)) / layers, uv.y));
      if (!lightShaftBehind(layer.a, w, bias * translucentBiasScale))
      {
        break; // the layers are sorted by depth: none further is in front
      }
      transmittance *= layer.rgb;
    }
  }
  return transmittance;
}
#endif
#endif

#ifdef LIGHTSHAFT_COOKIE
uniform sampler2D cookieTexture;
uniform float cookieSize; // texels across the light's square

// The cookie's colour at pointVC, pre-filtered over a footprint of `footprintInSquares`
// light-square widths (its mip level), so that it does not alias.
vec3 lightShaftCookie(vec3 pointVC, float footprintInSquares)
{
  return max(textureLod(cookieTexture, lightShaftSquareUV(pointVC),
    max(log2(footprintInSquares * cookieSize), 0.0)).rgb, vec3(0.0));
}
#endif

#ifdef LIGHTSHAFT_NOISE
uniform sampler2D noiseTexture;
uniform float noiseSize;      // texels across one tile
uniform float noiseAmplitude;
uniform float noiseScale;     // tiles across the light's square (layer 1; layer 2 is 1.37x)
uniform vec4 noiseShift;      // both layers' scroll offsets at the current time, in tiles

// The two layers' product at square coordinates uv, at mip level `lod` (layer 2 a little
// coarser, as it is 1.37 times denser).
float lightShaftNoiseLayers(vec2 uv, float lod)
{
  float n1 = textureLod(noiseTexture, uv * noiseScale + noiseShift.xy, lod).r;
  float n2 = textureLod(noiseTexture, uv * (1.37 * noiseScale) + noiseShift.zw, lod + 0.45).r;
  return n1 * n2;
}

// The density factor 1 + amplitude (n1 n2 - 1) at pointVC. A point light projects the noise on
// the planes across its unit sphere of directions, blended by the direction (triplanar: no
// seams).
float lightShaftNoiseDensity(vec3 pointVC, float footprintInSquares)
{
  float lod = max(log2(footprintInSquares * noiseScale * noiseSize), 0.0);
#ifdef LIGHTSHAFT_POINT
  vec3 d = normalize(worldFromVC * (pointVC - lightPositionVC));
  vec3 d2 = d * d;
  vec3 w = d2 * d2 / max(dot(d2, d2), 1e-30);
  float layers = w.x * lightShaftNoiseLayers(0.5 * d.yz + 0.5, lod) +
    w.y * lightShaftNoiseLayers(0.5 * d.zx + 0.5, lod) +
    w.z * lightShaftNoiseLayers(0.5 * d.xy + 0.5, lod);
#else
  float layers = lightShaftNoiseLayers(lightShaftSquareUV(pointVC), lod);
#endif
  return 1.0 + noiseAmplitude * (layers - 1.0);
}
#endif

#endif
