"""Cookie, scrolling-noise density, and the quality controls: each does what it says, each can
be measured, and each is absent from the compiled shader when off."""

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkTexture

import lightshaft_reference as ref
import render_helpers as rh


def image_texture(rgb):
    """A vtkTexture of an (h, w, 3) uint8 array (row 0 at the bottom)."""
    h, w, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    scalars = numpy_to_vtk(np.ascontiguousarray(rgb.reshape(-1, 3)), deep=1)
    image.GetPointData().SetScalars(scalars)
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


def half_black(size=64):
    """White for u < 0.5, black for u >= 0.5."""
    rgb = np.zeros((size, size, 3), np.uint8)
    rgb[:, : size // 2] = 255
    return rgb


def shaft_scene(width=240, height=180, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
    # Plain slabs: each test turns on what it tests.
    shafts = rh.plain_slab_pass(**{"Exposure": 40.0, **params})
    renderer.SetPass(shafts)
    window.Render()
    return renderer, window, info, shafts


def features(shafts):
    return set(shafts.GetLastFrame().GetShaderVariant().split())


# --- cookie ---------------------------------------------------------------------------------

def test_half_black_cookie_removes_half_the_shafts_and_floor_light():
    renderer, window, info, shafts = shaft_scene()
    shafts.SetCookie(image_texture(half_black()))
    window.Render()
    assert "cookie" in features(shafts)
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 2
    measured = rh.in_scatter(shafts)
    plain = rh.reference_for(renderer, window, info, shafts)
    cookie = lambda u, v: np.where(u < 0.5, 1.0, 0.0)[..., None]  # noqa: E731
    reference = rh.reference_for(renderer, window, info, shafts, cookie=cookie)
    # Pixels whose rays see only the black half: no shafts there (the reference says so, and
    # without the cookie they are lit).
    peak = plain.max()
    dark = (reference.mean(-1) < 1e-4 * peak) & (plain.mean(-1) > 0.05 * peak)
    assert dark.sum() > 500
    assert measured[dark].max() < 0.01 * peak
    # Everywhere: the pass agrees with the reference of the same cookie (the cookie's edge is
    # pre-filtered by the mip level, hence the looser bound than without a cookie).
    error, _ = ref.relative_rms_error(measured, reference)
    assert error < 0.1
    # The floor: dark where the cookie is black, lit where it is white.
    pixels = rh.screenshot(window).max(axis=-1)
    w, h = window.GetSize()
    hit, on_floor = rh.surface_points(renderer, window, info)
    L = info.light
    u, _ = ref.cookie_uv(rh.reference_light(L), hit)
    lpos = np.asarray(L.GetPosition())
    axis = ref._normalize(np.asarray(L.GetFocalPoint()) - lpos)
    in_cone = ((hit - lpos) @ axis) / np.linalg.norm(hit - lpos, axis=1) > np.cos(np.radians(29))
    (centre, radius), = info.spheres
    clear_of_sphere = np.linalg.norm(hit[:, [0, 2]] - np.asarray(centre)[[0, 2]], axis=1) > 1.6
    floor_white = (on_floor & in_cone & clear_of_sphere & (u < 0.45)).reshape(h, w)
    floor_black = (on_floor & in_cone & (u > 0.55)).reshape(h, w)
    assert floor_white.sum() > 300 and floor_black.sum() > 300
    assert np.mean(pixels[floor_black] < 12) > 0.98
    assert np.mean(pixels[floor_white] > 40) > 0.98


def test_coloured_cookie_colours_the_shafts():
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=64)
    plain = rh.in_scatter(shafts)
    red = np.zeros((16, 16, 3), np.uint8)
    red[..., 0] = 255
    shafts.SetCookie(image_texture(red))
    window.Render()
    coloured = rh.in_scatter(shafts)
    np.testing.assert_allclose(coloured[..., 0], plain[..., 0], rtol=1e-3, atol=1e-9)
    assert np.all(coloured[..., 1:] == 0.0)


def test_cookie_off_is_identical_to_no_cookie():
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=64)
    before = rh.in_scatter(shafts)
    before_pixels = rh.screenshot(window)
    shafts.SetCookie(image_texture(half_black()))
    window.Render()
    shafts.SetCookie(None)
    window.Render()
    assert "cookie" not in features(shafts)
    assert "#define LIGHTSHAFT_COOKIE" not in shafts.GetLastFrame().GetSliceShaderSource()
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 1
    np.testing.assert_array_equal(rh.in_scatter(shafts), before)
    np.testing.assert_array_equal(rh.screenshot(window), before_pixels)


def test_cookie_without_image_warns_once_and_is_ignored(messages):
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=32)
    before = rh.in_scatter(shafts)
    log = messages(shafts)
    shafts.SetCookie(vtkTexture())
    window.Render()
    window.Render()
    assert len(log.warnings) == 1 and "cookie" in log.warnings[0]
    np.testing.assert_array_equal(rh.in_scatter(shafts), before)


