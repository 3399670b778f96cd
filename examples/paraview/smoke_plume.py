"""ParaView-style script: a spotlight's shafts through a plume from the pipeline (MediumDensity).

    xvfb-run -a tools/pvbatch examples/paraview/smoke_plume.py -o plume.png
    mpirun -np 2 tools/pvbatch examples/paraview/smoke_plume.py -o plume.png   (the same picture)

The plume is made by the pipeline, as a simulation's output would come: VTK's wavelet
(Wavelet) as turbulence, a Calculator that shapes it into a column rising from the floor,
leaning and widening (its "smoke" array), chosen as the view's MediumDensity. The view renders the shafts
through it: the smoke scatters where it is, and shadows the beam beyond it. Changing the
Wavelet's or the Calculator's properties changes the medium at the next render.

(tools/pvbatch is pvbatch with ParaView's Python package; LIGHTSHAFTS_PARAVIEW_PLUGIN may name
the plugin, else the build tree's or /usr/local's LightShafts.so is used.)
"""
import argparse
import glob
import os

from paraview.simple import (AddLight, Calculator, CreateView, LoadPlugin, Plane, Render,
                             SaveScreenshot, Show, Wavelet)

here = os.path.dirname(os.path.abspath(__file__))
candidates = ([os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN", "")]
              + glob.glob(os.path.join(here, "..", "..", "build", "paraview-plugin", "lib",
                                       "paraview-*", "plugins", "LightShafts", "LightShafts.so"))
              + glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so"))
parser = argparse.ArgumentParser()
parser.add_argument("-o", "--output", default="smoke_plume.png")
parser.add_argument("--size", type=int, nargs=2, default=[800, 600], metavar=("W", "H"))
parser.add_argument("--absorb-only", action="store_true",
                    help="scattering 0: the plume only dims what lies behind it")
parser.add_argument("--points", type=int, default=37,
                    help="the plume's samples across (37; 256 gives a 257 x 335 x 257 field)")
parser.add_argument("--field-resolution", type=int, default=2048,
                    help="the most samples per axis the shafts read (MediumFieldResolution)")
args = parser.parse_args()

LoadPlugin(next(p for p in candidates if p and os.path.exists(p)), remote=False, ns=globals())
view = CreateView("LightShaftsRenderView")
view.ViewSize = args.size
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.01, 0.01, 0.015]
view.UseLight = 0                                   # the spotlight alone


# The wavelet's points sit at their indices (spacing 1): the plume spans [-18, 18] x [0, 47]
# x [-18, 18] world units, and the scene is built to that scale (S world units to the Python
# example's one: examples/smoke_plume.py). --points scales the plume's samples and the scene
# with them.
half = args.points // 2
S = 6.0 * half / 18
top = round(47 * half / 18)
turbulence = Wavelet(WholeExtent=[-half, half, 0, top, -half, half], Center=[0, 24 * half / 18, 0])
plume = Calculator(Input=turbulence, ResultArrayName="smoke")
x, y, z = f"(coordsX / {S})", f"(coordsY / {S})", f"(coordsZ / {S})"
width = f"(0.35 + 0.22 * {y})"                      # the column widens as it rises
plume.Function = (f"exp(-(({x} - 0.08 * {y}^2)^2 + {z}^2) / (2 * {width}^2))"  # and leans
                  f" * exp(-0.12 * {y}) * (0.4 + 1.2 * abs(RTData - 37) / 240)")

Show(Plane(Origin=[-8 * S, 0, -8 * S], Point1=[8 * S, 0, -8 * S], Point2=[-8 * S, 0, 8 * S],
           XResolution=64, YResolution=64), view)

light = AddLight(view=view)                         # ParaView's light API (Light Inspector)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [-4.5 * S, 9.0 * S, 1.5 * S]
light.FocalPoint = [0.5 * S, 1.0 * S, 0.0]
light.ConeAngle = 24.0

view.MediumDensity = plume
view.MediumDensityArray = "smoke"
view.MediumDensityScale = 5.0
view.MediumFieldResolution = args.field_resolution  # (more are resampled: a bounded grid)
view.MediumBackgroundDensity = 0.08                 # the haze around the plume
scattering = 0.0 if args.absorb_only else 1.0
view.ScatteringCoefficient = [scattering * 0.3 / S, scattering * 0.28 / S, scattering * 0.26 / S]
view.AbsorptionCoefficient = [0.05 / S, 0.05 / S, 0.05 / S]
view.ShaftMethod = 1                                # RAY_MARCH
view.NumberOfSteps = 128
view.InterleaveSize = 1
view.ShaftExposure = 25.0
Render(view)  # the first render resets the camera to the data: place it afterwards
view.CameraPosition = [0.5 * S, 4.5 * S, 19.0 * S]
view.CameraFocalPoint = [0.0, 3.2 * S, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 38.0
Render(view)
SaveScreenshot(args.output, view, ImageResolution=args.size)
print("wrote", args.output)
# How the plume is held: on several processes (mpirun) each computes its piece of the image and
# the view gathers what the shafts need, so its points summed over the processes are about the
# whole image's, not a multiple of it.
extent = turbulence.WholeExtent
whole = (extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1) * (extent[5] - extent[4] + 1)
print(f"the plume: {plume.GetDataInformation().GetNumberOfPoints()} points over the processes"
      f" (its whole image: {whole})")
