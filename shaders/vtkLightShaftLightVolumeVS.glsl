//VTK::System::Dec

// LIGHT_VOLUME (Billeter, Sintorn and Assarsson 2010): the region the shadow map puts in shadow,
// behind its casters, as one closed mesh per map (per cube face of a point light). The mesh is
// a grid of (cells + 4)^2 vertices over the map's square, then one more vertex:
// - columns and rows 0 and cells + 3: the ring, on the square's edge at the far cap's depth;
// - 1 and cells + 2: on the square's edge at the depth of the map's edge texel;
// - 2 .. cells + 1: at the centres of `cells` cells, at the depth of the texel there;
// - the last vertex: the far cap's centre (the cap is a fan from it to the ring).
// Depths are the casters' plus the lookup's bias, or the far cap's where no caster is; the
// quads between the ring and the edge are the volume's side walls. Grid triangles turn
// counter-clockwise seen from the light, the cap's clockwise: front faces enter the volume.
// Features (#defines): the light's kind, LIGHTSHAFT_SHADOW_VOLUME.
//VTK::LightShaft::Features
//VTK::LightShaft::LightSpace

uniform int lightVolumeCells;   // grid cells across the square
uniform int shadowTexels;       // texels across one face of the map
uniform ivec2 shadowFaceOrigin; // the face's first texel in the map (a point light's atlas)
uniform float shadowBias;       // the lookup's depth tolerance (relative; directional: absolute)
uniform float lightVolumeFar;   // the far cap's light depth, beyond the whole lit volume
uniform mat4 vcFromLightClip;   // the face's light clip coordinates -> VC
uniform mat4 meshClipFromVC;    // the scene camera's projection, nothing clipped beyond

out vec3 crossingVC;

// Where grid column (or row) c lies across the square, in the light's NDC.
float lightVolumeGridNDC(int c)
{
  int cells = lightVolumeCells;
  if (c <= 1 || c >= cells + 2)
  {
    return c <= 1 ? -1.0 : 1.0;
  }
  return -1.0 + (2.0 * float(c - 2) + 1.0) / float(cells);
}

// The light depth where the shadow starts at `ndc`: the nearest texel's caster with the bias,
// or the far cap where the texel holds no caster.
float lightVolumeShadowDepth(vec2 ndc)
{
  ivec2 texel = clamp(ivec2(floor((0.5 * ndc + 0.5) * float(shadowTexels))), ivec2(0),
    ivec2(shadowTexels - 1));
  float stored = texelFetch(shadowMap, shadowFaceOrigin + texel, 0).r;
  if (stored >= 1.0)
  {
    return lightVolumeFar;
  }
#ifdef LIGHTSHAFT_DIRECTIONAL
  float depth = lightShaftCasterDepth(stored) + shadowBias;
#else
  float depth = lightShaftCasterDepth(stored) * (1.0 + shadowBias);
#endif
  return min(depth, lightVolumeFar);
}

void main()
{
  int side = lightVolumeCells + 4;
  vec2 ndc = vec2(0.0);
  float depth = lightVolumeFar;
  if (gl_VertexID < side * side)
  {
    ivec2 c = ivec2(gl_VertexID % side, gl_VertexID / side);
    ndc = vec2(lightVolumeGridNDC(c.x), lightVolumeGridNDC(c.y));
    if (all(greaterThan(c, ivec2(0))) && all(lessThan(c, ivec2(side - 1))))
    {
      depth = lightVolumeShadowDepth(ndc);
    }
  }
  // Along the line through ndc from the light camera's near plane to its far plane, light
  // depth (axial distance, or distance from a directional light's plane) is linear.
  vec4 nearVC = vcFromLightClip * vec4(ndc, -1.0, 1.0);
  vec4 farVC = vcFromLightClip * vec4(ndc, 1.0, 1.0);
  float n = lightDepthRange.x;
  float f = lightDepthRange.y;
  crossingVC = mix(nearVC.xyz / nearVC.w, farVC.xyz / farVC.w, (depth - n) / (f - n));
  gl_Position = meshClipFromVC * vec4(crossingVC, 1.0);
}
