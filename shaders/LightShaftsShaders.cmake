# The GLSL sources vtkLightShaftPass embeds (vtk_encode_string), shared by the VTK module
# (plugin/pass/CMakeLists.txt) and the ParaView plugin's module (paraview/plugin/module).
set(lightshafts_pass_shaders
  vtkLightShaftAddFS
  vtkLightShaftAnalyticFS
  vtkLightShaftBlurFS
  vtkLightShaftCameraLayers
  vtkLightShaftCommon
  vtkLightShaftCompositeFS
  vtkLightShaftDepthDownsampleFS
  vtkLightShaftDepthResolveFS
  vtkLightShaftEpipolarFS
  vtkLightShaftEpipolarMarkFS
  vtkLightShaftExactFinishFS
  vtkLightShaftField
  vtkLightShaftIntegrand
  vtkLightShaftLightKind
  vtkLightShaftLightSpace
  vtkLightShaftLightVolumeFS
  vtkLightShaftLightVolumeVS
  vtkLightShaftOcclusionFS
  vtkLightShaftRadialBlurFS
  vtkLightShaftRayMarchFS
  vtkLightShaftRefineFS
  vtkLightShaftResolveFS
  vtkLightShaftSegment
  vtkLightShaftSlabVS
  vtkLightShaftSliceFS
  vtkLightShaftSurfaceLightFS
  vtkLightShaftUpsampleFS
  vtkLightShaftVolume)
set(lightshafts_shader_dir "${CMAKE_CURRENT_LIST_DIR}")

# Embed shaders/<name>.glsl for each name as C strings; the generated sources and headers are
# returned in <sources_var> and <headers_var>.
function (lightshafts_encode_shaders sources_var headers_var)
  set(sources)
  set(headers)
  foreach (shader IN LISTS ARGN)
    vtk_encode_string(
      INPUT         "${lightshafts_shader_dir}/${shader}.glsl"
      NAME          "${shader}"
      HEADER_OUTPUT header
      SOURCE_OUTPUT source)
    list(APPEND sources "${source}")
    list(APPEND headers "${header}")
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
