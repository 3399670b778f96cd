"""pvbatch script (serial or under mpirun): the test scene with the sphere turned so that the
pieces ParaView splits it into are its left and right halves, rendered with the shafts on and
off; writes the in-scatter images (shafts minus no shafts) with DistributedShadowMap off and on,
the rows of the in-scatter process 0 computed (the shafts' work divided), the largest difference
an empty medium makes to the picture, and how the sphere was split, to OUTPUT.npz. Usage: pvbatch mpi_shafts.py OUTPUT.npz"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402


def main():
    import numpy as np
    from paraview import servermanager, simple
    output = sys.argv[1]
    scene.load_plugin()
    # Bright shafts and an unattenuated scene: the in-scatter is the difference of two shots.
    view, light, ball_display = scene.make_scene(ShaftExposure=60.0, AttenuateScene=0)
    # The sphere source splits into pieces by longitude around its own z axis (halves y > 0 and
    # y < 0); turned 90 degrees about z, the pieces are its left and right halves.
    ball = ball_display.Input
    simple.Hide(ball, view)
    turned = simple.Transform(Input=ball)
    turned.Transform.Translate = list(scene.SPHERE_CENTER)
    turned.Transform.Rotate = [0.0, 0.0, 90.0]
    ball.Center = [0.0, 0.0, 0.0]
    ids, ids_array = scene.process_ids(turned)
    simple.Show(ids, view)
    simple.Render(view)
    info = ids.GetDataInformation().GetPointDataInformation().GetArrayInformation(ids_array)
    process_range = info.GetComponentRange(0) if info else (0.0, 0.0)
    processes = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    images = {}
    for distributed in (0, 1):
        view.DistributedShadowMap = distributed
        view.LightShafts = 1
        shafts = scene.screenshot(view, output + f".d{distributed}.png")
        # The shafts' work divided (DivideShaftWork, on): this process's rows of the in-scatter
        # (0: not divided) and the fragments it marched there (-1: not divided).
        view.UpdatePropertyInformation()
        images[f"piece_rows_{distributed}"] = view.GetProperty("LastImagePieceRows").GetElement(0)
        images[f"piece_fragments_{distributed}"] = view.GetProperty(
            "LastInScatterFragments").GetElement(0)
        view.LightShafts = 0
        plain = scene.screenshot(view, output + ".plain.png")
        images[f"in_scatter_{distributed}"] = (shafts - plain).mean(axis=-1)
    # A medium that neither scatters nor absorbs: the view's picture is ParaView's own, bit for
    # bit (its FXAA included), on one process or several.
    view.LightShafts = 1
    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    view.AbsorptionCoefficient = [0.0, 0.0, 0.0]
    empty = scene.screenshot(view, output + ".empty.png")
    images["empty_medium_difference"] = np.abs(empty.astype(float) - plain.astype(float)).max()
    np.savez(output, processes=processes, process_range=np.array(process_range),
             left=np.array(scene.to_pixel(view, (-0.45, 1.6, 0.0))),
             right=np.array(scene.to_pixel(view, (0.45, 1.6, 0.0))),
             lit=np.array(scene.to_pixel(view, scene.LIT_POINT)), **images)
    print(f"processes {processes}, ProcessId range {process_range}; wrote {output}")
    return 0


if __name__ == "__main__":
    scene.finish(main())
