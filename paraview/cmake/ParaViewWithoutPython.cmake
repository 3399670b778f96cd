# Debian 12's paraview-dev describes ParaView's Python modules and pvpython
# (VTKPython-targets.cmake, ParaViewPython-targets.cmake, ParaViewTools-targets.cmake), whose
# files come with python3-paraview. That package conflicts
# with python3-vtk9 (the VTK module's bindings), so it is usually not installed, and CMake's
# generated target files then stop with "references the file ... but this file does not exist".
# The plugin does not use those targets: when their files are missing, declare them as empty
# imported targets first, which makes the generated files return early ("already imported").
function (lightshafts_stub_missing_paraview_python_targets paraview_dir)
  foreach (targets_file IN ITEMS
      "${paraview_dir}/vtk/VTKPython-targets.cmake"
      "${paraview_dir}/ParaViewPython-targets.cmake"
      "${paraview_dir}/ParaViewTools-targets.cmake")
    if (NOT EXISTS "${targets_file}")
      continue ()
    endif ()
    file(STRINGS "${targets_file}" expected REGEX "^foreach\\(_(cmake_)?expected_target IN ITEMS ")
    string(REGEX REPLACE "^foreach\\(_(cmake_)?expected_target IN ITEMS (.*)\\)$" "\\2"
      expected "${expected}")
    string(REPLACE " " ";" expected "${expected}")
    # Are all the files there? (python3-paraview installed: nothing to do.)
    string(REGEX REPLACE "\\.cmake$" "-*.cmake" config_glob "${targets_file}")
    file(GLOB config_files "${config_glob}")
    # _IMPORT_PREFIX is four levels above <prefix>/lib/<arch>/cmake/paraview-X.Y.
    get_filename_component(prefix "${paraview_dir}/../../../.." ABSOLUTE)
    set(missing FALSE)
    foreach (config_file IN LISTS config_files)
      file(STRINGS "${config_file}" locations REGEX "IMPORTED_LOCATION_")
      foreach (location IN LISTS locations)
        string(REGEX REPLACE ".*\\$\\{_IMPORT_PREFIX\\}([^\"]*)\".*" "\\1" file "${location}")
        if (NOT EXISTS "${prefix}${file}")
          set(missing TRUE)
        endif ()
      endforeach ()
    endforeach ()
    if (missing)
      message(STATUS "Some targets of ${targets_file} have no files "
        "(python3-paraview not installed): stubbing them; the plugin does not need them.")
      foreach (target IN LISTS expected)
        if (NOT TARGET "${target}")
          add_library("${target}" INTERFACE IMPORTED GLOBAL)
        endif ()
      endforeach ()
    endif ()
  endforeach ()
endfunction ()

# The client-server wrapping of the plugin's module reads the "hierarchy" files of the modules
# it depends on; Debian ships ParaView's in python3-paraview as well
# (<libdir>/vtk/hierarchy/ParaView). Without that package installed, take them from a copy of
# its files unpacked elsewhere (tools/quickstart.sh: dpkg -x into `root`), by pointing the
# imported targets' hierarchy property there.
function (lightshafts_use_unpacked_paraview_hierarchy root)
  get_property(targets DIRECTORY PROPERTY IMPORTED_TARGETS)
  set(redirected 0)
  set(missing "")
  foreach (target IN LISTS targets)
    get_property(hierarchy TARGET "${target}" PROPERTY INTERFACE_vtk_module_hierarchy)
    if (NOT hierarchy OR EXISTS "${hierarchy}")
      continue ()
    endif ()
    set(unpacked "${root}${hierarchy}")
    if (EXISTS "${unpacked}")
      set_property(TARGET "${target}" PROPERTY INTERFACE_vtk_module_hierarchy "${unpacked}")
      math(EXPR redirected "${redirected} + 1")
    else ()
      list(APPEND missing "${hierarchy}")
    endif ()
  endforeach ()
  if (redirected)
    message(STATUS "Wrapping hierarchy of ${redirected} ParaView modules taken from ${root}")
  endif ()
  set(LIGHTSHAFTS_MISSING_PARAVIEW_HIERARCHY "${missing}" PARENT_SCOPE)
endfunction ()
