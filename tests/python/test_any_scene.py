"""Any VTK scene as VTK draws it (docs/any-scene.md): a gallery of scenes covering what VTK's
examples draw (gallery_scenes.py) is VTK's own picture through the pass at zero scattering, and
renders shafts with no error or warning the user did not cause; a picture that no clipping
range changes; a renderer with no 3D prop left as it is; warnings only for a method the user
named; and a medium chosen from the scene that gives the same picture at any scale."""

import numpy as np
import pytest
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer, vtkTextActor

from lightshafts import add_light_shafts, scenes, vtkLightShaftPass

import gallery_scenes
import render_helpers as rh
from vtk_output import LIGHT_VOLUME_GIVES_WAY, VTK_OUTPUT

WIDTH, HEIGHT = 200, 150


def gallery_window(name, samples=0):
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    window.SetMultiSamples(samples)
    window.SetNumberOfLayers(1)
    renderer.SetBackground(0.15, 0.2, 0.35)
    shafted = gallery_scenes.GALLERY[name](renderer, window)
    return shafted, window


def spotlight(position=(0.3, 6.0, 0.2), focal=(0.0, 0.0, 0.0), cone=25.0):
    spot = vtkLight()
    spot.SetPositional(True)
    spot.SetPosition(*position)
    spot.SetFocalPoint(*focal)
    spot.SetConeAngle(cone)
    return spot


# Multisampled too, but for two of VTK 9.1's own faults (docs/known-issues.md): its render of a
# multisampled window with FXAA is black (llvmpipe), and its depth peeling of one raises
# GL_INVALID_OPERATION (a depth blit between formats), with or without the pass.
NOT_MULTISAMPLED = ("FXAA", "translucent, depth peeling", "volume and translucent, peeled together")
GALLERY_RUNS = [(name, 0) for name in gallery_scenes.GALLERY] + \
    [(name, 4) for name in gallery_scenes.GALLERY if name not in NOT_MULTISAMPLED]


@pytest.mark.parametrize("name,samples", GALLERY_RUNS,
                         ids=[f"{name}, {samples} samples" for name, samples in GALLERY_RUNS])
def test_the_gallery_is_vtks_picture_at_zero_scattering_and_renders_shafts(name, samples):
    renderer, window = gallery_window(name, samples)
    spot = spotlight()
    renderer.AddLight(spot)  # (a positional light: VTK adds no headlight)
    window.Render()
    window.Render()
    plain = rh.screenshot(window).astype(int)
    # Through the pass at zero scattering: the delegate only.
    shafts = add_light_shafts(renderer, light=spot, quality="interactive",
                              ScatteringCoefficient=0.0)
    window.Render()
    zero = rh.screenshot(window).astype(int)
    difference = np.abs(zero - plain)
    assert difference.max() <= 1, f"{name}: up to {difference.max()} levels at zero scattering"
    # The limit: a vanishing medium through the whole composite is the same picture.
    shafts.GetMedium().SetScatteringCoefficient(1e-9)
    shafts.SetExposure(1.0)
    window.Render()
    vanishing = np.abs(rh.screenshot(window).astype(int) - plain)
    assert vanishing.max() <= 1, f"{name}: up to {vanishing.max()} levels as sigma -> 0"
    # Shafts, silently (the test fails on any VTK output), finite.
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(40.0)
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetGLErrorCount() == 0
    assert frame.GetNumberOfUsedLights() == 1
    in_scatter = rh.in_scatter(shafts)
    assert np.all(np.isfinite(in_scatter))
    assert in_scatter.max() > 0.0, name
    window.SetMultiSamples(0)  # (the shared window, as the other tests expect it)


