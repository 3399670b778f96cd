#!/usr/bin/env bash
# Proves the pass rendering with no X server, through EGL (Mesa's EGL on llvmpipe, or a GPU's)
# and OSMesa (CPU only), on the route the system's VTK offers (docs/headless.md):
#
#   run-time choice (VTK 9.4 and later: Debian unstable's 9.6): the distribution's VTK picks its
#     window class when a window is made (VTK_DEFAULT_OPENGL_WINDOW). Per backend whose library
#     the system has (EGL: Mesa's libEGL; OSMesa: libOSMesa, which Mesa 25.1 dropped), with
#     DISPLAY unset: the pass's C++ tests built against the system VTK in
#     build-headless-<backend>/ and run by ctest, then the Python tests that render through
#     windows (the pass's rendering and API, PyVista, the examples) with the quick start's
#     build/, and ParaView's render test when the plugin was built (ParaView 6.1 on the system's
#     VTK). All fail unless VTK rendered through that backend's class.
#   built VTK (Debian 12's VTK 9.1, which fixes its window system when it is built: one VTK per
#     backend): tools/build-headless-vtk.sh builds (or reuses) VTK 9.1 for the backend, then
#     the pass's C++ library and tests against it in build-headless-<backend>/, run by ctest
#     with DISPLAY unset; the tests must load no X library (ldd) and render through that
#     backend's class.
#   VTK 9.2 and 9.3 (Debian 13's 9.3) have neither: their distribution builds are X only and
#     this script builds only Debian 12's VTK 9.1 source. It says so and tests nothing.
#
# The ctest tests, on either route: the image regression against the X build's baseline, the
# geometry, the accuracy against the float64 reference and the X build's stored in-scatter,
# the contexts (1x1, 4096x4096, resizes, windows re-created), the installed package.
# One result line per backend ("egl: passed (...)", or "osmesa: not available: ..." where the
# system cannot have it), then "N passed, N failed" (and "N not available"); the exit status is
# non-zero when any backend failed, including one that could not be built (with the reason).
#
#   tools/test-headless.sh [egl] [osmesa]
#
# Environment: LIGHTSHAFTS_HEADLESS_ROUTE=runtime|built (default: from the system VTK's version),
# and for the built route those of tools/build-headless-vtk.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

# No X server: nothing here may reach one, even when the caller has a display.
unset DISPLAY WAYLAND_DISPLAY XAUTHORITY

root=${LIGHTSHAFTS_HEADLESS_ROOT:-/opt/lightshafts}
export CCACHE_DIR=${CCACHE_DIR:-$root/ccache}
jobs=$(nproc 2>/dev/null || echo 2)
backends=("$@")
[ ${#backends[@]} -gt 0 ] || backends=(egl osmesa)

# The system VTK's version (libvtk9-dev's CMake package), e.g. 9.6.
system_vtk_dir=$(ls -d /usr/lib/*/cmake/vtk-9.* /usr/lib/cmake/vtk-9.* 2> /dev/null | sort -V |
  tail -1 || true)
system_vtk=${system_vtk_dir##*/vtk-}
route=${LIGHTSHAFTS_HEADLESS_ROUTE:-}
if [ -z "$route" ]; then
  case "$system_vtk" in
    9.[0-3]) route=built ;;
    "") route=built ;;
    *) route=runtime ;;
  esac
  if [ "$route" = built ] && [ -n "$system_vtk" ] && [ "$system_vtk" != 9.1 ]; then
    echo "== headless: the system's VTK $system_vtk picks its window system when it is built" \
      "(its Debian build: X only), and tools/build-headless-vtk.sh builds Debian 12's VTK 9.1" \
      "only: no headless route here (docs/headless.md)"
    echo "0 passed, 0 failed, ${#backends[@]} not available"
    exit 0
  fi
fi
echo "== headless route: $route (system VTK ${system_vtk:-none})"

passed=0
failed=0
unavailable=0
results=()
start=$(date +%s)

window_class() {
  case "$1" in
    egl) echo vtkEGLRenderWindow ;;
    osmesa) echo vtkOSOpenGLRenderWindow ;;
    *) return 1 ;;
  esac
}

