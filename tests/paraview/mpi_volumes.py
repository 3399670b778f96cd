"""pvbatch --symmetric script (serial or under mpirun): a scene whose volume or translucent
surfaces ParaView splits across the processes, rendered with the shafts by SLICES, RAY_MARCH and
EPIPOLAR and without them, into OUTPUT-<method>.png and OUTPUT-plain.png (400x300). Each process
writes OUTPUT.rank<r>.json: the cells or points of the split data it holds.

    --scene volume   examples/paraview/volume_in_beam.py (its volume dims and shadows the beam,
                     its translucent sphere dims what is seen through it)
    --scene medium   the same with --as-medium (the volume is the medium)
    --scene panes    translucent panes split across the processes: a red one across the beam
                     (the light leg: it tints the shafts below it) and a grey one between the
                     camera and the beam (the camera leg: it dims the shafts behind it)

Usage: pvbatch --symmetric mpi_volumes.py OUTPUT --scene volume|medium|panes"""

import argparse
import json
import os
import runpy
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lightshafts_pvscene as scene  # noqa: E402

SIZE = [400, 300]
METHODS = (("slices", 0), ("raymarch", 1), ("epipolar", 5))


def panes():
    """Two translucent panes, each split across the processes (RedistributeDataSet), in a
    spotlight's beam over a floor; returns the view and the panes' sources."""
    from paraview import simple
    scene.load_plugin()
    view = simple.CreateView("LightShaftsRenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.01, 0.01, 0.015]
    view.UseLight = 0
    simple.Show(simple.Plane(Origin=[-6, 0, -6], Point1=[6, 0, -6], Point2=[-6, 0, 6],
                             XResolution=16, YResolution=16), view)
    # Across the beam, 3 units below the light: it tints the shafts and the floor below it.
    red = simple.RedistributeDataSet(Input=simple.Plane(
        Origin=[-3, 3, -3], Point1=[3, 3, -3], Point2=[-3, 3, 3], XResolution=32,
        YResolution=32))
    shown = simple.Show(red, view)
    shown.AmbientColor = shown.DiffuseColor = [1.0, 0.2, 0.2]
    shown.Opacity = 0.5
    # Between the camera and the beam, over the left half of the view: it dims what it hides.
    grey = simple.RedistributeDataSet(Input=simple.Plane(
        Origin=[-4, 0, 3], Point1=[0, 0, 3], Point2=[-4, 6, 3], XResolution=32,
        YResolution=32))
    shown = simple.Show(grey, view)
    shown.AmbientColor = shown.DiffuseColor = [0.2, 0.2, 0.2]
    shown.Opacity = 0.5
    light = simple.AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = [0.0, 6.0, 0.0]
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.ConeAngle = 24.0
    view.ScatteringCoefficient = [0.08, 0.08, 0.08]
    view.ShaftExposure = 12.0
    simple.Render(view)
    view.CameraPosition = [0.0, 3.0, 14.0]
    view.CameraFocalPoint = [0.0, 2.5, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    return view, [red, grey]


def main():
    from paraview import servermanager, simple
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("--scene", choices=("volume", "medium", "panes"), required=True)
    args = parser.parse_args()
    if args.scene == "panes":
        view, split = panes()
    else:
        sys.argv = [sys.argv[0], "-o", args.output + "-example.png"]
        sys.argv += ["--as-medium"] if args.scene == "medium" else []
        # The example's own 800x600 screenshot is left out (the pictures compared follow).
        save = simple.SaveScreenshot
        simple.SaveScreenshot = lambda *arguments, **keywords: True
        runpy.run_path(os.path.join(HERE, "..", "..", "examples", "paraview",
                                    "volume_in_beam.py"))
        simple.SaveScreenshot = save
        view = simple.GetActiveView()
        split = [simple.FindSource("ResampleToImage1"), simple.FindSource("Sphere1")]
    # The split data this process holds (its part of each source's cells, or points).
    held = []
    for source in split:
        data = source.GetClientSideObject().GetOutputDataObject(0)
        held.append(int(data.GetNumberOfCells() or data.GetNumberOfPoints()))
    for name, method in METHODS:
        view.ShaftMethod = method
        simple.SaveScreenshot(f"{args.output}-{name}.png", view, ImageResolution=SIZE)
    # Without shafts: the same view in an empty medium, whose picture is its delegate's, bit for
    # bit (with the shafts off, ParaView antialiases a volume's edges otherwise: up to 15 levels
    # apart at np 4, docs/known-issues.md).
    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    view.AbsorptionCoefficient = [0.0, 0.0, 0.0]
    simple.SaveScreenshot(f"{args.output}-plain.png", view, ImageResolution=SIZE)
    module = servermanager.vtkProcessModule.GetProcessModule()
    rank = module.GetPartitionId()
    with open(f"{args.output}.rank{rank}.json", "w") as out:
        json.dump({"rank": rank, "held": held}, out)
    module.GetGlobalController().Barrier()  # every process writes before any leaves (os._exit)
    return 0


if __name__ == "__main__":
    scene.finish(main())
