//VTK::System::Dec
//VTK::Output::Dec

// Composite: out = scene * exp(-sigma_t * t_surface) + Exposure * L_in, depth passed through.

in vec2 texCoord;

//VTK::LightShaft::Common

uniform sampler2D sceneColor;
uniform sampler2D inScatter;
uniform vec3 sigmaT;
uniform float exposure;

void main()
{
  // texCoord runs over the viewport, pixel centres at (i + 0.5) / size.
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(sceneColor, 0)));
  vec4 color = texelFetch(sceneColor, pixel, 0);
  float depth = texelFetch(sceneDepth, pixel, 0).r;
  vec3 inScattered = texelFetch(inScatter, pixel, 0).rgb;

  //VTK::LightShaft::Attenuate

  gl_FragData[0] = vec4(color.rgb + exposure * inScattered, color.a);
  gl_FragDepth = depth;
}
