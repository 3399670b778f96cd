"""pvbatch test: volume representations and translucent surfaces in the LightShaftsRenderView.

    pvbatch test_volumes.py OUTPUT_DIR

The test scene (floor, sphere hidden, spotlight) with VTK's wavelet shown as a Volume in the
beam (its opacity 0 up to 160, rising to 0.9 at 277):
  1. the volume dims and shadows the shafts: the pass's shader variant models it ("volume"),
     and the picture differs from the one without the volume's opacity;
  2. a translucent surface (the sphere at opacity 0.5, in front of the beam) dims the shafts
     seen through it: the camera's layers are peeled ("camera-layers");
  3. MediumFromVolume on: the volume is the medium (a field, no volume filter); off again: the
     first picture back, exactly;
  4. no scattering: the picture is the view's with its light shafts off (a render view's),
     with FXAA off;
  5. examples/paraview/volume_in_beam.py runs silently, with and without --as-medium.
Any VTK error or warning fails the test (ctest's FAIL_REGULAR_EXPRESSION).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402


def main():
    import numpy as np
    from paraview import simple
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    scene.load_plugin()
    view, light, ball = scene.make_scene(occluder=False)

    def readout(name):
        view.UpdatePropertyInformation()
        return view.GetPropertyValue(name)
    failures = []

    wavelet = simple.Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
    transform = simple.Transform(Input=wavelet)
    transform.Transform.Scale = [0.1, 0.1, 0.1]
    transform.Transform.Translate = [0.3, 2.5, 0.0]
    image = simple.ResampleToImage(Input=transform)
    shown = simple.Show(image, view)
    shown.Representation = "Volume"
    simple.ColorBy(shown, ("POINTS", "RTData"))
    opacity = simple.GetOpacityTransferFunction("RTData")
    opacity.Points = [37.0, 0.0, 0.5, 0.0, 160.0, 0.0, 0.5, 0.0, 277.0, 0.9, 0.5, 0.0]
    dimmed = scene.screenshot(view, os.path.join(out, "volume.png"))
    variant = readout("LastShaderVariant")
    if "volume" not in variant.split():
        failures.append(f"the volume is not modelled: {variant}")
    opacity.Points = [37.0, 0.0, 0.5, 0.0, 277.0, 0.0, 0.5, 0.0]
    transparent = scene.screenshot(view, os.path.join(out, "transparent.png"))
    if np.abs(dimmed.astype(float) - transparent).mean() < 0.5:
        failures.append("the volume's opacity does not change the shafts")
    opacity.Points = [37.0, 0.0, 0.5, 0.0, 160.0, 0.0, 0.5, 0.0, 277.0, 0.9, 0.5, 0.0]

    ball.Visibility = 1
    ball.Opacity = 0.5
    scene.screenshot(view, os.path.join(out, "translucent.png"))
    if "camera-layers" not in readout("LastShaderVariant").split():
        failures.append(f"no camera layers: {readout('LastShaderVariant')}")
    ball.Visibility = 0

    view.MediumFromVolume = 1
    scene.screenshot(view, os.path.join(out, "medium.png"))
    variant = readout("LastShaderVariant").split()
    if "field" not in variant or "volume" in variant:
        failures.append(f"the volume is not the medium: {' '.join(variant)}")
    view.MediumFromVolume = 0
    again = scene.screenshot(view, os.path.join(out, "again.png"))
    if not np.array_equal(again, dimmed):
        failures.append("MediumFromVolume off does not give back the first picture")

    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    # (FXAA off: with it, ParaView 5.11 antialiases the volume's jagged edges differently with
    # the shafts' pass in its image-processing slot than without; docs/known-issues.md.)
    view.UseFXAA = 0
    plain = scene.screenshot(view, os.path.join(out, "plain.png"))
    view.LightShafts = 0
    reference = scene.screenshot(view, os.path.join(out, "off.png"))
    difference = np.abs(plain.astype(float) - reference).max()
    print(f"max |no scattering - shafts off| {difference:.0f} (8-bit levels)")
    if difference > 1.0:
        failures.append("with no scattering the picture is not the plain view's")

    # The example runs as a user runs it, silently, both ways, and draws its scene.
    import shutil
    import subprocess
    example = os.path.join(scene.ROOT, "examples", "paraview", "volume_in_beam.py")
    for extra in ([], ["--as-medium"]):
        picture = os.path.join(out, f"example{''.join(extra)}.png")
        run = subprocess.run([shutil.which("pvbatch"), example, "-o", picture, *extra],
                             capture_output=True, text=True, timeout=300)
        if run.returncode != 0 or "ERR|" in run.stderr or "Warning" in run.stderr:
            failures.append(f"examples/paraview/volume_in_beam.py {extra}: {run.returncode} "
                            f"{run.stderr}")
        elif scene.read_png(picture).mean() < 5.0:
            failures.append(f"examples/paraview/volume_in_beam.py {extra} drew a black picture")
    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
