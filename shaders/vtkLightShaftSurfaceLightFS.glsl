//VTK::System::Dec
// One light's surface light where its shadow map shadows the visible surfaces, the medium dims
// the light on its way to them or the cookie darkens them: the light's share of each surface's
// colour, lit - unlit (the scene rendered with and without that light), times what it loses
// there, 1 - visibility * cookie * transmittance; added into the correction the composite
// subtracts from the scene. The visibility is the shafts' own shadow map, with a depth
// tolerance that grows with the surface's slope to the light (its normal from the depth of the
// neighbouring pixels). Features (#defines): LIGHTSHAFT_SHADOW, LIGHTSHAFT_TRANSLUCENT,
// LIGHTSHAFT_VOLUME_SHADOW (the light's leg through the scene's volume), LIGHTSHAFT_LIGHT_LEG
// (the medium's: homogeneous, or with LIGHTSHAFT_FIELD and LIGHTSHAFT_FIELD_SHADOW its field,
// as the shafts' light leg), LIGHTSHAFT_COOKIE, LIGHTSHAFT_MULTISAMPLE (per sample), the light's
// kind.
//VTK::LightShaft::Features
#ifdef LIGHTSHAFT_MULTISAMPLE
#extension GL_ARB_sample_shading : require
#endif
//VTK::Output::Dec

in vec2 texCoord;

//VTK::LightShaft::Common
//VTK::LightShaft::LightSpace
//VTK::LightShaft::Field

#ifdef LIGHTSHAFT_VOLUME_SHADOW
uniform sampler3D volumeShadowTexture;
uniform LightShaftTable volumeShadow;
#endif

#ifdef LIGHTSHAFT_LIGHT_LEG
uniform vec3 sigmaT;

// The medium's optical depth (in units of sigma_t) from the light to pointVC, at light distance
// r: to a spot or point light, or back to a directional light's plane (as the shafts' leg).
float lightShaftLightLeg(vec3 pointVC, float r)
{
#ifdef LIGHTSHAFT_FIELD
  return lightShaftFieldLightLeg(pointVC, r);
#else
  return max(r, 0.0);
#endif
}
#endif

#ifdef LIGHTSHAFT_SHADOW
uniform float shadowTexel; // a texel's extent: at unit distance (spot, point), or world units
uniform float shadowFloor; // the smallest tolerance (relative, or world units)
#endif

#ifdef LIGHTSHAFT_MULTISAMPLE
uniform sampler2DMS sceneColorSamples;
uniform sampler2DMS sceneColorUnlitSamples;
uniform sampler2DMS sceneDepthSamples;
ivec2 sceneSize() { return textureSize(sceneColorSamples); }
vec3 litAt(ivec2 pixel) { return texelFetch(sceneColorSamples, pixel, gl_SampleID).rgb; }
vec3 unlitAt(ivec2 pixel) { return texelFetch(sceneColorUnlitSamples, pixel, gl_SampleID).rgb; }
float depthAt(ivec2 pixel) { return texelFetch(sceneDepthSamples, pixel, gl_SampleID).r; }
// Where in its pixel this sample lies: its depth is the surface's there, not at the centre (read
// at the centre, a sloped surface's point is off by up to half a pixel's slope, which the map's
// tolerance does not cover: acne).
vec2 sampleOffset() { return gl_SamplePosition; }
#else
uniform sampler2D sceneColor;
uniform sampler2D sceneColorUnlit;
ivec2 sceneSize() { return textureSize(sceneColor, 0); }
vec3 litAt(ivec2 pixel) { return texelFetch(sceneColor, pixel, 0).rgb; }
vec3 unlitAt(ivec2 pixel) { return texelFetch(sceneColorUnlit, pixel, 0).rgb; }
float depthAt(ivec2 pixel) { return texelFetch(sceneDepth, pixel, 0).r; }
vec2 sampleOffset() { return vec2(0.5); }
#endif

// The surface point (view coordinates) this fragment's sample sees in `pixel`.
vec3 surfaceAt(ivec2 pixel, float depth)
{
  vec2 ndc = 2.0 * (vec2(pixel) + sampleOffset()) / vec2(sceneSize()) - 1.0;
  vec4 pointVC = invProjectionDCVC * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  return pointVC.xyz / pointVC.w;
}

#ifdef LIGHTSHAFT_SHADOW
// The surface's tangent along one screen axis: towards the neighbour on the same surface (the
// one whose depth differs less).
vec3 surfaceTangent(ivec2 pixel, vec3 centre, ivec2 step)
{
  ivec2 size = sceneSize();
  ivec2 ahead = clamp(pixel + step, ivec2(0), size - 1);
  ivec2 behind = clamp(pixel - step, ivec2(0), size - 1);
  vec3 a = surfaceAt(ahead, depthAt(ahead)) - centre;
  vec3 b = centre - surfaceAt(behind, depthAt(behind));
  return (abs(a.z) < abs(b.z)) ? a : b;
}
#endif

void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(sceneSize()));
  vec3 share = max(litAt(pixel) - unlitAt(pixel), vec3(0.0));
  float depth = depthAt(pixel);
  if (depth >= 1.0 || all(equal(share, vec3(0.0))))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec3 surfaceVC = surfaceAt(pixel, depth);
  float r = lightShaftLightDistance(surfaceVC);
  float visibility = 1.0;
  vec3 cookie = vec3(1.0); // with the translucent casters' transmittance
#ifdef LIGHTSHAFT_SHADOW
  // Nearest-texel depths err by up to a texel's extent times the slope: tolerate that, and
  // look up from a point a texel off the surface along its normal (towards the light) as the
  // slope grows, where the tolerance alone would need to grow without bound (the terminator).
  vec3 normal = cross(surfaceTangent(pixel, surfaceVC, ivec2(1, 0)),
    surfaceTangent(pixel, surfaceVC, ivec2(0, 1)));
  normal /= max(length(normal), 1e-30);
  vec3 toLight = -lightShaftLightDirection(surfaceVC, r);
  float facing = dot(normal, toLight);
  float cosine = abs(facing);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  float slope = sine / max(cosine, 1e-3);
  float bias = shadowTexel * (1.0 + 1.5 * min(slope, 10.0)) + shadowFloor;
#ifdef LIGHTSHAFT_DIRECTIONAL
  float texelWC = shadowTexel;
#else
  float texelWC = shadowTexel * r;
#endif
  vec3 lookupVC = surfaceVC + (facing < 0.0 ? -normal : normal) * (1.5 * texelWC * sine);
  float lookupR = lightShaftLightDistance(lookupVC);
  visibility = lightShaftVisibility(lookupVC, lookupR, bias);
#ifdef LIGHTSHAFT_TRANSLUCENT
  cookie *= lightShaftTranslucency(lookupVC, lookupR, bias);
#endif
#endif
#ifdef LIGHTSHAFT_VOLUME_SHADOW
  cookie *= exp(-lightShaftTableLookup(volumeShadowTexture, volumeShadow, surfaceVC));
#endif
#ifdef LIGHTSHAFT_LIGHT_LEG
  cookie *= exp(-sigmaT * lightShaftLightLeg(surfaceVC, r));
#endif
#ifdef LIGHTSHAFT_COOKIE
  float footprint = pixelFootprint.x * (-surfaceVC.z) + pixelFootprint.y;
  cookie *= lightShaftCookie(surfaceVC,
    footprint / max(lightSquareWidth.x * r + lightSquareWidth.y, 1e-30));
#endif
  gl_FragData[0] = vec4((vec3(1.0) - visibility * cookie) * share, 0.0);
}
