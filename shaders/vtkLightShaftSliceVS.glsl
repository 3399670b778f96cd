//VTK::System::Dec

// One vertex of a slab's screen footprint: xy in NDC, z the slab's index, w the view depth the
// footprint starts at (the slab is drawn there so that the depth test culls it where it starts
// behind the surface).
in vec4 sliceVertex;
flat out float slabIndex;

// (P[2][2], P[3][2], P[2][3], P[3][3]) of the scene projection P (glm indexing: [column][row]).
uniform vec4 depthProjection;

void main()
{
  float viewZ = -sliceVertex.w;
  float clipZ = depthProjection.x * viewZ + depthProjection.y;
  float clipW = depthProjection.z * viewZ + depthProjection.w;
  gl_Position = vec4(sliceVertex.xy, clipZ / clipW, 1.0);
  slabIndex = sliceVertex.z;
}
