#!/usr/bin/python3
"""Interactive light shafts: move the light and change the live parameters from the keyboard,
as the OpenGL article's demo does, and compare the methods on one scene.

    /usr/bin/python3 examples/interactive_shafts.py            # with a display: a window
    /usr/bin/python3 examples/interactive_shafts.py --record my.keys   # ... and record it
    xvfb-run -a /usr/bin/python3 examples/interactive_shafts.py \
        --play examples/interactive_shafts.keys -o last.png          # replay, offscreen

Keys (press h for this list):
  m / M          next / previous method (slices, ray march, radial blur, analytic, automatic,
                 epipolar, light volume)
  arrows         move the light in x and z; PageUp / PageDown: up and down
  + / -          Exposure x1.25 / /1.25
  s / S          scattering coefficient /1.25 / x1.25
  ] / [          twice / half the slices (SLICES), steps (RAY_MARCH, EPIPOLAR), samples
                 (RADIAL_BLUR) or cells (LIGHT_VOLUME)
  d / D          radial blur Decay -0.01 / +0.01
  w / W          radial blur Weight -0.1 / +0.1
  y / Y          radial blur Density -0.05 / +0.05
  n              noise on / off;  t: Time + 1 (the noise scrolls)
  h              this help;  q / e: quit (VTK's default); the mouse moves the camera

After every key the current values and the last frame's statistics are printed. --play replays
a vtkInteractorEventRecorder log (lines "KeyPressEvent x y ctrl shift keycode repeat keysym")
without a window on screen, which is how the test suite drives it.
"""

import argparse
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (
    vtkInteractorEventRecorder, vtkRenderer, vtkRenderWindow, vtkRenderWindowInteractor)

import lightshafts
from lightshafts import scenes, vtkLightShaftPass, write_png

METHODS = [vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH, vtkLightShaftPass.RADIAL_BLUR,
           vtkLightShaftPass.ANALYTIC, vtkLightShaftPass.AUTOMATIC, vtkLightShaftPass.EPIPOLAR,
           vtkLightShaftPass.LIGHT_VOLUME]


