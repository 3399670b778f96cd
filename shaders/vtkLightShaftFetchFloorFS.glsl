//VTK::System::Dec
//VTK::Output::Dec

// The fetch floor: `fetches` texel fetches per pixel and nothing else (a sum, so none is
// optimised away), from a neighbourhood that walks like a slab's depth and shadow lookups do.
in vec2 texCoord;
uniform sampler2D source;
uniform int fetches;

void main()
{
  ivec2 size = textureSize(source, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
  vec4 sum = vec4(0.0);
  for (int k = 0; k < fetches; ++k)
  {
    sum += texelFetch(source, (p + ivec2(k * 7, k * 3)) % size, 0);
  }
  gl_FragData[0] = sum;
}
