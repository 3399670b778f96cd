#!/usr/bin/env bash
# Distributed volumes and translucent surfaces (tests/paraview/mpi_volumes.py: the three scenes in
# one run) under `mpirun -np N pvbatch --symmetric` against a serial pvbatch, at 400x300:
# - examples/paraview/volume_in_beam.py (its volume dims and shadows the beam, its translucent
#   sphere dims what is seen through it), the same as with --as-medium (the volume is the medium),
#   and two translucent panes (one across the beam, one between the camera and the beam), each
#   split across the processes (checked: two processes or more hold part of it, none all);
# - for SLICES, RAY_MARCH and EPIPOLAR at np 2 and 4: the picture with shafts within 0.5% of the
#   serial in-scatter (relative RMS: |shafts(np) - shafts(serial)| over |in-scatter(serial)|,
#   the in-scatter being the picture less the one in an empty medium), over the pixels where
#   ParaView's own picture (the empty medium's) is serial's within 2 levels: it is not, on at
#   most 2% of them, where ParaView draws a split volume's edges (up to 15 levels at np 4, a
#   plain RenderView too), a difference that is not the shafts'. The in-scatter measured on each
#   run alone (its own empty-medium picture subtracted), over all pixels, is printed too.
# - no VTK error or warning in any run.
# Usage: run_mpi_volumes.sh OUTPUT_DIR   (PYTHONPATH and the plugin from the environment)
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
status=0
for np in 1 2 4; do
  log="$out/np$np.log"
  rm -f "$out"/*-np"$np"-*.png "$out"/*-np"$np".rank*.json
  # (pvbatch ends with os._exit, so mpirun's status is not the test's: the files are.)
  mpirun --allow-run-as-root --oversubscribe -np "$np" -x PYTHONPATH \
    -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x LIGHTSHAFTS_PARAVIEW_PLUGIN -x DISPLAY \
    pvbatch --symmetric "$here/mpi_volumes.py" "$out" "np$np" > "$log" 2>&1
  if [ ! -f "$out/panes-np$np-plain.png" ] || [ ! -f "$out/panes-np$np.rank$((np - 1)).json" ]; then
    cat "$log"
    echo "FAIL: no pictures from the run at np $np"
    exit 1
  fi
  # (Mesa's shader compiler, with a cold shader cache, warns of two variables of VTK's own
  # shaders that ParaView 6.1 compiles under MPI for a volume or a translucent surface: a plain
  # RenderView prints the same. Nothing else is let through.)
  if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$log" |
    grep -v -E "SOURCE_SHADER_COMPILER.*warning: \`(fragOutput0|g_dataPos)' used uninitialized"; then
    echo "FAIL: VTK printed errors or warnings in the run at np $np"
    status=1
  fi
done
/usr/bin/python3 - "$out" <<'PY' || status=1
import json
import sys
import numpy as np
from matplotlib.image import imread
out = sys.argv[1]
failures = []


def picture(scene, np_, name):
    return imread(f"{out}/{scene}-np{np_}-{name}.png")[..., :3].astype(float) * 255.0


for scene in ("volume", "medium", "panes"):
    # Split, not copied: at least two processes hold part of each split source, none all of it
    # (RedistributeDataSet gives a pane to 2 of 4 processes).
    serial = json.load(open(f"{out}/{scene}-np1.rank0.json"))["held"]
    for np_ in (2, 4):
        held = [json.load(open(f"{out}/{scene}-np{np_}.rank{r}.json"))["held"]
                for r in range(np_)]
        for s, whole in enumerate(serial):
            parts = [h[s] for h in held]
            if sum(part > 0 for part in parts) < 2 or max(parts) >= whole:
                failures.append(f"{scene} at np {np_}: source {s} is not split ({parts} of "
                                f"{whole})")
    for method in ("slices", "raymarch", "epipolar"):
        in_scatter = picture(scene, 1, method) - picture(scene, 1, "plain")
        for np_ in (2, 4):
            # Where ParaView's own picture (the empty medium's) differs from serial's, the
            # difference is not the shafts': those pixels are left out, and counted.
            plain = np.abs(picture(scene, np_, "plain") - picture(scene, 1, "plain")).max(axis=-1)
            kept = plain <= 2.5
            norm = np.sqrt(np.mean(in_scatter[kept] ** 2))
            error = np.sqrt(np.mean((picture(scene, np_, method) - picture(scene, 1, method))
                                    [kept] ** 2)) / norm
            own = picture(scene, np_, method) - picture(scene, np_, "plain")
            alone = np.sqrt(np.mean((own - in_scatter) ** 2)) / np.sqrt(np.mean(in_scatter ** 2))
            left = 1.0 - kept.mean()
            print(f"{scene}, {method}, np {np_}: {100 * error:.3f}% of the serial in-scatter, "
                  f"{100 * left:.2f}% of the pixels left out (ParaView's empty-medium picture "
                  f"there up to {plain.max():.0f} levels off serial's; each run's own in-scatter, "
                  f"all pixels: {100 * alone:.3f}%)")
            if not error <= 0.005:
                failures.append(f"{scene}, {method} at np {np_}: {100 * error:.2f}% off serial")
            if left > 0.02:
                failures.append(f"{scene} at np {np_}: ParaView's own picture differs from "
                                f"serial's on {100 * left:.1f}% of the pixels")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
PY
exit $status