def test_a_preset_gives_way_silently_and_the_report_says_why():
    renderer, window = gallery_window("translucent, blending")
    spot = spotlight()
    shafts = add_light_shafts(renderer, light=spot, quality="interactive",
                              ScatteringCoefficient=0.05)
    window.Render()  # no warning: the preset chose LIGHT_VOLUME, not the user
    frame = shafts.GetLastFrame()
    assert frame.GetLightMethod(0) == vtkLightShaftPass.RAY_MARCH
    assert "LIGHT_VOLUME has no closed form with translucent casters" in \
        frame.GetLightMethodFallback(0)
    # A target error chooses too.
    shafts.SetTargetError(0.05)
    window.Render()
    shafts.SetTargetError(0.0)
    # The same method named by the user: one warning.
    shafts.SetMethodToLightVolume()
    VTK_OUTPUT.expect(LIGHT_VOLUME_GIVES_WAY)
    window.Render()
    assert any("LIGHT_VOLUME" in text for _, text in VTK_OUTPUT.messages)
    assert shafts.GetLastFrame().GetLightMethod(0) == vtkLightShaftPass.RAY_MARCH
    # A preset after it: silent again (nothing new is printed).
    count = len(VTK_OUTPUT.messages)
    shafts.SetQualityToInteractive()
    window.Render()
    assert len(VTK_OUTPUT.messages) == count
    # Opaque casters only: the method is used as set, and nothing is reported.
    renderer.RemoveAllViewProps()
    gallery_scenes.surfaces(renderer, window)
    window.Render()
    assert shafts.GetLastFrame().GetLightMethod(0) == vtkLightShaftPass.LIGHT_VOLUME
    assert shafts.GetLastFrame().GetLightMethodFallback(0) == ""


# --- the clipping range --------------------------------------------------------------------

def readme_scene(scale=1.0, **params):
    """The README's sphere scene (a 48 x 48 sphere over a 12 x 12 floor under a 25-degree
    spot), scaled by `scale`, through add_light_shafts(quality="interactive", **params)."""
    from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    renderer, window = rh.make_window(320, 240)
    renderer.SetBackground(0.2, 0.3, 0.8)
    sphere = vtkSphereSource()
    sphere.SetCenter(0.0, 3.0 * scale, 0.0)
    sphere.SetRadius(0.8 * scale)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(48)
    floor = vtkPlaneSource()
    floor.SetOrigin(-6.0 * scale, 0.0, -6.0 * scale)
    floor.SetPoint1(6.0 * scale, 0.0, -6.0 * scale)
    floor.SetPoint2(-6.0 * scale, 0.0, 6.0 * scale)
    for source in (sphere, floor):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    spot = spotlight((0.0, 6.0 * scale, 0.0), cone=25.0)
    shafts = add_light_shafts(renderer, light=spot, quality="interactive", **params)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2.0 * scale, 3.5 * scale, 14.0 * scale)
    camera.SetFocalPoint(0.0, 2.0 * scale, 0.0)
    renderer.ResetCameraClippingRange()
    return renderer, window, shafts


def test_no_clipping_range_changes_the_picture():
    renderer, window, shafts = readme_scene(ScatteringCoefficient=0.05, Exposure=40)
    camera = renderer.GetActiveCamera()
    near, far = camera.GetClippingRange()
    window.Render()
    reference = rh.screenshot(window).astype(int)
    backdrop = shafts.GetLastFrame().GetBackdropDepth()
    assert backdrop == pytest.approx(rh.backdrop_depth(renderer), rel=1e-9)
    # The background is the renderer's, dimmed by the medium up to the backdrop (not black).
    top_left = reference[-3, 3]
    assert 0 < top_left[2] < 0.8 * 255
    for near_plane, far_plane in ((near, 10.0 * far), (near, 1000.0), (0.5 * near, far),
                                  (0.01, 1000.0)):
        camera.SetClippingRange(near_plane, far_plane)
        window.Render()
        assert shafts.GetLastFrame().GetBackdropDepth() == pytest.approx(backdrop, rel=1e-9)
        difference = np.abs(rh.screenshot(window).astype(int) - reference)
        assert difference.max() <= 1, f"({near_plane}, {far_plane}): {difference.max()} levels"


def test_the_reference_ends_rays_at_the_same_backdrop():
    renderer, window, shafts = readme_scene(ScatteringCoefficient=0.05, Exposure=40)
    shafts.SetQualityToFinal()
    window.Render()
    before = rh.scene_reference(renderer, shafts)
    renderer.GetActiveCamera().SetClippingRange(0.1, 1000.0)
    window.Render()
    after = rh.scene_reference(renderer, shafts)
    np.testing.assert_allclose(after, before, rtol=1e-9, atol=1e-12)
    error, _ = rh.ref.relative_rms_error(rh.in_scatter(shafts), after)
    assert error < 0.02


