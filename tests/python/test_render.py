"""Offscreen rendering: invariants, readback layout, any-scene compatibility, robustness."""

import numpy as np
import pytest

from lightshafts import parameter_owner, scenes, vtkLightShaftPass
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction, vtkRenderer, vtkTextActor, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingOpenGL2 import (
    vtkCameraPass, vtkRenderPassCollection, vtkRenderStepsPass, vtkSequencePass)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
import vtkmodules.vtkRenderingFreeType  # noqa: F401

import lightshaft_reference as ref
import render_helpers as rh


def shaft_scene(width=200, height=150, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.GetMedium().SetAbsorptionCoefficient(0.01)
    shafts.SetExposure(40.0)
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    renderer.SetPass(shafts)
    return renderer, window, info, shafts


def test_render_smoke_and_statistics():
    renderer, window, _, shafts = shaft_scene(NumberOfSlices=64)
    window.Render()
    assert shafts.GetJitter()  # default: one more slab, each pixel's boundaries shifted
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == 65
    shafts.JitterOff()
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == 64
    assert shafts.GetLastFrame().GetShadowMapRendered()
    near, far = shafts.GetLastFrame().GetSliceDepthRange()
    assert 0 < near < far
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert shafts.GetLastFrame().GetUsedLight() is renderer.GetLights().GetItemAsObject(0)
    pixels = rh.screenshot(window)
    assert pixels.max() > 0


def test_readback_shape_and_orientation():
    renderer, window, info, shafts = shaft_scene(NumberOfSlices=128)
    info.light.SetPosition(2.5, 6.0, 0.0)  # off-centre: a mirrored image must not match
    window.Render()
    image = vtkImageData()
    assert shafts.GetInScatteredRadiance(image)
    assert image.GetDimensions() == (200, 150, 1)
    scalars = image.GetPointData().GetScalars()
    assert scalars.GetName() == "InScatteredRadiance"
    assert scalars.GetNumberOfComponents() == 3
    assert scalars.GetDataType() == 10  # VTK_FLOAT
    measured = rh.in_scatter(shafts)
    reference = rh.reference_for(renderer, window, info, shafts)
    upright, _ = ref.relative_rms_error(measured, reference)
    flipped, _ = ref.relative_rms_error(measured[::-1], reference)
    mirrored, _ = ref.relative_rms_error(measured[:, ::-1], reference)
    assert upright < 0.05
    assert flipped > 0.5 and mirrored > 0.2
    # The readback is before exposure: independent of Exposure.
    shafts.SetExposure(1.0)
    window.Render()
    np.testing.assert_array_equal(rh.in_scatter(shafts), measured)


def test_zero_medium_is_pixel_identical_to_delegate():
    renderer, window = rh.make_window(200, 150)
    scenes.sphere_and_floor(renderer, sphere_resolution=64)
    window.Render()
    plain = rh.screenshot(window)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    shafts.GetMedium().SetAbsorptionCoefficient(0.0)
    renderer.SetPass(shafts)
    window.Render()
    np.testing.assert_array_equal(rh.screenshot(window), plain)
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == 0
    assert not shafts.GetLastFrame().GetShadowMapRendered()
    assert np.all(rh.in_scatter(shafts) == 0.0)


def test_composite_path_preserves_scene_exactly():
    # Medium present but nothing added and no attenuation: the off-screen scene copy and the
    # composite must reproduce the delegate's pixels exactly.
    renderer, window = rh.make_window(200, 150)
    scenes.sphere_and_floor(renderer, sphere_resolution=64)
    window.Render()
    plain = rh.screenshot(window)
    shafts = vtkLightShaftPass()
    shafts.SetExposure(0.0)
    shafts.AttenuateSceneOff()
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() > 0
    np.testing.assert_array_equal(rh.screenshot(window), plain)


def test_aerial_perspective_matches_transmittance():
    # Only absorption: no in-scatter; the scene is multiplied by exp(-sigma_a t_surface).
    renderer, window = rh.make_window(200, 150)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    renderer.SetBackground(0.5, 0.5, 0.5)
    window.Render()
    plain = rh.screenshot(window).astype(float)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    shafts.GetMedium().SetAbsorptionCoefficient(0.05, 0.1, 0.2)
    renderer.SetPass(shafts)
    window.Render()
    fogged = rh.screenshot(window).astype(float)
    hit, _ = rh.surface_points(renderer, window, info)
    t = np.linalg.norm(hit - np.asarray(renderer.GetActiveCamera().GetPosition()), axis=1)
    transmittance = np.exp(-np.outer(t, [0.05, 0.1, 0.2])).reshape(150, 200, 3)
    expected = plain * transmittance
    # 8-bit rounding (and the tessellated sphere's silhouette) aside, they agree.
    close = np.abs(fogged - expected) <= 1.0
    assert close.mean() > 0.995
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == 0


def test_no_light_renders_unchanged_and_warns_once(messages):
    renderer, window = rh.make_window(160, 120)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=32)
    renderer.RemoveAllLights()
    window.Render()
    plain = rh.screenshot(window)
    shafts = vtkLightShaftPass()
    log = messages(shafts)
    renderer.SetPass(shafts)
    for _ in range(5):
        window.Render()
    np.testing.assert_array_equal(rh.screenshot(window), plain)
    assert len(log.warnings) == 1
    assert shafts.GetLastFrame().GetUsedLight() is None
    # A given light that is switched off: same answer, one more warning.
    info.light.SwitchOff()
    shafts.SetLight(info.light)
    window.Render()
    window.Render()
    assert len(log.warnings) == 2
    assert log.errors == []


