// The scene's vtkVolume (LIGHTSHAFT_VOLUME): its extinction kappa per world unit
// (vtkLightShaftVolumeField's rule), a 3D texture (trilinear) over the volume's box, 0 outside.
// It dims what lies behind it for the camera, shafts included, by exp(-integral of kappa)
// along the view ray, and the light that reaches a sample through it by the light leg's
// integral, tabulated per light (LightShaftTable, vtkLightShaftFieldTableTexture). Included once.
#ifdef LIGHTSHAFT_VOLUME
#ifndef LIGHTSHAFT_VOLUME_CHUNK
#define LIGHTSHAFT_VOLUME_CHUNK
uniform sampler3D volumeTexture;
uniform mat4 volumeTCFromVC; // view coordinates to the texture's coordinates
uniform vec3 volumeLowTC;    // the volume's box in texture coordinates
uniform vec3 volumeHighTC;
uniform int volumeSteps;     // samples of the camera leg from the eye to a segment
uniform sampler3D volumeShadowTexture;
uniform LightShaftTable volumeShadow;

// The integral of kappa along aVC -> bVC by `steps` midpoint samples over the part inside the
// volume's box.
float lightShaftVolumeDepth(vec3 aVC, vec3 bVC, int steps)
{
  vec3 ta = (volumeTCFromVC * vec4(aVC, 1.0)).xyz;
  vec3 delta = (volumeTCFromVC * vec4(bVC, 1.0)).xyz - ta;
  float s0 = 0.0;
  float s1 = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    if (abs(delta[k]) < 1e-30)
    {
      if (ta[k] < volumeLowTC[k] || ta[k] > volumeHighTC[k])
      {
        s1 = -1.0;
      }
      continue;
    }
    float enter = (volumeLowTC[k] - ta[k]) / delta[k];
    float leave = (volumeHighTC[k] - ta[k]) / delta[k];
    s0 = max(s0, min(enter, leave));
    s1 = min(s1, max(enter, leave));
  }
  if (!(s1 > s0))
  {
    return 0.0;
  }
  float ds = (s1 - s0) / float(steps);
  float sum = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    sum += texture(volumeTexture, ta + (s0 + (float(i) + 0.5) * ds) * delta).r;
  }
  return sum * ds * length(bVC - aVC);
}

// The camera leg's integral from the eye to the ray parameter x (x = t + b, lightShaftSegment),
// started when the ray is set up (lightShaftVolumeStart, in lightShaftLitIntervalAt: outside the
// march's loop, where llvmpipe would pay for the full march at every step) and carried from one
// piece to the next: each adds the stretch from the last point to its own midpoint.
float lightShaftVolumeSoFar = 0.0;
float lightShaftVolumeSoFarX = 0.0;

void lightShaftVolumeStart(vec3 originVC, vec3 dirVC, float b, float x)
{
  lightShaftVolumeSoFar = lightShaftVolumeDepth(originVC, originVC + (x - b) * dirVC, volumeSteps);
  lightShaftVolumeSoFarX = x;
}

// kappa at pointVC (0 outside the volume's box), without a branch.
float lightShaftVolumeKappa(vec3 pointVC)
{
  vec3 tc = (volumeTCFromVC * vec4(pointVC, 1.0)).xyz;
  vec3 inside = step(volumeLowTC, tc) * step(tc, volumeHighTC);
  return inside.x * inside.y * inside.z * texture(volumeTexture, tc).r;
}

// What of the in-scatter at the piece x in [x0, x1] of the ray reaches the camera through the
// volume, and what of the light reaches the piece's sample through it. The camera leg's stretch
// from the last point to this piece's midpoint by one midpoint sample, without a branch: the
// march runs it at every step (measured on llvmpipe: the clipped two-sample stretch cost 65% of a
// RAY_MARCH frame, this one ...).
float lightShaftVolumeLegs(vec3 originVC, vec3 dirVC, float b, float x0, float x1,
  vec3 sampleVC)
{
  float x = 0.5 * (x0 + x1);
  // (Signed: a piece before the last point takes its stretch back.)
  float middle = 0.5 * (x + lightShaftVolumeSoFarX) - b;
  lightShaftVolumeSoFar +=
    (x - lightShaftVolumeSoFarX) * lightShaftVolumeKappa(originVC + middle * dirVC);
  lightShaftVolumeSoFarX = x;
  float lightLeg = lightShaftTableLookup(volumeShadowTexture, volumeShadow, sampleVC);
  return exp(-(lightShaftVolumeSoFar + lightLeg));
}
#endif
#endif
