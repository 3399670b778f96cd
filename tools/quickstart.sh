#!/usr/bin/env bash
# LightShafts quick start for a fresh Debian 12 machine:
#   1. installs every dependency with apt (needs root: run as root, or it uses sudo),
#   2. configures, builds and installs LightShafts to /usr/local (C++ package + Python module,
#      and the ParaView plugin in /usr/local/lib/paraview-5.11/plugins/LightShafts),
#   3. builds the C++ example against the installed package, and
#   4. renders the example scene offscreen (Xvfb) to window_shafts.png.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

packages=(
  build-essential cmake pkg-config
  libvtk9-dev python3-vtk9 libglm-dev
  xvfb xauth libgl1-mesa-dri
  python3-numpy python3-pytest python3-tqdm python3-matplotlib python3-skimage
)
# ParaView for the plugin, without its Recommends: one of them, python3-paraview, Conflicts with
# python3-vtk9 (installing it would remove the VTK module's dependencies); see below.
paraview_packages=(paraview paraview-dev openmpi-bin)
missing_packages() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
missing=($(missing_packages "${packages[@]}"))
missing_paraview=($(missing_packages "${paraview_packages[@]}"))
if [ $((${#missing[@]} + ${#missing_paraview[@]})) -gt 0 ]; then
  echo "== installing: ${missing[*]} ${missing_paraview[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
    "${missing[@]}" > /dev/null
fi
if [ ${#missing_paraview[@]} -gt 0 ]; then
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing_paraview[@]}" > /dev/null
fi

# ParaView's Python package (pvbatch scripts, the plugin's wrapping hierarchy) is in
# python3-paraview, which Conflicts with python3-vtk9 (apt would remove the VTK module's
# dependencies): fetch that .deb and unpack it privately instead of installing it.
pv_python=/usr/local/lib/lightshafts/python3-paraview
if [ ! -d "$pv_python/usr/lib/python3/dist-packages/paraview" ]; then
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
echo "== building (build/)"
# Debian's VTK Python bindings are for /usr/bin/python3 (another python3 may come first on PATH).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 > build.log
cmake --build build -j "$jobs" >> build.log
echo "== installing to /usr/local"
as_root cmake --install build >> build.log
as_root ldconfig

echo "== building the C++ example against the installed package (build/example)"
cmake -S examples/cpp -B build/example -DCMAKE_BUILD_TYPE=Release >> build.log
cmake --build build/example -j "$jobs" >> build.log

echo "== rendering the example scene offscreen"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 examples/window_shafts.py -o window_shafts.png
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" build/example/window_shafts window_shafts_cpp.png
echo "== done: window_shafts.png (Python) and window_shafts_cpp.png (C++)"
