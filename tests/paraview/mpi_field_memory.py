"""pvbatch --symmetric script (serial or under mpirun): examples/paraview/smoke_plume.py at
--points samples across the plume (37: the example's), then this process's peak resident memory
(/proc/self/status VmHWM, bytes) into OUTPUT.rank<r>.json; the picture is OUTPUT.png. The
field's memory is the peak at a large --points less the peak at the example's. Usage:
pvbatch --symmetric mpi_field_memory.py OUTPUT --points N"""

import argparse
import json
import os
import runpy
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lightshafts_pvscene as scene  # noqa: E402


def main():
    from paraview import servermanager
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--points", type=int, default=37)
    args = parser.parse_args()
    sys.argv = [sys.argv[0], "-o", args.output + ".png", "--size", "400", "300",
                "--points", str(args.points)]
    runpy.run_path(os.path.join(HERE, "..", "..", "examples", "paraview", "smoke_plume.py"))
    with open("/proc/self/status") as lines:
        peak = next(int(line.split()[1]) * 1024 for line in lines if line.startswith("VmHWM:"))
    module = servermanager.vtkProcessModule.GetProcessModule()
    rank = module.GetPartitionId()
    with open(f"{args.output}.rank{rank}.json", "w") as out:
        json.dump({"rank": rank, "processes": module.GetNumberOfLocalPartitions(),
                   "points": args.points, "peak": peak}, out)
    module.GetGlobalController().Barrier()  # every process writes before any leaves (os._exit)
    return 0


if __name__ == "__main__":
    scene.finish(main())
