//VTK::System::Dec
//VTK::Output::Dec

// EPIPOLAR (Engelhardt and Dachsbacher 2010, Yusov 2013): the in-scatter is marched at samples
// along lines through the light's screen image (the epipole), where it changes smoothly except
// where the scene's depth jumps, and interpolated along and across those lines. One program,
// six stages, each its own program (LIGHTSHAFT_EPIPOLAR_STAGE: a GPU, and llvmpipe even more,
// pays for the code of branches it does not take) and a draw of the slab drawer:
//   0 coordinates: each (sample, line) texel's pixel and its depth;
//   1 coarse:      the march at every epipolarStep-th sample of each line (and its last);
//                  a split setting's share also marches them the way all its shares decide by;
//   2 refine:      the sources of the interpolation along the lines: the coarse samples, the
//                  samples on either side of a depth break (marched), and every sample
//                  between coarse neighbours whose in-scatter differs too much (marched);
//   3 fine:        every other sample, interpolated between the sources on either side of it
//                  (no depth break lies between: the samples next to a break are sources);
//   4 unwarp:      each pixel interpolated from the four samples around it on its two
//                  neighbouring lines whose depth matches its own; a pixel with none is marked
//                  (second output);
//   5 march:       the marked pixels marched themselves (the others are discarded first:
//                  llvmpipe skips a block whose pixels are all discarded, not a branch none
//                  takes; measured: the march inside stage 4 cost 26 of its 42 ms at 720p).
// Features (#defines): LIGHTSHAFT_PHASE_HG / _RAYLEIGH, LIGHTSHAFT_SHADOW, LIGHTSHAFT_COOKIE,
// LIGHTSHAFT_NOISE, the light's kind.
//VTK::LightShaft::Features

uniform float slabStart; // the lit depth range
uniform float slabEnd;
uniform int numberOfSteps;
uniform float samplingRotation; // in [0, 1): progressive refinement's shift of the steps
uniform int sampleShare; // the frames a split setting's steps are shared among (1: whole)
uniform int samplePart;  // which of them this is (lightShaftMarch)

uniform int epipolarLines;
uniform int epipolarSamples;
uniform int epipolarStep;
// The layout (vtkLightShaftEpipolarGeometry::Layout): 0 radial, 1 fan, 2 parallel; the epipole; the
// lines' axis and normal; where line 0 starts and how far the lines span (perimeter or offset).
uniform int epipolarForm;
uniform vec2 epipolarOrigin;
uniform vec2 epipolarAxis;
uniform vec2 epipolarNormal;
uniform float epipolarStart;
uniform float epipolarSpan;
uniform sampler2D epipolarEnds;        // lines x 1: entry (xy) and exit (zw), target pixels
uniform sampler2D epipolarCoordinates; // samples x lines: position (xy), view depth (z),
                                       // depth-buffer value (w)
uniform sampler2D epipolarCoarse;      // coarse samples x lines: in-scatter (rgb); a split
                                       // setting's share: its own, then the columns' deciding
uniform int epipolarColumns;           // the coarse samples per line
uniform sampler2D epipolarRefined;     // samples x lines: a source's in-scatter (rgb), 1 (a);
                                       // 0 elsewhere
uniform sampler2D epipolarFine;        // samples x lines: in-scatter (rgb), view depth (a)
uniform sampler2D epipolarMarked;      // target: 1 (r) where stage 4 found no sample

// Depths within this fraction of each other belong to the same surface; coarse neighbours
// whose in-scatter differs by more than this fraction of the larger are not interpolated.
const float epipolarDepthTolerance = 0.02;
const float epipolarRadianceTolerance = 0.25;
// Pixels this near the light's image (target pixels) are marched, not interpolated: there the
// in-scatter of a point or spot light changes by its whole value within a pixel.
const float epipolarNearEpipole = 1.5;

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
//VTK::LightShaft::Segment

// The ray through a pixel marched (refinement's estimates shift the steps).
vec3 epipolarMarchRay(LightShaftRay ray)
{
  return lightShaftMarch(ray, numberOfSteps, 1.0 - samplingRotation, sampleShare, samplePart);
}

