//VTK::System::Dec
//VTK::Output::Dec

// Multisampled scene: the one depth per pixel that the shafts read is the nearest of the
// pixel's samples (a pixel on a silhouette integrates its ray up to the nearer surface, as the
// reduced-resolution depth does for its block).
in vec2 texCoord;
uniform sampler2DMS sceneDepthSamples;
uniform int sampleCount;

void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(sceneDepthSamples)));
  float nearest = 1.0;
  for (int i = 0; i < sampleCount; ++i)
  {
    nearest = min(nearest, texelFetch(sceneDepthSamples, pixel, i).r);
  }
  gl_FragDepth = nearest;
  gl_FragData[0] = vec4(0.0);
}
