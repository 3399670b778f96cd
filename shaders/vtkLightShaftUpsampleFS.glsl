//VTK::System::Dec
//VTK::Output::Dec

// Depth-aware upsampling of the reduced-resolution in-scatter buffer: of the four reduced
// samples around a full-resolution pixel, bilinear weights are kept only for those whose depth
// matches the pixel's (relative difference below depthTolerance); with none matching, the
// sample of nearest depth is taken. No halo of background shafts on foreground edges.
in vec2 texCoord;

//VTK::LightShaft::Common

uniform sampler2D reduced;       // reduced in-scatter
uniform sampler2D reducedDepth;  // its depth
uniform sampler2D fullDepth;     // full-resolution depth (sceneDepth is the reduced one here)
uniform vec2 fullSize;
uniform float depthTolerance;

void main()
{
  vec2 fullPixel = texCoord * fullSize; // pixel centre
  vec2 fullNdc = 2.0 * fullPixel / fullSize - 1.0;
  float depth = lightShaftViewDepth(fullNdc, texelFetch(fullDepth, ivec2(floor(fullPixel)), 0).r);
  ivec2 reducedSize = textureSize(reduced, 0);
  vec2 position = fullPixel / fullSize * vec2(reducedSize) - 0.5;
  ivec2 base = ivec2(floor(position));
  vec2 f = position - vec2(base);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  vec3 nearestValue = vec3(0.0);
  float nearestDifference = 3.0e38;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      ivec2 q = clamp(base + ivec2(i, j), ivec2(0), reducedSize - 1);
      vec2 qndc = 2.0 * (vec2(q) + 0.5) / vec2(reducedSize) - 1.0;
      float qDepth = lightShaftViewDepth(qndc, texelFetch(reducedDepth, q, 0).r);
      vec3 value = texelFetch(reduced, q, 0).rgb;
      float difference = abs(qDepth - depth);
      if (difference < nearestDifference)
      {
        nearestDifference = difference;
        nearestValue = value;
      }
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      if (difference <= depthTolerance * depth)
      {
        sum += w * value;
        weights += w;
      }
    }
  }
  gl_FragData[0] = vec4(weights > 1e-6 ? sum / weights : nearestValue, 0.0);
}
