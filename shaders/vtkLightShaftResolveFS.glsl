//VTK::System::Dec
//VTK::Output::Dec

// 8-bit accumulation (the GDC 2004 trick): the four channels of each colour's RGBA8 buffer hold
// the partial sums of every fourth slab; add them and undo the display scale.
in vec2 texCoord;
uniform sampler2D accumulatedRed;
uniform sampler2D accumulatedGreen;
uniform sampler2D accumulatedBlue;
uniform float inverseScale;

void main()
{
  ivec2 p = ivec2(texCoord * vec2(textureSize(accumulatedRed, 0)));
  const vec4 ones = vec4(1.0);
  vec3 sum = vec3(dot(texelFetch(accumulatedRed, p, 0), ones),
    dot(texelFetch(accumulatedGreen, p, 0), ones), dot(texelFetch(accumulatedBlue, p, 0), ones));
  gl_FragData[0] = vec4(inverseScale * sum, 0.0);
}