# --- noise ----------------------------------------------------------------------------------

def test_noise_amplitude_zero_is_identical_to_no_noise():
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=64)
    before = rh.in_scatter(shafts)
    shafts.GetMedium().SetNoiseAmplitude(0.0)
    shafts.GetMedium().SetTime(3.0)
    window.Render()
    assert "noise" not in features(shafts)
    assert "#define LIGHTSHAFT_NOISE" not in shafts.GetLastFrame().GetSliceShaderSource()
    np.testing.assert_array_equal(rh.in_scatter(shafts), before)


def test_noise_is_a_pure_function_of_time_and_keeps_the_mean():
    renderer, window, info, shafts = shaft_scene(200, 150, NumberOfSlices=128)
    homogeneous = rh.in_scatter(shafts)
    shafts.GetMedium().SetNoiseAmplitude(1.0)
    shafts.GetMedium().SetTime(2.5)
    window.Render()
    assert "noise" in features(shafts)
    first = rh.in_scatter(shafts)
    shafts.GetMedium().SetTime(7.0)
    window.Render()
    other = rh.in_scatter(shafts)
    shafts.GetMedium().SetTime(2.5)
    window.Render()
    again = rh.in_scatter(shafts)
    np.testing.assert_array_equal(again, first)
    assert np.abs(other - first).max() > 0.05 * homogeneous.max()
    # Texture, not brightness: the image mean stays within 5% of the homogeneous one (the
    # layers' tile means are exactly 1; the cone covers a few tiles, not infinitely many).
    for image in (first, other):
        assert abs(image.mean() / homogeneous.mean() - 1.0) < 0.05
    # ... while pixels do vary.
    lit = homogeneous.mean(-1) > 0.2 * homogeneous.max()
    ratio = first.mean(-1)[lit] / homogeneous.mean(-1)[lit]
    assert ratio.std() > 0.05


# --- quality controls -----------------------------------------------------------------------

def test_8bit_accumulation_error_grows_with_slices_as_predicted():
    renderer, window, info, shafts = shaft_scene(160, 120)
    errors = []
    for slices in (32, 128, 512):
        shafts.SetNumberOfSlices(slices)
        shafts.SetAccumulationPrecisionToFloat32()
        window.Render()
        exact = rh.in_scatter(shafts)
        shafts.SetAccumulationPrecisionTo8Bit()
        window.Render()
        assert "accumulate=8bit" in features(shafts)
        quantized = rh.in_scatter(shafts)
        # Each slab's displayed value (Exposure * L) is rounded to 1/255 when it is added:
        # at most half a level per slab, N slabs per pixel at most.
        bound = (slices + 1) * 0.5 / 255.0 / shafts.GetExposure()
        assert np.abs(quantized - exact).max() <= bound * 1.0001
        errors.append(np.sqrt(np.mean((quantized - exact) ** 2)) / np.sqrt(np.mean(exact ** 2)))
    assert errors[0] < errors[1] < errors[2], errors
    shafts.SetAccumulationPrecisionToFloat16()
    window.Render()
    half = rh.in_scatter(shafts)
    assert np.sqrt(np.mean((half - exact) ** 2)) / np.sqrt(np.mean(exact ** 2)) < 0.06


def silhouette_masks(renderer, window, info):
    """Pixels on the sphere (foreground) next to shaft-lit background, and the background."""
    camera = rh.reference_camera(renderer, window)
    w, h = window.GetSize()
    eye, dirs, forward = ref.camera_rays(camera)
    d = dirs.reshape(-1, 3)
    (centre, radius), = info.spheres
    m = eye - np.asarray(centre)
    b = d @ m
    disc = b * b - (m @ m - radius * radius)
    sphere = (disc > 0).reshape(h, w)
    grown = sphere.copy()
    for shift in (-3, -2, -1, 1, 2, 3):
        grown |= np.roll(sphere, shift, 0) | np.roll(sphere, shift, 1)
    inner = sphere.copy()
    for shift in (-1, 1):
        inner &= np.roll(sphere, shift, 0) & np.roll(sphere, shift, 1)
    return inner, grown & ~sphere


def test_blur_does_not_cross_a_depth_edge():
    renderer, window, info, shafts = shaft_scene(200, 150)
    sharp = rh.in_scatter(shafts)
    shafts.SetBlurRadius(6)
    window.Render()
    blurred = rh.in_scatter(shafts)
    inner, ring = silhouette_masks(renderer, window, info)
    # The sphere's own pixels (short segments in front of it) are not brightened by the bright
    # background around them...
    assert sharp[ring].mean() > 2.0 * sharp[inner].mean()
    assert abs(blurred[inner].mean() / sharp[inner].mean() - 1.0) < 0.05
    # ... and the blur does smooth: with 16 jittered slabs, the difference from a 512-slab
    # image (mostly the jitter's noise) shrinks.
    shafts.SetBlurRadius(0)
    shafts.SetNumberOfSlices(512)
    window.Render()
    fine = rh.in_scatter(shafts)
    shafts.JitterOn()
    shafts.SetNumberOfSlices(16)
    window.Render()
    noisy = rh.in_scatter(shafts)
    shafts.SetBlurRadius(2)
    window.Render()
    smooth = rh.in_scatter(shafts)
    rms = lambda im: np.sqrt(np.mean((im - fine) ** 2))  # noqa: E731
    assert rms(smooth) < 0.7 * rms(noisy)


