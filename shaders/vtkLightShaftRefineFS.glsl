//VTK::System::Dec
//VTK::Output::Dec

// Progressive refinement: the running mean of a still view's in-scatter estimates. The new
// estimate gets weight 1 / n for the n-th (1 for the first: the history starts as it).
in vec2 texCoord;

uniform sampler2D history;  // mean of the n - 1 estimates before
uniform sampler2D estimate; // this frame's
uniform float estimateWeight;

void main()
{
  // The history and the estimate have the same size: texel centres, nearest texel.
  vec3 latest = texture(estimate, texCoord).rgb;
  // The first estimate is not mixed: the history's old texels may hold anything.
  vec3 mean = estimateWeight < 1.0 ? texture(history, texCoord).rgb : latest;
  gl_FragData[0] = vec4(mix(mean, latest, estimateWeight), 0.0);
}
