"""pvbatch --symmetric script (serial or under mpirun): examples/paraview/smoke_plume.py at
--points samples across the plume (37: the example's), then this process's peak resident memory
when the picture is saved (/proc/self/status VmHWM, bytes) into OUTPUT.rank<r>.json; the picture is OUTPUT.png. The
field's memory is the peak at a large --points less the peak at the example's. --methods: the
scene again with SLICES and EPIPOLAR, without the shafts, with absorption only (the example's
--absorb-only: scattering 0, RAY_MARCH), and with the plume as cell data resampled to 24 samples
across, in the same process (one pvbatch start for all six pictures). Usage:
pvbatch --symmetric mpi_field_memory.py OUTPUT --points N [--field-resolution R] [the example's
other options]"""

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
    parser.add_argument("--field-resolution", type=int, default=2048)
    parser.add_argument("--methods", action="store_true",
                        help="also OUTPUT-slices.png, OUTPUT-epipolar.png, OUTPUT-plain.png, "
                        "OUTPUT-absorb-only.png and OUTPUT-cells.png")
    args, example = parser.parse_known_args()  # (the others: the example's, as --absorb-only)
    sys.argv = [sys.argv[0], "-o", args.output + ".png", "--size", "400", "300",
                "--points", str(args.points), "--field-resolution", str(args.field_resolution)]
    sys.argv += example
    # The peak when the picture is saved (before the example's summary asks ParaView for the
    # plume's data information, which updates it again without the gather's ghost level).
    from paraview import simple
    save = simple.SaveScreenshot
    peaks = []

    def saved(*arguments, **keywords):
        result = save(*arguments, **keywords)
        with open("/proc/self/status") as lines:
            peaks.append(next(int(line.split()[1]) * 1024 for line in lines
                              if line.startswith("VmHWM:")))
        return result

    simple.SaveScreenshot = saved
    example = runpy.run_path(os.path.join(HERE, "..", "..", "examples", "paraview",
                                          "smoke_plume.py"))
    peak = peaks[0]
    if args.methods:
        # The same scene with the other methods that render a medium from data, and without the
        # shafts: the in-scatter of each method is its picture less that one.
        view = simple.GetActiveView()
        size = [400, 300]
        for method, name in ((0, "slices"), (5, "epipolar")):
            view.ShaftMethod = method
            save(f"{args.output}-{name}.png", view, ImageResolution=size)
        view.LightShafts = 0
        save(f"{args.output}-plain.png", view, ImageResolution=size)
        # The example's --absorb-only: its settings with scattering 0.
        view.LightShafts = 1
        view.ShaftMethod = 1
        scattering = list(view.ScatteringCoefficient)
        view.ScatteringCoefficient = [0.0, 0.0, 0.0]
        save(f"{args.output}-absorb-only.png", view, ImageResolution=size)
        # The plume as cell data, resampled to a coarser grid (36 along y, where it has 47
        # cells): a grid point between two processes' pieces reads cells of both (the gather
        # asks for a ghost level; without it, a plane of the grid at np 2 and 4 has no value).
        view.ScatteringCoefficient = scattering
        view.MediumDensity = simple.PointDatatoCellData(Input=example["plume"])
        view.MediumFieldResolution = 36
        save(f"{args.output}-cells.png", view, ImageResolution=size)
    module = servermanager.vtkProcessModule.GetProcessModule()
    rank = module.GetPartitionId()
    with open(f"{args.output}.rank{rank}.json", "w") as out:
        json.dump({"rank": rank, "processes": module.GetNumberOfLocalPartitions(),
                   "points": args.points, "peak": peak}, out)
    module.GetGlobalController().Barrier()  # every process writes before any leaves (os._exit)
    return 0


if __name__ == "__main__":
    scene.finish(main())