def test_light_chosen_explicitly_over_automatic():
    renderer, window, info, shafts = shaft_scene(NumberOfSlices=32)
    other = scenes.add_spotlight(renderer, (0, 8, 8), (0, 0, 0), cone_angle=10)
    shafts.SetLight(other)
    window.Render()
    assert shafts.GetLastFrame().GetUsedLight() is other


def test_many_frames_and_resizes_without_gl_errors():
    renderer, window, _, shafts = shaft_scene(NumberOfSlices=32)
    for size in [(200, 150), (64, 48), (1, 1), (333, 211), (200, 150)]:
        window.SetSize(*size)
        for _ in range(3):
            window.Render()
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
        assert rh.in_scatter(shafts).shape == (size[1], size[0], 3)
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.SetShadowMapSize(256)
    for _ in range(3):
        window.Render()
        assert shafts.GetLastFrame().GetGLErrorCount() == 0


def test_release_graphics_resources_is_idempotent():
    renderer, window, _, shafts = shaft_scene(NumberOfSlices=32)
    window.Render()
    first = rh.in_scatter(shafts)
    shafts.ReleaseGraphicsResources(window)
    shafts.ReleaseGraphicsResources(window)
    window.Render()
    np.testing.assert_allclose(rh.in_scatter(shafts), first, rtol=1e-5, atol=1e-9)
    assert shafts.GetLastFrame().GetGLErrorCount() == 0


@pytest.mark.parametrize("delegate", ["default", "camera and sequence"])
def test_overlay_stays_on_top_unfogged(delegate):
    # "camera and sequence": the scene's steps inside a vtkCameraPass and a vtkSequencePass,
    # as PyVista's chain has them.
    def text_pixels(with_pass):
        renderer, window = rh.make_window(200, 150)
        scenes.sphere_and_floor(renderer, sphere_resolution=32)
        text = vtkTextActor()
        text.SetInput("SHAFT")
        text.GetTextProperty().SetFontSize(40)
        text.GetTextProperty().SetColor(1.0, 0.0, 0.0)
        text.SetPosition(50, 60)  # over the lit cone
        renderer.AddViewProp(text)
        if with_pass:
            shafts = vtkLightShaftPass()
            shafts.GetMedium().SetScatteringCoefficient(0.2)
            shafts.AttenuateSceneOff()
            shafts.SetExposure(100.0)
            if delegate != "default":
                shafts.SetDelegatePass(camera_and_sequence())
            renderer.SetPass(shafts)
        window.Render()
        return rh.screenshot(window)

    plain = text_pixels(False)
    fogged = text_pixels(True)
    pure_red = np.all(plain == [255, 0, 0], axis=-1)
    assert pure_red.sum() > 50
    # Wherever the text is opaque red without the pass it is still exactly red with it.
    assert np.all(fogged[pure_red] == [255, 0, 0])
    # ... while the shafts brightened the rest of the image.
    assert fogged[~pure_red].astype(int).sum() > plain[~pure_red].astype(int).sum()


def camera_and_sequence():
    """VTK's default steps inside a sequence inside a camera pass (PyVista's chain)."""
    steps = vtkRenderStepsPass()
    passes = vtkRenderPassCollection()
    passes.AddItem(steps)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    camera = vtkCameraPass()
    camera.SetDelegatePass(sequence)
    return camera


