"""Multisampled windows keep their antialiasing.

The pass renders the scene with the samples of the target it draws into and composites per
sample, so the window resolves the picture as it would without the pass:
  - with the medium off, and in the limit sigma -> 0, the picture equals the plain render
    pixel for pixel, for every MultiSamples setting (back and front buffer);
  - with shafts, pixels the shafts do not reach (L_in exactly 0, scene not attenuated) equal
    the plain multisampled render there, silhouettes included, and differ from the
    single-sampled render on those silhouettes (the antialiasing is there).
"""

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass

import render_helpers as rh

WIDTH, HEIGHT = 200, 150
SAMPLES = [0, 2, 4, 8]


def render(multisamples, configure=None):
    """(back buffer, front buffer, pass) of the test scene: a sphere and floor under the
    spotlight, and a second sphere off to the side, outside the light's cone."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    window.SetMultiSamples(multisamples)
    scenes.sphere_and_floor(renderer, sphere_resolution=48)
    # A bright fill and background, so that silhouettes show the antialiasing.
    scenes.add_fill_light(renderer, intensity=0.8)
    renderer.SetBackground(0.25, 0.35, 0.5)
    rh.add_sphere(renderer, (-4.5, 2.5, 2.0), 0.9, (0.3, 0.7, 0.9), resolution=48)
    renderer.GetActiveCamera().SetPosition(0.0, 3.0, 14.0)
    renderer.ResetCameraClippingRange()
    shafts = None
    if configure:
        shafts = vtkLightShaftPass()
        configure(shafts)
        renderer.SetPass(shafts)
    window.Render()
    back = rh.screenshot(window)
    front = rh.screenshot(window, front=True)
    if shafts:
        assert shafts.GetLastFrame().GetGLErrorCount() == 0
    window.SetMultiSamples(0)
    return back, front, shafts


def medium_off(shafts):
    shafts.GetMedium().SetScatteringCoefficient(0.0)


def vanishing_medium(shafts):
    shafts.GetMedium().SetScatteringCoefficient(1e-9)
    shafts.GetMedium().SetAbsorptionCoefficient(1e-9)


def vanishing_medium_not_attenuated(shafts):
    vanishing_medium(shafts)
    shafts.AttenuateSceneOff()


@pytest.mark.parametrize("multisamples", SAMPLES)
@pytest.mark.parametrize("configure", [medium_off, vanishing_medium,
                                       vanishing_medium_not_attenuated])
def test_no_medium_is_the_plain_render(multisamples, configure):
    plain_back, plain_front, _ = render(multisamples)
    back, front, shafts = render(multisamples, configure)
    if configure is not medium_off:
        # The window's samples (llvmpipe gives 4 for any request).
        assert (shafts.GetLastFrame().GetMultiSamples() > 1) == (multisamples > 0)
        assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() > 0
    np.testing.assert_array_equal(back, plain_back)
    np.testing.assert_array_equal(front, plain_front)


def test_multisampling_changes_the_plain_render():
    # The comparison above means something only if the window's antialiasing changes pixels.
    single, _, _ = render(0)
    multi, _, _ = render(8)
    assert np.count_nonzero(np.any(single != multi, axis=2)) > 300


@pytest.mark.parametrize("multisamples", [4, 8])
def test_shafts_keep_the_antialiasing_where_they_add_nothing(multisamples):
    def shafted(shafts):
        shafts.GetMedium().SetScatteringCoefficient(0.1)
        shafts.AttenuateSceneOff()
        shafts.SetBlurRadius(0)
    plain, _, _ = render(multisamples)
    single, _, _ = render(0)
    picture, _, shafts = render(multisamples, shafted)
    in_scatter = rh.in_scatter(shafts)
    assert in_scatter.max() > 0.0
    # Pixels whose own and neighbouring in-scatter is exactly zero.
    dark = (in_scatter.max(axis=2) == 0.0)
    untouched = dark.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            untouched &= np.roll(np.roll(dark, dy, axis=0), dx, axis=1)
    assert untouched.sum() > 0.3 * untouched.size
    np.testing.assert_array_equal(picture[untouched], plain[untouched])
    # ... and there the antialiasing shows: the side sphere's silhouette.
    edges = untouched & np.any(plain != single, axis=2)
    assert edges.sum() > 50
