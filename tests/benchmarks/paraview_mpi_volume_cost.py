"""pvbatch --symmetric script (serial or under mpirun): the cost of the distributed volume path.
examples/paraview/volume_in_beam.py at 800x600 (its default sampling), the camera moved a
little each frame so that nothing is kept; medians of 7 renders (after one), without the shafts
(LightShafts off) and with them, and the bytes the view exchanged in the last frame
(LastBytesExchanged). Each process prints one line.

    LP_NUM_THREADS=1 xvfb-run -a -s -noreset tools/pvbatch --symmetric \\
        tests/benchmarks/paraview_mpi_volume_cost.py
    xvfb-run -a -s -noreset mpirun -np 2 -x LP_NUM_THREADS=1 -x PYTHONPATH \\
        -x LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST -x DISPLAY pvbatch --symmetric \\
        tests/benchmarks/paraview_mpi_volume_cost.py
"""
import os
import runpy
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "paraview"))
import lightshafts_pvscene as scene  # noqa: E402


def median_frame(simple, view, frames=8):
    seconds = []
    for i in range(frames):
        view.CameraPosition = [0.01 * i, 3.0, 14.0]
        start = time.perf_counter()
        simple.Render(view)
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds[1:])


def main():
    from paraview import servermanager, simple
    sys.argv = [sys.argv[0], "-o", os.devnull]
    save = simple.SaveScreenshot
    simple.SaveScreenshot = lambda *arguments, **keywords: True  # (the example's own)
    runpy.run_path(os.path.join(ROOT, "examples", "paraview", "volume_in_beam.py"))
    simple.SaveScreenshot = save
    view = simple.GetActiveView()
    view.ViewSize = [800, 600]
    view.LightShafts = 0
    plain = median_frame(simple, view)
    view.LightShafts = 1
    shafts = median_frame(simple, view)
    view.UpdatePropertyInformation()
    exchanged = view.GetPropertyValue("LastBytesExchanged")
    module = servermanager.vtkProcessModule.GetProcessModule()
    print(f"process {module.GetPartitionId()} of {module.GetNumberOfLocalPartitions()}: "
          f"without shafts {plain:.3f} s, with {shafts:.3f} s, shafts' time "
          f"{shafts - plain:.3f} s; {exchanged / 2**20:.1f} MiB exchanged in the last frame")
    module.GetGlobalController().Barrier()
    return 0


if __name__ == "__main__":
    scene.finish(main())
