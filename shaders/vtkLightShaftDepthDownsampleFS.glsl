//VTK::System::Dec
//VTK::Output::Dec

// Depth of a reduced-resolution pixel: the nearest surface of its factor x factor block of the
// full-resolution depth buffer (so the slabs stop at the nearest surface of the block; the
// upsampling then picks, per full-resolution pixel, the reduced sample of matching depth).
in vec2 texCoord;
uniform sampler2D fullDepth;
uniform int factor;
uniform vec2 reducedSize;

void main()
{
  ivec2 size = textureSize(fullDepth, 0);
  ivec2 first = ivec2(texCoord * reducedSize) * factor;
  float nearest = 1.0;
  for (int j = 0; j < factor; ++j)
  {
    for (int i = 0; i < factor; ++i)
    {
      ivec2 p = min(first + ivec2(i, j), size - 1);
      nearest = min(nearest, texelFetch(fullDepth, p, 0).r);
    }
  }
  gl_FragDepth = nearest;
  gl_FragData[0] = vec4(0.0);
}
