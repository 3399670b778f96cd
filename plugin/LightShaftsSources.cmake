# The plugin's files by layer (docs/architecture.md, "Layers"), each layer a folder that includes
# only the folders before it:
#   core/       the model, the medium and its fields, geometry, the error and cost models (no GL)
#   reference/  the float64 reference integrator (no GL)
#   gl/         the pass's GL components: resources, shaders, shadow maps, textures, scene,
#               post-processing, composite, refinement, the exact finish
#   methods/    one file per in-scatter method, and the dispatch between them
#   pass/       the public classes that render (vtkLightShaftPass and its split files, the frame
#               report, the reference filter, the fetch-floor probe)
# core/ and reference/ make the VTK module LightShafts::Core (core/vtk.module), gl/, methods/ and
# pass/ the module LightShafts::OpenGL (pass/vtk.module). The ParaView plugin's module
# (paraview/plugin/module) compiles all of them against ParaView's VTK.
set(lightshafts_plugin_dir "${CMAKE_CURRENT_LIST_DIR}")
set(lightshafts_layers core reference gl methods pass)

# Public classes (wrapped, installed).
set(lightshafts_core_public_classes vtkLightShaftMedium)
set(lightshafts_opengl_public_classes
  vtkLightShaftFetchFloor
  vtkLightShaftFrameReport
  vtkLightShaftPass
  vtkLightShaftReference)

# Private classes (not wrapped, not installed), by folder.
set(lightshafts_core_private_classes
  vtkLightShaftCostModel
  vtkLightShaftDensityField
  vtkLightShaftEpipolarGeometry
  vtkLightShaftErrorModel
  vtkLightShaftFieldError
  vtkLightShaftFieldTable
  vtkLightShaftGeometry
  vtkLightShaftGeometryBudget
  vtkLightShaftGeometryClipping
  vtkLightShaftGeometryLights
  vtkLightShaftGeometryLitVolume
  vtkLightShaftGeometrySlabs
  vtkLightShaftModel
  vtkLightShaftNoise
  vtkLightShaftVolumeField)
set(lightshafts_reference_private_classes
  vtkLightShaftReferenceIntegrator
  vtkLightShaftReferenceModel
  vtkLightShaftReferenceJob
  vtkLightShaftReferenceScene
  vtkLightShaftReferenceTriangleTree)
set(lightshafts_gl_private_classes
  vtkLightShaftCasterRender
  vtkLightShaftComposite
  vtkLightShaftExactFinish
  vtkLightShaftFieldTableTexture
  vtkLightShaftInScatterTarget
  vtkLightShaftLightTextures
  vtkLightShaftLights
  vtkLightShaftMediumTexture
  vtkLightShaftPostProcess
  vtkLightShaftRefinement
  vtkLightShaftRendererStep
  vtkLightShaftResources
  vtkLightShaftSceneRenderer
  vtkLightShaftSeparableFilter
  vtkLightShaftShaderText
  vtkLightShaftShaders
  vtkLightShaftShadowMap
  vtkLightShaftSlabDrawer
  vtkLightShaftSurfaceLight
  vtkLightShaftTranslucentLayers
  vtkLightShaftTranslucentPeel
  vtkLightShaftVolumeTexture)
set(lightshafts_methods_private_classes
  vtkLightShaftAnalyticMethod
  vtkLightShaftEpipolarMethod
  vtkLightShaftInScatter
  vtkLightShaftLightVolumeMethod
  vtkLightShaftMethod
  vtkLightShaftRadialBlurMethod
  vtkLightShaftRayMarchMethod
  vtkLightShaftSlicesMethod)
set(lightshafts_pass_private_classes vtkLightShaftSceneCheck)

# Headers without a source file, by folder; and vtkLightShaftPass's second and third source
# files (its read-backs and its choice of sampling).
set(lightshafts_core_private_headers_only
  vtkLightShaftEnums vtkLightShaftErrorModelTable vtkLightShaftMediumInternals
  vtkLightShaftSetters)
set(lightshafts_reference_private_headers_only vtkLightShaftReferenceInput)
set(lightshafts_gl_private_headers_only vtkLightShaftFrame vtkLightShaftOpenGL)
set(lightshafts_methods_private_headers_only)
set(lightshafts_pass_private_headers_only vtkLightShaftPassInternals)
set(lightshafts_pass_split_sources vtkLightShaftPassReadouts vtkLightShaftPassSampling)

# lightshafts_private_files(<sources_var> <headers_var> <layer>...): the private sources and
# headers of the given folders, as absolute paths.
function (lightshafts_private_files sources_var headers_var)
  set(sources)
  set(headers)
  foreach (layer IN LISTS ARGN)
    set(dir "${lightshafts_plugin_dir}/${layer}")
    foreach (class IN LISTS lightshafts_${layer}_private_classes)
      list(APPEND sources "${dir}/${class}.cxx")
      list(APPEND headers "${dir}/${class}.h")
    endforeach ()
    foreach (header IN LISTS lightshafts_${layer}_private_headers_only)
      list(APPEND headers "${dir}/${header}.h")
    endforeach ()
    if (layer STREQUAL "pass")
      foreach (source IN LISTS lightshafts_pass_split_sources)
        list(APPEND sources "${dir}/${source}.cxx")
      endforeach ()
    endif ()
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
