#!/usr/bin/env bash
# The state-file test (tests/paraview/test_state.py): a state saved by one pvbatch and loaded by
# another (every property and the picture), the state ParaView 5.11 saved
# (tests/baselines/paraview-5.11.pvsm) loaded by this ParaView against 5.11's picture, and the
# Python trace. Each step is its own pvbatch, as users share states. Fails when any step does;
# ctest fails it too on any VTK error or warning in this output.
# Usage: run_state.sh OUTPUT_DIR   (PYTHONPATH and the plugin from the environment, as for pvbatch)
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
baselines="$here/../baselines"
mkdir -p "$out"
status=0
step() {
  echo "== pvbatch test_state.py $*"
  pvbatch "$here/test_state.py" "$@" || status=1
}
step save "$out/saved"
step load "$out/saved/state.pvsm" "$out/saved/state.png" "$out/loaded"
step load "$baselines/paraview-5.11.pvsm" "$baselines/paraview-5.11.png" "$out/from-5.11" \
  --tolerance baseline
step trace
exit $status
