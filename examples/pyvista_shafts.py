#!/usr/bin/python3
"""Light shafts in a PyVista plotter: a spotlight through a colonnade onto a hilly terrain
coloured by height, with PyVista's own SSAO and FXAA, and its scalar bar on top.

    /usr/bin/python3 examples/pyvista_shafts.py                 # writes pyvista_shafts.png
    /usr/bin/python3 examples/pyvista_shafts.py -o out.png --size 1280 720 --quality draft
    /usr/bin/python3 examples/pyvista_shafts.py --interactive   # needs a display

Needs PyVista (Debian 13 and later: apt install python3-pyvista). Offscreen rendering needs an
X server (without a display run it under `xvfb-run -a`) or, with VTK 9.4 or later, EGL:
VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow.
"""

import argparse

import numpy as np
import pyvista as pv

from lightshafts.pyvista import enable_light_shafts


def colonnade():
    """Two rows of columns with a lintel across each row."""
    parts = []
    for x in np.linspace(-6.0, 6.0, 7):
        for z in (-1.6, 1.6):
            parts.append(pv.Cylinder(center=(x, 2.5, z), direction=(0, 1, 0), radius=0.35,
                                     height=5.0, resolution=24))
    for z in (-1.6, 1.6):
        parts.append(pv.Cube(center=(0.0, 5.25, z), x_length=13.4, y_length=0.5, z_length=0.9))
    return pv.merge(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="pyvista_shafts.png")
    parser.add_argument("--size", type=int, nargs=2, default=(960, 540))
    parser.add_argument("--quality", default="final",
                        choices=("draft", "interactive", "final"))
    parser.add_argument("--interactive", action="store_true")
    args = parser.parse_args()

    plotter = pv.Plotter(off_screen=not args.interactive, window_size=args.size,
                         lighting="none")
    plotter.set_background("black")
    terrain = pv.ParametricRandomHills(random_seed=3, number_of_hills=24, u_res=120,
                                       v_res=120)
    terrain.rotate_x(-90.0, inplace=True)  # its heights along y, the up axis here
    terrain.scale((1.2, 0.35, 1.2), inplace=True)
    terrain.translate((0.0, -terrain.bounds[2] - 0.6, 0.0), inplace=True)
    terrain["height"] = terrain.points[:, 1]
    plotter.add_mesh(terrain, scalars="height", cmap="gist_earth", smooth_shading=True,
                     scalar_bar_args={"title": "height", "color": "white"})
    plotter.add_mesh(colonnade(), color="wheat", smooth_shading=True)

    # The light: a spotlight high behind the colonnade, shining through it towards the viewer;
    # a dim fill so that what the spot misses is not black.
    spot = pv.Light(position=(-4.0, 9.0, -12.0), focal_point=(1.5, 0.0, 3.0),
                    light_type="scene light", positional=True, cone_angle=30.0,
                    intensity=1.0, color=(1.0, 0.93, 0.8))
    plotter.add_light(spot)
    plotter.add_light(pv.Light(position=(4, 8, 10), light_type="scene light", intensity=0.25))

    # PyVista's passes and the shafts, in any order.
    plotter.enable_ssao(radius=0.6, bias=0.05, kernel_size=64)
    plotter.enable_anti_aliasing("fxaa")
    enable_light_shafts(plotter, light=spot, quality=args.quality,
                        ScatteringCoefficient=(0.04, 0.037, 0.034),
                        AbsorptionCoefficient=0.004, PhaseFunction=1, Anisotropy=0.35,
                        Exposure=10.0)
    plotter.camera.position = (5.0, 5.5, 16.0)
    plotter.camera.focal_point = (0.0, 2.2, 0.0)
    plotter.camera.up = (0.0, 1.0, 0.0)
    plotter.camera.view_angle = 42.0

    if args.interactive:
        plotter.show()
        return
    plotter.screenshot(args.output)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