@pytest.mark.parametrize("medium", [0.0, 0.05])
def test_the_renderers_fxaa_applies_as_without_the_pass(medium):
    # VTK's own render applies the renderer's FXAA after the geometry, before overlays; with a
    # pass set it is the pass's to do (VTK's render steps ignore it).
    def render(with_pass, fxaa, samples=0):
        renderer, window = rh.make_window(200, 150)
        window.SetMultiSamples(samples)
        scenes.sphere_and_floor(renderer, sphere_resolution=16)
        renderer.SetUseFXAA(fxaa)
        shafts = None
        if with_pass:
            shafts = vtkLightShaftPass()
            shafts.GetMedium().SetScatteringCoefficient(medium)
            shafts.SetNumberOfSlices(64)
            renderer.SetPass(shafts)
        window.Render()
        pixels = rh.screenshot(window)
        window.SetMultiSamples(0)
        return pixels, shafts

    aliased, _ = render(True, False)
    antialiased, shafts = render(True, True)
    assert shafts.GetLastFrame().GetRendererFXAA() and shafts.GetLastFrame().GetGLErrorCount() == 0
    changed = np.abs(antialiased.astype(int) - aliased).max(axis=-1) > 0
    assert 0.001 < changed.mean() < 0.2  # the edges, not the whole picture
    if medium == 0.0:
        np.testing.assert_array_equal(antialiased, render(False, True)[0])
    # A multisampled target is antialiased already: FXAA is not applied there.
    _, shafts = render(True, True, samples=4)
    assert not shafts.GetLastFrame().GetRendererFXAA() and shafts.GetLastFrame().GetGLErrorCount() == 0


def test_user_render_steps_delegate_keeps_its_overlay():
    renderer, window, _, shafts = shaft_scene(NumberOfSlices=16)
    steps = vtkRenderStepsPass()
    shafts.SetDelegatePass(steps)
    overlay = steps.GetOverlayPass()
    window.Render()
    assert steps.GetOverlayPass() is overlay
    assert shafts.GetLastFrame().GetGLErrorCount() == 0


