//VTK::System::Dec
//VTK::Output::Dec

// The radial blur's occlusion pre-pass, at a reduced resolution: for each texel the light
// distance r of the surface seen there when the light reaches that surface (inside a spot's
// cone, beyond a directional light's plane, anywhere for a point light): it can cast a shadow
// into the shafts; else a huge value (background, or a surface the light does not reach).
// Storing the distance instead of the chapter's black/white lets the blur treat a surface as
// an occluder only for shafts farther from the light than it: a lit floor does not darken the
// beam above it. Features (#defines): the light's kind.
//VTK::LightShaft::Features
in vec2 texCoord;

//VTK::LightShaft::Common
//VTK::LightShaft::LightKind

void main()
{
  ivec2 depthSize = textureSize(sceneDepth, 0);
  ivec2 p = min(ivec2(texCoord * vec2(depthSize)), depthSize - 1);
  float depth = texelFetch(sceneDepth, p, 0).r;
  float distanceToLight = 1e30;
  if (depth < 1.0)
  {
    vec2 ndc = 2.0 * (vec2(p) + 0.5) / vec2(depthSize) - 1.0;
    vec4 surfaceVC = invProjectionDCVC * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    vec3 pointVC = surfaceVC.xyz / surfaceVC.w;
    float r = lightShaftLightDistance(pointVC);
#if defined(LIGHTSHAFT_POINT)
    distanceToLight = r;
#elif defined(LIGHTSHAFT_DIRECTIONAL)
    distanceToLight = (r >= 0.0) ? r : distanceToLight;
#else
    if (dot(pointVC - lightPositionVC, lightAxisVC) >= cosConeAngle * r)
    {
      distanceToLight = r;
    }
#endif
  }
  gl_FragData[0] = vec4(distanceToLight, 0.0, 0.0, 0.0);
}
