"""The camera leg through translucent surfaces: what lies behind a translucent surface reaches
the camera dimmed as VTK blends it (1 - a), the shafts behind it as the scene behind it
(docs/translucent-and-volumes.md#the-camera-leg).

Scene: scenes.sphere_and_floor without its sphere (the camera at (0, 3, 12) looking at
(0, 2, 0); the spot at (0.5, 6, 0) aiming at the origin), each light kind of
render_helpers.make_light_kind, medium sigma_s = (0.05, 0.04, 0.03), sigma_a = (0.02, 0.01,
0.03), 120x90, SetQualityToFinal(). A vertical pane at z = 9 (between the camera and the beam)
covers the left half of the view. The pass is checked against the C++ float64 reference
(vtkLightShaftReference, which splits each view ray at the panes it crosses).
"""

import numpy as np
import pytest
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

from lightshafts import scenes, vtkLightShaftPass

import lightshaft_reference as ref
import render_helpers as rh

WIDTH, HEIGHT = 120, 90
KINDS = ["spot", "point", "directional"]
POINT_POSITION = (0.3, 5.5, 0.2)
BLACK = (0.0, 0.0, 0.0)
RED = (1.0, 0.0, 0.0)


def add_pane(renderer, z, color, opacity, x_range=(-20.0, 0.0)):
    """A vertical pane at depth z over x in x_range, y in [-5, 20]."""
    pane = vtkPlaneSource()
    pane.SetOrigin(x_range[0], -5.0, z)
    pane.SetPoint1(x_range[1], -5.0, z)
    pane.SetPoint2(x_range[0], 20.0, z)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(pane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    return actor


def render(kind, panes=(), method=None, **params):
    """The scene with `panes` ((z, colour, opacity) each), rendered once: (renderer, window,
    pass)."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    renderer.RemoveActor(info.actors[0])
    info.spheres = []
    lights = rh.make_light_kind(renderer, info, kind, POINT_POSITION)
    for pane in panes:
        add_pane(renderer, *pane)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    shafts.SetQualityToFinal()
    if method is not None:
        shafts.SetMethod(method)
    for light in lights:
        shafts.AddLight(light)
    for name, value in params.items():
        getattr(shafts, "Set" + name)(value)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return renderer, window, shafts


def covered():
    """The pixels that see the pane at z = 9 over x < 0 (the left of the view, with a margin)."""
    mask = np.zeros((HEIGHT, WIDTH), dtype=bool)
    mask[:, : WIDTH // 2 - 8] = True
    return mask


def measured(kind, panes, method=None, **params):
    """(pass, reference) with the panes and (pass, reference) without them (the panes at
    opacity 0: VTK draws nothing of them, and the scene keeps its bounds, so rays that hit
    nothing end at the same backdrop)."""
    renderer, _, shafts = render(kind, panes, method, **params)
    with_panes = (rh.in_scatter(shafts), rh.scene_reference(renderer, shafts), shafts)
    clear = [(z, color, 0.0) for z, color, _ in panes]
    renderer, _, shafts = render(kind, clear, method, **params)
    without = (rh.in_scatter(shafts), rh.scene_reference(renderer, shafts), shafts)
    return with_panes, without


def covered_ratio(with_panes, without, mask):
    """The covered pixels' in-scatter with the panes over that without, per channel."""
    return with_panes[mask].sum(axis=0) / without[mask].sum(axis=0)


@pytest.mark.parametrize("kind", KINDS)
def test_a_black_pane_at_half_opacity_halves_the_shafts_seen_through_it(kind):
    (pane, pane_ref, shafts), (clear, clear_ref, _) = measured(kind, [(9.0, BLACK, 0.5)])
    report = shafts.GetLastFrame()
    assert report.GetCameraTranslucentLayers() == 1
    assert report.GetCameraTranslucentBytes() == 16 * WIDTH * HEIGHT
    assert "camera-layers" in report.GetShaderVariant()
    error, pixels = ref.relative_rms_error(pane, pane_ref)
    assert pixels > 1000 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"
    mask = covered() & (clear_ref.max(axis=-1) > 0.01 * clear_ref.max())
    assert mask.sum() > 500
    measured_ratio = covered_ratio(pane, clear, mask)
    expected_ratio = covered_ratio(pane_ref, clear_ref, mask)
    assert np.allclose(measured_ratio, expected_ratio, rtol=0.02), (measured_ratio, expected_ratio)
    if kind == "spot":
        # The whole lit stretch lies behind the pane: exactly half.
        assert np.allclose(expected_ratio, 0.5, rtol=1e-9)
        assert np.allclose(measured_ratio, 0.5, rtol=0.02), measured_ratio
    else:
        # The medium between the camera and the pane is lit too, and not dimmed.
        assert np.all(expected_ratio > 0.5) and np.all(expected_ratio < 0.75), expected_ratio
    # The uncovered pixels are not dimmed.
    right = ~covered()
    right[:, : WIDTH // 2 + 8] = False
    lit = right & (clear_ref.max(axis=-1) > 0.01 * clear_ref.max())
    assert np.allclose(covered_ratio(pane, clear, lit), 1.0, rtol=1e-3)


def test_behind_the_pane_only_half_is_seen_directional():
    """The directional light's light leg does not cross the pane (it travels in x and y): with
    the pane at opacity 0, 0.5 and 1 the in-scatter is F + B, F + B / 2 and F, where F lies in
    front of the pane and B behind it."""
    images = {}
    for opacity in (0.0, 0.5, 1.0):
        renderer, _, shafts = render("directional", [(9.0, BLACK, opacity)])
        images[opacity] = rh.in_scatter(shafts)
    mask = covered() & (images[0.0].max(axis=-1) > 0.01 * images[0.0].max())
    behind_half = (images[0.5] - images[1.0])[mask].sum(axis=0)
    behind_all = (images[0.0] - images[1.0])[mask].sum(axis=0)
    assert np.allclose(behind_half / behind_all, 0.5, rtol=0.02), behind_half / behind_all


def test_a_coloured_pane_dims_the_shafts_as_the_scene_behind_it():
    """A red pane at opacity 0.5 keeps half of what lies behind it in every channel, as VTK's
    blending does (the light leg's filter rule is for the light that passes it)."""
    (pane, pane_ref, _), (clear, clear_ref, _) = measured("spot", [(9.0, RED, 0.5)])
    mask = covered() & (clear_ref.max(axis=-1) > 0.01 * clear_ref.max())
    assert np.allclose(covered_ratio(pane_ref, clear_ref, mask), 0.5, rtol=1e-9)
    assert np.allclose(covered_ratio(pane, clear, mask), 0.5, rtol=0.02)


def test_two_panes_multiply_and_the_layers_beyond_the_maximum_are_left_out():
    panes = [(9.0, BLACK, 0.5), (10.0, BLACK, 0.25)]
    (both, both_ref, shafts), (clear, clear_ref, _) = measured("spot", panes)
    assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 2
    mask = covered() & (clear_ref.max(axis=-1) > 0.01 * clear_ref.max())
    assert np.allclose(covered_ratio(both_ref, clear_ref, mask), 0.375, rtol=1e-9)
    assert np.allclose(covered_ratio(both, clear, mask), 0.375, rtol=0.02)
    # One layer: the nearer pane (z = 10) only.
    _, _, shafts = render("spot", panes, TranslucentShadowLayers=1)
    assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 1
    one = rh.in_scatter(shafts)
    assert np.allclose(covered_ratio(one, clear, mask), 0.75, rtol=0.02)


@pytest.mark.parametrize(
    "method",
    [vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH, vtkLightShaftPass.EPIPOLAR,
     vtkLightShaftPass.LIGHT_VOLUME, vtkLightShaftPass.ANALYTIC],
)
def test_every_method_with_a_view_ray_dims_behind_the_pane(method, vtk_messages):
    # (The pane's bounds reach into the light's volume: ANALYTIC says it ignores shadows.)
    vtk_messages.expect("ANALYTIC ignores shadows")
    (pane, _, shafts), (clear, clear_ref, _) = measured("spot", [(9.0, BLACK, 0.5)], method)
    assert shafts.GetLastFrame().GetLightMethod(0) == method
    mask = covered() & (clear_ref.max(axis=-1) > 0.01 * clear_ref.max())
    assert np.allclose(covered_ratio(pane, clear, mask), 0.5, rtol=0.02)


def test_a_pane_behind_the_beam_changes_nothing_in_front_of_it():
    """A pane behind the beam (z = -6, in front of nothing opaque on the covered side's upper
    part) is peeled, but no lit medium lies behind it."""
    renderer, _, shafts = render("spot", [(-6.0, BLACK, 0.5)])
    assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 1
    behind = rh.in_scatter(shafts)
    _, _, shafts = render("spot")
    clear = rh.in_scatter(shafts)
    assert np.abs(behind - clear).max() <= 1e-6 * clear.max()


def test_opaque_and_invisible_panes_peel_nothing():
    """Opacity 0 (VTK discards its fragments) and opacity 1 (an opaque prop) leave no layer;
    an opaque-only scene compiles no camera-leg code."""
    for opacity in (0.0, 1.0):
        _, _, shafts = render("spot", [(9.0, BLACK, opacity)])
        assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 0
        assert "camera-layers" not in shafts.GetLastFrame().GetShaderVariant()
    _, _, shafts = render("spot", [(9.0, BLACK, 0.0)])
    invisible = rh.in_scatter(shafts)
    _, _, shafts = render("spot")
    assert np.array_equal(invisible, rh.in_scatter(shafts))
    assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 0
    assert shafts.GetLastFrame().GetCameraTranslucentBytes() == 0


def test_the_camera_leg_follows_the_camera():
    """The layers are peeled each frame the shafts are computed: a camera that moves so that the
    pane leaves the view leaves the shafts undimmed."""
    renderer, window, shafts = render("spot", [(9.0, BLACK, 0.5)])
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 3.0, 8.0)  # in front of the pane: it is behind the camera
    renderer.ResetCameraClippingRange()
    window.Render()
    assert shafts.GetLastFrame().GetCameraTranslucentLayers() == 0
    moved = rh.in_scatter(shafts)
    renderer, window, shafts = render("spot")
    renderer.GetActiveCamera().SetPosition(0.0, 3.0, 8.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    # (Equal but for the depth ranges: the pane is still in the scene's bounds, which set the
    # camera's clipping range and the light camera's.)
    clear = rh.in_scatter(shafts)
    assert np.abs(moved - clear).sum() <= 1e-4 * clear.sum()
