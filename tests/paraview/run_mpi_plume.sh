#!/usr/bin/env bash
# Distributed medium from data: examples/paraview/smoke_plume.py (the plume from a Wavelet and a
# Calculator as the view's MediumDensity) at 400x300 under `mpirun -np 2` and `-np 4` pvbatch
# against a serial pvbatch, with scattering and with absorption only. Each must be the serial
# picture: a mean difference of at most 0.2 levels, at most 0.3% of the pixels off by more than
# 4 levels (docs/paraview-mpi.md). And the plume must be split, not copied: its points summed over
# the processes at most 1.2 times its whole image's (each process computes its piece).
# Usage: run_mpi_plume.sh OUTPUT_DIR   (PYTHONPATH and the plugin from the environment)
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
script="$here/../../examples/paraview/smoke_plume.py"
mkdir -p "$out"
status=0
for mode in scattering absorb-only; do
  flags=(--size 400 300)
  [ "$mode" = absorb-only ] && flags+=(--absorb-only)
  for np in 1 2 4; do
    image="$out/$mode-np$np.png"
    rm -f "$image"
    if [ "$np" = 1 ]; then
      pvbatch "$script" -o "$image" "${flags[@]}" > "$out/$mode-np$np.log" 2>&1
    else
      # (pvbatch 5.11 ends with os._exit, so mpirun's status is not the test's: the image is.)
      mpirun --allow-run-as-root --oversubscribe -np "$np" -x PYTHONPATH \
        -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x LIGHTSHAFTS_PARAVIEW_PLUGIN -x DISPLAY \
        pvbatch "$script" -o "$image" "${flags[@]}" > "$out/$mode-np$np.log" 2>&1
    fi
    if [ ! -f "$image" ]; then
      cat "$out/$mode-np$np.log"
      echo "FAIL: no image from the $mode run at np $np"
      exit 1
    fi
    if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$out/$mode-np$np.log"; then
      echo "FAIL: VTK printed errors or warnings in the $mode run at np $np"
      status=1
    fi
  done
done
/usr/bin/python3 - "$out" <<'PY' || status=1
import re
import sys
import numpy as np
from matplotlib.image import imread
out = sys.argv[1]
failures = []
for mode in ("scattering", "absorb-only"):
    serial = imread(f"{out}/{mode}-np1.png")[..., :3].astype(float) * 255.0
    for np_ in (2, 4):
        image = imread(f"{out}/{mode}-np{np_}.png")[..., :3].astype(float) * 255.0
        diff = np.abs(image - serial)
        mean = float(diff.mean())
        off = float((diff.max(axis=-1) > 4.5).mean())
        print(f"{mode}, np {np_} against serial: mean |diff| {mean:.3f} levels, "
              f"{100 * off:.2f}% of pixels off by > 4 levels, at most {diff.max():.0f}")
        if mean > 0.2 or off > 0.003:
            failures.append(f"{mode} at np {np_} is not the serial picture")
for mode in ("scattering", "absorb-only"):
    for np_ in (1, 2, 4):
        with open(f"{out}/{mode}-np{np_}.log") as log:
            found = re.search(r"the plume: (\d+) points over the processes \(its whole image: (\d+)\)",
                              log.read())
        if not found:
            failures.append(f"{mode} at np {np_}: the example did not say how the plume is held")
            continue
        held, whole = int(found.group(1)), int(found.group(2))
        if mode == "scattering":
            print(f"np {np_}: the plume's points over the processes {held} (whole image {whole}:"
                  f" {held / whole:.3f} times)")
        if held > (whole if np_ == 1 else 1.2 * whole):
            failures.append(f"{mode} at np {np_}: the plume is held {held / whole:.2f} times")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
PY
exit $status
