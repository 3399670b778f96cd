//VTK::System::Dec
//VTK::Output::Dec

// The exact finish: where a tile of the float64 reference is finished (exact.a = 1), it
// replaces the estimate.
in vec2 texCoord;

uniform sampler2D estimate; // the picture's in-scatter, refined so far
uniform sampler2D exact;    // rgb: the reference's in-scatter, a: 1 where it is finished

void main()
{
  // Both have the viewport's size: texel centres, nearest texel.
  vec4 finished = texture(exact, texCoord);
  vec3 estimated = texture(estimate, texCoord).rgb;
  gl_FragData[0] = vec4(finished.a > 0.5 ? finished.rgb : estimated, 0.0);
}
