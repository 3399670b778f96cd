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

// The layers of the pixel a ray goes through, read when the ray is set up
// (lightShaftLitIntervalAt: outside the march's loop, where llvmpipe would pay for the read at
// every step): the ray distance of each surface (in order: peeled front to back; an
// empty layer, and those after it, at a distance no ray reaches) and the product of the
// fractions kept by the surfaces before each, four layers to a vec4.
vec4 lightShaftCameraT[2];
vec4 lightShaftCameraKeptBefore[2];
float lightShaftCameraKeptBehind = 1.0; // by them all

// The layers of the ray through `ndc` (direction dirVC).
void lightShaftReadCameraLayers(vec2 ndc, vec3 dirVC)
{
  ivec2 size = textureSize(cameraLayers, 0);
  int width = size.x / max(cameraLayerCount, 1);
  ivec2 texel = clamp(ivec2(floor((0.5 * ndc + 0.5) * vec2(width, size.y))), ivec2(0),
    ivec2(width - 1, size.y - 1));
  lightShaftCameraT[0] = vec4(3.0e38);
  lightShaftCameraT[1] = vec4(3.0e38);
  lightShaftCameraKeptBefore[0] = vec4(1.0);
  lightShaftCameraKeptBefore[1] = vec4(1.0);
  lightShaftCameraKeptBehind = 1.0;
  bool more = true;
  for (int k = 0; k < cameraLayerCount; ++k)
  {
    vec4 layer = texelFetch(cameraLayers, texel + ivec2(k * width, 0), 0);
    more = more && layer.a < 1.0;
    if (more)
    {
      lightShaftCameraT[k / 4][k % 4] = lightShaftSurfaceDistance(ndc, layer.a, dirVC);
      lightShaftCameraKeptBefore[k / 4][k % 4] = lightShaftCameraKeptBehind;
      lightShaftCameraKeptBehind *= layer.r;
    }
  }
  // Past the last surface: everything before it.
  for (int k = 0; k < 8; ++k)
  {
    if (lightShaftCameraT[k / 4][k % 4] > 1.0e38)
    {
      lightShaftCameraKeptBefore[k / 4][k % 4] = lightShaftCameraKeptBehind;
    }
  }
}

// What of the in-scatter over the piece x in [x0, x1] of the ray (x = t + b, lightShaftSegment)
// reaches the camera through the translucent surfaces in front of it: the product of those in
// front of each part of the piece, averaged over its length (a surface inside a piece splits it;
// the pieces are short). Vector arithmetic, no branch: the march runs it at every step
// (measured on llvmpipe: a branching, falloff-weighted split cost 60% of a RAY_MARCH frame).
float lightShaftCameraLeg(float b, float x0, float x1)
{
  // Surface k ends the part [end k-1, end k) dimmed by those before it.
  vec4 end0 = clamp(lightShaftCameraT[0] + b, x0, x1);
  vec4 end1 = clamp(lightShaftCameraT[1] + b, x0, x1);
  vec4 start0 = vec4(x0, end0.xyz);
  vec4 start1 = vec4(end0.w, end1.xyz);
  float mean = dot(lightShaftCameraKeptBefore[0], end0 - start0) +
    dot(lightShaftCameraKeptBefore[1], end1 - start1) +
    lightShaftCameraKeptBehind * (x1 - end1.w);
  return x1 > x0 ? mean / (x1 - x0) : lightShaftCameraKeptBefore[0].x;
}
#endif
#endif
