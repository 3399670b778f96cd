//VTK::System::Dec
//VTK::Output::Dec

// RAY_MARCH: one slab spans the lit depth range; each pixel marches numberOfSteps segments of
// its lit interval (shorter towards the light when A falls off), with interleaved sampling over
// interleaveSize^2 pixel blocks. Features (#defines): LIGHTSHAFT_RAY_MARCH, LIGHTSHAFT_PHASE_HG
// / _RAYLEIGH (else isotropic), LIGHTSHAFT_SHADOW, LIGHTSHAFT_COOKIE, LIGHTSHAFT_NOISE.
//VTK::LightShaft::Features

uniform float slabStart; // the lit depth range
uniform float slabEnd;
uniform int numberOfSteps;
uniform int interleaveSize; // M: the pixels of an M x M block march with M^2 offsets
uniform float samplingRotation; // in [0, 1): progressive refinement's shift of every offset
uniform int sampleShare; // the frames a split setting's steps are shared among (1: whole)
uniform int samplePart;  // which of them this is (lightShaftMarch)

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
//VTK::LightShaft::Segment

void main()
{
  LightShaftRay ray;
  if (!lightShaftLitInterval(slabStart, slabEnd, ray))
  {
    discard;
  }
  // Interleaved sampling: the M^2 pixels of a block shift the step boundaries by different
  // fractions o of a step, so the block together takes M^2 N samples; the gather passes that
  // follow average the block back.
  float offset = 1.0;
  if (interleaveSize > 1)
  {
    ivec2 cellM = ivec2(gl_FragCoord.xy) % interleaveSize;
    int cellIndex = cellM.y * interleaveSize + cellM.x;
    // Scatter neighbouring indices across the step: multiplying by cells / 2 + 1 (coprime
    // with cells for every M) permutes 0 .. M^2 - 1.
    int cells = interleaveSize * interleaveSize;
    int scrambled = (cellIndex * (cells / 2 + 1)) % cells;
    offset = (float(scrambled) + 0.5) / float(cells);
  }
  // Refinement's estimates shift the offsets together (0: unchanged), within (0, 1].
  offset -= samplingRotation;
  offset += offset <= 0.0 ? 1.0 : 0.0;
  gl_FragData[0] =
    vec4(lightShaftMarch(ray, numberOfSteps, offset, sampleShare, samplePart), 0.0);
}