// The in-scatter of the ray through `pixel` (target pixels) whose surface's depth-buffer
// value is `depth`, marched in full; `deciding`: the same for every share of a split setting
// (the whole march's longer spans, not the share's pieces), for stage 2 to decide by.
vec3 epipolarMarch(vec2 pixel, float depth, bool deciding)
{
  LightShaftRay ray;
  if (!lightShaftLitIntervalAt(pixel, depth, slabStart, slabEnd, ray))
  {
    return vec3(0.0);
  }
  if (deciding)
  {
    return lightShaftMarch(ray, max(numberOfSteps / sampleShare, 1), 1.0, 1, 0);
  }
  return epipolarMarchRay(ray);
}

// Stage 0: where sample `sampleIndex` of line `line` lies (kept inside the outer pixel
// centres), with the depth of the pixel it falls in. The samples are not moved to pixel
// centres: the pixels interpolate them by their exact positions, and near the light's image,
// where the in-scatter changes by its whole value within a pixel, half a pixel's shift would
// be a large error (measured: 3.4% on a random scene with a spot light in view).
vec4 epipolarCoordinate(int sampleIndex, int line)
{
  vec4 ends = texelFetch(epipolarEnds, ivec2(line, 0), 0);
  vec2 point = mix(ends.xy, ends.zw, float(sampleIndex) / float(epipolarSamples - 1));
  if (epipolarForm == 0 && distance(point, epipolarOrigin) < epipolarNearEpipole)
  {
    // Not on the light's image itself, where a point or spot light's ray meets the light
    // (the pixels that near it are marched themselves).
    vec2 along = ends.zw - ends.xy;
    point = epipolarOrigin + epipolarNearEpipole * along / max(length(along), 1e-6);
  }
  point = clamp(point, vec2(0.5), targetSize - 0.5);
  ivec2 pixel = clamp(ivec2(floor(point)), ivec2(0), ivec2(targetSize) - 1);
  float depth = texelFetch(sceneDepth, pixel, 0).r;
  float viewDepth = lightShaftViewDepth(2.0 * point / targetSize - 1.0, depth);
  return vec4(point, viewDepth, depth);
}

bool epipolarSameSurface(float a, float b)
{
  return abs(a - b) <= epipolarDepthTolerance * min(abs(a), abs(b));
}

float epipolarViewDepth(int sampleIndex, int line)
{
  return texelFetch(epipolarCoordinates, ivec2(sampleIndex, line), 0).z;
}

// Stage 2: sample `sampleIndex` of line `line` as a source of the interpolation (alpha 1),
// or nothing (alpha 0) where it can be interpolated.
vec4 epipolarRefinedSample(int sampleIndex, int line)
{
  int column = sampleIndex / epipolarStep;
  int s0 = column * epipolarStep;
  int s1 = min(s0 + epipolarStep, epipolarSamples - 1);
  if (sampleIndex == s0 || sampleIndex == s1)
  {
    int coarse = (sampleIndex == s0) ? column : column + 1;
    return vec4(texelFetch(epipolarCoarse, ivec2(coarse, line), 0).rgb, 1.0);
  }
  // (A split setting's shares decide alike, by the columns' deciding march: their group adds
  // up to one frame of the setting that interpolates the same samples.)
  int deciding = sampleShare > 1 ? epipolarColumns : 0;
  vec3 l0 = texelFetch(epipolarCoarse, ivec2(deciding + column, line), 0).rgb;
  vec3 l1 = texelFetch(epipolarCoarse, ivec2(deciding + column + 1, line), 0).rgb;
  bool smooth_ = all(lessThanEqual(abs(l1 - l0), epipolarRadianceTolerance * max(l0, l1)));
  float here = epipolarViewDepth(sampleIndex, line);
  if (smooth_ && epipolarSameSurface(here, epipolarViewDepth(sampleIndex - 1, line)) &&
    epipolarSameSurface(here, epipolarViewDepth(sampleIndex + 1, line)))
  {
    return vec4(0.0);
  }
  vec4 point = texelFetch(epipolarCoordinates, ivec2(sampleIndex, line), 0);
  return vec4(epipolarMarch(point.xy, point.w, false), 1.0);
}

