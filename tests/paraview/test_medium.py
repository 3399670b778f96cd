"""pvbatch test: a medium from data in the LightShaftsRenderView (the MediumDensity property).

    pvbatch test_medium.py OUTPUT_DIR     # (runs `pvbatch test_medium.py load STATE` itself)

A pipeline's image (VTK's wavelet made a non-negative density by a Calculator, its array
named) chosen as the view's MediumDensity, with the test scene's spotlight:
  1. the pass renders a field (its shader variant says so) and the picture differs from the
     homogeneous medium's;
  2. a change of the wavelet's parameter reaches the picture at the next render (the pipeline
     drives the field), and the light leg's table is rebuilt for it;
  3. MediumDensityScale 0 with no background is no medium at all: the picture is the view's
     with no scattering;
  4. clearing MediumDensity gives back exactly the homogeneous picture;
  5. a state saved with the medium set loads back in a fresh pvbatch with the same source,
     array and scale, and renders the field;
  6. examples/paraview/smoke_plume.py runs silently and draws its plume.
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

    homogeneous = scene.screenshot(view, os.path.join(out, "homogeneous.png"))
    wavelet = simple.Wavelet(WholeExtent=[-8, 8, -1, 9, -8, 8])
    # (The wavelet dips below 0 at its corners: a density is not negative.)
    density = simple.Calculator(Input=wavelet, ResultArrayName="density",
                                Function="abs(RTData) * 0.01")
    view.MediumDensity = density
    view.MediumDensityArray = "density"
    view.MediumDensityScale = 3.0
    field = scene.screenshot(view, os.path.join(out, "field.png"))
    variant = readout("LastShaderVariant")
    if "field" not in variant:
        failures.append(f"no field in the shader variant: {variant}")
    if np.abs(field - homogeneous).mean() < 1.0:
        failures.append("the field's picture is the homogeneous one")

    wavelet.Maximum = 60.0
    thinner = scene.screenshot(view, os.path.join(out, "thinner.png"))
    if readout("LastMediumShadowBuildTime") <= 0.0:
        failures.append("the light leg's table was not rebuilt for the changed data")
    if np.abs(thinner - field).mean() < 1.0:
        failures.append("a change of the wavelet did not reach the picture")

    view.MediumDensityScale = 0.0
    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    plain = scene.screenshot(view, os.path.join(out, "plain.png"))
    view.ScatteringCoefficient = [0.08, 0.08, 0.08]
    zero = scene.screenshot(view, os.path.join(out, "zero.png"))
    print(f"mean |field - homogeneous| {np.abs(field - homogeneous).mean():.2f}, "
          f"|thinner - field| {np.abs(thinner - field).mean():.2f}, "
          f"max |zero field - plain| {np.abs(zero - plain).max():.0f} (8-bit levels)")
    if np.abs(zero - plain).max() > 1.0:
        failures.append("a zero field is not the plain picture")
    view.MediumDensityScale = 3.0

    state = os.path.join(out, "medium.pvsm")
    simple.SaveState(state)
    view.MediumDensity = None
    cleared = scene.screenshot(view, os.path.join(out, "cleared.png"))
    if not np.array_equal(cleared, homogeneous):
        failures.append("clearing MediumDensity does not give back the homogeneous picture")

    # A fresh process loads the state, as users share them.
    import shutil
    import subprocess
    loaded = subprocess.run([shutil.which("pvbatch"), os.path.abspath(__file__), "load", state],
                            capture_output=True, text=True, timeout=300)
    sys.stdout.write(loaded.stdout)
    sys.stderr.write(loaded.stderr)
    if loaded.returncode != 0:
        failures.append(f"loading the state failed ({loaded.returncode})")

    # The example runs as a user runs it, silently, and draws its plume.
    example = os.path.join(scene.ROOT, "examples", "paraview", "smoke_plume.py")
    picture = os.path.join(out, "example.png")
    run = subprocess.run([shutil.which("pvbatch"), example, "-o", picture],
                         capture_output=True, text=True, timeout=300)
    if run.returncode != 0 or "ERR|" in run.stderr or "Warning" in run.stderr:
        failures.append(f"examples/paraview/smoke_plume.py: {run.returncode} {run.stderr}")
    elif scene.read_png(picture).mean() < 10.0:
        failures.append("examples/paraview/smoke_plume.py drew a black picture")
    return scene.report(failures)


def load(state):
    """Load `state` in this (fresh) process: the medium's source and array as saved."""
    from paraview import simple
    scene.load_plugin()
    simple.LoadState(state)
    view = simple.GetActiveViewOrCreate("LightShaftsRenderView")
    source = view.MediumDensity
    failures = []
    if source is None or source.GetXMLName() != "Calculator":
        failures.append(f"the loaded state's MediumDensity is {source}")
    elif source.Function != "abs(RTData) * 0.01":
        failures.append(f"the loaded state's MediumDensity is another Calculator: {source.Function}")
    if view.MediumDensityArray != "density":
        failures.append(f"the loaded state's array is {view.MediumDensityArray!r}")
    if view.MediumDensityScale != 3.0:
        failures.append(f"the loaded state's scale is {view.MediumDensityScale}")
    simple.Render(view)
    view.UpdatePropertyInformation()
    if "field" not in view.GetPropertyValue("LastShaderVariant"):
        failures.append("the loaded state renders no field")
    return scene.report(failures)


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "load":
        scene.finish(load(sys.argv[2]))
    scene.finish(main())
