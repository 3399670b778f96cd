//VTK::System::Dec
//VTK::Output::Dec

// EPIPOLAR: the pixels its unwarp stage marked (no sample on their surface) as depth 1, the
// others as depth 0, so that the march stage's depth test rejects the others before they are
// shaded (a software rasteriser skips a block only when the depth test rejects all of it).
in vec2 texCoord;
uniform sampler2D marked;

void main()
{
  ivec2 pixel = min(ivec2(texCoord * vec2(textureSize(marked, 0))), textureSize(marked, 0) - 1);
  gl_FragDepth = texelFetch(marked, pixel, 0).r > 0.0 ? 1.0 : 0.0;
  gl_FragData[0] = vec4(0.0);
}
