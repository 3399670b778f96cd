#!/usr/bin/env bash
# Runs the whole test suite offscreen (under Xvfb) against the build in build/:
# the C++ tests (ctest) and the Python tests (pytest). Run tools/quickstart.sh first.
# Xvfb gets -noreset: without it the server resets whenever its last client disconnects and
# drops a client connecting at that moment (VTK: "bad X server connection"; README, Known
# issues), which pvbatch's display probe and any window re-creation run into.
set -uo pipefail
cd "$(dirname "$0")/.."

if [ ! -f build/CMakeCache.txt ]; then
  echo "build/ not found: run tools/quickstart.sh first" >&2
  exit 2
fi
cmake --build build -j "$(nproc 2>/dev/null || echo 2)" > /dev/null || exit 1

python_dir=$(sed -n 's/^LIGHTSHAFTS_PYTHON_DESTINATION:STRING=//p' build/CMakeCache.txt)
export PYTHONPATH="$PWD/build/$python_dir${PYTHONPATH:+:$PYTHONPATH}"

status=0
echo "== C++ and ParaView tests (ctest; the ParaView ones when the plugin was built)"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --test-dir build --output-on-failure || status=1
echo "== Python tests (pytest)"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 -m pytest -p no:cacheprovider \
  -q -ra tests/python "$@" || status=1
exit $status
