// Shared by the slab fragment shaders when the medium comes from data (LIGHTSHAFT_FIELD): the
// density rho(x) of vtkLightShaftMedium::SetDensityField, a 3D texture (trilinear, clamped to
// its edge, as vtkLightShaftDensityField's rule), and its integral along a segment for the
// extinction of both legs. Without the feature nothing here is compiled.
#ifdef LIGHTSHAFT_FIELD
uniform sampler3D densityTexture;
uniform mat4 densityTCFromVC;  // view coordinates to the texture's coordinates
uniform vec3 densityLowTC;     // the field's bounds in texture coordinates (0 outside)
uniform vec3 densityHighTC;
uniform float densityScale;    // MediumDensityScale
uniform float densityBackground; // MediumBackgroundDensity
uniform int densitySteps;      // samples of an optical depth (the light leg, the eye's leg)

vec3 lightShaftDensityTC(vec3 pointVC)
{
  return (densityTCFromVC * vec4(pointVC, 1.0)).xyz;
}

// Background + scale * rho at pointVC.
float lightShaftDensity(vec3 pointVC)
{
  vec3 tc = lightShaftDensityTC(pointVC);
  bool inside = all(greaterThanEqual(tc, densityLowTC)) && all(lessThanEqual(tc, densityHighTC));
  return densityBackground + (inside ? densityScale * texture(densityTexture, tc).r : 0.0);
}

// The integral of the density along aVC -> bVC: the background over the whole length, rho by
// densitySteps midpoint samples over the part inside the field's bounds.
float lightShaftOpticalDepth(vec3 aVC, vec3 bVC)
{
  float len = length(bVC - aVC);
  vec3 ta = lightShaftDensityTC(aVC);
  vec3 delta = lightShaftDensityTC(bVC) - ta;
  // The segment's parameters s in [s0, s1] inside the box (slab test, per axis).
  float s0 = 0.0;
  float s1 = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    if (abs(delta[k]) < 1e-30)
    {
      if (ta[k] < densityLowTC[k] || ta[k] > densityHighTC[k])
      {
        s1 = -1.0;
      }
      continue;
    }
    float enter = (densityLowTC[k] - ta[k]) / delta[k];
    float leave = (densityHighTC[k] - ta[k]) / delta[k];
    s0 = max(s0, min(enter, leave));
    s1 = min(s1, max(enter, leave));
  }
  float inside = 0.0;
  if (s1 > s0)
  {
    float ds = (s1 - s0) / float(densitySteps);
    for (int i = 0; i < densitySteps; ++i)
    {
      inside += texture(densityTexture, ta + (s0 + (float(i) + 0.5) * ds) * delta).r;
    }
    inside *= ds;
  }
  return len * (densityBackground + densityScale * inside);
}
#endif

#if defined(LIGHTSHAFT_FIELD_SHADOW) || defined(LIGHTSHAFT_VOLUME) || defined(LIGHTSHAFT_VOLUME_SHADOW)
#ifndef LIGHTSHAFT_TABLE_CHUNK
#define LIGHTSHAFT_TABLE_CHUNK
// A light leg precomputed per light (vtkLightShaftFieldTableTexture): the integral of a field from
// the light to the point, tabulated in the light's frame. One face (orthographic for a
// directional light, else perspective) or six (a cube around the light, world-axis aligned).
struct LightShaftTable
{
  mat4 fromVC;  // view coordinates to the face's frame (the cube's: world axes)
  int faces;    // 1 or 6
  vec3 scale;   // (u, v, w) to texture coordinates: offset + scale * (u, v, w)
  vec3 offset;
  vec4 lateral; // a single face's (u, v) range: rays outside it miss the field
  float lateralTexels; // texels along u (and v) per face
  float depth;         // texels along w
};

float lightShaftTableLookup(sampler3D table, LightShaftTable t, vec3 pointVC)
{
  vec3 q = (t.fromVC * vec4(pointVC, 1.0)).xyz;
  vec3 uvw;
  float face = 0.0;
  if (t.faces == 6)
  {
    vec3 a = abs(q);
    int k = (a.x >= a.y && a.x >= a.z) ? 0 : ((a.y >= a.z) ? 1 : 2);
    float major = max(a[k], 1e-30);
    uvw = vec3(q[(k + 1) % 3] / major, q[(k + 2) % 3] / major, length(q));
    face = float(2 * k + ((q[k] < 0.0) ? 1 : 0));
  }
  else
  {
#ifdef LIGHTSHAFT_DIRECTIONAL
    uvw = q;
#else
    if (q.z <= 0.0)
    {
      return 0.0;
    }
    uvw = vec3(q.xy / q.z, length(q));
#endif
    if (any(lessThan(uvw.xy, t.lateral.xy)) || any(greaterThan(uvw.xy, t.lateral.zw)))
    {
      return 0.0;
    }
  }
  vec3 tc = t.offset + t.scale * uvw;
  // The faces lie side by side along x: within the face's own texels. Before the first depth
  // texel centre tau is 0 (the field starts later), past the last it stays the box's total.
  tc.x = (clamp(tc.x, 0.5 / t.lateralTexels, 1.0 - 0.5 / t.lateralTexels) + face) /
    float(t.faces);
  tc.z = clamp(tc.z, 0.5 / t.depth, 1.0 - 0.5 / t.depth);
  return texture(table, tc).r;
}
#endif
#endif

#ifdef LIGHTSHAFT_FIELD_SHADOW
// The light leg's field part: the integral of rho from the light to the point.
uniform sampler3D fieldShadowTexture;
uniform LightShaftTable fieldShadow;

float lightShaftFieldShadow(vec3 pointVC)
{
  return lightShaftTableLookup(fieldShadowTexture, fieldShadow, pointVC);
}
#endif

#if defined(LIGHTSHAFT_FIELD) && defined(LIGHTSHAFT_LIGHT_CHUNK)
// The light leg's optical depth through the medium (in units of sigma_t) from the light to
// pointVC, at light distance r: to a spot or point light, or back to a directional light's
// plane. The background over its length and the field's part from the light's table
// (LIGHTSHAFT_FIELD_SHADOW), else marched. The shafts' and the surfaces' light leg.
float lightShaftFieldLightLeg(vec3 pointVC, float r)
{
  float leg = max(r, 0.0);
#ifdef LIGHTSHAFT_FIELD_SHADOW
  return densityBackground * leg + densityScale * lightShaftFieldShadow(pointVC);
#else
#ifdef LIGHTSHAFT_DIRECTIONAL
  vec3 sourceVC = pointVC - leg * lightAxisVC;
#else
  vec3 sourceVC = lightPositionVC;
#endif
  return lightShaftOpticalDepth(pointVC, sourceVC);
#endif
}
#endif
