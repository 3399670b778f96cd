#!/usr/bin/env bash
# Builds a minimal VTK 9.1 for headless rendering, with no X: EGL (Mesa's EGL on llvmpipe, or a
# GPU's) or OSMesa (CPU only). Debian 12's own VTK 9.1 is X/GLX only, and VTK 9.1 fixes its
# window system when it is built (one of EGL or OSMesa per build), hence one build per backend.
#
#   tools/build-headless-vtk.sh egl|osmesa
#
# What it does:
#   1. apt-installs what the build needs (non-interactive; nothing when all is there), adding a
#      deb-src entry for Debian's sources when apt has none;
#   2. fetches Debian's VTK 9.1 and GLEW 2.2 sources (apt-get source) into $root/src;
#   3. builds GLEW for the backend (Debian's libGLEW is GLX only: under EGL, VTK then stops with
#      "GLEW could not be initialized") and installs it into the prefix;
#   4. configures VTK with only the modules the pass and its C++ tests need, no Python, no X,
#      and builds and installs it into $root/vtk-9.1-<backend> (compiles go through ccache);
#   5. writes a stamp (sources, options, compiler): when the stamp matches, nothing is rebuilt.
#
# Then: cmake -S . -B <build> -DVTK_DIR=$root/vtk-9.1-<backend>/lib/cmake/vtk-9.1
#         -DLIGHTSHAFTS_WRAP_PYTHON=OFF -DLIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN=OFF
# (tools/test-headless.sh does it and runs the C++ tests with no X server).
#
# Environment: LIGHTSHAFTS_HEADLESS_ROOT (default /opt/lightshafts), CCACHE_DIR (default
# $root/ccache), LIGHTSHAFTS_JOBS (default: nproc).
set -euo pipefail
shopt -s inherit_errexit # command substitutions stop at the first failure too

backend=${1:-}
case "$backend" in
  egl | osmesa) ;;
  *)
    echo "usage: $0 egl|osmesa" >&2
    exit 2
    ;;
esac

root=${LIGHTSHAFTS_HEADLESS_ROOT:-/opt/lightshafts}
prefix=$root/vtk-9.1-$backend
src_root=$root/src
build_dir=$root/build/vtk-9.1-$backend
log_dir=$root/logs
stamp_file=$prefix/lightshafts-build.stamp
jobs=${LIGHTSHAFTS_JOBS:-$(nproc 2>/dev/null || echo 2)}
export CCACHE_DIR=${CCACHE_DIR:-$root/ccache}
# Paths under $root are hashed relative to the build directory, so the two backends' builds
# share the cache for every file whose compile does not depend on the backend.
export CCACHE_BASEDIR=$root
export CCACHE_NOHASHDIR=1

start=$(date +%s)
say() { echo "== [vtk-$backend $(($(date +%s) - start)) s] $*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}
# apt-get as root, non-interactive, waiting for another apt run to finish rather than failing
# (dpkg's lock, and the project's own: tools/quickstart.sh and tools/test-distros.sh take it).
apt_get() {
  as_root flock /var/lock/lightshafts-apt.lock \
    env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 "$@"
}

# --- 1. packages -------------------------------------------------------------------------------
packages=(
  build-essential cmake ninja-build ccache dpkg-dev xz-utils pkg-config
  # VTK's third-party libraries for the modules below, from Debian (the source package has them
  # stripped); libglm-dev for the LightShafts module itself.
  zlib1g-dev libpng-dev libjpeg-dev libtiff-dev libdouble-conversion-dev liblz4-dev
  liblzma-dev libeigen3-dev libutfcpp-dev libexpat1-dev libglm-dev
  libgl-dev libopengl-dev
)
case "$backend" in
  egl) packages+=(libegl-dev libegl-mesa0 libgl1-mesa-dri) ;;
  osmesa) packages+=(libosmesa6-dev) ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "apt-get install ${missing[*]}"
  apt_get update -qq
  apt_get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
else
  say "packages: all ${#packages[@]} installed"
fi

# --- 2. sources --------------------------------------------------------------------------------
# apt-get source needs a deb-src entry; a fresh Debian 12 has only deb ones.
if ! grep -rqsE '^[[:space:]]*(deb-src[[:space:]]|Types:.*deb-src)' \
  /etc/apt/sources.list /etc/apt/sources.list.d/; then
  # shellcheck disable=SC1091 # (Debian's own file)
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  say "adding /etc/apt/sources.list.d/lightshafts-deb-src.sources (deb-src $codename main)"
  printf '%s\n' "Types: deb-src" "URIs: http://deb.debian.org/debian" "Suites: $codename" \
    "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" |
    as_root tee /etc/apt/sources.list.d/lightshafts-deb-src.sources > /dev/null
  apt_get update -qq
