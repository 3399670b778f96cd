# The GLSL sources vtkLightShaftPass embeds (vtk_encode_string), shared by the VTK module
# (plugin/CMakeLists.txt) and the ParaView plugin's module (paraview/plugin/module).
set(lightshafts_pass_shaders
  vtkLightShaftBlurFS
  vtkLightShaftCommon
  vtkLightShaftCompositeFS
  vtkLightShaftDepthDownsampleFS
  vtkLightShaftIntegrand
  vtkLightShaftOcclusionFS
  vtkLightShaftRadialBlurFS
  vtkLightShaftResolveFS
  vtkLightShaftSliceFS
  vtkLightShaftSliceVS
  vtkLightShaftUpsampleFS)
