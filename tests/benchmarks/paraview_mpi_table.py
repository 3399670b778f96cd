#!/usr/bin/python3
"""The shafts' work divided among ParaView's MPI processes: np 1, 2 and 4, measured.

    tools/measure.sh mpi-scaling        (writes docs/paraview-mpi-scaling.md; about 3 minutes)

Runs tests/benchmarks/paraview_mpi_scaling.py under `mpirun -np N pvbatch --symmetric` for N in
--processes, twice: with Mesa's llvmpipe on one thread per process (LP_NUM_THREADS=1: each
process has a core to itself up to this machine's cores, as each would have its own GPU) and on
llvmpipe's default threads (all cores per process: the processes share them). Writes the table
of the shafts' time per frame (the render with the shafts minus without, medians; every process
waits for the others, so this is the slowest process's), the rows and fragments each process's
in-scatter took, and the bytes each exchanged.
"""

import argparse
import glob
import json
import os
import platform
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def run(processes, threads, size, frames, work):
    env = dict(os.environ)
    env["PYTHONPATH"] = glob.glob("/usr/local/lib/lightshafts/python3-paraview/usr/lib/python3/"
                                  "dist-packages")[0]
    env.setdefault("LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST",
                   os.path.join(ROOT, "build", "paraview-plugin", "LightShaftsPluginPath.txt"))
    env.pop("LP_NUM_THREADS", None)
    if threads:
        env["LP_NUM_THREADS"] = str(threads)
    output = os.path.join(work, f"np{processes}-t{threads or 0}")
    command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(processes)]
    for name in ("PYTHONPATH", "LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST", "DISPLAY", "LP_NUM_THREADS"):
        if name in env:
            command += ["-x", name]
    command += ["pvbatch", "--symmetric", os.path.join(HERE, "paraview_mpi_scaling.py"), output,
                "--size", str(size[0]), str(size[1]), "--frames", str(frames)]
    subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    ranks = []
    for rank in range(processes):
        with open(f"{output}.rank{rank}.json") as results:
            ranks.append(json.load(results))
    return ranks


def row(processes, threads, ranks, serial_shafts):
    first = ranks[0]
    divided = first["divided"]
    shafts = divided["with_shafts"] - first["without_shafts"]
    whole = first["whole"]["with_shafts"] - first["without_shafts"]
    fragments = [r["divided"]["fragments"] for r in ranks]
    shares = ("—" if fragments[0] < 0 else
              " / ".join(f"{100 * f / sum(fragments):.0f}%" for f in fragments))
    rows = " / ".join(str(int(r["divided"]["rows"])) for r in ranks) if processes > 1 else "all"
    megabytes = " / ".join(f"{r['divided']['bytes'] / 2**20:.1f}" for r in ranks)
    return (f"| {processes} | {threads or 'default'} | {first['without_shafts']:.3f} | "
            f"{divided['with_shafts']:.3f} | {shafts:.3f} | {shafts / serial_shafts:.2f} | "
            f"{whole:.3f} | {rows} | {shares} | {megabytes} |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--processes", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--output", default=os.path.join(ROOT, "docs",
                                                         "paraview-mpi-scaling.md"))
    args = parser.parse_args()
    lines = [
        "# The shafts' work divided among ParaView's MPI processes (measured)",
        "",
        "Written by `tools/measure.sh mpi-scaling` (tests/benchmarks/paraview_mpi_table.py). The "
        "ParaView tests' scene (a spotlight, a sphere nearly filling its cone, a floor; "
        f"tests/paraview/lightshafts_pvscene.py) at {args.size[0]}x{args.size[1]}, the Final "
        "preset (RAY_MARCH, 256 steps, 2048² shadow map), `mpirun -np N pvbatch --symmetric`; "
        f"medians of {args.frames} renders. Seconds per frame: the render without the shafts "
        "(the view with LightShafts off), with them (DivideShaftWork on, the default), and "
        "their difference, the shafts' time; the same difference with DivideShaftWork off "
        "(every process computes the whole in-scatter). Each process's rows of the in-scatter, "
        "its share of the fragments marched, and the MiB it sent and received per frame.",
        "",
        f"({platform.platform()}, {os.cpu_count()} cores, Mesa llvmpipe under Xvfb, no GPU. "
        "LP_NUM_THREADS=1 gives each process one rendering thread, as each would have its own "
        "GPU; 4 processes share this machine's 2 cores. Each frame renders the whole Final "
        "setting (ProgressiveRefinement off), as while the camera moves.)",
        "",
        "| np | llvmpipe threads | without shafts (s) | with shafts (s) | shafts' time (s) | "
        "vs serial | shafts' time, not divided (s) | rows per process | fragments per process "
        "| MiB exchanged per process |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    with tempfile.TemporaryDirectory() as work:
        for threads in (1, None):
            serial = None
            for processes in args.processes:
                ranks = run(processes, threads, args.size, args.frames, work)
                shafts = ranks[0]["divided"]["with_shafts"] - ranks[0]["without_shafts"]
                serial = serial or shafts
                lines.append(row(processes, threads, ranks, serial))
                print(lines[-1], flush=True)
    with open(args.output, "w") as out:
        out.write("\n".join(lines) + "\n")
    print("wrote", args.output)


if __name__ == "__main__":
    main()