// Stage 3: sample `sampleIndex` of line `line`, a source or interpolated between the nearest
// sources on either side (the segment's ends are sources).
vec4 epipolarFineSample(int sampleIndex, int line)
{
  float viewDepth = epipolarViewDepth(sampleIndex, line);
  vec4 here = texelFetch(epipolarRefined, ivec2(sampleIndex, line), 0);
  if (here.a > 0.0)
  {
    return vec4(here.rgb, viewDepth);
  }
  // At most a step away each (bounded loops: the segment's ends are sources).
  int s0 = sampleIndex - 1;
  vec4 left = texelFetch(epipolarRefined, ivec2(s0, line), 0);
  for (int k = 1; k < epipolarStep && left.a == 0.0 && s0 > 0; ++k)
  {
    left = texelFetch(epipolarRefined, ivec2(--s0, line), 0);
  }
  int s1 = sampleIndex + 1;
  vec4 right = texelFetch(epipolarRefined, ivec2(s1, line), 0);
  for (int k = 1; k < epipolarStep && right.a == 0.0 && s1 < epipolarSamples - 1; ++k)
  {
    right = texelFetch(epipolarRefined, ivec2(++s1, line), 0);
  }
  return vec4(mix(left.rgb, right.rgb, float(sampleIndex - s0) / float(s1 - s0)), viewDepth);
}

// Where, as a fraction, the point p + s d (s in [s0, s1]) of the line through p along d lies
// within the target; false when the line misses it.
bool epipolarClip(vec2 p, vec2 d, out float s0, out float s1)
{
  s0 = -1e30;
  s1 = 1e30;
  for (int k = 0; k < 2; ++k)
  {
    if (d[k] == 0.0)
    {
      if (p[k] < 0.0 || p[k] > targetSize[k])
      {
        return false;
      }
      continue;
    }
    float a = -p[k] / d[k];
    float b = (targetSize[k] - p[k]) / d[k];
    s0 = max(s0, min(a, b));
    s1 = min(s1, max(a, b));
  }
  return s1 >= s0;
}

// A boundary point's coordinate along the target's perimeter, counter-clockwise from the
// lower-left corner (vtkLightShaftEpipolarGeometry's).
float epipolarPerimeterCoordinate(vec2 b)
{
  vec4 distances = vec4(abs(b.y), abs(b.x - targetSize.x), abs(b.y - targetSize.y), abs(b.x));
  float nearest = min(min(distances.x, distances.y), min(distances.z, distances.w));
  vec2 c = clamp(b, vec2(0.0), targetSize);
  if (distances.x == nearest)
  {
    return c.x;
  }
  if (distances.y == nearest)
  {
    return targetSize.x + c.y;
  }
  if (distances.z == nearest)
  {
    return targetSize.x + targetSize.y + (targetSize.x - c.x);
  }
  return 2.0 * targetSize.x + targetSize.y + (targetSize.y - c.y);
}

// Stage 3's Locate (vtkLightShaftEpipolarGeometry::Layout::Locate): the fractional line and sample
// of pixel centre p. The line through p is clipped from p itself, so that an epipole far off
// the target costs no precision.
bool epipolarLocate(vec2 p, out float line, out float sampleIndex)
{
  vec2 d = epipolarAxis;
  if (epipolarForm != 2)
  {
    vec2 v = p - epipolarOrigin;
    float distance = length(v);
    if (distance <= 1e-4)
    {
      return false; // the epipole: on every line
    }
    d = v / distance;
  }
  float s0;
  float s1;
  if (!epipolarClip(p, d, s0, s1))
  {
    return false;
  }
  if (epipolarForm == 0)
  {
    s0 = max(s0, -length(p - epipolarOrigin)); // the line starts at the epipole
  }
  if (epipolarForm == 2)
  {
    line = (dot(p, epipolarNormal) - epipolarStart) / epipolarSpan * float(epipolarLines) - 0.5;
  }
  else
  {
    float perimeter = 2.0 * (targetSize.x + targetSize.y);
    float along = epipolarPerimeterCoordinate(p + s1 * d) - epipolarStart;
    along += (along < -1e-3) ? perimeter : 0.0;
    line = along / epipolarSpan * float(epipolarLines) - 0.5;
  }
  float fraction = (s1 > s0) ? -s0 / (s1 - s0) : 0.0;
  line = clamp(line, -0.5, float(epipolarLines) - 0.5);
  sampleIndex = clamp(fraction, 0.0, 1.0) * float(epipolarSamples - 1);
  return true;
}

