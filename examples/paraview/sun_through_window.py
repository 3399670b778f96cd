"""ParaView-style script: sunlight through a window (a directional light of the Light
Inspector casting shafts into a closed room, the floor shadowed by the same map).

    xvfb-run -a -s "-noreset" tools/pvbatch examples/paraview/sun_through_window.py -o sun.png

(tools/pvbatch is pvbatch with ParaView's Python package; LIGHTSHAFTS_PARAVIEW_PLUGIN may name
the plugin, else the build tree's or /usr/local's LightShafts.so is used.) A directional light
scatters only when listed in ShaftLights (the light kit's lights are directional too); it lights
the half-space beyond the plane through its Position, perpendicular to its direction.
"""
import argparse
import glob
import os

from paraview.simple import (AddLight, Box, CreateView, LoadPlugin, Plane, Render,
                             SaveScreenshot, Show)

here = os.path.dirname(os.path.abspath(__file__))
candidates = ([os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN", "")]
              + glob.glob(os.path.join(here, "..", "..", "build", "paraview-plugin", "lib",
                                       "paraview-*", "plugins", "LightShafts", "LightShafts.so"))
              + glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so"))
parser = argparse.ArgumentParser()
parser.add_argument("-o", "--output", default="sun_through_window.png")
parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
args = parser.parse_args()

LoadPlugin(next(p for p in candidates if p and os.path.exists(p)), remote=False, ns=globals())
view = CreateView("LightShaftsRenderView")
view.ViewSize = list(args.size)
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.01, 0.01, 0.02]
view.UseLight = 0                                   # the sun alone

Show(Plane(Origin=[-15, 0, -15], Point1=[15, 0, -15], Point2=[-15, 0, 15]), view)
# A wall at x = -3 with a four-pane window, and a ceiling: centre, lengths.
for centre, lengths in (([-3.0, 0.75, 0.0], [0.2, 1.5, 30.0]),
                        ([-3.0, 6.25, 0.0], [0.2, 2.5, 30.0]),
                        ([-3.0, 3.25, -8.25], [0.2, 3.5, 13.5]),
                        ([-3.0, 3.25, 8.25], [0.2, 3.5, 13.5]),
                        ([-3.0, 3.25, 0.0], [0.2, 3.5, 0.25]),
                        ([-3.0, 3.25, 0.0], [0.2, 0.25, 3.0]),
                        ([4.5, 7.6, 0.0], [15.2, 0.2, 30.0])):
    display = Show(Box(Center=centre, XLength=lengths[0], YLength=lengths[1],
                       ZLength=lengths[2]), view)
    display.AmbientColor = display.DiffuseColor = [0.55, 0.45, 0.35]

sun = AddLight(view=view)                           # ParaView's light API (Light Inspector)
sun.Coords = "Scene"
sun.Type = "Directional"
sun.Position = [-12.0, 10.0, 1.5]                   # the plane the light starts from
sun.FocalPoint = [0.5, 0.0, -0.5]                   # the direction it travels
sun.DiffuseColor = [1.0, 0.92, 0.78]

view.ShaftLights = [1]                              # the sun (directional: listed)
view.ScatteringCoefficient = [0.05, 0.047, 0.043]
view.PhaseFunction = 1                              # Henyey-Greenstein
view.Anisotropy = 0.4
view.ShaftExposure = 40.0
view.ShaftQuality = 3                               # Final preset
view.ShadowSurfaces = 1                             # the floor shows the window's pattern
Render(view)  # the first render resets the camera to the data: place it afterwards
view.CameraPosition = [7.0, 2.2, 8.0]
view.CameraFocalPoint = [-3.0, 3.0, -1.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 40.0
Render(view)
SaveScreenshot(args.output, view, ImageResolution=list(args.size))
print("wrote", args.output)
