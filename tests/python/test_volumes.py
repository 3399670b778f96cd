"""vtkVolume props in the scene: a volume dims the shafts behind it as the camera sees it and
the light that crosses it, by its extinction kappa = -ln(1 - alpha) / u (its scalar opacity
alpha per unit distance u, as VTK's mappers composite it); a volume can be the medium
(docs/translucent-and-volumes.md#volumes).

Scene: scenes.sphere_and_floor without its sphere (the camera at (0, 3, 12) looking at
(0, 2, 0)), medium sigma_s = (0.05, 0.04, 0.03), sigma_a = (0.02, 0.01, 0.03), 120x90, Final.
The slab: a vtkVolume of constant scalar over x, z in [-30, 30], y in [4, 4.4], opacity 0.5 per
unit distance: a vertical crossing passes 0.5^0.4 = 0.758. The pass is checked against the C++
float64 reference (vtkLightShaftReference), which integrates the volume's extinction exactly
along both legs.
"""

import numpy as np
import pytest
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume, vtkVolumeProperty
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper

from lightshafts import scenes, vtkLightShaftPass

import lightshaft_reference as ref
import render_helpers as rh

WIDTH, HEIGHT = 120, 90
KINDS = ["spot", "point", "directional"]
POINT_POSITION = (0.3, 3.5, 0.2)
SLAB = 0.5 ** 0.4


def add_volume(renderer, image, opacity_points, unit=1.0):
    """A vtkVolume of `image` (GPU ray cast) with the scalar opacity function through
    `opacity_points` ((scalar, alpha) each) per `unit` distance."""
    mapper = vtkOpenGLGPUVolumeRayCastMapper()
    mapper.SetInputData(image)
    opacity = vtkPiecewiseFunction()
    for scalar, alpha in opacity_points:
        opacity.AddPoint(scalar, alpha)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0.0, 0.8, 0.8, 0.9)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(unit)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    return volume


def box_image(low, high, dimensions=(13, 3, 13), value=1.0):
    """Image data over the box low..high with a constant point scalar."""
    image = vtkImageData()
    image.SetDimensions(*dimensions)
    image.SetOrigin(*low)
    image.SetSpacing(*[(h - l) / (n - 1) for l, h, n in zip(low, high, dimensions)])
    values = vtkFloatArray()
    values.SetName("s")
    values.SetNumberOfTuples(int(np.prod(dimensions)))
    values.Fill(value)
    image.GetPointData().SetScalars(values)
    return image


def add_slab(renderer, low=(-30.0, 4.0, -30.0), high=(30.0, 4.4, 30.0), alpha=0.5):
    return add_volume(renderer, box_image(low, high), [(0.0, alpha), (2.0, alpha)])