def test_a_renderer_with_only_2d_actors_is_left_as_it_is():
    renderer, window = rh.make_window(160, 120)
    renderer.SetBackground(0.3, 0.4, 0.5)
    text = vtkTextActor()
    text.SetInput("2D only")
    text.SetDisplayPosition(10, 10)
    renderer.AddViewProp(text)
    renderer.GetActiveCamera().SetClippingRange(0.1, 1000.0)
    window.Render()
    plain = rh.screenshot(window)
    shafts = add_light_shafts(renderer, light=spotlight(), ScatteringCoefficient=0.05,
                              Exposure=40)
    window.Render()
    np.testing.assert_array_equal(rh.screenshot(window), plain)
    assert shafts.GetLastFrame().GetBackdropDepth() == 0.0


def test_a_scene_behind_the_camera_is_left_as_it_is():
    renderer, window = rh.make_window(160, 120)
    scenes.sphere_and_floor(renderer, sphere_resolution=16)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 3.0, 30.0)
    camera.SetFocalPoint(0.0, 3.0, 60.0)  # looking away from everything
    renderer.ResetCameraClippingRange()
    window.Render()
    plain = rh.screenshot(window)
    shafts = add_light_shafts(renderer, ScatteringCoefficient=0.05, Exposure=40)
    window.Render()
    np.testing.assert_array_equal(rh.screenshot(window), plain)
    assert shafts.GetLastFrame().GetBackdropDepth() == 0.0


# --- the medium from the scene --------------------------------------------------------------

def test_the_one_liner_gives_the_same_shafts_at_any_scale():
    pictures = {}
    for scale in (0.01, 1.0, 100.0):
        renderer, window, shafts = readme_scene(scale)
        assert shafts.GetFitMediumToScene()
        window.Render()
        frame = shafts.GetLastFrame()
        assert frame.GetMediumFitted()
        sigma = shafts.GetMedium().GetScatteringCoefficient()
        assert sigma[0] == sigma[1] == sigma[2] > 0.0
        pictures[scale] = (rh.in_scatter(shafts), sigma[0] * scale, shafts.GetExposure(),
                           rh.screenshot(window).astype(int))
        window.Render()
        assert not shafts.GetLastFrame().GetMediumFitted()  # chosen once, then kept
        assert shafts.GetMedium().GetScatteringCoefficient() == sigma
    in_scatter, sigma_unit, exposure, picture = pictures[1.0]
    # The README's own values, near enough: sigma 0.05, exposure 40.
    assert 0.03 < sigma_unit < 0.08 and 20.0 < exposure < 60.0
    shafts_only = np.clip(picture - readme_scene_plain(), 0, None)
    assert shafts_only.max() > 30
    for scale in (0.01, 100.0):
        other, other_sigma, other_exposure, _ = pictures[scale]
        # (The scene's bounds are float32 points.)
        assert other_sigma == pytest.approx(sigma_unit, rel=1e-6)
        assert other_exposure == pytest.approx(exposure, rel=1e-6)
        error, _ = rh.ref.relative_rms_error(other, in_scatter)
        assert error < 0.01, f"scale {scale}: {error:.3%}"


def readme_scene_plain():
    renderer, window, shafts = readme_scene(ScatteringCoefficient=0.0)
    window.Render()
    return rh.screenshot(window).astype(int)


def test_explicit_values_win_over_the_scenes():
    renderer, window, shafts = readme_scene(Exposure=25.0)
    assert not shafts.GetFitMediumToScene()  # a value given: nothing is chosen
    window.Render()
    assert shafts.GetExposure() == 25.0
    assert shafts.GetMedium().GetScatteringCoefficient() == (0.1, 0.1, 0.1)
    # Asked to choose, with the exposure set after the request: that one is kept.
    shafts.FitMediumToSceneOn()
    shafts.SetExposure(12.0)
    window.Render()
    assert shafts.GetLastFrame().GetMediumFitted()
    assert shafts.GetExposure() == 12.0
    sigma = shafts.GetMedium().GetScatteringCoefficient()[0]
    assert sigma != 0.1
    # Set by the user after the fit: kept.
    shafts.GetMedium().SetScatteringCoefficient(0.2)
    window.Render()
    assert shafts.GetMedium().GetScatteringCoefficient() == (0.2, 0.2, 0.2)
    # Asked again: chosen again (the coefficient the same as the first time).
    shafts.FitMediumToSceneOn()
    window.Render()
    assert shafts.GetMedium().GetScatteringCoefficient()[0] == pytest.approx(sigma, rel=1e-12)
    assert shafts.GetExposure() != 12.0
