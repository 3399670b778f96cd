"""pvbatch test: the plugin loads, LightShaftsRenderView renders shadowed shafts.

Checks, on a spotlight above a floor with a sphere nearly filling its cone:
  1. the screenshot matches tests/baselines/ParaViewLightShafts.png (mean absolute difference
     <= MEAN_TOLERANCE levels, <= PIXEL_FRACTION of the pixels off by more than PIXEL_LEVEL);
  2. shadowed shafts: the in-scatter (shafts on minus off, scene not attenuated) on the cone's
     axis above the sphere is > LIT_OVER_SHADOW times that below it, and removing the sphere
     brightens the point below it by > SHADOW_GAIN times;
  3. LightShafts = 0 is the plain render view (pixel-identical to a RenderView), and so is an
     empty medium (ScatteringCoefficient 0, AttenuateScene on; ParaView's FXAA on);
  4. tone mapping chains after the shafts: with UseToneMapping on (Reinhard) the shafts are
     still there and the picture is the Reinhard curve of the picture without it;
  5. a view given no coefficient or exposure chooses them from the scene, and keeps one set
     after.
Usage: pvbatch test_render.py OUTPUT_DIR [--update]
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402

MEAN_TOLERANCE = 1.5
PIXEL_FRACTION = 0.005
PIXEL_LEVEL = 12
LIT_OVER_SHADOW = 3.0
SHADOW_GAIN = 3.0

BASELINE = os.path.join(scene.ROOT, "tests", "baselines", "ParaViewLightShafts.png")


def main():
    import numpy as np
    from paraview import simple
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    update = "--update" in sys.argv
    failures = []

    scene.load_plugin()
    view, light, ball = scene.make_scene()

    # 1. Baseline.
    shot = scene.screenshot(view, os.path.join(out, "ParaViewLightShafts.png"))
    if update:
        simple.SaveScreenshot(BASELINE, view, ImageResolution=[scene.WIDTH, scene.HEIGHT])
        print("baseline updated:", BASELINE)
    baseline = scene.read_png(BASELINE)
    mean, fraction, ok = scene.compare_images(shot, baseline,
                                              MEAN_TOLERANCE, PIXEL_FRACTION, PIXEL_LEVEL)
    print(f"baseline: mean |diff| {mean:.3f} levels (<= {MEAN_TOLERANCE}), "
          f"{100 * fraction:.3f}% pixels off by > {PIXEL_LEVEL} (<= {100 * PIXEL_FRACTION}%)")
    if not ok:
        failures.append("screenshot differs from the baseline")

    # 2. Shadowed shafts, from the in-scatter alone (scene not attenuated).
    view.AttenuateScene = 0
    lit_px = scene.to_pixel(view, scene.LIT_POINT)
    shadow_px = scene.to_pixel(view, scene.SHADOW_POINT)
    on = scene.screenshot(view, os.path.join(out, "on.png"))
    view.LightShafts = 0
    off = scene.screenshot(view, os.path.join(out, "off.png"))
    view.LightShafts = 1
    in_scatter = on - off
    lit = scene.patch_mean(in_scatter, lit_px)
    shadow = scene.patch_mean(in_scatter, shadow_px)
    ball.Visibility = 0
    open_on = scene.screenshot(view, os.path.join(out, "no_occluder_on.png"))
    view.LightShafts = 0
    open_off = scene.screenshot(view, os.path.join(out, "no_occluder_off.png"))
    view.LightShafts = 1
    ball.Visibility = 1
    unshadowed = scene.patch_mean(open_on - open_off, shadow_px)
    print(f"in-scatter: lit cone {lit:.1f} at {lit_px}, occluder's shadow {shadow:.1f} at "
          f"{shadow_px}, same point without the occluder {unshadowed:.1f} (levels)")
    if not lit > LIT_OVER_SHADOW * max(shadow, 0.5):
        failures.append(f"lit cone {lit:.1f} not > {LIT_OVER_SHADOW} x shadow {shadow:.1f}")
    if not unshadowed > SHADOW_GAIN * max(shadow, 0.5):
        failures.append(f"no occluder {unshadowed:.1f} not > {SHADOW_GAIN} x shadow {shadow:.1f}")
    view.AttenuateScene = 1

    # 3. Shafts off = a plain render view.
    plain = simple.CreateView("RenderView")
    scene.make_scene(plain)
    plain_shot = scene.screenshot(plain, os.path.join(out, "plain.png"))
    view.LightShafts = 0
    off_shot = scene.screenshot(view, os.path.join(out, "shafts_off.png"))
    view.LightShafts = 1
    identical = float(np.abs(plain_shot - off_shot).max())
    print(f"shafts off vs RenderView: max |diff| {identical}")
    if identical > 0:
        failures.append("LightShafts = 0 differs from a plain RenderView")
    # The medium off: the view's pass renders the scene unchanged, ParaView's FXAA (on by
    # default) included: it runs once, as in a RenderView.
    plain_shot = scene.screenshot(plain, os.path.join(out, "plain_fxaa.png"))
    scattering = list(view.ScatteringCoefficient)
    view.ScatteringCoefficient = [0.0, 0.0, 0.0]
    empty = scene.screenshot(view, os.path.join(out, "empty_medium.png"))
    view.ScatteringCoefficient = scattering
    identical = float(np.abs(plain_shot - empty).max())
    print(f"medium off vs RenderView (FXAA {plain.UseFXAA}): max |diff| {identical}")
    if identical > 0:
        failures.append("an empty medium differs from a plain RenderView")
    # (The plain view is left to the end of the run: deleting one of several views makes
    # ParaView 6.1 warn about its own composite mappers' active textures; docs/known-issues.md.)

    # 4. Tone mapping is chained, not replaced.
    # A bright picture (this scene is dark, where the curve is nearly the identity).
    exposure = view.ShaftExposure
    view.ShaftExposure = 10.0 * exposure
    shot = scene.screenshot(view, os.path.join(out, "bright.png"))
    view.UseToneMapping = 1
    view.ToneMappingType = 1  # vtkToneMappingPass::Reinhard
    mapped = scene.screenshot(view, os.path.join(out, "tonemapped.png"))
    view.LightShafts = 0
    mapped_off = scene.screenshot(view, os.path.join(out, "tonemapped_off.png"))
    view.LightShafts = 1
    view.UseToneMapping = 0
    view.ShaftExposure = exposure
    tone_change = float(np.abs(mapped - shot).mean())
    mapped_lit = scene.patch_mean(mapped - mapped_off, lit_px)
    # What Reinhard does to the picture the view made without it (VTK's curve in sRGB).
    linear = (shot / 255.0) ** 2.2
    curve = (linear / (linear + 1.0)) ** (1.0 / 2.2) * 255.0
    bright = shot.max(axis=-1) > 40  # where the curve bends (most of the picture is black)
    curve_change = float(np.abs(curve - shot)[bright].mean())
    off_curve = float(np.abs(mapped - curve)[bright].mean())
    print(f"tone mapping: mean |change| {tone_change:.2f} levels; where bright, the curve alone "
          f"{curve_change:.2f}, mapped vs curve {off_curve:.2f}; shafts under tone mapping "
          f"{mapped_lit:.1f} levels at the lit point")
    if mapped_lit < 5.0:
        failures.append("no shafts with tone mapping on")
    if not (curve_change > 1.0 and off_curve < 0.35 * curve_change):
        failures.append("tone mapping does not map the light-shaft picture")

    # 5. The medium chosen from the scene (FitMediumToScene, on by default): a view given no
    # coefficient or exposure; then one set in the script is kept.
    chosen, _, _ = scene.make_scene(medium=False)
    scene.screenshot(chosen, os.path.join(out, "medium_from_scene.png"))
    def in_use():
        chosen.UpdatePropertyInformation()
        return (list(chosen.GetPropertyValue("ScatteringCoefficientInUse")),
                chosen.GetPropertyValue("ShaftExposureInUse"))

    sigma, fitted_exposure = in_use()
    print(f"medium from the scene: sigma_s {sigma[0]:.4f}, exposure {fitted_exposure:.1f}")
    if not (sigma[0] == sigma[1] == sigma[2] and 0.0 < sigma[0] < 0.1 and fitted_exposure > 1.0):
        failures.append(f"no medium chosen from the scene: {sigma}, {fitted_exposure}")
    chosen.ScatteringCoefficient = [0.03, 0.03, 0.03]
    scene.screenshot(chosen, os.path.join(out, "medium_set.png"))
    if in_use() != ([0.03, 0.03, 0.03], fitted_exposure):
        failures.append(f"a coefficient set after the choice is not kept: {in_use()}")

    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
