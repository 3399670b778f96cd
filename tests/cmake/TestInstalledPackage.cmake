# Installs the build into a scratch prefix, builds examples/cpp against it with
# find_package(LightShafts), and runs the example: proves the installed CMake package works.
# Variables: BUILD_DIR, SOURCE_DIR, WORK_DIR, VTK_DIR (the VTK the build used, so that the example
# finds that one: Debian's, or a headless build of tools/build-headless-vtk.sh).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${out}")
  endif ()
endfunction ()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/examples/cpp" -B "${WORK_DIR}/example"
  "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DVTK_DIR=${VTK_DIR}" -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/example")
run("${WORK_DIR}/example/window_shafts" "${WORK_DIR}/window_shafts.png")
if (NOT EXISTS "${WORK_DIR}/window_shafts.png")
  message(FATAL_ERROR "the example wrote no image")
endif ()
message(STATUS "installed package: find_package, build and render OK")
