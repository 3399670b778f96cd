"""Feature transitions render cleanly, in any order, and leave no state behind.

Every ordered pair of a set of feature states (method, precision, downsampling, blur, lattice,
cookie, noise, window size, viewport) is rendered one after the other: no GL error and no VTK
message (conftest fails a test on any), and each state's image is the same whatever came
before it. The cookie is decided once per frame: replacing it by a texture without an image,
or removing it, gives exactly the image without a cookie.
"""

import itertools

import numpy as np
import pytest

from lightshafts import parameter_owner, scenes, vtkLightShaftPass
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkTexture
from vtkmodules.util.numpy_support import numpy_to_vtk

import render_helpers as rh
from vtk_output import ANALYTIC_IGNORES_SHADOWS, VTK_OUTPUT


def stripes_cookie():
    image = vtkImageData()
    image.SetDimensions(32, 32, 1)
    pixels = np.zeros((32, 32, 3), np.uint8)
    pixels[::4] = (255, 200, 100)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels.reshape(-1, 3), deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


COOKIE = stripes_cookie()

# Feature states: (name, {setter: value}, window size, viewport).
STATES = [
    ("default", {}, (96, 72), (0, 0, 1, 1)),
    ("8-bit, quarter resolution",
     {"AccumulationPrecision": 2, "DownsampleFactor": 4}, (96, 72), (0, 0, 1, 1)),
    ("16F, half resolution, blur 5",
     {"AccumulationPrecision": 1, "DownsampleFactor": 2, "BlurRadius": 5}, (96, 72), (0, 0, 1, 1)),
    ("lattice 8, 8-bit", {"LatticeResolution": 8, "AccumulationPrecision": 2}, (80, 64),
     (0, 0, 1, 1)),
    ("ray march, interleave 3, half", {"Method": 1, "InterleaveSize": 3, "DownsampleFactor": 2},
     (96, 72), (0.1, 0.2, 0.9, 1.0)),
    ("radial blur, guard band 2", {"Method": 2, "RadialGuardBand": 2.0}, (64, 48),
     (0, 0, 1, 1)),
    ("analytic, cookie", {"Method": 3, "Cookie": COOKIE}, (96, 72), (0, 0, 1, 1)),
    ("cookie, noise, quarter", {"Cookie": COOKIE, "NoiseAmplitude": 0.7, "DownsampleFactor": 4},
     (1, 1), (0, 0, 1, 1)),
]
DEFAULTS = {"AccumulationPrecision": 0, "DownsampleFactor": 1, "BlurRadius": 2,
            "LatticeResolution": 0, "Method": 0, "InterleaveSize": 2, "RadialGuardBand": 1.0,
            "Cookie": None, "NoiseAmplitude": 0.0}


@pytest.fixture(autouse=True)
def allow_analytic_shadow_warning():
    # The ANALYTIC state says once that it ignores the scene's shadows (documented).
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)


@pytest.fixture(scope="module")
def setup():
    renderer, window = rh.make_window(96, 72)
    scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = vtkLightShaftPass()
    renderer.SetPass(shafts)
    return renderer, window, shafts


def apply(setup, state):
    renderer, window, shafts = setup
    _, params, size, viewport = state
    for name, value in {**DEFAULTS, **params}.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    window.SetSize(*size)
    renderer.SetViewport(*viewport)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    image = rh.in_scatter(shafts)
    assert np.all(np.isfinite(image))
    return image, shafts.GetLastFrame().GetShaderVariant()


@pytest.fixture(scope="module")
def fresh_images(setup):
    """Each state's image rendered right after the default state."""
    images = {}
    for state in STATES:
        apply(setup, STATES[0])
        images[state[0]] = apply(setup, state)
    return images


@pytest.mark.parametrize("first,second", list(itertools.permutations(STATES, 2)),
                         ids=lambda s: s[0].replace(" ", "_").replace(",", ""))
def test_any_transition_is_clean_and_forgets_the_previous_state(setup, fresh_images, first,
                                                                 second):
    apply(setup, first)
    image, variant = apply(setup, second)
    expected, expected_variant = fresh_images[second[0]]
    assert variant == expected_variant
    np.testing.assert_array_equal(image, expected)


def without_cookie(setup, messages):
    """(window, pass, its message log, the in-scatter without a cookie) in the default state."""
    renderer, window, shafts = setup
    apply(setup, STATES[0])
    log = messages(shafts)
    window.Render()
    assert "cookie" not in shafts.GetLastFrame().GetShaderVariant()
    return window, shafts, log, rh.in_scatter(shafts)


def test_cookie_replaced_by_an_empty_texture_or_removed(setup, messages):
    window, shafts, log, no_cookie = without_cookie(setup, messages)

    shafts.SetCookie(COOKIE)
    window.Render()
    with_cookie = rh.in_scatter(shafts)
    assert "cookie" in shafts.GetLastFrame().GetShaderVariant()
    assert np.abs(with_cookie - no_cookie).max() > 0.1 * no_cookie.max()
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 2

    empty = vtkTexture()  # no image: no cookie, one warning
    shafts.SetCookie(empty)
    window.Render()
    assert "cookie" not in shafts.GetLastFrame().GetShaderVariant()
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 1
    np.testing.assert_array_equal(rh.in_scatter(shafts), no_cookie)
    window.Render()
    assert len(log.warnings) == 1 and "cookie texture has no image" in log.warnings[0]

    shafts.SetCookie(COOKIE)  # back: the same image as before
    window.Render()
    np.testing.assert_array_equal(rh.in_scatter(shafts), with_cookie)

    shafts.SetCookie(None)
    window.Render()
    assert "cookie" not in shafts.GetLastFrame().GetShaderVariant()
    np.testing.assert_array_equal(rh.in_scatter(shafts), no_cookie)


def test_cookie_image_arriving_later_is_used(setup, messages):
    window, shafts, log, no_cookie = without_cookie(setup, messages)
    texture = vtkTexture()
    shafts.SetCookie(texture)
    window.Render()
    np.testing.assert_array_equal(rh.in_scatter(shafts), no_cookie)
    texture.SetInputData(COOKIE.GetInput())
    window.Render()
    assert "cookie" in shafts.GetLastFrame().GetShaderVariant()
    assert np.abs(rh.in_scatter(shafts) - no_cookie).max() > 0.1 * no_cookie.max()
    assert len(log.warnings) == 1
    shafts.SetCookie(None)
