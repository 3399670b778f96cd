// The camera leg through translucent surfaces (LIGHTSHAFT_CAMERA_LAYERS): the translucent
// surfaces in front of the scene's opaque ones, peeled front to back as the camera sees them
// (vtkLightShaftTranslucentLayers::RenderCamera), side by side; per pixel and layer, r is the
// fraction 1 - a of what lies behind the surface that VTK's blending keeps, a the surface's
// depth-buffer value (1: no surface). In-scatter behind n of them is dimmed by their product,
// as the scene behind them is. Included once (guarded).
#ifdef LIGHTSHAFT_CAMERA_LAYERS
#ifndef LIGHTSHAFT_CAMERA_LAYERS_CHUNK
#define LIGHTSHAFT_CAMERA_LAYERS_CHUNK
uniform sampler2D cameraLayers;
uniform int cameraLayerCount;
uniform mat4 projectionVCDC; // the scene camera's projection (VC -> DC)

// The layers of the pixel a ray goes through, read once per invocation (its rays all go
// through one pixel): the ray distance of each surface (in order: peeled front to back) and
// the fraction it keeps.
const int lightShaftMostCameraLayers = 8;
float lightShaftCameraLayerT[lightShaftMostCameraLayers];
float lightShaftCameraLayerKept[lightShaftMostCameraLayers];
bool lightShaftCameraLayersRead = false;

void lightShaftReadCameraLayers(vec3 pointVC, vec3 dirVC)
{
  vec4 clip = projectionVCDC * vec4(pointVC, 1.0);
  vec2 ndc = clip.xy / clip.w;
  ivec2 size = textureSize(cameraLayers, 0);
  int width = size.x / max(cameraLayerCount, 1);
  ivec2 texel = clamp(ivec2(floor((0.5 * ndc + 0.5) * vec2(width, size.y))), ivec2(0),
    ivec2(width - 1, size.y - 1));
  for (int k = 0; k < lightShaftMostCameraLayers; ++k)
  {
    lightShaftCameraLayerT[k] = 3.0e38;
    lightShaftCameraLayerKept[k] = 1.0;
    if (k < cameraLayerCount)
    {
      vec4 layer = texelFetch(cameraLayers, texel + ivec2(k * width, 0), 0);
      if (layer.a < 1.0)
      {
        lightShaftCameraLayerT[k] = lightShaftSurfaceDistance(ndc, layer.a, dirVC);
        lightShaftCameraLayerKept[k] = layer.r;
      }
    }
  }
  lightShaftCameraLayersRead = true;
}

// What of the in-scatter over the piece x in [x0, x1] of the ray (x = t + b, lightShaftSegment)
// reaches the camera through the translucent surfaces in front of it: the product of those in
// front of the piece, and for a surface inside it the mean weighted by the light's falloff A
// (lightShaftAttenuationIntegral) of each part's.
float lightShaftCameraLeg(vec3 originVC, vec3 dirVC, float b, float h2, float x0, float x1)
{
  if (!lightShaftCameraLayersRead)
  {
    lightShaftReadCameraLayers(originVC + (0.5 * (x0 + x1) - b) * dirVC, dirVC);
  }
  float kept = 1.0;
  float weighted = 0.0;
  float xa = x0;
  bool split = false;
  for (int k = 0; k < lightShaftMostCameraLayers; ++k)
  {
    float xk = lightShaftCameraLayerT[k] + b;
    if (xk <= xa)
    {
      kept *= lightShaftCameraLayerKept[k];
    }
    else if (xk < x1)
    {
      weighted += kept * lightShaftAttenuationIntegral(xa, xk, h2);
      kept *= lightShaftCameraLayerKept[k];
      xa = xk;
      split = true;
    }
  }
  if (!split)
  {
    return kept;
  }
  weighted += kept * lightShaftAttenuationIntegral(xa, x1, h2);
  float whole = lightShaftAttenuationIntegral(x0, x1, h2);
  return whole > 0.0 ? weighted / whole : kept;
}
#endif
#endif
