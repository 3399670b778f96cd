# Where ParaView's CMake package is, without loading it (find_package(ParaView) would import
# ParaView's VTK targets, which may have the same names as the VTK module's). One rule for the
# top-level project and the plugin's (paraview/CMakeLists.txt).
#
#   lightshafts_find_paraview_dir(<variable>)
#
# sets <variable> to ParaView_DIR when that holds a package, else to the newest
# <prefix>/lib[/<arch>]/cmake/paraview-X.Y found under CMAKE_PREFIX_PATH and the system
# prefixes (Debian 12: paraview-5.11, Debian 13: paraview-5.13, unstable: paraview-6.1), else to
# an empty string. The oldest ParaView the plugin supports is LIGHTSHAFTS_PARAVIEW_MIN_VERSION.
set(LIGHTSHAFTS_PARAVIEW_MIN_VERSION 5.10)

function (lightshafts_find_paraview_dir variable)
  set(package_files paraview-config.cmake ParaViewConfig.cmake)
  if (ParaView_DIR)
    foreach (file IN LISTS package_files)
      if (EXISTS "${ParaView_DIR}/${file}")
        set("${variable}" "${ParaView_DIR}" PARENT_SCOPE)
        return ()
      endif ()
    endforeach ()
  endif ()
  set(best_dir "")
  set(best_version "0")
  foreach (prefix IN LISTS CMAKE_PREFIX_PATH CMAKE_SYSTEM_PREFIX_PATH)
    file(GLOB candidates LIST_DIRECTORIES TRUE
      "${prefix}/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-*"
      "${prefix}/lib/cmake/paraview-*")
    foreach (candidate IN LISTS candidates)
      string(REGEX MATCH "paraview-([0-9]+\\.[0-9]+)$" version_match "${candidate}")
      set(version "${CMAKE_MATCH_1}")
      if (NOT version OR version VERSION_LESS LIGHTSHAFTS_PARAVIEW_MIN_VERSION
          OR NOT version VERSION_GREATER best_version)
        continue ()
      endif ()
      foreach (file IN LISTS package_files)
        if (EXISTS "${candidate}/${file}")
          set(best_dir "${candidate}")
          set(best_version "${version}")
        endif ()
      endforeach ()
    endforeach ()
  endforeach ()
  set("${variable}" "${best_dir}" PARENT_SCOPE)
endfunction ()
