#!/usr/bin/python3
"""Dust in the light: scrolling-noise density animated over time, rendered to numbered frames.

    /usr/bin/python3 examples/dusty_room.py --frames 48 --output-dir dusty_frames
    # writes dusty_frames/frame_0000.png ... and dusty_frames/dusty_room.ogv (Ogg Theora)

Each frame sets vtkLightShaftPass.GetMedium().SetTime(t): the noise is a pure function of t, so frame k is
the same image on every run. Without a display, run it under `xvfb-run -a`.
"""

import argparse
import os

import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkRenderingCore import (
    vtkRenderWindow, vtkRenderer, vtkWindowToImageFilter)

from lightshafts import scenes, vtkLightShaftPass, write_png

try:
    from tqdm import tqdm
except ImportError:  # python3-tqdm is optional: a plain counter instead
    def tqdm(iterable, **kwargs):
        items = list(iterable)
        for i, item in enumerate(items):
            print(f"\r{kwargs.get('desc', '')} {i + 1}/{len(items)}", end="", flush=True)
            yield item
        print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default="dusty_frames")
    parser.add_argument("--frames", type=int, default=48)
    parser.add_argument("--fps", type=int, default=24)
    parser.add_argument("--size", type=int, nargs=2, default=(640, 360))
    parser.add_argument("--no-movie", action="store_true", help="PNG frames only")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)

    renderer = vtkRenderer()
    renderer.SetBackground(0.01, 0.01, 0.02)
    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*args.size)
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    scenes.window_room(renderer)
    scenes.add_fill_light(renderer, 0.12)

    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.06, 0.057, 0.052)
    shafts.GetMedium().SetAbsorptionCoefficient(0.004)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(0.3)
    shafts.SetExposure(40.0)
    shafts.SetNumberOfSlices(160)
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()
    shafts.GetMedium().SetNoiseAmplitude(0.9)  # dust: density varies, mean brightness does not
    shafts.GetMedium().SetNoiseScale(3.0)
    renderer.SetPass(shafts)

    movie = None
    if not args.no_movie:
        from vtkmodules.vtkIOOggTheora import vtkOggTheoraWriter
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        movie = vtkOggTheoraWriter()
        movie.SetInputConnection(grab.GetOutputPort())
        movie.SetFileName(os.path.join(args.output_dir, "dusty_room.ogv"))
        movie.SetRate(args.fps)
        movie.SetQuality(2)
        movie.Start()
    for frame in tqdm(range(args.frames), desc="frames", unit="frame"):
        shafts.GetMedium().SetTime(frame / args.fps)
        window.Render()
        write_png(window, os.path.join(args.output_dir, f"frame_{frame:04d}.png"))
        if movie:
            grab.Modified()
            movie.Write()
    if movie:
        movie.End()
    print(f"wrote {args.frames} frames to {args.output_dir}/")


if __name__ == "__main__":
    main()
