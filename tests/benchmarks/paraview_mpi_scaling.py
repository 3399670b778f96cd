"""The shafts' work under ParaView's MPI rendering, measured per process (pvbatch --symmetric).

    tools/measure.sh mpi-scaling            (np 1, 2 and 4; writes docs/paraview-mpi-scaling.md)

One run of this script is one process count: every process runs it (`mpirun -np N pvbatch
--symmetric`), renders the ParaView tests' scene (tests/paraview/lightshafts_pvscene.py: a
spotlight, a sphere that nearly fills its cone, a floor) at --size with the Final preset (and no
progressive refinement: every frame the whole setting), --frames times with the shafts and
--frames times without (the light-shafts view with LightShafts off:
ParaView's own picture), and writes what it measured to OUTPUT.rank<r>.json: the medians of the
render times (wall clock around Render, every process in lock step), the rows and fragments of
the in-scatter it computed (vtkLightShaftFrameReport), the bytes it sent and received
(GetLastBytesExchanged), with DivideShaftWork on and off. Usage: pvbatch --symmetric
paraview_mpi_scaling.py OUTPUT [--size W H] [--frames N]
"""

import argparse
import json
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "paraview"))
import lightshafts_pvscene as scene  # noqa: E402


def timed_renders(view, frames):
    from paraview import simple
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        simple.Render(view)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    from paraview import servermanager, simple
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
    parser.add_argument("--frames", type=int, default=9)
    args = parser.parse_args()
    scene.load_plugin()
    scene.WIDTH, scene.HEIGHT = args.size
    view, _, _ = scene.make_scene(ShaftExposure=12.0)
    view.ShaftQuality = 3  # Final
    # Each frame the whole Final setting, as while the camera moves (a refining still view's
    # estimates shift the shadow map's texels, so that each renders and combines its maps).
    view.ProgressiveRefinement = 0
    module = servermanager.vtkProcessModule.GetProcessModule()
    rank, processes = module.GetPartitionId(), module.GetNumberOfLocalPartitions()
    results = {"processes": processes, "rank": rank, "size": args.size, "frames": args.frames}
    simple.Render(view)  # (shaders compiled, maps sized: not timed)
    view.LightShafts = 0
    results["without_shafts"] = timed_renders(view, args.frames)
    view.LightShafts = 1
    for divide in (1, 0):
        view.DivideShaftWork = divide
        simple.Render(view)
        seconds = timed_renders(view, args.frames)
        view.UpdatePropertyInformation()
        results["divided" if divide else "whole"] = {
            "with_shafts": seconds,
            "rows": view.GetProperty("LastImagePieceRows").GetElement(0),
            "fragments": view.GetProperty("LastInScatterFragments").GetElement(0),
            "bytes": view.GetProperty("LastBytesExchanged").GetElement(0),
            "variant": view.GetProperty("LastShaderVariant").GetElement(0),
        }
    with open(f"{args.output}.rank{rank}.json", "w") as out:
        json.dump(results, out, indent=1)
    # Every process has written before any leaves: pvbatch ends with os._exit (finish), which
    # mpirun takes for a failure and answers by stopping the others.
    module.GetGlobalController().Barrier()
    return 0


if __name__ == "__main__":
    scene.finish(main())