fi

# The .dsc of the source package apt would fetch for $1 (empty when apt offers none).
source_dsc() {
  apt-get source --print-uris -qq "$1" 2> /dev/null | awk '$2 ~ /\.dsc$/ { print $2 }' || true
}
# Fetches and unpacks the source package apt offers for $1 into $src_root/$1-<version> (kept for
# later runs) and sets source_dir to that directory.
fetch_source() {
  local package=$1 dsc version tmp fetched
  source_dir=
  dsc=$(source_dsc "$package")
  if [ -z "$dsc" ]; then
    # No source index yet (deb-src configured but never updated), or apt's lists are being
    # rewritten by another apt run at this moment.
    say "apt offers no source package $package: apt-get update"
    apt_get update -qq > /dev/null 2>&1 || true
    dsc=$(source_dsc "$package")
  fi
  if [ -z "$dsc" ]; then
    fetched=("$src_root/$package"-*/.complete)
    if [ ${#fetched[@]} -eq 1 ] && [ -f "${fetched[0]}" ]; then
      say "apt offers no source package $package now; using the one fetched before"
      source_dir=$(dirname "${fetched[0]}")
      return 0
    fi
    echo "apt offers no source package $package (deb-src entries: /etc/apt/sources.list.d)" >&2
    return 1
  fi
  version=${dsc#"${package}_"}
  version=${version%.dsc}
  source_dir=$src_root/$package-$version
  if [ -f "$source_dir/.complete" ]; then
    return 0
  fi
  say "apt-get source $package=$version"
  rm -rf "$source_dir"
  mkdir -p "$src_root"
  tmp=$(mktemp -d "$src_root/.fetch.XXXXXX")
  [ -d "$tmp" ] || return 1
  if ! (cd "$tmp" && apt-get source -qq "$package=$version" > .log 2>&1); then
    cat "$tmp/.log" >&2
    rm -rf "$tmp"
    echo "apt-get source $package=$version failed" >&2
    return 1
  fi
  mv "$tmp/$(cd "$tmp" && find . -mindepth 1 -maxdepth 1 -type d | head -1)" "$source_dir"
  rm -rf "$tmp"
  touch "$source_dir/.complete"
}
fetch_source vtk9
vtk_src=$source_dir
fetch_source glew
glew_src=$source_dir

# --- 3./4. what the build is -------------------------------------------------------------------
# The smallest module set: the LightShafts modules' dependencies (plugin/core/vtk.module and
# plugin/pass/vtk.module) and what the C++ tests use (FiltersSources, IOImage, InteractionStyle);
# the rest follows as dependencies.
modules=(
  CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
  FiltersCore FiltersGeneral FiltersSources
  IOImage InteractionStyle RenderingCore RenderingOpenGL2
)
# Third-party libraries the Debian source still vendors (ThirdParty/<name>/vtk<name>) are built
# from it; every other one (stripped from the source) comes from Debian's -dev packages.
vendored=()
for d in "$vtk_src"/ThirdParty/*/; do
  name=$(basename "$d")
  [ -d "$d/vtk$name" ] && vendored+=("$name")
done
cmake_args=(
  -G Ninja
  -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_INSTALL_PREFIX=$prefix"
  -DCMAKE_INSTALL_LIBDIR=lib
  "-DCMAKE_INSTALL_RPATH=$prefix/lib"
  -DCMAKE_C_COMPILER_LAUNCHER=ccache
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
  -DBUILD_SHARED_LIBS=ON
  -DBUILD_TESTING=OFF
  -DVTK_BUILD_TESTING=OFF
  -DVTK_BUILD_EXAMPLES=OFF
  -DVTK_BUILD_DOCUMENTATION=OFF
  -DVTK_ENABLE_WRAPPING=OFF
  -DVTK_WRAP_PYTHON=OFF
  -DVTK_WRAP_JAVA=OFF
  -DVTK_ENABLE_REMOTE_MODULES=OFF
  -DVTK_FORBID_DOWNLOADS=ON
  -DVTK_SMP_IMPLEMENTATION_TYPE=STDThread
  -DVTK_BUILD_ALL_MODULES=OFF
)
for group in Imaging MPI Qt Rendering StandAlone Views; do
  cmake_args+=("-DVTK_GROUP_ENABLE_$group=DONT_WANT")
done
for module in "${modules[@]}"; do
  cmake_args+=("-DVTK_MODULE_ENABLE_VTK_$module=YES")
done
cmake_args+=(-DVTK_USE_EXTERNAL=ON)
for name in "${vendored[@]}"; do
  cmake_args+=("-DVTK_MODULE_USE_EXTERNAL_VTK_$name=OFF")
done
cmake_args+=(
  -DVTK_USE_X=OFF
  "-DGLEW_INCLUDE_DIR=$prefix/include"
  "-DGLEW_LIBRARY=$prefix/lib/libGLEW.so"
)
case "$backend" in
  egl)
    cmake_args+=(-DVTK_OPENGL_HAS_EGL=ON -DVTK_OPENGL_HAS_OSMESA=OFF)
    glew_system=linux-egl
    ;;
  osmesa)
    cmake_args+=(-DVTK_OPENGL_HAS_EGL=OFF -DVTK_OPENGL_HAS_OSMESA=ON)
    glew_system=linux-osmesa
    ;;
esac

stamp="vtk9 source: $(basename "$vtk_src")
glew source: $(basename "$glew_src") SYSTEM=$glew_system
compiler: $(c++ --version | head -1)
cmake: $(cmake --version | head -1)
options: ${cmake_args[*]}"
if [ -f "$stamp_file" ] && [ "$(cat "$stamp_file")" = "$stamp" ] &&
  [ -f "$prefix/lib/cmake/vtk-9.1/vtk-config.cmake" ]; then
  say "up to date, reused: $prefix (stamp $stamp_file)"
  exit 0
fi

# --- 3. GLEW for the backend -------------------------------------------------------------------
say "building GLEW (SYSTEM=$glew_system) into $prefix"
rm -rf "$prefix" "$build_dir"
mkdir -p "$prefix/lib" "$prefix/include/GL" "$log_dir"
glew_build=$root/build/glew-$backend
rm -rf "$glew_build"
mkdir -p "$(dirname "$glew_build")"
cp -a "$glew_src" "$glew_build"
# (Its Makefile makes a directory in /tmp on every run, for packaging: not wanted here.)
sed -i 's|^DIST_DIR := .*|DIST_DIR := dist|' "$glew_build/Makefile"
if ! make -C "$glew_build" "SYSTEM=$glew_system" "CC=ccache cc" LD=cc -j "$jobs" glew.lib.shared \
  > "$log_dir/glew-$backend.log" 2>&1; then
  tail -30 "$log_dir/glew-$backend.log" >&2
  echo "GLEW build failed ($log_dir/glew-$backend.log)" >&2
  exit 1
fi
cp -P "$glew_build"/lib/libGLEW.so* "$prefix/lib/"
cp "$glew_build"/include/GL/*.h "$prefix/include/GL/"
rm -rf "$glew_build"

# --- 4. VTK ------------------------------------------------------------------------------------
ccache --max-size=4G > /dev/null
ccache --zero-stats > /dev/null
say "configuring VTK ($(basename "$vtk_src"), ${#modules[@]} modules requested, vendored: ${vendored[*]})"
if ! cmake -S "$vtk_src" -B "$build_dir" "${cmake_args[@]}" > "$log_dir/vtk-$backend.configure.log" 2>&1; then
  tail -40 "$log_dir/vtk-$backend.configure.log" >&2
  echo "VTK configure failed ($log_dir/vtk-$backend.configure.log)" >&2
  exit 1
fi
steps=$(ninja -C "$build_dir" -n 2> /dev/null | grep -c '^\[' || true)
say "building VTK: $steps steps, -j$jobs (log: $log_dir/vtk-$backend.build.log)"
if ! cmake --build "$build_dir" -j "$jobs" > "$log_dir/vtk-$backend.build.log" 2>&1; then
  grep -B2 -A20 -m3 "FAILED\|error:" "$log_dir/vtk-$backend.build.log" >&2 || true
  echo "VTK build failed ($log_dir/vtk-$backend.build.log)" >&2
  exit 1
fi
say "installing VTK into $prefix"
cmake --install "$build_dir" > "$log_dir/vtk-$backend.install.log" 2>&1
printf '%s\n' "$stamp" > "$stamp_file"
rm -rf "$build_dir"
hits=$(ccache --print-stats 2> /dev/null | awk -F'\t' '
  /^(direct|preprocessed)_cache_hit\t/ { h += $2 } /^cache_miss\t/ { m = $2 }
  END { printf "%d hits, %d misses", h, m }') || hits="(no stats)"
say "done: $prefix (ccache: $hits; $CCACHE_DIR $(du -sh "$CCACHE_DIR" | cut -f1))"