int epipolarLineIndex(int line)
{
  if (epipolarForm == 0)
  {
    return (line + epipolarLines) % epipolarLines; // radial lines go round
  }
  return clamp(line, 0, epipolarLines - 1);
}

// Stage 4: the pixel's in-scatter from the samples around it whose surface is its own; false
// when none is.
bool epipolarUnwarp(out vec3 radiance)
{
  vec2 pixel = gl_FragCoord.xy;
  float depth = texelFetch(sceneDepth, ivec2(pixel), 0).r;
  float viewDepth = lightShaftViewDepth(2.0 * pixel / targetSize - 1.0, depth);
  float line;
  float sampleIndex;
  radiance = vec3(0.0);
  if ((epipolarForm != 2 && distance(pixel, epipolarOrigin) < epipolarNearEpipole) ||
    !epipolarLocate(pixel, line, sampleIndex))
  {
    return false;
  }
  float l = floor(line);
  float s = min(floor(sampleIndex), float(epipolarSamples - 2));
  vec2 f = vec2(sampleIndex - s, line - l);
  vec4 sum = vec4(0.0);
  for (int j = 0; j < 2; ++j)
  {
    int lineIndex = epipolarLineIndex(int(l) + j);
    for (int i = 0; i < 2; ++i)
    {
      vec4 fine = texelFetch(epipolarFine, ivec2(int(s) + i, lineIndex), 0);
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) + 1e-4;
      if (epipolarSameSurface(fine.a, viewDepth))
      {
        sum += w * vec4(fine.rgb, 1.0);
      }
    }
  }
  radiance = sum.rgb / max(sum.a, 1e-30);
  return sum.a > 0.0;
}

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
#if LIGHTSHAFT_EPIPOLAR_STAGE == 0
  gl_FragData[0] = epipolarCoordinate(texel.x, texel.y);
#elif LIGHTSHAFT_EPIPOLAR_STAGE == 1
  bool deciding = texel.x >= epipolarColumns; // (only a split setting's share has them)
  int column = deciding ? texel.x - epipolarColumns : texel.x;
  int sampleIndex = min(column * epipolarStep, epipolarSamples - 1);
  vec4 here = texelFetch(epipolarCoordinates, ivec2(sampleIndex, texel.y), 0);
  gl_FragData[0] = vec4(epipolarMarch(here.xy, here.w, deciding), 0.0);
#elif LIGHTSHAFT_EPIPOLAR_STAGE == 2
  gl_FragData[0] = epipolarRefinedSample(texel.x, texel.y);
#elif LIGHTSHAFT_EPIPOLAR_STAGE == 3
  gl_FragData[0] = epipolarFineSample(texel.x, texel.y);
#elif LIGHTSHAFT_EPIPOLAR_STAGE == 4
  // Interpolated where a sample on the pixel's surface is near, else marked for stage 5.
  vec3 radiance;
  bool interpolated = epipolarUnwarp(radiance);
  if (interpolated && all(equal(radiance, vec3(0.0))))
  {
    discard; // nothing to add
  }
  gl_FragData[0] = vec4(radiance, 0.0);
  gl_FragData[1] = vec4(interpolated ? 0.0 : 1.0);
#else
  if (texelFetch(epipolarMarked, texel, 0).r == 0.0)
  {
    discard;
  }
  LightShaftRay ray;
  if (!lightShaftLitInterval(slabStart, slabEnd, ray))
  {
    discard;
  }
  gl_FragData[0] = vec4(epipolarMarchRay(ray), 0.0);
#endif
}