# ctest in $1 with DISPLAY unset (and the environment given after it); every test this script
# stands for must have run and passed.
run_ctest() {
  local build=$1 backend=$2 test_name
  shift 2
  echo "== [$backend] ctest, DISPLAY unset"
  if ! env "$@" ctest --test-dir "$build" --output-on-failure -j 1 > "$build/ctest.log" 2>&1; then
    cat "$build/ctest.log" >&2
    echo "ctest failed ($build/ctest.log)" >&2
    return 1
  fi
  for test_name in LightShaftGeometry LightShaftReferenceCore LightShafts.CoreWithoutOpenGL \
    LightShaftPass.ImageRegression LightShaftAccuracy LightShaftContexts \
    LightShafts.InstalledPackage; do
    if ! grep -qE "Test +#[0-9]+: $test_name \.+ +Passed" "$build/ctest.log"; then
      cat "$build/ctest.log" >&2
      echo "ctest did not run and pass $test_name ($build/ctest.log)" >&2
      return 1
    fi
  done
  grep -E "tests passed|Total Test time" "$build/ctest.log"
  # The figures the tests print (their full output: $build/Testing/Temporary/LastTest.log).
  grep -E "^(mean absolute difference|accuracy:|contexts:)" \
    "$build/Testing/Temporary/LastTest.log" | sed "s/^/   [$backend] /"
}

# Configures and builds the library and the C++ tests in $1 against the VTK in $2 (a CMake
# package directory), expecting window class $3.
build_tests() {
  local build=$1 vtk_dir=$2 window=$3 log
  log=$build/build.log
  mkdir -p "$build"
  local launcher=()
  command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  echo "== building LightShafts against $vtk_dir in $build/ (log: $log)"
  if ! {
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "-DVTK_DIR=$vtk_dir" \
      -DLIGHTSHAFTS_WRAP_PYTHON=OFF -DLIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN=OFF \
      "-DLIGHTSHAFTS_EXPECTED_RENDER_WINDOW=$window" "${launcher[@]}" &&
      cmake --build "$build" -j "$jobs"
  } > "$log" 2>&1; then
    tail -30 "$log" >&2
    echo "LightShafts did not configure or build against $vtk_dir ($log)" >&2
    return 1
  fi
  # What VTK was found must be the one asked for.
  if ! grep -qx "VTK_DIR:[A-Z]*=$vtk_dir" "$build/CMakeCache.txt"; then
    echo "$build/ was configured with another VTK: $(grep '^VTK_DIR:' "$build/CMakeCache.txt")" >&2
    return 1
  fi
}

