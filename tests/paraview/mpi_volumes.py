"""pvbatch --symmetric script (serial or under mpirun): scenes whose volume or translucent
surfaces ParaView splits across the processes, each rendered with the shafts by SLICES,
RAY_MARCH and EPIPOLAR and in an empty medium, into OUTPUT/<scene>-<label>-<method>.png and
OUTPUT/<scene>-<label>-plain.png (400x300). Each process writes
OUTPUT/<scene>-<label>.rank<r>.json: the cells or points of the split data it holds.

    volume   examples/paraview/volume_in_beam.py (its volume dims and shadows the beam, its
             translucent sphere dims what is seen through it)
    medium   the same view after the example's volume_as_medium (its --as-medium: the volume is
             the medium)
    panes    translucent panes split across the processes: a red one across the beam (the light
             leg: it tints the shafts below it) and a grey one between the camera and the beam
             (the camera leg: it dims the shafts behind it)

Usage: pvbatch --symmetric mpi_volumes.py OUTPUT LABEL"""

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
    spotlight's beam; returns the view and the panes' sources. (No floor: under the panes'
    ordered compositing ParaView 5.13 draws a crack between an opaque floor's pieces, up to 122
    levels dark in its own picture, through which the shafts then reach the backdrop.)"""
    from paraview import simple
    view = simple.CreateView("LightShaftsRenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]  # (black: what IceT composites the panes over)
    view.UseLight = 0
    # Across the beam, 3 units below the light: it tints the shafts below it.
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
    view.ShaftExposure = 48.0  # (no floor: a bright beam)
    simple.Render(view)
    view.CameraPosition = [0.0, 3.0, 14.0]
    view.CameraFocalPoint = [0.0, 2.5, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    return view, [red, grey]


def held(sources):
    """The cells (or points) of each split source this process holds."""
    counts = []
    for source in sources:
        data = source.GetClientSideObject().GetOutputDataObject(0)
        counts.append(int(data.GetNumberOfCells() or data.GetNumberOfPoints()))
    return counts


def render(view, base, sources):
    """One scene's pictures: each method's, then the empty medium's (its picture is the view's
    delegate's, bit for bit; with the shafts off ParaView antialiases a volume's edges otherwise,
    docs/known-issues.md); and the split data this process holds."""
    from paraview import servermanager, simple
    for name, method in METHODS:
        view.ShaftMethod = method
        simple.SaveScreenshot(f"{base}-{name}.png", view, ImageResolution=SIZE)
    scattering = list(view.ScatteringCoefficient)
    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    view.AbsorptionCoefficient = [0.0, 0.0, 0.0]
    simple.SaveScreenshot(f"{base}-plain.png", view, ImageResolution=SIZE)
    view.ScatteringCoefficient = scattering
    rank = servermanager.vtkProcessModule.GetProcessModule().GetPartitionId()
    with open(f"{base}.rank{rank}.json", "w") as out:
        json.dump({"rank": rank, "held": held(sources)}, out)


def main():
    from paraview import servermanager, simple
    output, label = sys.argv[1], sys.argv[2]
    # The example, without its own 800x600 screenshot (the pictures compared follow).
    sys.argv = [sys.argv[0], "-o", os.path.join(output, "example.png")]
    save = simple.SaveScreenshot
    simple.SaveScreenshot = lambda *arguments, **keywords: True
    example = runpy.run_path(os.path.join(HERE, "..", "..", "examples", "paraview",
                                          "volume_in_beam.py"))
    simple.SaveScreenshot = save
    view = simple.GetActiveView()
    split = [simple.FindSource("ResampleToImage1"), simple.FindSource("Sphere1")]
    render(view, os.path.join(output, f"volume-{label}"), split)
    example["volume_as_medium"](view)
    render(view, os.path.join(output, f"medium-{label}"), split)
    view, split = panes()
    render(view, os.path.join(output, f"panes-{label}"), split)
    module = servermanager.vtkProcessModule.GetProcessModule()
    module.GetGlobalController().Barrier()  # every process writes before any leaves (os._exit)
    return 0


if __name__ == "__main__":
    scene.finish(main())