class Demo:
    """The scene, the pass, and the key bindings."""

    def __init__(self, width, height):
        self.renderer = vtkRenderer()
        self.window = vtkRenderWindow()
        self.window.AddRenderer(self.renderer)
        self.window.SetSize(width, height)
        self.window.SetWindowName("LightShafts: press h for keys")
        self.info = scenes.sphere_and_floor(self.renderer)
        scenes.add_fill_light(self.renderer)
        self.shafts = vtkLightShaftPass()
        self.shafts.GetMedium().SetScatteringCoefficient(0.05, 0.045, 0.04)
        self.shafts.SetExposure(40.0)
        self.renderer.SetPass(self.shafts)
        self.last_frame_ms = 0.0
        self.keys = {
            "m": lambda: self.cycle_method(1), "M": lambda: self.cycle_method(-1),
            "Left": lambda: self.move_light(-0.25, 0, 0), "Right": lambda: self.move_light(0.25, 0, 0),
            "Up": lambda: self.move_light(0, 0, -0.25), "Down": lambda: self.move_light(0, 0, 0.25),
            "Prior": lambda: self.move_light(0, 0.25, 0), "Next": lambda: self.move_light(0, -0.25, 0),
            "plus": lambda: self.scale("Exposure", 1.25), "equal": lambda: self.scale("Exposure", 1.25),
            "KP_Add": lambda: self.scale("Exposure", 1.25),
            "minus": lambda: self.scale("Exposure", 0.8), "KP_Subtract": lambda: self.scale("Exposure", 0.8),
            "s": lambda: self.scale_sigma(0.8), "S": lambda: self.scale_sigma(1.25),
            "bracketright": lambda: self.scale_count(2.0), "bracketleft": lambda: self.scale_count(0.5),
            "d": lambda: self.add("Decay", -0.01), "D": lambda: self.add("Decay", 0.01),
            "w": lambda: self.add("Weight", -0.1), "W": lambda: self.add("Weight", 0.1),
            "y": lambda: self.add("Density", -0.05), "Y": lambda: self.add("Density", 0.05),
            "n": self.toggle_noise, "t": lambda: self.add("Time", 1.0),
            "h": lambda: print(__doc__.split("Keys")[1].split("After every key")[0]),
        }

    # --- parameter changes -----------------------------------------------------------------
    def cycle_method(self, step):
        index = (METHODS.index(self.shafts.GetMethod()) + step) % len(METHODS)
        self.shafts.SetMethod(METHODS[index])

    def move_light(self, dx, dy, dz):
        light = self.info.light
        x, y, z = light.GetPosition()
        light.SetPosition(x + dx, y + dy, z + dz)

    def scale(self, name, factor):
        owner = lightshafts.parameter_owner(self.shafts, name)  # the pass or its medium
        getattr(owner, "Set" + name)(getattr(owner, "Get" + name)() * factor)

    def add(self, name, delta):
        owner = lightshafts.parameter_owner(self.shafts, name)
        getattr(owner, "Set" + name)(getattr(owner, "Get" + name)() + delta)

    def scale_sigma(self, factor):
        self.shafts.GetMedium().SetScatteringCoefficient(
            *[factor * c for c in self.shafts.GetMedium().GetScatteringCoefficient()])

    def scale_count(self, factor):
        name = {vtkLightShaftPass.RAY_MARCH: "NumberOfSteps",
                vtkLightShaftPass.EPIPOLAR: "NumberOfSteps",
                vtkLightShaftPass.RADIAL_BLUR: "RadialSamples",
                vtkLightShaftPass.LIGHT_VOLUME: "LightVolumeResolution"}.get(
                    self.shafts.GetMethod(), "NumberOfSlices")
        current = getattr(self.shafts, "Get" + name)()
        getattr(self.shafts, "Set" + name)(max(1, int(round(current * factor))))

    def toggle_noise(self):
        medium = self.shafts.GetMedium()
        medium.SetNoiseAmplitude(0.0 if medium.GetNoiseAmplitude() > 0.0 else 0.8)

    # --- frames and reports ----------------------------------------------------------------
    def render(self):
        start = time.perf_counter()
        self.window.Render()
        self.window.WaitForCompletion()
        self.last_frame_ms = 1000.0 * (time.perf_counter() - start)

    def report(self, key):
        p, medium, frame = self.shafts, self.shafts.GetMedium(), self.shafts.GetLastFrame()
        method = vtkLightShaftPass.GetMethodName(p.GetMethod())
        used = vtkLightShaftPass.GetMethodName(frame.GetMethod())
        print(f"[{key}] method={method} (used {used}) light={self.info.light.GetPosition()} "
              f"exposure={p.GetExposure():.4g} sigma_s={medium.GetScatteringCoefficient()[0]:.4g} "
              f"slices={p.GetNumberOfSlices()} steps={p.GetNumberOfSteps()} "
              f"samples={p.GetRadialSamples()} cells={p.GetLightVolumeResolution()} "
              f"decay={p.GetDecay():.3g} "
              f"weight={p.GetWeight():.3g} density={p.GetDensity():.3g} "
              f"noise={medium.GetNoiseAmplitude():.3g} time={medium.GetTime():.4g}")
        print(f"    last frame: {self.last_frame_ms:.1f} ms, slabs {frame.GetNumberOfSlicesDrawn()}, "
              f"shadow map {'yes' if frame.GetShadowMapRendered() else 'no'}, "
              f"post passes {frame.GetNumberOfPostPasses()}, "
              f"shader '{frame.GetShaderVariant()}', GL errors {frame.GetGLErrorCount()}",
              flush=True)

    def on_key(self, interactor, _event):
        key = interactor.GetKeySym()
        action = self.keys.get(key)
        if action is None:
            return
        action()
        self.render()
        self.report(key)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--play", help="replay a vtkInteractorEventRecorder log, no window shown")
    parser.add_argument("-o", "--output", help="write the last frame to this PNG (with --play)")
    parser.add_argument("--record", help="record the session's events to this file")
    parser.add_argument("--size", type=int, nargs=2, default=(640, 480))
    args = parser.parse_args()

    demo = Demo(*args.size)
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(demo.window)
    style = vtkInteractorStyleTrackballCamera()
    interactor.SetInteractorStyle(style)
    # Our keys replace the style's own letter commands (w: wireframe, s: surface, ...): an
    # observer on the style's CharEvent stands in for its OnChar, which then forwards only the
    # keys the demo does not use (q/e quit, r reset the camera, ...).
    def on_char(_style, _event):
        if interactor.GetKeySym() not in demo.keys:
            style.OnChar()
    style.AddObserver("CharEvent", on_char)
    interactor.AddObserver("KeyPressEvent", demo.on_key)

    if args.play:
        demo.window.SetOffScreenRendering(1)
        interactor.Initialize()
        demo.render()
        demo.report("start")
        recorder = vtkInteractorEventRecorder()
        recorder.SetInteractor(interactor)
        with open(args.play) as f:
            recorder.SetInputString(f.read())
        recorder.ReadFromInputStringOn()
        recorder.Play()
        recorder.Off()
        if args.output:
            write_png(demo.window, args.output)
        return
    interactor.Initialize()
    demo.render()
    demo.report("start")
    if args.record:
        recorder = vtkInteractorEventRecorder()
        recorder.SetInteractor(interactor)
        recorder.SetFileName(args.record)
        recorder.On()
        recorder.Record()
    print("press h for the keys", flush=True)
    interactor.Start()


if __name__ == "__main__":
    main()
