//VTK::System::Dec
//VTK::Output::Dec

// Adds one light's in-scattered radiance (rgb) into the sum of the frame's lights (blended
// additively); the sum's alpha stays 0.
in vec2 texCoord;

uniform sampler2D source;

void main()
{
  // The sum and the source have the same size: texel centres, nearest texel.
  gl_FragData[0] = vec4(texture(source, texCoord).rgb, 0.0);
}
