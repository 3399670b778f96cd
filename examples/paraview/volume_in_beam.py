"""ParaView-style script: a volume representation in a spotlight's beam (and, with
--as-medium, the volume as the medium).

    xvfb-run -a tools/pvbatch examples/paraview/volume_in_beam.py -o volume.png
    xvfb-run -a tools/pvbatch examples/paraview/volume_in_beam.py --as-medium -o medium.png

VTK's wavelet, shown as a Volume (its opacity rising from 0 at 160 to 0.8 at 277), stands in
the beam over a floor, with a translucent sphere beside it. In the light-shaft view the volume
dims the shafts behind it and casts its shadow into the beam, and the shafts seen through the
sphere are dimmed as the floor behind it is. With --as-medium the view's MediumFromVolume makes
the volume the medium: its opacity transfer function is the density that scatters the light.

(tools/pvbatch is pvbatch with ParaView's Python package; LIGHTSHAFTS_PARAVIEW_PLUGIN may name
the plugin, else the build tree's or /usr/local's LightShafts.so is used.)
"""
import argparse
import glob
import os

from paraview.simple import (AddLight, ColorBy, CreateView, GetOpacityTransferFunction,
                             LoadPlugin, Plane, Render, ResampleToImage, SaveScreenshot, Show,
                             Sphere, Transform, Wavelet)

here = os.path.dirname(os.path.abspath(__file__))
candidates = ([os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN", "")]
              + glob.glob(os.path.join(here, "..", "..", "build", "paraview-plugin", "lib",
                                       "paraview-*", "plugins", "LightShafts", "LightShafts.so"))
              + glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so"))
parser = argparse.ArgumentParser()
parser.add_argument("-o", "--output", default="volume_in_beam.png")
parser.add_argument("--as-medium", action="store_true")
args = parser.parse_args()

LoadPlugin(next(p for p in candidates if p and os.path.exists(p)), remote=False, ns=globals())
view = CreateView("LightShaftsRenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.01, 0.01, 0.015]
view.UseLight = 0                                   # the spotlight alone

Show(Plane(Origin=[-6, 0, -6], Point1=[6, 0, -6], Point2=[-6, 0, 6],
           XResolution=64, YResolution=64), view)
glass = Show(Sphere(Center=[2.2, 1.2, 2.0], Radius=0.9, ThetaResolution=48,
                    PhiResolution=48), view)
glass.Opacity = 0.5                                 # a translucent surface in front of the beam

wavelet = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
placed = Transform(Input=wavelet)
placed.Transform.Scale = [0.1, 0.1, 0.1]
placed.Transform.Translate = [0.3, 2.6, 0.0]
volume = Show(ResampleToImage(Input=placed), view)
volume.Representation = "Volume"
ColorBy(volume, ("POINTS", "RTData"))
GetOpacityTransferFunction("RTData").Points = [37.0, 0.0, 0.5, 0.0, 160.0, 0.0, 0.5, 0.0,
                                               277.0, 0.8, 0.5, 0.0]

light = AddLight(view=view)                         # ParaView's light API (Light Inspector)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [0.0, 6.0, 0.0]
light.FocalPoint = [0.0, 0.0, 0.0]
light.ConeAngle = 24.0

view.ScatteringCoefficient = [0.08, 0.08, 0.08]
view.ShaftExposure = 12.0


def volume_as_medium(view):
    """The view's first volume representation as the medium (--as-medium)."""
    view.MediumFromVolume = 1
    view.ScatteringCoefficient = [1.5, 1.4, 1.3]    # per unit of the volume's opacity
    view.MediumBackgroundDensity = 0.05


if args.as_medium:
    volume_as_medium(view)
Render(view)  # the first render resets the camera to the data: place it afterwards
view.CameraPosition = [0.0, 3.0, 14.0]
view.CameraFocalPoint = [0.0, 2.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
SaveScreenshot(args.output, view, ImageResolution=[800, 600])
