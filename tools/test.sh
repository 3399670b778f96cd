#!/usr/bin/env bash
# Runs the whole test suite offscreen (under Xvfb) against the build in build/:
# the C++ tests (ctest) and the Python tests (pytest). Run tools/quickstart.sh first.
# Xvfb gets -noreset: without it the server resets whenever its last client disconnects and
# drops a client connecting at that moment (VTK: "bad X server connection"; docs/known-issues.md
# ), which pvbatch's display probe and any window re-creation run into.
# LIGHTSHAFTS_XVFB_SERVERNUM (default 99) is the first display number xvfb-run tries: lanes run
# side by side in chroots (tools/test-distros.sh) need their own, since an X server's abstract
# socket is shared by every root of the machine (a second :99 fails to start, and a client could
# reach the other lane's server).
set -uo pipefail
cd "$(dirname "$0")/.."

if [ ! -f build/CMakeCache.txt ]; then
  echo "build/ not found: run tools/quickstart.sh first" >&2
  exit 2
fi
cmake --build build -j "$(nproc 2>/dev/null || echo 2)" > /dev/null || exit 1

python_dir=$(sed -n 's/^LIGHTSHAFTS_PYTHON_DESTINATION:STRING=//p' build/CMakeCache.txt)
export PYTHONPATH="$PWD/build/$python_dir${PYTHONPATH:+:$PYTHONPATH}"

xvfb=(xvfb-run -a -n "${LIGHTSHAFTS_XVFB_SERVERNUM:-99}" -s "-screen 0 1280x1024x24 -noreset")
status=0
echo "== C++ and ParaView tests (ctest; the ParaView ones when the plugin was built)"
"${xvfb[@]}" ctest --test-dir build --output-on-failure || status=1
echo "== Python tests (pytest)"
"${xvfb[@]}" /usr/bin/python3 -m pytest -p no:cacheprovider \
  -q -ra tests/python "$@" || status=1
exit $status
