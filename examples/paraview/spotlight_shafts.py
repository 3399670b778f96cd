"""ParaView-style script: light shafts of a spotlight through a sphere over a floor.

    xvfb-run -a tools/pvbatch examples/paraview/spotlight_shafts.py -o shafts.png

(tools/pvbatch is pvbatch with ParaView's Python package; LIGHTSHAFTS_PARAVIEW_PLUGIN may name
the plugin, else the build tree's or /usr/local's LightShafts.so is used.)
"""
import argparse
import glob
import os

from paraview.simple import (AddLight, CreateView, LoadPlugin, Plane, Render, SaveScreenshot,
                             Show, Sphere)

here = os.path.dirname(os.path.abspath(__file__))
candidates = ([os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN", "")]
              + glob.glob(os.path.join(here, "..", "..", "build", "paraview-plugin", "lib",
                                       "paraview-*", "plugins", "LightShafts", "LightShafts.so"))
              + glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so"))
parser = argparse.ArgumentParser()
parser.add_argument("-o", "--output", default="spotlight_shafts.png")
args = parser.parse_args()

LoadPlugin(next(p for p in candidates if p and os.path.exists(p)), remote=False, ns=globals())
view = CreateView("LightShaftsRenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.UseLight = 0                                   # the spotlight alone

Show(Plane(Origin=[-6, 0, -6], Point1=[6, 0, -6], Point2=[-6, 0, 6],
           XResolution=64, YResolution=64), view)
Show(Sphere(Center=[0.4, 3.0, 0.0], Radius=0.9, ThetaResolution=64, PhiResolution=64), view)

light = AddLight(view=view)                         # ParaView's light API (Light Inspector)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [0.0, 6.0, 0.0]
light.FocalPoint = [0.0, 0.0, 0.0]
light.ConeAngle = 25.0

view.ScatteringCoefficient = [0.08, 0.07, 0.06]
view.ShaftExposure = 100.0
view.AttenuateScene = 0
view.ShaftQuality = 3                               # Final preset
view.ShadowSurfaces = 1                             # the floor shows the sphere's shadow too
Render(view)  # the first render resets the camera to the data: place it afterwards
view.CameraPosition = [2.0, 3.5, 14.0]
view.CameraFocalPoint = [0.0, 2.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)
SaveScreenshot(args.output, view, ImageResolution=[800, 600])
print("wrote", args.output)