@pytest.mark.parametrize("factor", [2, 4])
def test_downsampling_keeps_silhouettes(factor):
    renderer, window, info, shafts = shaft_scene(200, 152)
    full = rh.in_scatter(shafts)
    shafts.SetDownsampleFactor(factor)
    window.Render()
    reduced = rh.in_scatter(shafts)
    assert reduced.shape == full.shape
    inner, ring = silhouette_masks(renderer, window, info)
    assert full[ring].mean() > 2.0 * full[inner].mean()
    # No halo: the sphere keeps its own (dim) in-scatter right up to its edge.
    assert abs(reduced[inner].mean() / full[inner].mean() - 1.0) < 0.15
    reference = rh.reference_for(renderer, window, info, shafts)
    error, _ = ref.relative_rms_error(reduced, reference)
    assert error < (0.03 if factor == 2 else 0.08)


def test_jitter_is_deterministic_and_trades_banding_for_noise():
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=16)
    banded = rh.in_scatter(shafts)
    shafts.JitterOn()
    window.Render()
    assert "jitter" in features(shafts)
    jittered = rh.in_scatter(shafts)
    window.Render()
    np.testing.assert_array_equal(rh.in_scatter(shafts), jittered)
    assert np.abs(jittered - banded).max() > 0.0
    reference = rh.reference_for(renderer, window, info, shafts)
    assert ref.relative_rms_error(jittered, reference)[0] < \
        1.5 * ref.relative_rms_error(banded, reference)[0]
    assert ref.energy_error(jittered, reference) < 0.01


def test_automatic_slice_count_follows_the_lit_depth_range():
    renderer, window, info, shafts = shaft_scene(160, 120, AutomaticSliceCount=True,
                                                 MaximumNumberOfSlices=400)
    near, far = shafts.GetLastFrame().GetSliceDepthRange()
    backdrop = shafts.GetLastFrame().GetBackdropDepth()
    assert backdrop == pytest.approx(rh.backdrop_depth(renderer), rel=1e-6)
    expected = int(np.ceil((far - near) / (backdrop / 400)))
    assert abs(shafts.GetLastFrame().GetNumberOfSlicesDrawn() - expected) <= 1
    # A narrower cone spans less depth: fewer slabs.
    info.light.SetConeAngle(8.0)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() < expected
    shafts.SetMaximumNumberOfSlices(20)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() <= 20


# --- model only what the scene requires -----------------------------------------------------

def test_features_that_are_off_are_not_compiled():
    renderer, window, info, shafts = shaft_scene(120, 90, NumberOfSlices=16)
    source = shafts.GetLastFrame().GetSliceShaderSource()
    for feature in ("COOKIE", "NOISE", "JITTER", "ACCUMULATE_8BIT", "PHASE_HG"):
        assert f"#define LIGHTSHAFT_{feature}" not in source
    assert "#define LIGHTSHAFT_SHADOW" in source
    shafts.SetCookie(image_texture(half_black(8)))
    shafts.GetMedium().SetNoiseAmplitude(0.5)
    shafts.JitterOn()
    shafts.SetAccumulationPrecisionTo8Bit()
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    window.Render()
    source = shafts.GetLastFrame().GetSliceShaderSource()
    for feature in ("COOKIE", "NOISE", "JITTER", "ACCUMULATE_8BIT", "PHASE_HG", "SHADOW"):
        assert f"#define LIGHTSHAFT_{feature}" in source
    assert shafts.GetLastFrame().GetGLErrorCount() == 0


def test_no_shadow_map_when_nothing_can_cast_into_the_light():
    renderer, window, info, shafts = shaft_scene(160, 120, NumberOfSlices=128)
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() == 2  # sphere and floor
    # A box far outside the cone is no caster.
    cube = vtkCubeSource()
    cube.SetCenter(9.0, 1.0, -4.0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(cube.GetOutputPort())
    box = vtkActor()
    box.SetMapper(mapper)
    renderer.AddActor(box)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() == 2
    # Without the sphere and the floor nothing is in the light: no shadow map, no shadow code,
    # and the shafts are the unshadowed reference.
    for actor in info.actors:
        renderer.RemoveActor(actor)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() == 0
    assert not shafts.GetLastFrame().GetShadowMapRendered()
    assert "shadow" not in features(shafts)
    reference = rh.reference_for(renderer, window, info, shafts, with_props=False)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), reference)
    assert error < 0.01
