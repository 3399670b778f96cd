"""pvbatch script (serial or under mpirun): the light-shaft view's features on the test scene,
each picture written to OUTPUT_DIR for run_mpi_features.sh to compare with the serial run's:
the presets (Draft, Interactive, Final), ShaftTargetError, a still view refined until converged,
DistributedShadowMap off; and, whose pictures depend on each process's clock so that only their
completing is checked, a frame budget over moving frames and Exact Finish (off under MPI, with
one warning); and selections, which must select what a plain RenderView selects in the same run.
Writes OUTPUT_DIR/results.json. Usage: pvbatch mpi_features.py OUTPUT_DIR"""

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lightshafts_pvscene as scene  # noqa: E402
from test_selection import selections  # noqa: E402


def place_camera(view):
    view.CameraPosition = [0.0, 3.0, 14.0]
    view.CameraFocalPoint = [0.0, 3.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 40.0


def converge(view, frames=40):
    """Still renders until converged; the renders it took (-1: not converged)."""
    from paraview import simple
    for count in range(1, frames + 1):
        simple.Render(view)
        view.UpdatePropertyInformation()
        if view.GetPropertyValue("RefinementConverged"):
            return count
    return -1


def main():
    from paraview import servermanager, simple
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    scene.load_plugin()
    module = servermanager.vtkProcessModule.GetProcessModule()
    results = {"processes": module.GetNumberOfLocalPartitions()}
    view, _, _ = scene.make_scene()
    view.ProgressiveRefinement = 0
    simple.Render(view)  # (the first render resets the camera to the data: place it again)
    place_camera(view)
    simple.Render(view)
    for value, name in ((1, "draft"), (2, "interactive"), (3, "final")):
        view.ShaftQuality = value
        scene.screenshot(view, os.path.join(out, f"{name}.png"))
    view.ShaftQuality = 0
    view.ShaftTargetError = 0.02
    scene.screenshot(view, os.path.join(out, "target.png"))
    view.ShaftTargetError = 0.0
    view.DistributedShadowMap = 0
    simple.Render(view)  # (alone: each process its own occluders; under MPI, not the serial one)
    view.DistributedShadowMap = 1
    # A frame budget over moving frames: every process's cost model learns the slowest one's
    # times, so that they choose the same settings (else their collective calls would not match).
    view.ShaftTimeBudget = 0.05
    for step in range(6):
        view.CameraPosition = [0.2 * step, 3.0, 14.0]
        simple.Render(view)
    view.UpdatePropertyInformation()
    results["budget"] = view.GetPropertyValue("LastTimeBudget")
    view.ShaftTimeBudget = 0.0
    place_camera(view)
    view.ProgressiveRefinement = 1
    view.RefinementFrames = 8
    results["converged_after"] = converge(view)
    scene.screenshot(view, os.path.join(out, "refined.png"))
    view.ExactFinish = 1
    simple.Render(view)
    simple.Render(view)
    view.UpdatePropertyInformation()
    results["exact_finish_state"] = view.GetPropertyValue("ExactFinishState")
    view.ExactFinish = 0
    view.ProgressiveRefinement = 0
    loaded = view
    # Selections: the light-shaft view against a plain RenderView, both in this run.
    sources = {"sphere": None, "floor": None}
    for source in simple.GetSources().values():
        name = source.GetXMLName()
        if name == "SphereSource":
            sources["sphere"] = source
        elif name == "PlaneSource":
            sources["floor"] = source
    plain = simple.CreateView("RenderView")
    plain.ViewSize = [scene.WIDTH, scene.HEIGHT]
    for source in sources.values():
        simple.Show(source, plain)
    simple.Render(plain)
    for target in (plain, loaded):
        place_camera(target)
        simple.Render(target)
    picked = {name: selections(target, sources)
              for name, target in (("plain", plain), ("shafts", loaded))}
    results["selections_equal"] = picked["plain"] == picked["shafts"]
    results["selected"] = {f"{k[0]} {k[1]}": {label: len(ids) for label, ids in v.items()}
                           for k, v in picked["shafts"].items()}
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    print(json.dumps(results))
    return 0


if __name__ == "__main__":
    scene.finish(main())
