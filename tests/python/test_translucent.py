"""Translucent casters: a prop with opacity a < 1 and diffuse colour c passes 1 - a (1 - c) of
the light per channel, several surfaces multiply (docs/translucent-and-volumes.md).

Scene: scenes.sphere_and_floor without its sphere (the spot at (0.5, 6, 0) aiming at the
origin, 30 degrees), a pane at y = 4 across the whole scene (and a second at y = 3.5 for
two panes; the camera, at y = 3, looks down from under them), each light kind of render_helpers.make_light_kind; medium sigma_s = (0.05, 0.04,
0.03), sigma_a = (0.02, 0.01, 0.03). The pass at SetQualityToFinal() is checked against the C++
float64 reference (vtkLightShaftReference, which crosses the panes exactly), over the image and
on the pixels whose whole lit stretch lies beyond the panes, where the reference's ratio to the
scene without them is the panes' transmittance.
"""

import numpy as np
import pytest
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

from lightshafts import parameter_owner, scenes, vtkLightShaftPass

import lightshaft_reference as ref
import render_helpers as rh

WIDTH, HEIGHT = 120, 90
KINDS = ["spot", "point", "directional"]
POINT_POSITION = (0.3, 5.5, 0.2)
RED = (1.0, 0.0, 0.0)
GREEN = (0.0, 1.0, 0.0)


