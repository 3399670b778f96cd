//VTK::System::Dec
// Composite: out = (scene - correction) * exp(-sigma_t * t_surface) + Exposure * L_in, depth
// passed through. Features (#defines): LIGHTSHAFT_ATTENUATE (aerial perspective; with
// LIGHTSHAFT_FIELD, through the medium's density field),
// LIGHTSHAFT_SURFACE_CORRECTION (the light the lights' shadow maps and cookie take away from
// the surfaces, vtkLightShaftSurfaceLightFS), LIGHTSHAFT_MULTISAMPLE (the
// scene was rendered multisampled: the composite runs once per sample, reading and writing that
// sample's colour and depth, so the target keeps its antialiasing and resolves as it would
// have without the pass), LIGHTSHAFT_WRITE_DEPTH (the scene's depth is written here, when the
// target's depth format differs from the scene's; else it is copied after the composite),
// LIGHTSHAFT_BACKGROUND (the renderer's flat background painted behind the scene's uncovered
// part, 1 - alpha, before the medium dims it: a compositor rendered the scene over a transparent
// background, premultiplied, and blends the background in after the pass).
//VTK::LightShaft::Features
#ifdef LIGHTSHAFT_MULTISAMPLE
#extension GL_ARB_sample_shading : require
#endif
//VTK::Output::Dec

in vec2 texCoord;

//VTK::LightShaft::Common
//VTK::LightShaft::Field

uniform sampler2D inScatter;
uniform vec3 sigmaT;
uniform float exposure;
#ifdef LIGHTSHAFT_BACKGROUND
uniform vec3 background;
#endif

#ifdef LIGHTSHAFT_MULTISAMPLE
uniform sampler2DMS sceneColorSamples;
uniform sampler2DMS sceneDepthSamples;
ivec2 sceneSize() { return textureSize(sceneColorSamples); }
vec4 sceneColorAt(ivec2 pixel) { return texelFetch(sceneColorSamples, pixel, gl_SampleID); }
float sceneDepthAt(ivec2 pixel) { return texelFetch(sceneDepthSamples, pixel, gl_SampleID).r; }
vec2 sampleOffset() { return gl_SamplePosition; } // where the sample's depth was taken
#else
uniform sampler2D sceneColor;
ivec2 sceneSize() { return textureSize(sceneColor, 0); }
vec4 sceneColorAt(ivec2 pixel) { return texelFetch(sceneColor, pixel, 0); }
float sceneDepthAt(ivec2 pixel) { return texelFetch(sceneDepth, pixel, 0).r; }
vec2 sampleOffset() { return vec2(0.5); }
#endif

#ifdef LIGHTSHAFT_SURFACE_CORRECTION
#ifdef LIGHTSHAFT_MULTISAMPLE
uniform sampler2DMS surfaceCorrectionSamples;
vec3 surfaceCorrectionAt(ivec2 pixel)
{
  return texelFetch(surfaceCorrectionSamples, pixel, gl_SampleID).rgb;
}
#else
uniform sampler2D surfaceCorrection;
vec3 surfaceCorrectionAt(ivec2 pixel) { return texelFetch(surfaceCorrection, pixel, 0).rgb; }
#endif
#endif

void main()
{
  // texCoord runs over the viewport, pixel centres at (i + 0.5) / size.
  ivec2 pixel = ivec2(texCoord * vec2(sceneSize()));
  vec4 color = sceneColorAt(pixel);
  float depth = sceneDepthAt(pixel);
  // Nearest sample: the in-scatter buffer is full size here (upsampled when it was computed
  // at a lower resolution).
  vec3 inScattered = texture(inScatter, texCoord).rgb;
#ifdef LIGHTSHAFT_BACKGROUND
  color = vec4(color.rgb + (1.0 - color.a) * background, 1.0);
#endif

#ifdef LIGHTSHAFT_SURFACE_CORRECTION
  color.rgb = max(color.rgb - surfaceCorrectionAt(pixel), vec3(0.0));
#endif
#ifdef LIGHTSHAFT_ATTENUATE
  vec3 originVC;
  vec3 dirVC;
  vec2 ndc;
  lightShaftViewRay(vec2(pixel) + sampleOffset(), originVC, dirVC, ndc);
  float surfaceDistance = lightShaftSurfaceDistance(ndc, depth, dirVC);
#ifdef LIGHTSHAFT_FIELD
  // A medium from data: its optical depth up to the surface.
  color.rgb *= exp(-sigmaT * lightShaftOpticalDepth(originVC, originVC + surfaceDistance * dirVC));
#else
  color.rgb *= exp(-sigmaT * surfaceDistance);
#endif
#endif

  // Alpha: the shafts are light in front of whatever lies behind, so a pixel is at least as
  // opaque as its brightest added channel; passes that blend by alpha (vtkToneMappingPass maps
  // mix(pixel, toned, alpha)) then treat shafts over the background as part of the picture.
  vec3 added = exposure * inScattered;
  float coverage = clamp(max(added.r, max(added.g, added.b)), 0.0, 1.0);
  gl_FragData[0] = vec4(color.rgb + added, color.a + (1.0 - color.a) * coverage);
#ifdef LIGHTSHAFT_WRITE_DEPTH
  gl_FragDepth = depth;
#endif
}