# The run-time route for one backend. Returns 3 (with the reason) when the system cannot have it.
run_runtime_backend() {
  local backend=$1 window build
  window=$(window_class "$backend") || {
    echo "unknown backend '$backend' (egl, osmesa)" >&2
    return 1
  }
  # (grep reads all of ldconfig's list, not -q: under pipefail, grep -q leaving at the first
  # match can end ldconfig by SIGPIPE, and the pipeline then fails though the library is there.)
  case "$backend" in
    egl)
      if ! ldconfig -p | grep -E 'libEGL_mesa\.so|libEGL\.so\.1' > /dev/null; then
        echo "not available: no EGL library (apt install libegl1 libegl-mesa0)" >&2
        return 3
      fi
      ;;
    osmesa)
      if ! ldconfig -p | grep 'libOSMesa\.so' > /dev/null; then
        echo "not available: this system's Mesa has no OSMesa (Mesa 25.1 removed it)" >&2
        return 3
      fi
      ;;
  esac
  build=build-headless-$backend
  build_tests "$build" "$system_vtk_dir" "$window" || return 1
  run_ctest "$build" "$backend" "VTK_DEFAULT_OPENGL_WINDOW=$window" || return 1

  # The Python tests that render through windows, with the quick start's build.
  if [ ! -f build/CMakeCache.txt ]; then
    echo "build/ not found (tools/quickstart.sh): the Python tests could not run" >&2
    return 1
  fi
  local python_dir
  python_dir=$(sed -n 's/^LIGHTSHAFTS_PYTHON_DESTINATION:STRING=//p' build/CMakeCache.txt)
  echo "== [$backend] Python tests through $window, DISPLAY unset"
  if ! env "VTK_DEFAULT_OPENGL_WINDOW=$window" "LIGHTSHAFTS_EXPECTED_RENDER_WINDOW=$window" \
    "PYTHONPATH=$PWD/build/$python_dir${PYTHONPATH:+:$PYTHONPATH}" \
    /usr/bin/python3 -m pytest -p no:cacheprovider -q tests/python/test_render.py \
    tests/python/test_api.py tests/python/test_multisample.py tests/python/test_selection.py \
    tests/python/test_pyvista.py tests/python/test_examples.py > "$build/pytest.log" 2>&1; then
    tail -40 "$build/pytest.log" >&2
    echo "Python tests failed ($build/pytest.log)" >&2
    return 1
  fi
  tail -1 "$build/pytest.log" | sed "s/^/   [$backend] pytest: /"

  # ParaView on the system's VTK (Debian unstable's 6.1) takes the same route: the plugin's
  # render test through the backend's class.
  local listing=$PWD/build/paraview-plugin/LightShaftsPluginPath.txt
  if command -v pvbatch > /dev/null && [ -f "$listing" ]; then
    echo "== [$backend] ParaView's render test through $window, DISPLAY unset"
    if ! env "VTK_DEFAULT_OPENGL_WINDOW=$window" "LIGHTSHAFTS_EXPECTED_RENDER_WINDOW=$window" \
      "LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST=$listing" \
      pvbatch tests/paraview/test_render.py "$build/paraview" > "$build/paraview.log" 2>&1 ||
      grep -qE "FAIL:|ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$build/paraview.log"; then
      cat "$build/paraview.log" >&2
      echo "ParaView's render test failed ($build/paraview.log)" >&2
      return 1
    fi
    grep -E "^(baseline|in-scatter|shafts off)" "$build/paraview.log" | sed "s/^/   [$backend] ParaView: /"
  fi
}

# The built-VTK route for one backend (Debian 12's VTK 9.1).
run_built_backend() {
  local backend=$1 window build prefix
  window=$(window_class "$backend") || {
    echo "unknown backend '$backend' (egl, osmesa)" >&2
    return 1
  }
  build=build-headless-$backend
  prefix=$root/vtk-9.1-$backend
  if ! tools/build-headless-vtk.sh "$backend"; then
    echo "its VTK could not be built (tools/build-headless-vtk.sh $backend, above)" >&2
    return 1
  fi
  build_tests "$build" "$prefix/lib/cmake/vtk-9.1" "$window" || return 1
  # Nor may the tests load any X library (Debian's VTK links libX11 and libGLX).
  local x_libraries
  x_libraries=$(ldd "$build/bin/TestLightShaftPass" | grep -oE 'lib(X11|xcb|GLX)[^ ]*' | sort -u |
    tr '\n' ' ' || true)
  if [ -n "$x_libraries" ]; then
    echo "the tests built against $prefix load X libraries: $x_libraries" >&2
    return 1
  fi
  run_ctest "$build" "$backend"
}

for backend in "${backends[@]}"; do
  backend_start=$(date +%s)
  reason_file=$(mktemp)
  outcome=0
  "run_${route}_backend" "$backend" 2> "$reason_file" || outcome=$?
  cat "$reason_file" >&2
  reason=$(tail -1 "$reason_file")
  rm -f "$reason_file"
  elapsed="$(($(date +%s) - backend_start)) s"
  case "$outcome" in
    0)
      results+=("$backend: passed ($route, $elapsed)")
      passed=$((passed + 1))
      ;;
    3)
      results+=("$backend: $reason")
      unavailable=$((unavailable + 1))
      ;;
    *)
      results+=("$backend: FAILED: ${reason:-see above} ($route, $elapsed)")
      failed=$((failed + 1))
      ;;
  esac
done

echo "== headless backends, no X server ($(($(date +%s) - start)) s in all)"
printf '%s\n' "${results[@]}"
if [ "$unavailable" -gt 0 ]; then
  echo "$passed passed, $failed failed, $unavailable not available"
else
  echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
