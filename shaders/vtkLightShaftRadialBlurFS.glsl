//VTK::System::Dec
//VTK::Output::Dec

// Screen-space radial blur (GPU Gems 3, ch. 13) applied to the visibility of the shafts: each
// pixel walks towards the light's screen position, counts the occlusion-buffer samples that
// hold an occluder nearer to the light than its own shaft (decay^i weighted), and darkens the
// unshadowed in-scatter (rgb of `unshadowed`; alpha: the shaft's distance to the light) by that
// fraction times weight. The occlusion buffer covers guardBand times the screen about its
// centre; samples beyond it have no data and count as unoccluded.
in vec2 texCoord;

uniform sampler2D unshadowed;
uniform sampler2D occlusion;
uniform vec2 lightUV;        // the light's position in texture coordinates (may be off-screen)
uniform float fade;          // 1 with the light in front of the camera, 0 at or behind it
uniform int samples;
uniform int sampleShare;   // the frames a split setting's samples are shared among (1: whole)
uniform int samplePart;    // which of them this is: samples samplePart + k sampleShare
uniform float decay;
uniform float decayTotal;  // the weights' sum over all samples, decay^0 + ... + decay^(n - 1)
uniform float weight;
uniform float density;       // fraction of the way to the light the samples cover
uniform int stochastic;      // per-pixel offset of the sample positions
uniform float guardBand;     // the occlusion buffer's extent relative to the screen (>= 1)

void main()
{
  vec4 shaft = texture(unshadowed, texCoord);
  if (fade <= 0.0 || samples < 1 || weight <= 0.0 || all(equal(shaft.rgb, vec3(0.0))))
  {
    gl_FragData[0] = vec4(shaft.rgb, 0.0);
    return;
  }
  vec2 toLight = lightUV - texCoord;
  // Keep the walk inside the occlusion buffer (the screen and its guard band): beyond it there
  // is no data. (The brightness, from the unshadowed integral, never depends on where the
  // light projects.)
  float low = 0.5 - 0.5 * guardBand;
  float high = 0.5 + 0.5 * guardBand;
  float reach = density;
  for (int axis = 0; axis < 2; ++axis)
  {
    if (toLight[axis] > 1e-9)
    {
      reach = min(reach, (high - texCoord[axis]) / toLight[axis]);
    }
    else if (toLight[axis] < -1e-9)
    {
      reach = min(reach, (low - texCoord[axis]) / toLight[axis]);
    }
  }
  vec2 step = toLight * (max(reach, 0.0) / float(samples));
  float start = 0.5;
  if (stochastic != 0)
  {
    // Interleaved gradient noise: a different offset for each pixel, stable over frames.
    start = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  }
  float shaftDistance = shaft.a;
  // A split setting's share takes every sampleShare-th sample, standing for sampleShare of
  // them: a group of shares adds up to the whole walk, sample for sample.
  float illuminationDecay = samplePart == 0 ? 1.0 : pow(decay, float(samplePart));
  float decayPerSample = sampleShare == 1 ? decay : pow(decay, float(sampleShare));
  float visible = 0.0;
  for (int i = samplePart; i < samples; i += sampleShare)
  {
    vec2 uv = texCoord + (float(i) + start) * step;
    float occluderDistance = texture(occlusion, 0.5 + (uv - 0.5) / guardBand).r;
    visible += illuminationDecay * ((occluderDistance < 0.99 * shaftDistance) ? 0.0 : 1.0);
    illuminationDecay *= decayPerSample;
  }
  float visibility = (decayTotal > 0.0) ? float(sampleShare) * visible / decayTotal : 1.0;
  gl_FragData[0] = vec4(shaft.rgb * (1.0 - weight * fade * (1.0 - visibility)), 0.0);
}