def render(kind, build=None, method=None, sigma=((0.05, 0.04, 0.03), (0.02, 0.01, 0.03))):
    """The scene with `build(renderer)` added, rendered once: (renderer, window, pass)."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    renderer.RemoveActor(info.actors[0])
    info.spheres = []
    if kind == "vertical":
        info.light.SetPositional(False)
        info.light.SetPosition(0.0, 6.0, 0.0)
        info.light.SetFocalPoint(0.0, 0.0, 0.0)
        lights = [info.light]
    else:
        lights = rh.make_light_kind(renderer, info, kind, POINT_POSITION)
    if build:
        build(renderer)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(*sigma[0])
    shafts.GetMedium().SetAbsorptionCoefficient(*sigma[1])
    shafts.SetQualityToFinal()
    if method is not None:
        shafts.SetMethod(method)
    for light in lights:
        shafts.AddLight(light)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return renderer, window, shafts


def measured(kind, build, method=None):
    """(pass, reference, the frame report's read-outs) with `build` and (pass, reference)
    without."""
    renderer, _, shafts = render(kind, build, method)
    report = shafts.GetLastFrame()
    read = {"volume": report.GetVolume() is not None, "variant": report.GetShaderVariant(),
            "bytes": report.GetLightVolumeShadowBytes(0), "method": report.GetLightMethod(0)}
    with_volume = (rh.in_scatter(shafts), rh.scene_reference(renderer, shafts), read)
    renderer, _, plain = render(kind, None, method)
    return with_volume, (rh.in_scatter(plain), rh.scene_reference(renderer, plain))


def lit(image):
    return image.max(axis=-1) > 0.01 * image.max()


def test_a_slab_across_a_vertical_beam_passes_its_transmittance():
    (slab, slab_ref, read), (clear, clear_ref) = measured("vertical", add_slab)
    assert read["volume"] and "volume" in read["variant"].split() and read["bytes"] > 0
    # Below the slab, where the view rays do not cross it: its transmittance, exactly in the
    # reference.
    mask = lit(clear_ref) & np.all(np.abs(slab_ref / np.maximum(clear_ref, 1e-300) - SLAB) < 1e-6,
                                   axis=-1)
    assert mask.sum() > 1000
    ratio = slab[mask].sum(axis=0) / clear[mask].sum(axis=0)
    assert np.allclose(ratio, SLAB, rtol=0.02), ratio
    error, pixels = ref.relative_rms_error(slab, slab_ref)
    assert pixels > 1000 and error < 0.01, f"{error:.4%} over {pixels} pixels"


@pytest.mark.parametrize("kind", KINDS)
def test_a_slab_dims_both_legs_as_the_reference(kind):
    # (Across the spot's cone, or the whole scene: the light-leg table spans the slab, and a
    # wider one is coarser; measured at FieldShadowResolution 64, 128 and 256: 0.15%, 0.05% and
    # 0.02% from the reference for the spot's slab, 1.4%, 0.55% and 0.19% for the scene's.)
    if kind == "directional":
        build = add_slab
    else:
        def build(renderer):
            add_slab(renderer, low=(-6.0, 4.0, -6.0), high=(6.0, 4.4, 6.0))
    (slab, slab_ref, _), (clear, clear_ref) = measured(kind, build)
    error, pixels = ref.relative_rms_error(slab, slab_ref)
    assert pixels > 1000 and error < 0.01, f"{kind}: {error:.4%} over {pixels} pixels"
    expected = slab_ref.sum() / clear_ref.sum()
    assert expected < 0.95
    assert slab.sum() / clear.sum() == pytest.approx(expected, rel=0.02)


def test_a_slab_in_front_of_the_beam_dims_what_the_camera_sees_through_it():
    """A vertical slab 0.4 thick between the camera and the spot's beam over x < 0: the light
    leg does not cross it, the camera's does."""
    def build(renderer):
        add_slab(renderer, low=(-20.0, -5.0, 9.0), high=(0.0, 20.0, 9.4))

    (slab, slab_ref, _), (clear, clear_ref) = measured("spot", build)
    covered = np.zeros((HEIGHT, WIDTH), dtype=bool)
    covered[:, : WIDTH // 2 - 8] = True
    mask = covered & lit(clear_ref)
    # (The view rays cross it obliquely: a little more than 0.4 of it.)
    expected = slab_ref[mask].sum(axis=0) / clear_ref[mask].sum(axis=0)
    assert np.all(expected < SLAB) and np.all(expected > SLAB - 0.02), expected
    assert np.allclose(slab[mask].sum(axis=0) / clear[mask].sum(axis=0), expected, rtol=0.02)
    error, pixels = ref.relative_rms_error(slab, slab_ref)
    assert pixels > 1000 and error < 0.01, f"{error:.4%} over {pixels} pixels"


@pytest.mark.parametrize(
    "method",
    [vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH, vtkLightShaftPass.EPIPOLAR,
     vtkLightShaftPass.LIGHT_VOLUME],
)
def test_every_method_with_a_view_ray_models_the_volume(method):
    (slab, slab_ref, read), (clear, clear_ref) = measured("vertical", add_slab, method)
    assert read["method"] == method
    mask = lit(clear_ref) & np.all(np.abs(slab_ref / np.maximum(clear_ref, 1e-300) - SLAB) < 1e-6,
                                   axis=-1)
    ratio = slab[mask].sum(axis=0) / clear[mask].sum(axis=0)
    assert np.allclose(ratio, SLAB, rtol=0.02), ratio


def wavelet(renderer, opacity_points):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    source.Update()
    image = source.GetOutput()
    image.SetSpacing(0.12, 0.12, 0.12)
    image.SetOrigin(-1.0, 1.0, -1.2)
    return add_volume(renderer, image, opacity_points, unit=0.5)


def test_the_wavelet_in_a_beam_shows_no_box_edge():
    """VTK's wavelet (values 37 to 277; at most 160 on its box's faces) with an opacity that
    is 0 up to 160, in the spot's beam: the pass follows the reference everywhere, with no
    edge of its own where the box's faces project."""
    def build(renderer):
        wavelet(renderer, [(160.0, 0.0), (277.0, 0.9)])

    (image, expected, _), (clear, _) = measured("spot", build)
    error, pixels = ref.relative_rms_error(image, expected)
    assert pixels > 1000 and error < 0.01, f"{error:.4%} over {pixels} pixels"
    assert image.sum() < 0.97 * clear.sum()  # (it does dim the shafts)
    assert np.abs(image - expected).max() < 0.03 * expected.max()


def test_zero_density_leaves_the_volumes_picture_as_without_the_pass():
    def build(renderer):
        wavelet(renderer, [(37.0, 0.0), (277.0, 0.8)])

    renderer, window, shafts = render("spot", build, sigma=((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
    with_pass = rh.screenshot(window)
    renderer.SetPass(None)
    window.Render()
    assert np.array_equal(with_pass, rh.screenshot(window))


def test_a_transparent_volume_and_an_opaque_scene_compute_no_volume():
    """A volume transparent everywhere dims nothing and costs nothing (no volume code); the
    in-scatter is the scene's without it but for its bounds, which move the camera's and the
    light's depth ranges (float rounding: within 1e-4 of the sum)."""
    _, _, shafts = render("spot", lambda r: add_slab(r, alpha=0.0))
    assert shafts.GetLastFrame().GetVolume() is None
    assert "volume" not in shafts.GetLastFrame().GetShaderVariant().split()
    transparent = rh.in_scatter(shafts)
    _, _, shafts = render("spot")
    assert shafts.GetLastFrame().GetVolume() is None
    assert "volume" not in shafts.GetLastFrame().GetShaderVariant().split()
    clear = rh.in_scatter(shafts)
    assert np.abs(transparent - clear).sum() <= 1e-4 * clear.sum()


def test_a_changed_opacity_function_is_read_again():
    renderer, window, shafts = render("vertical", add_slab)
    before = rh.in_scatter(shafts)
    volume = shafts.GetLastFrame().GetVolume()
    opacity = volume.GetProperty().GetScalarOpacity()
    opacity.RemoveAllPoints()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(2.0, 0.0)
    window.Render()
    after = rh.in_scatter(shafts)
    # Without it (its bounds held: rays that hit nothing end at the scene's far side).
    rh.hold_bounds(renderer, volume.GetBounds())
    renderer.RemoveVolume(volume)
    window.Render()
    assert shafts.GetLastFrame().GetVolume() is None
    assert np.array_equal(after, rh.in_scatter(shafts))
    assert before.sum() < 0.95 * after.sum()


def blob_image():
    """A Gaussian puff of scalars over [-2, 2] x [1, 5] x [-2, 2]: 1 at its centre."""
    n = 17
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(-2.0, 1.0, -2.0)
    image.SetSpacing(0.25, 0.25, 0.25)
    axis = np.linspace(-2.0, 2.0, n)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    values = np.exp(-(x ** 2 + y ** 2 + z ** 2) / 1.5).ravel().astype(np.float32)
    array = vtkFloatArray()
    array.SetName("s")
    array.SetNumberOfTuples(values.size)
    for i, v in enumerate(values):
        array.SetValue(i, float(v))
    image.GetPointData().SetScalars(array)
    return image


def test_a_volume_as_the_medium_scatters_as_the_reference():
    volumes = []

    def build(renderer):
        volumes.append(add_volume(renderer, blob_image(), [(0.0, 0.0), (1.0, 0.8)]))

    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    renderer.RemoveActor(info.actors[0])
    build(renderer)
    shafts = vtkLightShaftPass()
    shafts.SetLight(info.light)
    shafts.SetQualityToFinal()
    medium = shafts.GetMedium()
    medium.SetScatteringCoefficient(0.5, 0.4, 0.3)
    medium.SetAbsorptionCoefficient(0.1, 0.1, 0.1)
    medium.SetDensityVolume(volumes[0])
    assert medium.GetDensityVolume() is volumes[0]
    renderer.SetPass(shafts)
    window.Render()
    report = shafts.GetLastFrame()
    assert "field" in report.GetShaderVariant().split()
    assert report.GetVolume() is None  # (the medium's volume scatters; it is not also a filter)
    image = rh.in_scatter(shafts)
    expected = rh.scene_reference(renderer, shafts)
    error, pixels = ref.relative_rms_error(image, expected)
    assert pixels > 500 and error < 0.01, f"{error:.4%} over {pixels} pixels"
    # The same as the opacity image given as a field (the volume hidden: else it would dim the
    # shafts as a volume in that medium).
    density = medium.GetDensityField()
    assert density.GetPointData().GetScalars().GetRange()[1] == pytest.approx(0.8, rel=1e-6)
    copy = vtkImageData()
    copy.DeepCopy(density)
    medium.SetDensityField(copy)
    assert medium.GetDensityVolume() is None
    volumes[0].VisibilityOff()
    window.Render()
    assert shafts.GetLastFrame().GetVolume() is None
    assert np.array_equal(image, rh.in_scatter(shafts))


def box_outline_masks(renderer, bounds):
    """Pixels within 1.5 pixels of the outline of the box `bounds` as projected, and pixels
    inside it at least 3 pixels from it."""
    corners = []
    for i in range(8):
        renderer.SetWorldPoint(bounds[i & 1], bounds[2 + ((i >> 1) & 1)], bounds[4 + (i >> 2)],
                               1.0)
        renderer.WorldToDisplay()
        corners.append(renderer.GetDisplayPoint()[:2])
    # The outline: the convex hull of the corners (monotone chain).
    points = sorted(set(corners))

    def half(sequence):
        hull = []
        for p in sequence:
            while len(hull) >= 2 and ((hull[-1][0] - hull[-2][0]) * (p[1] - hull[-2][1]) -
                                      (hull[-1][1] - hull[-2][1]) * (p[0] - hull[-2][0])) <= 0:
                hull.pop()
            hull.append(p)
        return hull
    hull = half(points)[:-1] + half(points[::-1])[:-1]
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH] + 0.5
    distance = np.full((HEIGHT, WIDTH), np.inf)
    inside = np.ones((HEIGHT, WIDTH), dtype=bool)
    for (ax, ay), (bx, by) in zip(hull, hull[1:] + hull[:1]):
        ex, ey = bx - ax, by - ay
        t = np.clip(((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
        distance = np.minimum(distance, np.hypot(x - ax - t * ex, y - ay - t * ey))
        inside &= (ex * (y - ay) - ey * (x - ax)) >= 0.0  # (counter-clockwise hull)
    return distance <= 1.5, inside & (distance >= 3.0)


def test_the_wavelets_box_faces_show_no_edge():
    """What the wavelet does to the in-scatter (its ratio to the scene's without it, where the
    beam's own edges cancel) changes no faster across its box's faces as projected than inside
    the box (its opacity is 0 on the faces)."""
    volumes = []

    def build(renderer):
        volumes.append(wavelet(renderer, [(160.0, 0.0), (277.0, 0.9)]))

    renderer, _, shafts = render("spot", build)
    image = rh.in_scatter(shafts).sum(axis=-1)
    edge, inside = box_outline_masks(renderer, volumes[0].GetBounds())
    _, _, shafts = render("spot")
    clear = rh.in_scatter(shafts).sum(axis=-1)
    lit = clear > 0.05 * clear.max()
    ratio = image / np.maximum(clear, 1e-30)
    gradient = np.zeros_like(ratio)
    gradient[1:-1, 1:-1] = np.hypot(ratio[1:-1, 2:] - ratio[1:-1, :-2],
                                    ratio[2:, 1:-1] - ratio[:-2, 1:-1])
    # (Both neighbours lit: the beam's edge itself is left out.)
    both = lit.copy()
    both[1:-1, 1:-1] &= lit[1:-1, 2:] & lit[1:-1, :-2] & lit[2:, 1:-1] & lit[:-2, 1:-1]
    assert (edge & both).sum() > 50 and (inside & both).sum() > 200
    assert ratio[inside & both].min() < 0.9  # (the volume dims the shafts inside its box)
    across = gradient[edge & both].max()
    within = gradient[inside & both].max()
    assert across <= within, (across, within)
