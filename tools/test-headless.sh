#!/usr/bin/env bash
# Proves the pass on VTK built for headless rendering, with no X server: for each backend (EGL,
# OSMesa; default both, or those named on the command line):
#   1. builds that VTK, or reuses it when already built (tools/build-headless-vtk.sh);
#   2. builds the pass's C++ library and C++ tests against it in build-headless-<backend>/
#      (no Python, no ParaView: that VTK has neither);
#   3. runs their ctest tests with DISPLAY unset: the image regression against the X build's
#      baseline, the geometry, the accuracy against the float64 reference and the X build's
#      stored in-scatter, the contexts (1x1, 4096x4096, resizes, windows re-created), the
#      installed package; the accuracy and context tests fail unless VTK rendered through that
#      backend's window class (vtkEGLRenderWindow, vtkOSOpenGLRenderWindow).
# One result line per backend ("egl ... passed"), then "N passed, N failed"; the exit status is
# non-zero when any backend failed, including one that could not be built (with the reason).
#
#   tools/test-headless.sh [egl] [osmesa]
set -euo pipefail
cd "$(dirname "$0")/.."

# No X server: nothing here may reach one, even when the caller has a display.
unset DISPLAY WAYLAND_DISPLAY XAUTHORITY

root=${LIGHTSHAFTS_HEADLESS_ROOT:-/opt/lightshafts}
export CCACHE_DIR=${CCACHE_DIR:-$root/ccache}
jobs=$(nproc 2>/dev/null || echo 2)
backends=("$@")
[ ${#backends[@]} -gt 0 ] || backends=(egl osmesa)

passed=0
failed=0
results=()
start=$(date +%s)

# Runs one backend; prints its figures; returns non-zero with the reason on stderr.
run_backend() {
  local backend=$1 window build prefix log
  case "$backend" in
    egl) window=vtkEGLRenderWindow ;;
    osmesa) window=vtkOSOpenGLRenderWindow ;;
    *)
      echo "unknown backend '$backend' (egl, osmesa)" >&2
      return 1
      ;;
  esac
  build=build-headless-$backend
  prefix=$root/vtk-9.1-$backend
  log=$build/build.log
  mkdir -p "$build"

  if ! tools/build-headless-vtk.sh "$backend"; then
    echo "its VTK could not be built (tools/build-headless-vtk.sh $backend, above)" >&2
    return 1
  fi

  local launcher=()
  command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  echo "== [$backend] building LightShafts against $prefix in $build/ (log: $log)"
  if ! {
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
      "-DVTK_DIR=$prefix/lib/cmake/vtk-9.1" \
      -DLIGHTSHAFTS_WRAP_PYTHON=OFF -DLIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN=OFF \
      "-DLIGHTSHAFTS_EXPECTED_RENDER_WINDOW=$window" "${launcher[@]}" &&
      cmake --build "$build" -j "$jobs"
  } > "$log" 2>&1; then
    tail -30 "$log" >&2
    echo "LightShafts did not configure or build against $prefix ($log)" >&2
    return 1
  fi
  # What VTK was found must be the headless one.
  if ! grep -qx "VTK_DIR:[A-Z]*=$prefix/lib/cmake/vtk-9.1" "$build/CMakeCache.txt"; then
    echo "$build/ was configured with another VTK: $(grep '^VTK_DIR:' "$build/CMakeCache.txt")" >&2
    return 1
  fi

  # Nor may the tests load any X library (Debian's VTK links libX11 and libGLX).
  local x_libraries
  x_libraries=$(ldd "$build/bin/TestLightShaftPass" | grep -oE 'lib(X11|xcb|GLX)[^ ]*' | sort -u |
    tr '\n' ' ' || true)
  if [ -n "$x_libraries" ]; then
    echo "the tests built against $prefix load X libraries: $x_libraries" >&2
    return 1
  fi

  echo "== [$backend] ctest, DISPLAY unset, no X library loaded"
  if ! ctest --test-dir "$build" --output-on-failure -j 1 > "$build/ctest.log" 2>&1; then
    cat "$build/ctest.log" >&2
    echo "ctest failed ($build/ctest.log)" >&2
    return 1
  fi
  # Every test this script stands for must have run and passed (no test left out or skipped).
  local test_name
  for test_name in LightShaftGeometry LightShaftPass.ImageRegression LightShaftAccuracy \
    LightShaftContexts LightShafts.InstalledPackage; do
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

for backend in "${backends[@]}"; do
  backend_start=$(date +%s)
  reason_file=$(mktemp)
  if run_backend "$backend" 2> "$reason_file"; then
    cat "$reason_file" >&2
    results+=("$backend: passed ($(($(date +%s) - backend_start)) s)")
    passed=$((passed + 1))
  else
    cat "$reason_file" >&2
    reason=$(tail -1 "$reason_file")
    results+=("$backend: FAILED: ${reason:-see above} ($(($(date +%s) - backend_start)) s)")
    failed=$((failed + 1))
  fi
  rm -f "$reason_file"
done

echo "== headless backends, no X server ($(($(date +%s) - start)) s in all)"
printf '%s\n' "${results[@]}"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
