# Debian's paraview-dev describes ParaView's Python modules and pvpython (e.g.
# VTKPython-targets.cmake, ParaViewPython-targets.cmake, ParaViewTools-targets.cmake, and from
# ParaView 5.13 ParaViewPythonIncubator-targets.cmake), whose files come with python3-paraview.
# Up to ParaView 5.13 that package conflicts with python3-vtk9 (the VTK module's bindings), so
# it is usually not installed, and CMake's generated target files then stop with "references the
# file ... but this file does not exist". The plugin does not use those targets: for every
# targets file of the package whose files are missing, declare its targets as empty imported
# targets first, which makes the generated file return early ("already imported").
function (lightshafts_stub_missing_paraview_python_targets paraview_dir)
  file(GLOB targets_files "${paraview_dir}/*-targets.cmake" "${paraview_dir}/vtk/*-targets.cmake")
  foreach (targets_file IN LISTS targets_files)
    # (<name>-targets-<config>.cmake are the per-configuration parts of <name>-targets.cmake.)
    if (targets_file MATCHES "-targets-[^/]*\\.cmake$")
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

# The modules that `modules` depend on, directly or not, themselves included: through the
# dependency kinds named (depends, private_depends, optional_depends: the module properties).
function (lightshafts_vtk_module_closure variable kinds)
  set(queue ${ARGN})
  set(closure "")
  while (queue)
    list(POP_FRONT queue module)
    if (module IN_LIST closure OR NOT TARGET "${module}")
      continue ()
    endif ()
    list(APPEND closure "${module}")
    foreach (kind IN LISTS kinds)
      get_property(depends TARGET "${module}" PROPERTY "INTERFACE_vtk_module_${kind}")
      list(APPEND queue ${depends})
    endforeach ()
  endwhile ()
  set("${variable}" "${closure}" PARENT_SCOPE)
endfunction ()

# The client-server wrapping of the plugin's module reads the "hierarchy" files of the modules
# it depends on; Debian 12 and 13 ship ParaView's in python3-paraview as well
# (<libdir>/vtk/hierarchy/ParaView). Without that package installed, take them from a copy of
# its files unpacked elsewhere (tools/quickstart.sh: dpkg -x into `root`), by pointing the
# imported targets' hierarchy property there. Sets LIGHTSHAFTS_MISSING_PARAVIEW_HIERARCHY to
# the files still missing for the given modules (the ones the plugin's wrapping reads; a
# hierarchy of another module may be missing: Debian unstable ships some, e.g.
# vtkRenderingQt's, in packages the plugin does not need).
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
    elseif (target IN_LIST ARGN)
      list(APPEND missing "${hierarchy}")
    endif ()
  endforeach ()
  if (redirected)
    message(STATUS "Wrapping hierarchy of ${redirected} ParaView modules taken from ${root}")
  endif ()
  set(LIGHTSHAFTS_MISSING_PARAVIEW_HIERARCHY "${missing}" PARENT_SCOPE)
endfunction ()

# ParaView's package asks its VTK package only for the VTK modules that the requested ParaView
# components depend on directly. Modules deeper in the dependency graph are imported without
# the packages their targets link (ParaView 5.13: VTK::hdf5 links hdf5::hdf5, VTK::netcdf links
# NetCDF::NetCDF), and the plugin's generate step fails with "The link interface of target
# VTK::hdf5 contains hdf5::hdf5 but the target was not found" when the module system walks into
# them (optional dependencies too). Ask VTK's package for every given module whose linked
# targets are missing: it finds their packages (installed with paraview-dev).
function (lightshafts_find_vtk_module_packages)
  set(incomplete "")
  foreach (module IN LISTS ARGN)
    if (NOT module MATCHES "^VTK::(.+)$")
      continue ()
    endif ()
    set(name "${CMAKE_MATCH_1}")
    # The module's linked targets, and theirs where they are libraries the module builds
    # itself (VTK::xdmf3 links VTK::vtkxdmfcore, which links Boost::boost).
    set(linked_queue "${module}")
    set(linked_seen "")
    while (linked_queue)
      list(POP_FRONT linked_queue target)
      if (target IN_LIST linked_seen)
        continue ()
      endif ()
      list(APPEND linked_seen "${target}")
      if (NOT TARGET "${target}")
        list(APPEND incomplete "${name}")
        break ()
      endif ()
      get_property(links TARGET "${target}" PROPERTY INTERFACE_LINK_LIBRARIES)
      string(REGEX MATCHALL "[A-Za-z0-9_]+::[A-Za-z0-9_.+-]+" linked "${links}")
      foreach (next IN LISTS linked)
        if (NOT TARGET "${next}" OR (next MATCHES "^VTK::" AND NOT next IN_LIST ARGN))
          list(APPEND linked_queue "${next}")
        endif ()
      endforeach ()
    endwhile ()
  endforeach ()
  list(REMOVE_DUPLICATES incomplete)
  if (incomplete)
    message(STATUS "Finding the packages of VTK modules that ParaView's package left out: "
      "${incomplete}")
    find_package(VTK QUIET COMPONENTS ${incomplete})
  endif ()
endfunction ()
