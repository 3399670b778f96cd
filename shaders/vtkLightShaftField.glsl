// Shared by the slab fragment shaders when the medium comes from data (LIGHTSHAFT_FIELD): the
// density rho(x) of vtkLightShaftPass::SetMediumDensity, a 3D texture (trilinear, clamped to
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
