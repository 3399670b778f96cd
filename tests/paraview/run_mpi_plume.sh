#!/usr/bin/env bash
# Distributed medium from data: examples/paraview/smoke_plume.py (the plume from a Wavelet and a
# Calculator as the view's MediumDensity) at 400x300 under `mpirun -np N pvbatch --symmetric`
# against a serial pvbatch (tests/paraview/mpi_field_memory.py runs it and records each
# process's peak memory):
# - the example's plume (37 samples across) at np 2 and 4, with scattering and with absorption
#   only, and a 257 x 335 x 257 plume (--points 256) resampled to the shafts' 128³ grid
#   (MediumFieldResolution) at np 4: each the serial picture (a mean difference of at most 0.2
#   levels, at most 0.3% of the pixels off by more than 4 levels; docs/paraview-mpi.md);
# - the example's in-scatter (the picture less the one without shafts) with RAY_MARCH, SLICES
#   and EPIPOLAR at np 2 and 4 within 0.5% (relative RMS) of serial's;
# - the plume split, not copied: its points summed over the processes at most 1.2 times its
#   whole image's (each process computes its piece);
# - the plume as cell data resampled to 36 samples along its 47 cells: the serial picture at np 2
#   and 4 (the gather asks for a ghost level for cell data; without it the pass refuses a grid
#   with a plane missing, and says so);
# - the large plume's memory split: each process's peak above the small plume's run at most
#   0.45 of the serial run's (measured 0.37-0.41, 107-119 MiB: its piece, a quarter of the
#   plume, the pass's grid as the serial run holds it, and the gathered 128³ image; 0.42 while
#   point data asked for a ghost level, 0.52 while the gather read its piece whole as float32,
#   0.77 before it resampled the pieces and reduced a slab at a time; docs/paraview-mpi.md).
# Usage: run_mpi_plume.sh OUTPUT_DIR   (PYTHONPATH and the plugin from the environment)
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
status=0
# name processes flags...
# (scattering --methods: also absorption only, SLICES, EPIPOLAR, no shafts, and the plume as cell
# data resampled to 24 samples across, in the same run.)
runs=(
  "scattering 1 --methods" "scattering 2 --methods" "scattering 4 --methods"
  "large 1 --points 256 --field-resolution 128" "large 4 --points 256 --field-resolution 128"
)
for run in "${runs[@]}"; do
  read -r name np flags <<< "$run"
  # shellcheck disable=SC2086  # (flags: several words)
  set -- $flags
  base="$out/$name-np$np"
  rm -f "$base".png "$base".rank*.json
  # (pvbatch ends with os._exit, so mpirun's status is not the test's: the files are.)
  mpirun --allow-run-as-root --oversubscribe -np "$np" -x PYTHONPATH \
    -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x LIGHTSHAFTS_PARAVIEW_PLUGIN -x DISPLAY \
    pvbatch --symmetric "$here/mpi_field_memory.py" "$base" "$@" > "$base.log" 2>&1
  if [ ! -f "$base.png" ] || [ ! -f "$base.rank$((np - 1)).json" ]; then
    cat "$base.log"
    echo "FAIL: no picture or no memory figures from the $name run at np $np"
    exit 1
  fi
  if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$base.log"; then
    echo "FAIL: VTK printed errors or warnings in the $name run at np $np"
    status=1
  fi
done
/usr/bin/python3 - "$out" <<'PY' || status=1
import glob
import json
import re
import sys
import numpy as np
from matplotlib.image import imread
out = sys.argv[1]
failures = []
for name, counts, suffix in (("scattering", (2, 4), ""), ("absorb-only", (2, 4), "-absorb-only"),
                             ("cell data", (2, 4), "-cells"), ("large", (4,), "")):
    stem = "large" if name == "large" else "scattering"
    serial = imread(f"{out}/{stem}-np1{suffix}.png")[..., :3].astype(float) * 255.0
    for np_ in counts:
        image = imread(f"{out}/{stem}-np{np_}{suffix}.png")[..., :3].astype(float) * 255.0
        diff = np.abs(image - serial)
        mean = float(diff.mean())
        off = float((diff.max(axis=-1) > 4.5).mean())
        print(f"{name}, np {np_} against serial: mean |diff| {mean:.3f} levels, "
              f"{100 * off:.2f}% of pixels off by > 4 levels, at most {diff.max():.0f}")
        if mean > 0.2 or off > 0.003:
            failures.append(f"{name} at np {np_} is not the serial picture")
# The in-scatter (the picture less the one without shafts) of each method that renders a medium
# from data: within 0.5% (relative RMS) of serial's.
def in_scatter(path, np_, suffix):
    shafts = imread(f"{out}/scattering-np{np_}{suffix}.png")[..., :3].astype(float)
    plain = imread(f"{out}/scattering-np{np_}-plain.png")[..., :3].astype(float)
    return shafts - plain


for method, suffix in (("RAY_MARCH", ""), ("SLICES", "-slices"), ("EPIPOLAR", "-epipolar")):
    serial = in_scatter(out, 1, suffix)
    for np_ in (2, 4):
        error = float(np.sqrt(np.mean((in_scatter(out, np_, suffix) - serial) ** 2)) /
                      np.sqrt(np.mean(serial ** 2)))
        print(f"{method} in-scatter, np {np_} against serial: {100 * error:.3f}% (relative RMS)")
        if not error <= 0.005:
            failures.append(f"{method}'s in-scatter at np {np_} is {100 * error:.2f}% off serial")
# Each process prints the plume's points it holds (--symmetric: every process runs the script).
for name, counts in (("scattering", (1, 2, 4)), ("large", (1, 4))):
    for np_ in counts:
        with open(f"{out}/{name}-np{np_}.log") as log:
            found = re.findall(r"the plume: (\d+) points over the processes \(its whole image: "
                               r"(\d+)\)", log.read())
        if len(found) != np_:
            failures.append(f"{name} at np {np_}: the processes did not say how the plume is held")
            continue
        held, whole = sum(int(f[0]) for f in found), int(found[0][1])
        print(f"{name}, np {np_}: the plume's points over the processes {held} (whole image "
              f"{whole}: {held / whole:.3f} times)")
        if held > (whole if np_ == 1 else 1.2 * whole):
            failures.append(f"{name} at np {np_}: the plume is held {held / whole:.2f} times")


def peaks(name, np_):
    return [json.load(open(f"{out}/{name}-np{np_}.rank{r}.json"))["peak"] for r in range(np_)]


serial = peaks("large", 1)[0] - peaks("scattering", 1)[0]
split = [a - b for a, b in zip(peaks("large", 4), peaks("scattering", 4))]
print(f"the large plume's memory: serial {serial / 2**20:.0f} MiB, each of 4 processes "
      + ", ".join(f"{s / 2**20:.0f}" for s in split)
      + f" MiB (at most {max(split) / serial:.2f} of serial)")
if max(split) > 0.45 * serial:
    failures.append("the large plume's memory is not split among the processes")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
PY
exit $status
