#!/usr/bin/env bash
# Distributed test: the test scene under `mpirun -np 2 pvbatch` (the sphere split into its left
# and right halves, one per process) against a serial pvbatch run. With DistributedShadowMap off,
# each process's shadow map holds its own half only and light leaks below the other half; with it
# on (the default) the processes' maps are combined and the shafts match the serial run; and the
# processes divide the shafts' work (each marches its rows of the in-scatter).
# Usage: run_mpi.sh OUTPUT_DIR   (PYTHONPATH and the plugin from the environment, as for pvbatch)
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
rm -f "$out/serial.npz" "$out/np2.npz"
pvbatch "$here/mpi_shafts.py" "$out/serial.npz" > "$out/serial.log" 2>&1
# pvbatch 5.11 ends scripts with os._exit (docs/known-issues.md), so mpirun reports an improper exit of the
# other rank: its status is not the test's; the results file is.
mpirun --allow-run-as-root --oversubscribe -np 2 -x PYTHONPATH \
  -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x LIGHTSHAFTS_PARAVIEW_PLUGIN -x DISPLAY \
  pvbatch "$here/mpi_shafts.py" "$out/np2.npz" > "$out/np2.log" 2>&1
for f in serial np2; do
  if [ ! -f "$out/$f.npz" ]; then
    cat "$out/$f.log"
    echo "FAIL: no $f results"
    if grep -q "bad X server connection" "$out/$f.log"; then
      echo "(XOpenDisplay failed. Is the X server up? An Xvfb without -noreset drops a client" \
        "that connects as the server resets after its last client left: docs/known-issues.md.)"
    fi
    exit 1
  fi
  # Any error or warning VTK printed in a rank fails the test (as for the other tests).
  if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$out/$f.log"; then
    echo "FAIL: VTK printed errors or warnings in the $f run"
    exit 1
  fi
done
exec /usr/bin/python3 - "$out" <<'PY'
import sys
import numpy as np
out = sys.argv[1]
serial = np.load(f"{out}/serial.npz")
np2 = np.load(f"{out}/np2.npz")

def patch(image, pixel, r=3):
    col, row = pixel
    return float(image[row - r:row + r + 1, col - r:col + r + 1].mean())

failures = []
print(f"np 2: {int(np2['processes'])} processes, ProcessId range {tuple(np2['process_range'])}")
if int(np2["processes"]) != 2 or tuple(np2["process_range"]) != (0.0, 1.0):
    failures.append("the sphere was not split over two processes")
reference = serial["in_scatter_1"]
for distributed in (0, 1):
    image = np2[f"in_scatter_{distributed}"]
    below = [patch(image, np2[side]) for side in ("left", "right")]
    diff = np.abs(image - reference)
    # Combined maps give the serial picture (0.00% of the pixels off by more than 4 levels on
    # ParaView 5.11, 5.13 and 6.1); before the view kept the renderer's FXAA under MPI, the
    # sphere's silhouette was off in 0.13% of them.
    off = diff > 4
    rest = float(diff[~off].mean())
    print(f"DistributedShadowMap {distributed}: below the sphere left {below[0]:.2f}, right "
          f"{below[1]:.2f} levels (serial {patch(reference, serial['left']):.2f}, "
          f"{patch(reference, serial['right']):.2f}); lit point {patch(image, np2['lit']):.2f} "
          f"(serial {patch(reference, serial['lit']):.2f}); against serial: mean |diff| "
          f"{diff.mean():.3f}, {100 * off.mean():.2f}% of pixels off by > 4 levels, mean "
          f"|diff| of the others {rest:.4f}")
    if distributed == 0 and max(below) < 5.0:
        failures.append("without combining, no leak was seen (is the data split?)")
    if distributed == 1 and (max(below) > 1.0 or off.mean() > 0.0005 or rest > 0.01):
        failures.append("with the combined shadow map the shafts differ from the serial run")
# The shafts' work divided (DivideShaftWork): on two processes, process 0 marched its piece of
# the rows only (the picture above is still the serial one); serial, the whole image.
rows = [int(np2[f"piece_rows_{d}"]) for d in (0, 1)]
fragments = [int(np2[f"piece_fragments_{d}"]) for d in (0, 1)]
print(f"np 2: process 0 computed {rows} of the in-scatter's 300 rows, {fragments} fragments; "
      f"serial: {[int(serial[f'piece_rows_{d}']) for d in (0, 1)]} (0: not divided)")
if not all(100 <= r <= 200 for r in rows) or min(fragments) <= 0:
    failures.append("on two processes, process 0 did not compute about half the rows")
if any(int(serial[f"piece_rows_{d}"]) != 0 for d in (0, 1)):
    failures.append("a single process divided its work")
# An empty medium leaves ParaView's picture as it is, bit for bit (on several processes too:
# there the view once turned off the renderer's FXAA, which IceT's compositing does not replace).
for name, run in (("serial", serial), ("np 2", np2)):
    difference = float(run["empty_medium_difference"])
    print(f"{name}: an empty medium changes the picture by at most {difference:.0f} levels")
    if difference != 0.0:
        failures.append(f"{name}: an empty medium changed ParaView's picture")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
PY