def add_pane(renderer, height, color, opacity, half=20.0):
    """A horizontal square pane of side 2 * half at y = height, centred on the y axis (by
    default across the whole scene: all the light below it has passed it)."""
    pane = vtkPlaneSource()
    pane.SetOrigin(-half, height, -half)
    pane.SetPoint1(half, height, -half)
    pane.SetPoint2(-half, height, half)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(pane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    return actor


def make_scene(kind, panes=(), half=20.0, **params):
    """The scene with `panes` ((height, colour, opacity) each, of side 2 * half), rendered once
    at Final."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    renderer.RemoveActor(info.actors[0])
    info.spheres = []
    lights = rh.make_light_kind(renderer, info, kind, POINT_POSITION)
    # One backdrop with and without the panes.
    rh.hold_bounds(renderer, (-20.0, 20.0, -0.5, 4.5, -20.0, 20.0))
    actors = [add_pane(renderer, *pane, half=half) for pane in panes]
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.SetQualityToFinal()
    for light in lights:
        shafts.AddLight(light)
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return renderer, window, shafts, actors


def reference(renderer, shafts):
    return rh.scene_reference(renderer, shafts)


def nearly_same(image, expected):
    """Equal but for the shadow map's depth rounding: a prop added to the scene moves the light
    camera's depth range (its bounds), which can flip shadow-edge texels (measured: one pixel
    by 0.13% of the peak, 1.5e-6 to 3.6e-5 of the image's sum over all)."""
    return np.abs(image - expected).sum() <= 1e-4 * expected.sum()


def under_the_panes(renderer):
    """The rows whose view rays do not rise: they cannot meet the panes (all above the camera),
    so the camera leg does not dim them (test_camera_leg.py checks that part)."""
    camera = renderer.GetActiveCamera()
    forward = np.subtract(camera.GetFocalPoint(), camera.GetPosition())
    forward /= np.linalg.norm(forward)
    up = np.asarray(camera.GetViewUp(), dtype=float)
    up -= np.dot(up, forward) * forward
    up /= np.linalg.norm(up)
    half = np.tan(np.radians(camera.GetViewAngle() / 2.0))
    ndc = (2.0 * (np.arange(HEIGHT) + 0.5) / HEIGHT) - 1.0
    return (forward[1] + ndc * half * up[1]) <= 0.0


def beyond(with_panes, without, transmittance):
    """The pixels whose reference is the scene's without the panes times `transmittance`
    (their whole lit stretch lies beyond the panes), lit above 1% of the peak."""
    lit = without.max(axis=-1) > 0.01 * without.max()
    ratio = with_panes / np.maximum(without, 1e-300)
    return lit & np.all(np.abs(ratio - np.asarray(transmittance)) < 1e-9, axis=-1)


@pytest.mark.parametrize("kind", KINDS)
def test_a_red_pane_at_half_opacity_halves_green_and_blue_beyond_it(kind):
    renderer, window, shafts, _ = make_scene(kind, [(4.0, RED, 0.5)])
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1
    assert "translucent" in shafts.GetLastFrame().GetShaderVariant()
    pane = rh.in_scatter(shafts)
    expected = reference(renderer, shafts)
    error, pixels = ref.relative_rms_error(pane, expected)
    assert pixels > 1000 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"

    renderer, window, shafts, _ = make_scene(kind)
    clear = rh.in_scatter(shafts)
    clear_expected = reference(renderer, shafts)
    mask = beyond(expected, clear_expected, (1.0, 0.5, 0.5))
    assert mask.sum() > 200, f"{kind}: {mask.sum()} pixels beyond the pane"
    ratio = pane[mask].sum(axis=0) / clear[mask].sum(axis=0)
    assert np.allclose(ratio, (1.0, 0.5, 0.5), rtol=0.01), f"{kind}: {ratio}"


@pytest.mark.parametrize("kind", KINDS)
def test_two_panes_multiply(kind):
    panes = [(4.0, RED, 0.5), (3.5, GREEN, 0.25)]  # (1, .5, .5) then (.75, 1, .75)
    renderer, window, shafts, _ = make_scene(kind, panes)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 2
    both = rh.in_scatter(shafts)
    expected = reference(renderer, shafts)
    error, pixels = ref.relative_rms_error(both, expected)
    assert pixels > 1000 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"

    renderer, window, shafts, _ = make_scene(kind)
    clear = rh.in_scatter(shafts)
    product = (0.75, 0.5, 0.375)
    mask = beyond(expected, reference(renderer, shafts), product)
    assert mask.sum() > 100, f"{kind}: {mask.sum()} pixels beyond both panes"
    ratio = both[mask].sum(axis=0) / clear[mask].sum(axis=0)
    assert np.allclose(ratio, product, rtol=0.01), f"{kind}: {ratio}"


@pytest.mark.parametrize("kind", KINDS)
def test_opacity_zero_is_no_prop_and_one_is_an_opaque_prop(kind):
    _, _, shafts, _ = make_scene(kind)
    clear = rh.in_scatter(shafts)
    _, _, shafts, _ = make_scene(kind, [(4.0, RED, 0.0)])
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 0
    transparent = rh.in_scatter(shafts)
    assert nearly_same(transparent, clear)
    _, _, shafts, _ = make_scene(kind, [(4.0, RED, 0.0)], TranslucentShadows=False)
    assert np.array_equal(transparent, rh.in_scatter(shafts))
    # Towards 0 the light beyond changes continuously: by at most the opacity.
    # (float32 arithmetic: 3 times the opacity as the bound; measured 2.4 times.)
    _, _, shafts, _ = make_scene(kind, [(4.0, RED, 1e-6)])
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1
    change = np.abs(rh.in_scatter(shafts) - transparent)
    assert np.all(change <= 3e-6 * transparent + 1e-7 * transparent.max())

    # Opacity 1: VTK renders the pane with the opaque props; it blocks the light, exactly.
    renderer, _, shafts, _ = make_scene(kind, [(4.0, RED, 1.0)], half=2.0)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 0
    opaque = rh.in_scatter(shafts)
    error, pixels = ref.relative_rms_error(opaque, reference(renderer, shafts))
    assert pixels > 100 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"
    _, _, shafts, _ = make_scene(kind, [(4.0, RED, 1.0)], half=2.0, TranslucentShadows=False)
    assert np.array_equal(opaque, rh.in_scatter(shafts))


def test_translucent_shadows_off_lets_the_light_through():
    _, _, shafts, _ = make_scene("spot")
    clear = rh.in_scatter(shafts)
    renderer, _, shafts, _ = make_scene("spot", [(4.0, RED, 0.5)], TranslucentShadows=False)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 0
    assert "translucent" not in shafts.GetLastFrame().GetShaderVariant().split()
    rows = under_the_panes(renderer)
    assert 20 < rows.sum() < HEIGHT
    assert nearly_same(rh.in_scatter(shafts)[rows], clear[rows])


def test_layers_beyond_the_maximum_are_left_out():
    panes = [(4.5, RED, 0.5), (4.0, GREEN, 0.5), (3.5, (0.0, 0.0, 1.0), 0.5)]
    _, _, shafts, _ = make_scene("spot", panes)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 3
    three = rh.in_scatter(shafts)
    renderer, _, shafts, _ = make_scene("spot", panes, TranslucentShadowLayers=2)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 2
    two = rh.in_scatter(shafts)
    rows = under_the_panes(renderer)
    _, _, shafts, _ = make_scene("spot", panes[:2])
    assert nearly_same(two[rows], rh.in_scatter(shafts)[rows])
    assert not np.array_equal(two, three)


@pytest.mark.parametrize("kind", KINDS)
def test_the_largest_map_holds_its_layers_to_their_memory_budget(kind):
    """At ShadowMapSize 16384 a layer at the map's resolution would take 4 GiB (16 bytes a
    texel), more than the GL could allocate (GL_OUT_OF_MEMORY, found by the fuzz with seed
    23023); a light's layers are held to 512 MiB, coarser than the map, and still dim the light
    as the pane does."""
    renderer, window, shafts, _ = make_scene(kind, [(4.0, RED, 0.5)], ShadowMapSize=16384)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1
    assert 0.9 * 2**29 < shafts.GetLastFrame().GetLightTranslucentBytes(0) <= 2**29
    pane = rh.in_scatter(shafts)
    expected = reference(renderer, shafts)
    error, pixels = ref.relative_rms_error(pane, expected)
    assert pixels > 1000 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"
    renderer, window, shafts, _ = make_scene(kind, ShadowMapSize=16384)
    clear = rh.in_scatter(shafts)
    mask = beyond(expected, reference(renderer, shafts), (1.0, 0.5, 0.5))
    assert mask.sum() > 200, f"{kind}: {mask.sum()} pixels beyond the pane"
    ratio = pane[mask].sum(axis=0) / clear[mask].sum(axis=0)
    assert np.allclose(ratio, (1.0, 0.5, 0.5), rtol=0.01), f"{kind}: {ratio}"


def test_the_layers_are_kept_until_a_translucent_prop_or_the_light_changes():
    renderer, window, shafts, (pane,) = make_scene("spot", [(4.0, RED, 0.5)])
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0)
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1
    renderer.GetActiveCamera().Azimuth(5.0)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0)
    before = rh.in_scatter(shafts)
    pane.GetProperty().SetOpacity(0.25)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    after = rh.in_scatter(shafts)
    assert after[..., 1].sum() > before[..., 1].sum()  # 0.75 of green passes instead of 0.5
    shafts.GetLastFrame().GetUsedLight(0).SetPosition(0.6, 6.0, 0.0)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)


