//VTK::System::Dec

// One vertex of a slab's screen footprint: xy in NDC, z the slab's index, w the view depth the
// footprint starts at (the slab is drawn there so that the depth test culls it where it starts
// behind the surface). With LIGHTSHAFT_LATTICE the footprint is an n x n lattice and each
// vertex also evaluates the smooth factors' mean over its slab for the fragments to interpolate.
//VTK::LightShaft::Features

in vec4 sliceVertex;
flat out float slabIndex;

// (P[2][2], P[3][2], P[2][3], P[3][3]) of the scene projection P (glm indexing: [column][row]).
uniform vec4 depthProjection;

#ifdef LIGHTSHAFT_LATTICE
out vec3 latticeSmooth;

uniform float slabStart;
uniform float slabEnd;
uniform float slabThickness;
uniform float lastSlab;
uniform float latticeSlabShift; // -0.5 with jitter: the pixels' slabs straddle the nominal one

//VTK::LightShaft::Common
//VTK::LightShaft::Integrand
#endif

void main()
{
  float viewZ = -sliceVertex.w;
  float clipZ = depthProjection.x * viewZ + depthProjection.y;
  float clipW = depthProjection.z * viewZ + depthProjection.w;
  gl_Position = vec4(sliceVertex.xy, clipZ / clipW, 1.0);
  slabIndex = sliceVertex.z;
#ifdef LIGHTSHAFT_LATTICE
  vec3 originVC;
  vec3 dirVC;
  lightShaftViewRayNDC(sliceVertex.xy, originVC, dirVC);
  float k = slabIndex + latticeSlabShift;
  float nearDepth = clamp(slabStart + k * slabThickness, slabStart, slabEnd);
  float farDepth = clamp(slabStart + (k + 1.0) * slabThickness, slabStart, slabEnd);
  float tPerDepth = -1.0 / dirVC.z;
  float b;
  vec3 foot;
  lightShaftRayFoot(originVC, dirVC, b, foot);
  float x0 = nearDepth * tPerDepth + b;
  float x1 = max(farDepth * tPerDepth + b, x0);
  // The part of the slab the light reaches, as the fragments integrate it (the surface cut is
  // left to them): near the cone's edge the spot factor inside differs from the whole slab's.
  float litIn;
  float litOut;
  if (lightShaftLightInterval(foot, dirVC, litIn, litOut) && min(x1, litOut) > max(x0, litIn))
  {
    x0 = max(x0, litIn);
    x1 = min(x1, litOut);
  }
  bool constantA = attenuationCoefficients.y == 0.0 && attenuationCoefficients.z == 0.0;
  float h = lightShaftAngleScale(dot(foot, foot), x0, x1);
  vec3 middleVC;
  float middleR;
  float middleSinTheta;
  latticeSmooth = lightShaftSmoothMean(originVC, dirVC, b, h, constantA,
    constantA ? x0 : atan(x0, h), constantA ? x1 : atan(x1, h), middleVC, middleR,
    middleSinTheta);
#endif
}
