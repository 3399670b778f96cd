#!/usr/bin/env bash
# Client-server: `mpirun -np 2 pvserver`, and a single pvserver, on this machine's loopback with a
# pvpython client that runs examples/paraview/smoke_plume.py through it (the plume made by the
# server's pipeline, the view's MediumDensity, rendered on the server), against the same script
# in a serial builtin session (pvbatch): the same picture (a mean difference of at most 0.2
# levels, at most 0.3% of the pixels off by more than 4 levels) with ParaView's FXAA off and on
# (np 2) and on (a single pvserver), and the plume split over the server's two processes; then a
# bad array name and a NaN exposure: the server's messages reach the client's output.
# Usage: run_client_server.sh OUTPUT_DIR (PYTHONPATH and the plugin from the environment;
# LIGHTSHAFTS_PVPYTHON: the pvpython to use, default the one beside python3-paraview's package,
# else pvpython on PATH).
set -u
out="$1"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
rm -f "$out"/*.png
pvpython="${LIGHTSHAFTS_PVPYTHON:-}"
if [ -z "$pvpython" ]; then
  for candidate in "${PYTHONPATH%%:*}/../../../bin/pvpython" "$(command -v pvpython)"; do
    if [ -x "$candidate" ]; then
      pvpython="$candidate"
      break
    fi
  done
fi
if [ -z "$pvpython" ]; then
  echo "FAIL: no pvpython (set LIGHTSHAFTS_PVPYTHON)"
  exit 1
fi
# A pvserver on `$1` processes (1: without mpirun) on a free port of the loopback, and the
# client through it (its options: $3...), writing $out/$2.png and $out/$2.log
# ($out/server-$2.log: the server's).
serve() {
  local np=$1 name=$2 port server
  shift 2
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  if [ "$np" = 1 ]; then
    pvserver --server-port="$port" > "$out/server-$name.log" 2>&1 &
  else
    mpirun --allow-run-as-root --oversubscribe -np "$np" -x PYTHONPATH \
      -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x LIGHTSHAFTS_PARAVIEW_PLUGIN -x DISPLAY \
      pvserver --server-port="$port" > "$out/server-$name.log" 2>&1 &
  fi
  server=$!
  for _ in $(seq 1 150); do
    grep -q "Accepting connection" "$out/server-$name.log" && break
    sleep 0.2
  done
  timeout 240 "$pvpython" "$here/client_plume.py" localhost "$port" "$out/$name.png" "$@" \
    > "$out/$name.log" 2>&1
  kill "$server" 2> /dev/null
  wait "$server" 2> /dev/null
}
serve 2 client
# With ParaView's FXAA: the server composites the picture with IceT, without FXAA, and the
# client antialiases it as it shows it (before 2026-12-07 the view turned the client's FXAA off,
# and the picture had none: 0.38% of the pixels off by more than 4 levels).
serve 2 client-fxaa --fxaa
# A single pvserver too, with FXAA (there the server antialiases): its picture is composited
# over the background for its client as IceT's are (before 2026-12-07 its background was not
# dimmed by the medium: a mean of 1.36 levels off).
serve 1 client1 --fxaa
cat "$out"/server-client*.log > "$out/server.log"
pvbatch "$here/client_plume.py" builtin "$out/serial.png" > "$out/serial.log" 2>&1
pvbatch "$here/client_plume.py" builtin "$out/serial-fxaa.png" --fxaa > "$out/serial-fxaa.log" 2>&1
# The messages the bad input after the picture must give: on the server's processes, forwarded
# to the client (each after its "ERROR: In <file>" line), and the exposure's also from the
# client's own pass; no other error or warning anywhere. (The order of the client's printed
# lines and its log's is not kept: ParaView 6.1's Python output is buffered.)
expected='named "no-such-array"|Exposure: non-finite value refused|ERROR: In vtkLightShaftMediumTexture.cxx|ERROR: In vtkLightShaftSetters.h'
for run in client client-fxaa client1 serial serial-fxaa; do
  if [ ! -f "$out/$run.png" ]; then
    cat "$out/$run.log" "$out/server.log"
    echo "FAIL: no picture from the $run run"
    exit 1
  fi
  if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$out/$run.log" |
    grep -v -E "$expected"; then
    echo "FAIL: VTK printed errors or warnings in the $run run"
    exit 1
  fi
done
# (The client renders nothing itself: an error about the field can only be the server's.)
for client in client client-fxaa client1; do
  for message in 'no numeric point or cell array named "no-such-array"' 'Exposure: non-finite value refused'; do
    if ! grep -q "$message" "$out/$client.log"; then
      cat "$out/$client.log"
      echo "FAIL: the client's output ($client) lacks the server's message: $message"
      exit 1
    fi
  done
done
if grep -E "ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|" "$out/server.log" |
  grep -v -E "$expected|vtkSocketCommunicator|vtkTCPNetworkAccessMana"; then
  echo "FAIL: the server printed other errors or warnings"
  exit 1
fi
exec /usr/bin/python3 - "$out" <<'PY'
import re
import sys
import numpy as np
from matplotlib.image import imread
out = sys.argv[1]
failures = []
for name, server, reference in (("client", "pvserver -np 2", "serial"),
                                ("client-fxaa", "pvserver -np 2 with FXAA", "serial-fxaa"),
                                ("client1", "a single pvserver with FXAA", "serial-fxaa")):
    serial = imread(f"{out}/{reference}.png")[..., :3].astype(float) * 255.0
    client = imread(f"{out}/{name}.png")[..., :3].astype(float) * 255.0
    diff = np.abs(client - serial)
    mean, off = float(diff.mean()), float((diff.max(axis=-1) > 4.5).mean())
    print(f"{server} with a pvpython client against serial: mean |diff| {mean:.3f} levels, "
          f"{100 * off:.2f}% of pixels off by > 4 levels, at most {diff.max():.0f}")
    if mean > 0.2 or off > 0.003:
        failures.append(f"the client's picture through {server} is not the serial one")
with open(f"{out}/client.log") as log:
    found = re.search(r"the plume: (\d+) points over the processes \(its whole image: (\d+)\)",
                      log.read())
if not found:
    failures.append("the client did not say how the plume is held")
else:
    held, whole = int(found.group(1)), int(found.group(2))
    print(f"the plume on the server: {held} points over its processes (whole image {whole})")
    if not whole < held <= 1.2 * whole:
        failures.append("the plume was not made on the server's two processes")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
PY
