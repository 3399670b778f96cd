"""ParaView-style animation: scrolling-noise dust in the light shafts, the noise time linked to
ParaView's animation time (LinkShaftTimeToAnimation), one PNG per frame.

    xvfb-run -a tools/pvbatch examples/paraview/animate_noise.py --frames 48 --output-dir dust

(tools/pvbatch is pvbatch with ParaView's Python package; LIGHTSHAFTS_PARAVIEW_PLUGIN may name
the plugin, else the build tree's or /usr/local's LightShafts.so is used.)
"""
import argparse
import ctypes
import glob
import os
import sys

from paraview.simple import (AddLight, CreateView, GetAnimationScene, GetTimeKeeper, LoadPlugin,
                             Plane, Render, SaveScreenshot, Show, Sphere)

here = os.path.dirname(os.path.abspath(__file__))
candidates = ([os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN", "")]
              + glob.glob(os.path.join(here, "..", "..", "build", "paraview-plugin", "lib",
                                       "paraview-*", "plugins", "LightShafts", "LightShafts.so"))
              + glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so"))
parser = argparse.ArgumentParser()
parser.add_argument("--frames", type=int, default=24)
parser.add_argument("--seconds", type=float, default=12.0, help="animation time spanned")
parser.add_argument("--size", type=int, nargs=2, default=(640, 400))
parser.add_argument("--output-dir", default="dust_frames")
args = parser.parse_args()
os.makedirs(args.output_dir, exist_ok=True)

LoadPlugin(next(p for p in candidates if p and os.path.exists(p)), remote=False, ns=globals())
view = CreateView("LightShaftsRenderView")
view.ViewSize = list(args.size)
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.UseLight = 0

Show(Plane(Origin=[-6, 0, -6], Point1=[6, 0, -6], Point2=[-6, 0, 6]), view)
Show(Sphere(Center=[0.4, 3.0, 0.0], Radius=0.9, ThetaResolution=48, PhiResolution=48), view)
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [0.0, 6.0, 0.0]
light.FocalPoint = [0.0, 0.0, 0.0]
light.ConeAngle = 25.0

view.ScatteringCoefficient = [0.08, 0.07, 0.06]
view.ShaftExposure = 100.0
view.NoiseAmplitude = 0.9
view.NoiseScale = 4.0
view.LinkShaftTimeToAnimation = 1                   # noise time = the animation time
Render(view)  # the first render resets the camera to the data: place it afterwards
view.CameraPosition = [2.0, 3.5, 14.0]
view.CameraFocalPoint = [0.0, 2.5, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]

# No time-varying data here, so give the animation its own time range.
scene = GetAnimationScene()
scene.PlayMode = "Sequence"
scene.StartTime = 0.0
scene.EndTime = args.seconds
scene.NumberOfFrames = args.frames
for frame in range(args.frames):
    scene.AnimationTime = args.seconds * frame / max(args.frames - 1, 1)
    Render(view)
    path = os.path.join(args.output_dir, f"frame_{frame:04d}.png")
    SaveScreenshot(path, view, ImageResolution=list(args.size))
    print(f"frame {frame}: time {GetTimeKeeper().Time:.3f} -> {path}", flush=True)
# pvbatch 5.11 crashes in its own teardown after a script ends (docs/known-issues.md): skip
# it, with the output flushed (from ParaView 6.0 it goes through C stdio, which os._exit drops).
sys.stdout.flush()
ctypes.CDLL(None).fflush(None)
os._exit(0)
