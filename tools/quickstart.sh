#!/usr/bin/env bash
# LightShafts quick start for a fresh Debian machine: Debian 12 (bookworm: VTK 9.1, ParaView
# 5.11), Debian 13 (trixie: VTK 9.3, ParaView 5.13, PyVista 0.44) or Debian unstable (sid: VTK
# 9.6, ParaView 6.1, PyVista 0.49). It
#   1. installs every dependency of this release with apt (needs root: run as root, or it uses
#      sudo),
#   2. configures, builds and installs LightShafts to /usr/local (C++ package + Python module,
#      and the ParaView plugin in /usr/local/lib/paraview-X.Y/plugins/LightShafts),
#   3. builds the C++ example against the installed package, and
#   4. renders the example scene offscreen (Xvfb) to window_shafts.png.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# shellcheck disable=SC1091 # (Debian's own file)
release=$(. /etc/os-release && echo "${PRETTY_NAME:-unknown}")
echo "== $release"

packages=(
  build-essential cmake pkg-config
  libvtk9-dev python3-vtk9 libglm-dev
  xvfb xauth libgl1-mesa-dri libegl1 libegl-mesa0
  python3-numpy python3-pytest python3-tqdm python3-matplotlib python3-skimage
)
# ParaView for the plugin, without its Recommends (one of them, python3-paraview, may conflict
# with python3-vtk9; see below).
paraview_packages=(paraview paraview-dev openmpi-bin)
# apt_get: as root, non-interactive, waiting for another apt run rather than failing (dpkg's
# lock; and the project's own, which its scripts that may run beside this one take too).
apt_get() {
  as_root flock /var/lock/lightshafts-apt.lock \
    env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 "$@"
}
installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"
}
missing_packages() {
  for p in "$@"; do installed "$p" || echo "$p"; done
}
# What this release's apt offers, by name (no release is named below: each differs in what it
# has, and that is what is asked).
apt_has() {
  [ -n "$(apt-cache show --no-all-versions "$1" 2>/dev/null | head -1)" ]
}
apt_field() {
  apt-cache show --no-all-versions "$1" 2>/dev/null | sed -n "s/^$2: //p" | head -1
}
if ! apt_has libvtk9-dev; then
  echo "== apt-get update (apt has no package lists yet)"
  apt_get update -qq
fi
# PyVista (Debian 13 and later): the lightshafts.pyvista entry point and its tests.
apt_has python3-pyvista && packages+=(python3-pyvista)
# ParaView's Python package (pvbatch scripts, the plugin's wrapping hierarchy): python3-paraview.
# Up to ParaView 5.13 (Debian 12, 13) it Conflicts with python3-vtk9 (apt would remove the VTK
# module's dependencies): then its .deb is unpacked privately instead of installed. From 6.1
# (unstable) ParaView is built on the system's VTK and the package installs beside it.
if apt_field python3-paraview Conflicts | grep -qw python3-vtk9; then
  unpack_python3_paraview=1
else
  unpack_python3_paraview=0
  paraview_packages+=(python3-paraview)
fi
# Qt's development files, for the plugin's GUI piece (in the ParaView client, a still view renders
# again by itself until its shafts converge), in the Qt that this release's ParaView is built
# with: Qt 5 for ParaView 5.11 (Debian 12), Qt 6 from 5.13.
paraview_depends=$(apt_field paraview Depends)
if echo "$paraview_depends" | grep -qw "libqt6widgets6"; then
  paraview_packages+=(qt6-base-dev qt6-tools-dev qt6-5compat-dev)
elif echo "$paraview_depends" | grep -qw "libqt5widgets5"; then
  paraview_packages+=(qtbase5-dev qttools5-dev libqt5opengl5-dev)
fi
missing=($(missing_packages "${packages[@]}"))
missing_paraview=($(missing_packages "${paraview_packages[@]}"))
if [ $((${#missing[@]} + ${#missing_paraview[@]})) -gt 0 ]; then
  echo "== installing: ${missing[*]} ${missing_paraview[*]}"
  apt_get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  apt_get install -y -qq "${missing[@]}" > /dev/null
fi
if [ ${#missing_paraview[@]} -gt 0 ]; then
  apt_get install -y -qq --no-install-recommends "${missing_paraview[@]}" > /dev/null
fi

pv_python=/usr/local/lib/lightshafts/python3-paraview
if [ "$unpack_python3_paraview" = 1 ] && [ ! -d "$pv_python/usr/lib/python3/dist-packages/paraview" ]; then
  version=$(apt-cache madison python3-paraview | awk 'NR==1 {print $3}')
  echo "== unpacking python3-paraview $version into $pv_python (not installed: it conflicts with python3-vtk9)"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download -qq "python3-paraview=$version" 2>/dev/null) ||
    (cd "$tmp" && as_root apt-get download -qq "python3-paraview=$version")
  as_root mkdir -p "$pv_python"
  as_root dpkg -x "$tmp"/python3-paraview_*.deb "$pv_python"
  rm -rf "$tmp"
fi

jobs=$(nproc 2>/dev/null || echo 2)
echo "== building (build/; log: build.log)"
# The build's output goes to build.log; when a step fails, show its end.
trap 'status=$?; [ $status -eq 0 ] || { tail -40 build.log >&2; echo "== failed (build.log)" >&2; }' EXIT
# Debian's VTK Python bindings are for /usr/bin/python3 (another python3 may come first on PATH).
# ParaView was installed above: its plugin must be built (ON: a ParaView that is not found is an
# error, not a silent skip).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DLIGHTSHAFTS_BUILD_PARAVIEW_PLUGIN=ON > build.log
cmake --build build -j "$jobs" >> build.log
echo "== installing to /usr/local"
as_root cmake --install build >> build.log
as_root ldconfig

echo "== building the C++ example against the installed package (build/example)"
cmake -S examples/cpp -B build/example -DCMAKE_BUILD_TYPE=Release >> build.log
cmake --build build/example -j "$jobs" >> build.log

echo "== rendering the example scene offscreen"
# (LIGHTSHAFTS_XVFB_SERVERNUM: the first display number tried; tools/test.sh says why.)
xvfb=(xvfb-run -a -n "${LIGHTSHAFTS_XVFB_SERVERNUM:-99}" -s "-screen 0 1280x1024x24 -noreset")
"${xvfb[@]}" /usr/bin/python3 examples/window_shafts.py -o window_shafts.png
"${xvfb[@]}" build/example/window_shafts window_shafts_cpp.png
echo "== done: window_shafts.png (Python) and window_shafts_cpp.png (C++)"
