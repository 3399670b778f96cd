#!/usr/bin/env bash
# GUI smoke test: the ParaView client (paraview, Qt) starts under the X server of the caller
# (xvfb-run), loads the LightShafts plugin, creates the light-shaft view, and keeps it refining
# while still and paused while the user interacts (gui_smoke.py), with no error, warning or
# Python traceback in its output.
# Usage: run_gui_smoke.sh PLUGIN.so|LightShaftsPluginPath.txt OUTPUT_DIR
set -u
plugin="$1"
out="$2"
case "$plugin" in
  *.txt) plugin="$(head -n 1 "$plugin")" ;;
esac
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
rm -f "$out/smoke.txt"
PARAVIEW_LOG_RENDERING_VERBOSITY=INFO LIGHTSHAFTS_PARAVIEW_TESTS="$here" LIGHTSHAFTS_PARAVIEW_PLUGIN="$plugin" LIGHTSHAFTS_SMOKE_OUT="$out/smoke.txt" \
  timeout 240 paraview --dr --script="$here/gui_smoke.py" \
  --test-script="$here/gui_smoke_events.xml" --exit > "$out/paraview.log" 2>&1
status=$?
cat "$out/paraview.log"
if [ $status -ne 0 ]; then
  echo "FAIL: paraview exited with $status"
  exit 1
fi
if grep -E "ERR\||WARN\||Traceback|Error:" "$out/paraview.log"; then
  echo "FAIL: errors in paraview's output"
  exit 1
fi
cat "$out/smoke.txt" 2>/dev/null
if [ "$(tail -n 1 "$out/smoke.txt" 2>/dev/null)" != "ok" ]; then
  echo "FAIL: the GUI did not create, refine and pause the view as gui_smoke.py expects"
  exit 1
fi
echo "GUI smoke test passed: plugin loaded, LightShaftsRenderView refined by the GUI, paused while interacting"
