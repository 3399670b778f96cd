# The ParaView plugin (paraview/), built as a separate CMake project: ParaView may bring its own
# VTK (Debian 12's ParaView 5.11: VTK 9.2-based; Debian 13's 5.13: VTK 9.3.20240617), whose
# targets have the same names as the system VTK that the VTK module uses, so the two must never
# be found in one configure (nor loaded in one process). (Debian unstable's ParaView 6.1 uses the
# system VTK 9.6 itself.)
#
# LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN: AUTO (default) builds it when ParaView's CMake package is
# found, ON requires it, OFF skips it. The plugin's build tree is <build>/paraview-plugin; the
# plugin is <build>/paraview-plugin/lib/paraview-X.Y/plugins/LightShafts/LightShafts.so, and
# `cmake --install` installs it to <prefix>/lib/paraview-X.Y/plugins/LightShafts/.
set(LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN "AUTO" CACHE STRING
  "Build the ParaView plugin: AUTO (when ParaView is found), ON, OFF")
set_property(CACHE LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN PROPERTY STRINGS AUTO ON OFF)
set(LIGHTSHAFTS_PYTHON3_PARAVIEW_ROOT "/usr/local/lib/lightshafts/python3-paraview"
  CACHE PATH "Where python3-paraview is unpacked (dpkg -x; tools/quickstart.sh does it)")

include("${CMAKE_CURRENT_LIST_DIR}/LightShaftsFindParaView.cmake")
set(LIGHTSHAFTS_PARAVIEW_PLUGIN_BUILT FALSE)
if (NOT LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN STREQUAL "OFF")
  # Only locate the package here (find_package(ParaView) would import ParaView's VTK targets).
  lightshafts_find_paraview_dir(LIGHTSHAFTS_PARAVIEW_DIR)
  if (LIGHTSHAFTS_PARAVIEW_DIR)
    message(STATUS "ParaView found (${LIGHTSHAFTS_PARAVIEW_DIR}): building the LightShafts "
      "ParaView plugin in ${CMAKE_BINARY_DIR}/paraview-plugin")
    include(ExternalProject)
    ExternalProject_Add(LightShaftsParaViewPlugin
      SOURCE_DIR "${CMAKE_CURRENT_SOURCE_DIR}/paraview"
      BINARY_DIR "${CMAKE_BINARY_DIR}/paraview-plugin"
      CMAKE_ARGS
        "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
        "-DCMAKE_INSTALL_PREFIX=${CMAKE_INSTALL_PREFIX}"
        "-DParaView_DIR=${LIGHTSHAFTS_PARAVIEW_DIR}"
        "-DLIGHTSHAFTS_PYTHON3_PARAVIEW_ROOT=${LIGHTSHAFTS_PYTHON3_PARAVIEW_ROOT}"
      BUILD_ALWAYS ON
      INSTALL_COMMAND ""
      USES_TERMINAL_BUILD ON)
    install(CODE "execute_process(COMMAND \"${CMAKE_COMMAND}\" --install
      \"${CMAKE_BINARY_DIR}/paraview-plugin\" --prefix \"\${CMAKE_INSTALL_PREFIX}\"
      COMMAND_ERROR_IS_FATAL ANY)")
    set(LIGHTSHAFTS_PARAVIEW_PLUGIN_BUILT TRUE)
  elseif (LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN STREQUAL "ON")
    message(FATAL_ERROR "LIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN is ON but ParaView's CMake package "
      "was not found (apt install paraview-dev, or set ParaView_DIR).")
  else ()
    message(STATUS "ParaView not found: the ParaView plugin is not built.")
  endif ()
endif ()
