//VTK::System::Dec

// One vertex of a slab's screen footprint: xy in NDC, zw the slab's near and far view depths
// (positive distances in front of the camera plane).
in vec4 sliceVertex;
flat out vec2 slabDepths;

void main()
{
  gl_Position = vec4(sliceVertex.xy, 0.0, 1.0);
  slabDepths = sliceVertex.zw;
}
