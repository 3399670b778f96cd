//VTK::System::Dec

// One vertex of a slab's screen footprint: xy in NDC, zw the slab's near and far view depths
// (positive distances in front of the camera plane).
in vec4 sliceVertex;
flat out vec2 slabDepths;

// (P[2][2], P[3][2], P[2][3], P[3][3]) of the scene projection P (glm indexing: [column][row]),
// to place the slab at its near depth so that the depth test culls slabs behind surfaces.
uniform vec4 depthProjection;

void main()
{
  float viewZ = -sliceVertex.z;
  float clipZ = depthProjection.x * viewZ + depthProjection.y;
  float clipW = depthProjection.z * viewZ + depthProjection.w;
  gl_Position = vec4(sliceVertex.xy, clipZ / clipW, 1.0);
  slabDepths = sliceVertex.zw;
}
