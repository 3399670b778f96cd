//VTK::System::Dec
//VTK::Output::Dec

// One direction of a separable, depth-aware Gaussian blur of the in-scattered radiance: taps
// whose surface lies at a different depth (relative difference above depthTolerance) get no
// weight, so shafts do not bleed across silhouettes. With boxWidth > 0 it is instead the
// gather of interleaved sampling: an unweighted mean over boxWidth consecutive pixels, which
// holds every one of the block's offsets with the same weight.
in vec2 texCoord;

//VTK::LightShaft::Common

uniform sampler2D source;
uniform ivec2 direction; // (1, 0) or (0, 1)
uniform int radius;   // the Gaussian's taps: -radius .. radius
uniform float sigma;  // its standard deviation, in pixels
uniform float depthTolerance;
uniform int boxWidth;

void main()
{
  ivec2 size = textureSize(source, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
  vec2 ndc = 2.0 * (vec2(p) + 0.5) / targetSize - 1.0;
  float centreDepth = lightShaftViewDepth(ndc, texelFetch(sceneDepth, p, 0).r);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  // The gather is centred: an even width takes the two end taps (the same residue) at half
  // weight, so the image does not shift by half a pixel.
  int first = (boxWidth > 0) ? -(boxWidth / 2) : -radius;
  int last = (boxWidth > 0) ? boxWidth / 2 : radius;
  bool halfEnds = boxWidth > 0 && (boxWidth % 2) == 0;
  for (int i = first; i <= last; ++i)
  {
    ivec2 q = p + i * direction;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
    {
      continue;
    }
    vec2 qndc = 2.0 * (vec2(q) + 0.5) / targetSize - 1.0;
    float qDepth = lightShaftViewDepth(qndc, texelFetch(sceneDepth, q, 0).r);
    if (abs(qDepth - centreDepth) > depthTolerance * centreDepth)
    {
      continue;
    }
    float w = (boxWidth > 0) ? ((halfEnds && abs(i) == boxWidth / 2) ? 0.5 : 1.0) :
      exp(-0.5 * float(i * i) / (sigma * sigma));
    sum += w * texelFetch(source, q, 0).rgb;
    weights += w;
  }
  gl_FragData[0] = vec4(sum / max(weights, 1e-30), 0.0);
}