def test_viewport_is_honoured():
    width, height = 240, 120
    renderer, window = rh.make_window(width, height)
    renderer.SetViewport(0.0, 0.0, 0.5, 1.0)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    right = vtkRenderer()
    right.SetViewport(0.5, 0.0, 1.0, 1.0)
    right.SetBackground(0.2, 0.3, 0.4)
    window.AddRenderer(right)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetNumberOfSlices(256)
    renderer.SetPass(shafts)
    window.Render()
    assert tuple(shafts.GetLastFrame().GetViewportSize()) == (width // 2, height)
    measured = rh.in_scatter(shafts)
    assert measured.shape == (height, width // 2, 3)
    reference = rh.reference_for(renderer, window, info, shafts, size=(width // 2, height))
    error, _ = ref.relative_rms_error(measured, reference)
    assert error < 0.05
    # The other renderer's half is untouched.
    pixels = rh.screenshot(window)
    assert np.all(pixels[:, width // 2:] == [51, 76, 102])


def test_translucent_and_volume_props_still_render():
    def render(with_pass):
        renderer, window = rh.make_window(200, 150)
        scenes.sphere_and_floor(renderer, sphere_resolution=32)
        renderer.SetUseDepthPeeling(True)
        actor = rh.add_sphere(renderer, (-1.5, 1.0, 2.0), 0.6, (0.2, 0.4, 1.0), resolution=8)
        actor.GetProperty().SetOpacity(0.4)
        source = vtkRTAnalyticSource()
        source.SetWholeExtent(-8, 8, -8, 8, -8, 8)
        volume_mapper = vtkOpenGLGPUVolumeRayCastMapper()
        volume_mapper.SetInputConnection(source.GetOutputPort())
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(37, 0.0)
        opacity.AddPoint(276, 0.6)
        colors = vtkColorTransferFunction()
        colors.AddRGBPoint(37, 0.0, 1.0, 0.0)
        colors.AddRGBPoint(276, 1.0, 1.0, 0.0)
        prop = vtkVolumeProperty()
        prop.SetScalarOpacity(opacity)
        prop.SetColor(colors)
        volume = vtkVolume()
        volume.SetMapper(volume_mapper)
        volume.SetProperty(prop)
        volume.SetScale(0.06, 0.06, 0.06)
        volume.SetPosition(1.8, 1.0, 2.0)
        renderer.AddVolume(volume)
        shafts = None
        if with_pass:  # against VTK's own render, depth peeling included
            shafts = vtkLightShaftPass()
            shafts.GetMedium().SetScatteringCoefficient(1e-6)  # medium present, effect negligible
            shafts.AttenuateSceneOff()
            renderer.SetPass(shafts)
        window.Render()
        return rh.screenshot(window), shafts

    plain, _ = render(False)
    through_pass, shafts = render(True)
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    # Same picture (the medium is almost empty), translucent sphere and volume included.
    assert np.abs(through_pass.astype(int) - plain.astype(int)).max() <= 1


def test_light_volume_outside_view_skips_work():
    renderer, window, info, shafts = shaft_scene(NumberOfSlices=64)
    info.light.SetPosition(0.0, 6.0, 40.0)  # behind the camera, aiming away
    info.light.SetFocalPoint(0.0, 6.0, 80.0)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == 0
    assert not shafts.GetLastFrame().GetShadowMapRendered()
    assert np.all(rh.in_scatter(shafts) == 0.0)


def test_shadow_surfaces_agree_with_the_shafts_shadow():
    renderer, window = rh.make_window(320, 240)
    info = scenes.sphere_and_floor(renderer)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(0.0)  # look at the surfaces alone
    shafts.AttenuateSceneOff()
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    pixels = rh.screenshot(window).max(axis=-1)
    lit, dark = rh.floor_shadow_masks(renderer, window, info)
    assert lit.sum() > 1000 and dark.sum() > 200
    # The floor is dark exactly where the sphere shadows it from the spotlight...
    assert np.mean(pixels[dark] < 8) > 0.99
    assert np.mean(pixels[lit] > 40) > 0.99
    # ... and the shafts are shadowed by the same sphere (checked against the reference, which
    # uses the same analytic shadow).
    shafts.SetExposure(1.0)
    shafts.SetNumberOfSlices(256)
    window.Render()
    reference = rh.reference_for(renderer, window, info, shafts)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
    assert error < 0.01
    # Without it the floor under the sphere is lit (VTK lighting has no shadows).
    shafts.ShadowSurfacesOff()
    shafts.SetExposure(0.0)
    window.Render()
    pixels = rh.screenshot(window).max(axis=-1)
    assert np.mean(pixels[dark] > 40) > 0.99


def test_nested_in_another_image_pass_renders_into_its_framebuffer():
    # vtkToneMappingPass renders its delegate (our pass) into its own framebuffer object, given
    # to us in vtkRenderState: the shafts must land there, and the result must be the same
    # picture as without the outer pass (tone-mapped).
    from vtkmodules.vtkRenderingOpenGL2 import vtkToneMappingPass
    renderer, window, info, shafts = shaft_scene(NumberOfSlices=64)
    window.Render()
    reference = rh.in_scatter(shafts)
    tone = vtkToneMappingPass()
    tone.SetToneMappingType(vtkToneMappingPass.Clamp)
    tone.SetExposure(1.0)
    tone.SetDelegatePass(shafts)
    renderer.SetPass(tone)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert tuple(shafts.GetLastFrame().GetViewportSize()) == (200, 150)
    np.testing.assert_allclose(rh.in_scatter(shafts), reference, rtol=1e-5, atol=1e-9)
    with_shafts = rh.screenshot(window).astype(int).sum()
    shafts.SetExposure(0.0)
    window.Render()
    assert with_shafts > 1.2 * rh.screenshot(window).astype(int).sum()


def test_an_outer_tone_mapping_pass_maps_the_composited_shafts():
    # vtkToneMappingPass (Reinhard) around the pass maps the image the pass makes on its own:
    # where the scene is opaque its output is the Reinhard curve of that image; over the
    # background it maps mix(pixel, curve, alpha), and the pass gives the shafts an alpha (their
    # brightness), so they are mapped too instead of passing through untouched.
    from vtkmodules.vtkRenderingOpenGL2 import vtkToneMappingPass
    renderer, window, info, shafts = shaft_scene(NumberOfSlices=64)
    shafts.SetExposure(60.0)  # bright shafts, where the curve bends
    window.Render()
    alone = rh.screenshot(window).astype(float)
    tone = vtkToneMappingPass()
    tone.SetToneMappingType(vtkToneMappingPass.Reinhard)
    tone.SetDelegatePass(shafts)
    renderer.SetPass(tone)
    window.Render()
    mapped = rh.screenshot(window).astype(float)
    linear = (alone / 255.0) ** 2.2
    curve = (linear / (linear + 1.0)) ** (1.0 / 2.2) * 255.0
    # Opaque pixels: the scene drew a surface there (its depth buffer, from a plain frame).
    renderer.SetPass(None)
    window.Render()
    w, h = window.GetSize()
    from vtkmodules.vtkCommonCore import vtkFloatArray
    depth = vtkFloatArray()
    window.GetZbufferData(0, 0, w - 1, h - 1, depth)
    surface = np.array([depth.GetValue(i) for i in range(w * h)]).reshape(h, w) < 1.0
    renderer.SetPass(tone)
    # Where the pass alone saturates the 8-bit window, the tone mapper's float target kept the
    # true (brighter) value: compare the unsaturated surface pixels.
    check = surface & (alone.max(axis=-1) < 250)
    assert np.mean(check) > 0.2
    difference = np.abs(mapped - curve)[check].max(axis=-1)
    assert difference.mean() < 0.5
    assert difference.max() <= 2.0
    # Shafts over the background: darkened by the curve in proportion to their brightness.
    sky = ~surface & (alone.max(axis=-1) > 60) & (alone.max(axis=-1) < 250)
    assert sky.sum() > 200
    step = (alone - curve)[sky].mean()
    assert step > 2.0
    assert (alone - mapped)[sky].mean() > 0.25 * step
    renderer.SetPass(None)
    tone.ReleaseGraphicsResources(window)