def test_light_volume_gives_way_to_ray_march_with_translucent_casters(vtk_messages):
    vtk_messages.expect("Method LIGHT_VOLUME has no closed form with translucent casters")
    _, _, shafts, _ = make_scene("spot", [(4.0, RED, 0.5)], Method=vtkLightShaftPass.LIGHT_VOLUME)
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.RAY_MARCH
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1


def test_surfaces_beyond_a_pane_are_tinted():
    # No medium: only the surfaces' light changes. The floor's share of the spot's light under
    # the pane (4 x 4: across the spot's cone) keeps its red and loses half its green and blue.
    def floor(panes, intensity):
        renderer, window, shafts, _ = make_scene(
            "spot", panes, half=2.0, ScatteringCoefficient=0.0, AbsorptionCoefficient=0.0,
            ShadowSurfaces=True)
        renderer.GetLights().GetItemAsObject(0).SetIntensity(intensity)
        window.Render()
        return rh.screenshot(window).astype(np.float64)

    clear = floor([], 1.0) - floor([], 0.0)
    pane = [(4.0, RED, 0.5)]
    tinted = floor(pane, 1.0) - floor(pane, 0.0)
    pool = clear.max(axis=-1) > 40.0
    assert pool.sum() > 200
    ratio = tinted[pool].sum(axis=0) / clear[pool].sum(axis=0)
    assert abs(ratio[0] - 1.0) < 0.03 and np.all(np.abs(ratio[1:] - 0.5) < 0.03), ratio


def test_picking_and_selection_see_the_panes_as_without_the_pass():
    from vtkmodules.vtkRenderingCore import vtkPropPicker
    renderer, window, shafts, (pane,) = make_scene("spot", [(4.0, RED, 0.5)], half=2.0)
    # Look up at the pane from under it.
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 1.0, 0.5)
    camera.SetFocalPoint(0.0, 4.0, 0.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    picker = vtkPropPicker()
    assert picker.Pick(WIDTH / 2, HEIGHT / 2, 0.0, renderer)
    assert picker.GetViewProp() is pane
    window.Render()
    assert not shafts.GetLastFrame().GetPlainScene()
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1


@pytest.mark.parametrize("peeling", ["depth peeling", "blending"])
def test_the_cameras_translucency_modes_work_with_the_layers(peeling):
    renderer, window, shafts, _ = make_scene("spot", [(4.0, RED, 0.5)], half=2.0)
    plain = rh.in_scatter(shafts)
    renderer.SetUseDepthPeeling(peeling == "depth peeling")
    renderer.SetMaximumNumberOfPeels(8)
    window.Render()
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert shafts.GetLastFrame().GetLightTranslucentLayers(0) == 1
    assert np.array_equal(rh.in_scatter(shafts), plain)
    renderer.SetUseDepthPeeling(False)


def test_several_lights_each_through_their_own_layers():
    # The orange spot above the pane and a blue point light under it (render_helpers' "pair"):
    # each light peels the pane in its own view (the point light's in its upper cube faces).
    renderer, window, shafts, _ = make_scene("pair", [(4.0, RED, 0.5)])
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    assert [shafts.GetLastFrame().GetLightTranslucentLayers(i) for i in range(2)] == [1, 1]
    error, pixels = ref.relative_rms_error(rh.in_scatter(shafts), reference(renderer, shafts))
    assert pixels > 1000 and error < 0.01, f"{error:.4%} over {pixels} pixels"
