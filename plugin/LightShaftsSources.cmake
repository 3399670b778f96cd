# The pass's private components (not installed, not wrapped), compiled into the VTK module
# (plugin/CMakeLists.txt) and into the ParaView plugin's module (paraview/plugin/module).
set(lightshafts_private_classes
  vtkLightShaftAnalyticMethod
  vtkLightShaftCasterRender
  vtkLightShaftComposite
  vtkLightShaftCostModel
  vtkLightShaftDensityField
  vtkLightShaftEpipolar
  vtkLightShaftEpipolarMethod
  vtkLightShaftErrorModel
  vtkLightShaftExactFinish
  vtkLightShaftFieldError
  vtkLightShaftFieldShadow
  vtkLightShaftFieldTable
  vtkLightShaftGeometry
  vtkLightShaftInScatter
  vtkLightShaftInScatterTarget
  vtkLightShaftLightTextures
  vtkLightShaftLightVolumeMethod
  vtkLightShaftLights
  vtkLightShaftMediumTexture
  vtkLightShaftMethod
  vtkLightShaftModel
  vtkLightShaftNoise
  vtkLightShaftPostProcess
  vtkLightShaftRadialBlurMethod
  vtkLightShaftRayIntegrator
  vtkLightShaftRayMarchMethod
  vtkLightShaftReferenceJob
  vtkLightShaftReferenceScene
  vtkLightShaftRefinement
  vtkLightShaftRendererStep
  vtkLightShaftResources
  vtkLightShaftSceneCheck
  vtkLightShaftSceneRenderer
  vtkLightShaftSeparableFilter
  vtkLightShaftShaderText
  vtkLightShaftShaders
  vtkLightShaftShadowMap
  vtkLightShaftSlabDrawer
  vtkLightShaftSlicesMethod
  vtkLightShaftSurfaceLight
  vtkLightShaftTranslucentLayers
  vtkLightShaftTranslucentPeel
  vtkLightShaftTriangleTree
  vtkLightShaftVolumeField
  vtkLightShaftVolumeTexture)
# vtkLightShaftPass's read-backs and its choice of sampling are compiled with it (the public
# class's second and third source files).
set(lightshafts_private_sources "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftPassReadouts.cxx"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftPassSampling.cxx")
set(lightshafts_private_headers
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftEnums.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftFrame.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftErrorModelTable.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftMediumInternals.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftOpenGL.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftPassInternals.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftReferenceInput.h"
  "${CMAKE_CURRENT_LIST_DIR}/vtkLightShaftSetters.h")
foreach (class IN LISTS lightshafts_private_classes)
  list(APPEND lightshafts_private_sources "${CMAKE_CURRENT_LIST_DIR}/${class}.cxx")
  list(APPEND lightshafts_private_headers "${CMAKE_CURRENT_LIST_DIR}/${class}.h")
endforeach ()
# The public classes the pass's sources need besides it: what the medium is and what the last
# frame did (wrapped and installed by the VTK module; compiled into the ParaView plugin's too).
set(lightshafts_pass_public_classes
  vtkLightShaftFrameReport
  vtkLightShaftMedium)
