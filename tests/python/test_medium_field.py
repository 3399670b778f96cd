"""A medium from data (vtkLightShaftPass::SetMediumDensity): the image's checks, and
vtkLightShaftReference through the field against itself (uniform fields, scale and background)
and against the independent numpy reference with the same analytic density (a linear and a
cubic field, which trilinear interpolation reproduces exactly, on a rotated grid, from point
and cell data, for each kind of light)."""

import math

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

import lightshaft_reference as ref
import render_helpers as rh
from test_reference import cpp_reference

HALF = 60.0  # the fields' box: [-60, 60]^3 holds the camera, the lights and every ray's end


def field_image(function, samples=9, cells=False, angle_degrees=0.0, name="density"):
    """A vtkImageData of `function(x, y, z)` (world coordinates) over the box, rotated about y
    by `angle_degrees` (its direction matrix), sampled at its points, or at its cell centres
    (`cells`: samples cells along each axis). The box keeps HALF around the origin whatever the
    rotation (the grid is centred there)."""
    points = samples + 1 if cells else samples
    spacing = 2.0 * HALF / (points - 1)
    c, s = math.cos(math.radians(angle_degrees)), math.sin(math.radians(angle_degrees))
    direction = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    image = vtkImageData()
    image.SetDimensions(points, points, points)
    image.SetSpacing(spacing, spacing, spacing)
    image.SetDirectionMatrix(*direction.ravel())
    image.SetOrigin(*(direction @ np.full(3, -HALF)))
    index = np.arange(samples, dtype=float) + (0.5 if cells else 0.0)
    k, j, i = np.meshgrid(index, index, index, indexing="ij")  # x fastest when raveled
    local = np.stack([i, j, k], axis=-1).reshape(-1, 3) * spacing - HALF
    world = local @ direction.T
    values = numpy_to_vtk(function(world[:, 0], world[:, 1], world[:, 2]), deep=True)
    values.SetName(name)
    data = image.GetCellData() if cells else image.GetPointData()
    data.SetScalars(values)
    return image


def linear(x, y, z):
    return 0.5 + 0.002 * (x + 2.0 * y - z)


def cubic(x, y, z):
    return (1.0 + x / 120.0) * (1.0 + y / 120.0) * (1.0 + z / 120.0)


def rotated(function, angle_degrees):
    """`function` of the coordinates along a grid's axes when the grid is rotated about y by
    `angle_degrees` (field_image): trilinear reproduces a product of linear factors only along
    the grid's own axes."""
    c, s = math.cos(math.radians(angle_degrees)), math.sin(math.radians(angle_degrees))

    def along_grid(x, y, z):
        return function(c * x - s * z, y, s * x + c * z)
    return along_grid


def analytic_medium(shafts, function, scale=1.0, background=0.0):
    """The numpy reference's medium with density background + scale * function; its integral
    along a segment by two-point Gauss-Legendre, exact for these (at most cubic) fields."""
    def density(x):
        return background + scale * function(x[..., 0], x[..., 1], x[..., 2])

    def optical_depth(a, b):
        length = np.linalg.norm(b - a, axis=-1)
        node = 0.5 / math.sqrt(3.0)
        total = density(a + (0.5 - node) * (b - a)) + density(a + (0.5 + node) * (b - a))
        return 0.5 * length * total

    medium = rh.reference_medium(shafts)
    medium.density = density
    medium.optical_depth = optical_depth
    return medium


def scene(kind="spot", width=48, height=36, level=False):
    """The floor under the light of `kind`; `level`: the camera looks along -z, so that rays
    that hit nothing end on the field box's far face (the scene's far side, with the field set)
    without leaving the box, where the numpy reference's analytic density would go on."""
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    renderer.RemoveActor(info.actors[0])  # the floor alone: exact in both references
    info.spheres = []
    if level:
        camera = renderer.GetActiveCamera()
        camera.SetPosition(0.0, 3.0, 14.0)
        camera.SetFocalPoint(0.0, 3.0, 0.0)
        camera.SetViewUp(0.0, 1.0, 0.0)
    shafts = vtkLightShaftPass()
    if kind != "spot":
        for light in rh.make_light_kind(renderer, info, kind, (0.5, 6.0, 0.0)):
            shafts.AddLight(light)
    shafts.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    shafts.GetMedium().SetAbsorptionCoefficient(0.02, 0.01, 0.03)
    renderer.SetPass(shafts)
    window.Render()  # the clipping range both references read; the field is set after
    return renderer, window, info, shafts


def relative(values, expected):
    return np.abs(values - expected).max() / expected.max()


def test_a_uniform_field_is_the_homogeneous_medium():
    renderer, window, info, shafts = scene()
    homogeneous, _, _ = cpp_reference(renderer, shafts)
    assert homogeneous.max() > 0.0
    shafts.GetMedium().SetDensityField(field_image(lambda x, y, z: np.ones_like(x), samples=2))
    uniform, _, _ = cpp_reference(renderer, shafts)
    assert relative(uniform, homogeneous) < 1e-7
    # Scale halves sigma_s and sigma_t; the background alone (a zero field) is the medium.
    shafts.GetMedium().SetDensityScale(0.5)
    halved, _, _ = cpp_reference(renderer, shafts)
    shafts.GetMedium().SetDensityScale(1.0)
    shafts.GetMedium().SetDensityField(field_image(lambda x, y, z: np.zeros_like(x), samples=2))
    shafts.GetMedium().SetBackgroundDensity(1.0)
    background, _, _ = cpp_reference(renderer, shafts)
    assert relative(background, homogeneous) < 1e-7
    shafts.GetMedium().SetDensityField(None)
    shafts.GetMedium().SetBackgroundDensity(0.0)
    shafts.GetMedium().SetScatteringCoefficient(0.025, 0.02, 0.015)
    shafts.GetMedium().SetAbsorptionCoefficient(0.01, 0.005, 0.015)
    expected, _, _ = cpp_reference(renderer, shafts)
    assert relative(halved, expected) < 1e-7


@pytest.mark.parametrize("kind", ["spot", "point", "directional"])
def test_a_linear_field_agrees_with_the_numpy_reference(kind):
    renderer, window, info, shafts = scene(kind, level=True)
    shafts.GetMedium().SetDensityField(field_image(linear))
    shafts.GetMedium().SetDensityScale(0.7)
    shafts.GetMedium().SetBackgroundDensity(0.2)
    values, _, _ = cpp_reference(renderer, shafts)
    expected = ref.in_scattered_radiance(
        rh.reference_camera(renderer, window, shafts=shafts), rh.reference_lights(info.light),
        analytic_medium(shafts, linear, 0.7, 0.2),
        ref.Scene(floors=info.floors), panels=16)
    assert expected.max() > 0.0
    assert relative(values, expected) < 1e-6


@pytest.mark.parametrize("cells", [False, True])
def test_a_cubic_field_on_a_rotated_grid_agrees_with_the_numpy_reference(cells):
    renderer, window, info, shafts = scene(level=True)
    field = rotated(cubic, 30.0)
    shafts.GetMedium().SetDensityField(field_image(field, samples=7, cells=cells, angle_degrees=30.0))
    values, _, _ = cpp_reference(renderer, shafts)
    expected = ref.in_scattered_radiance(
        rh.reference_camera(renderer, window, shafts=shafts), rh.reference_lights(info.light),
        analytic_medium(shafts, field), ref.Scene(floors=info.floors), panels=16)
    assert relative(values, expected) < 1e-6


def test_outside_the_field_the_density_is_the_background():
    # A field far from every ray: only the background remains (here none: no in-scatter).
    renderer, window, info, shafts = scene()
    image = field_image(lambda x, y, z: np.ones_like(x), samples=2)
    image.SetOrigin(1000.0, 1000.0, 1000.0)
    shafts.GetMedium().SetDensityField(image)
    values, _, _ = cpp_reference(renderer, shafts)
    assert values.max() == 0.0


def test_the_named_array_is_read():
    renderer, window, info, shafts = scene()
    image = field_image(lambda x, y, z: np.ones_like(x), samples=2)
    other = numpy_to_vtk(np.zeros(8), deep=True)
    other.SetName("empty")
    image.GetPointData().AddArray(other)
    shafts.GetMedium().SetDensityField(image)
    ones, _, _ = cpp_reference(renderer, shafts)
    shafts.GetMedium().SetDensityArrayName("empty")
    assert shafts.GetMedium().GetDensityArrayName() == "empty"
    zeros, _, _ = cpp_reference(renderer, shafts)
    assert ones.max() > 0.0 and zeros.max() == 0.0


def refused(shafts, messages, call, *args):
    log = messages(shafts.GetMedium())  # (the medium's setters report on the medium)
    before = shafts.GetMTime()
    call(*args)
    assert shafts.GetMTime() == before, "a refused image changed the pass"
    assert len(log.errors) == 1, log.errors
    return log.errors[0]


def test_bad_images_are_refused_and_the_previous_field_kept(messages):
    shafts = vtkLightShaftPass()
    good = field_image(linear, samples=3)
    shafts.GetMedium().SetDensityField(good)

    no_scalars = vtkImageData()
    no_scalars.SetDimensions(4, 4, 4)
    assert "has no point or cell scalars" in refused(shafts, messages, shafts.GetMedium().SetDensityField,
                                                     no_scalars)
    flat = field_image(linear, samples=3)
    flat.SetDimensions(3, 3, 1)
    flat.GetPointData().SetScalars(numpy_to_vtk(np.ones(9), deep=True))
    assert "not a 3D image (3 x 3 x 1 points" in refused(shafts, messages,
                                                          shafts.GetMedium().SetDensityField, flat)
    for bad, words in ((math.nan, "nan at index 4"), (-0.5, "-0.5 at index 4")):
        image = field_image(linear, samples=3)
        image.GetPointData().GetScalars().SetValue(4, bad)
        message = refused(shafts, messages, shafts.GetMedium().SetDensityField, image)
        assert words in message and "finite and not negative" in message
    huge = vtkImageData()
    huge.SetDimensions(513, 512, 512)  # checked before the values are read: no array this big
    huge.GetPointData().SetScalars(numpy_to_vtk(np.ones(1), deep=True))
    assert "more than the 134217728 (512^3)" in refused(shafts, messages,
                                                        shafts.GetMedium().SetDensityField, huge)
    assert "no numeric point or cell array named \"nope\"" in refused(
        shafts, messages, shafts.GetMedium().SetDensityArrayName, "nope")
    for setter in (shafts.GetMedium().SetDensityScale, shafts.GetMedium().SetBackgroundDensity):
        assert "non-finite value refused" in refused(shafts, messages, setter, math.inf)
    assert shafts.GetMedium().GetDensityField() is good
    assert shafts.GetMedium().GetDensityArrayName() == ""
    shafts.GetMedium().SetDensityScale(-1.0)
    shafts.GetMedium().SetBackgroundDensity(1e9)
    assert (shafts.GetMedium().GetDensityScale(), shafts.GetMedium().GetBackgroundDensity()) == (0.0, 1e6)
    shafts.GetMedium().SetFieldShadowResolution(-5)
    assert shafts.GetMedium().GetFieldShadowResolution() == 0
    shafts.GetMedium().SetFieldShadowResolution(100000)
    assert shafts.GetMedium().GetFieldShadowResolution() == 256
    shafts.GetMedium().SetDensityField(None)
    assert shafts.GetMedium().GetDensityField() is None


def marching(kind="spot", steps=256, width=96, height=72):
    renderer, window, info, shafts = scene(kind, width, height)
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetNumberOfSteps(steps)
    shafts.SetInterleaveSize(1)
    shafts.SetBlurRadius(0)  # (the blur smears a field's edges in the picture)
    return renderer, window, info, shafts


def rendered(window, shafts):
    window.Render()
    return rh.in_scatter(shafts).copy()


@pytest.mark.parametrize("steps", [64, 4096])
def test_ray_march_renders_a_uniform_field_as_the_homogeneous_medium(steps):
    # 4096 steps: the light-leg samples stay within llvmpipe's 65535 loop iterations a pixel
    # (vtkLightShaftShaders::DensitySteps); past it the picture came out 4x too dark.
    renderer, window, info, shafts = marching(steps=steps, width=48, height=36)
    homogeneous = rendered(window, shafts)
    shafts.GetMedium().SetDensityField(field_image(lambda x, y, z: np.ones_like(x), samples=2))
    uniform = rendered(window, shafts)
    assert homogeneous.max() > 0.0
    assert relative(uniform, homogeneous) < 1e-4


def layer_image(samples=64):
    """Density 1 below y = 2.5 and 0 above, over the sphere scene's floor, as point data."""
    image = vtkImageData()
    image.SetDimensions(samples, samples, samples)
    spacing = 16.0 / (samples - 1)
    image.SetSpacing(spacing, spacing, spacing)
    image.SetOrigin(-8.0, -1.0, -8.0)
    y = -1.0 + spacing * np.arange(samples)
    values = np.broadcast_to((y < 2.5)[None, :, None], (samples,) * 3).astype(float)
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True))
    return image


@pytest.mark.parametrize("kind, function", [
    ("spot", linear), ("spot", cubic), ("spot", "layer"), ("point", linear),
    ("directional", linear)])
def test_ray_march_through_a_field_against_the_reference(kind, function):
    # Against the float64 reference with the pass's own shadow map (its error apart; a point
    # light's cube map is not read back: exact visibility). Measured at 96x72, 256 steps:
    # 0.01% or less for each, the layer (density 1 below y = 2.5, 0 above) too.
    renderer, window, info, shafts = marching(kind)
    shafts.GetMedium().SetDensityField(layer_image() if function == "layer" else field_image(function))
    image = rendered(window, shafts)
    visibility = 0 if kind == "point" else 1
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=visibility)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"{kind} {getattr(function, '__name__', function)}: {error:.5f}")
    assert expected.max() > 0.0
    assert error < 0.002


def test_a_zero_field_scatters_nothing_and_changes_of_the_data_are_seen(messages):
    renderer, window, info, shafts = marching(width=48, height=36)
    image = field_image(lambda x, y, z: np.zeros_like(x), samples=3)
    shafts.GetMedium().SetDensityField(image)
    assert rendered(window, shafts).max() == 0.0
    # The same image's values change (the pipeline's way): the next frame uses them.
    scalars = image.GetPointData().GetScalars()
    for i in range(scalars.GetNumberOfTuples()):
        scalars.SetValue(i, 1.0)
    scalars.Modified()
    ones = rendered(window, shafts)
    assert ones.max() > 0.0
    # Then it becomes unusable: one error, and the last usable field stays in use.
    log = messages(shafts)
    scalars.SetValue(0, math.nan)
    scalars.Modified()
    again = rendered(window, shafts)
    rendered(window, shafts)
    assert len(log.errors) == 1 and "the last usable density field is kept" in log.errors[0]
    assert np.array_equal(again, ones)


def test_methods_without_a_field_give_way_to_ray_march_once(messages):
    renderer, window, info, shafts = scene(width=48, height=36)
    log = messages(shafts)
    shafts.GetMedium().SetDensityField(field_image(linear, samples=3))
    shafts.SetMethod(vtkLightShaftPass.AUTOMATIC)
    window.Render()
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.RAY_MARCH and not log.warnings
    for method in (vtkLightShaftPass.SLICES, vtkLightShaftPass.EPIPOLAR):
        shafts.SetMethod(method)
        window.Render()
        assert shafts.GetLastFrame().GetMethod() == method and not log.warnings
    for method in (vtkLightShaftPass.LIGHT_VOLUME, vtkLightShaftPass.ANALYTIC,
                   vtkLightShaftPass.RADIAL_BLUR):
        shafts.SetMethod(method)
        for _ in range(2):
            window.Render()
        assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.RAY_MARCH
    assert len(log.warnings) == 1
    assert "rendered by SLICES, RAY_MARCH and EPIPOLAR" in log.warnings[0]


def test_the_scene_is_dimmed_by_the_field_not_by_the_coefficients():
    # AttenuateScene (on by default) dims the surfaces by the field's optical depth up to them:
    # a zero field leaves the picture as the plain scene's (in-scatter 0, nothing dimmed), a
    # uniform one as the homogeneous medium's.
    renderer, window, info, shafts = marching(width=96, height=72)
    renderer.SetPass(None)
    window.Render()
    plain = rh.screenshot(window).astype(int)
    renderer.SetPass(shafts)
    homogeneous = rh.screenshot(window).astype(int)
    shafts.GetMedium().SetDensityField(field_image(lambda x, y, z: np.zeros_like(x), samples=2))
    assert np.array_equal(rh.screenshot(window).astype(int), plain)
    shafts.GetMedium().SetDensityField(field_image(lambda x, y, z: np.ones_like(x), samples=2))
    uniform = rh.screenshot(window).astype(int)
    assert np.abs(uniform - homogeneous).max() <= 1
    assert np.abs(homogeneous - plain).max() > 20  # (the medium does dim and light the scene)


# The light leg's table (vtkLightShaftFieldTableTexture, MediumShadowResolution): one face in the
# light's frame when the light sees the field's box from outside, a cube around it otherwise.
def single_face_bytes(depth):
    """A table of one face at the default resolution (64^2 columns), `depth` texels deep."""
    return 4 * 64 ** 2 * depth


def cube_bytes(depth):
    """Half the default resolution on each of the cube's six faces."""
    return 4 * 6 * 32 ** 2 * depth


def plume_image(samples=48, low=(-3.0, -1.0, -3.0), high=(3.0, 3.0, 3.0)):
    """A smooth plume over the floor: a Gaussian of peak 4 at (0, 1, 0) (sigma 1.2) as point
    data over the box [low, high]. The scene's spot (0.5, 6, 0) sees the default box from
    outside; the "pair"'s point light (-1.5, 3.2, 1) is inside it."""
    image = vtkImageData()
    image.SetDimensions(samples, samples, samples)
    spacing = [(h - l) / (samples - 1) for l, h in zip(low, high)]
    image.SetSpacing(*spacing)
    image.SetOrigin(*low)
    axes = [l + s * np.arange(samples) for l, s in zip(low, spacing)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")  # x fastest when raveled
    r2 = x ** 2 + (y - 1.0) ** 2 + z ** 2
    values = 4.0 * np.exp(-r2 / (2.0 * 1.2 ** 2))
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True))
    return image


@pytest.mark.parametrize("kind, box, table_bytes", [
    # The depth: a texel per sample plane crossed along the most crossed column (the plume's
    # 48^3 samples, spacing 0.125 and 0.083), at least the lateral resolution.
    ("spot", "plume", [single_face_bytes(88)]),
    ("spot", "tall", [single_face_bytes(97)]),  # the spot's cone, not a cube: it is inside
    ("point", "plume", [single_face_bytes(92)]),
    ("point", "tall", [cube_bytes(104)]),
    ("directional", "plume", [single_face_bytes(64)]),
    ("pair", "plume", [single_face_bytes(88), cube_bytes(119)])])
def test_the_light_leg_table_against_the_reference(kind, box, table_bytes):
    # Each layout of the table, for each kind of light, against the float64 reference (which
    # integrates both legs through the trilinear field exactly). "tall" reaches above the
    # lights: they are inside the box, and get a cube (the spot a face over its cone). Measured at 96x72, 256 steps: 0.04-0.15%
    # (the table's interpolation; 0.01-0.05% at resolution 128; the leg marched, 0.01-0.07%).
    renderer, window, info, shafts = marching(kind)
    high = (3.0, 8.0, 3.0) if box == "tall" else (3.0, 3.0, 3.0)
    if kind == "point":
        info.light.SetPosition(0.5, 6.0, 0.0)  # outside the plume's box, inside the tall one
    shafts.GetMedium().SetDensityField(plume_image(high=high))
    image = rendered(window, shafts)
    lights = shafts.GetLastFrame().GetNumberOfUsedLights()
    assert [shafts.GetLastFrame().GetLightFieldShadowBytes(i) for i in range(lights)] == table_bytes
    assert "field-shadow" in shafts.GetLastFrame().GetShaderVariant()
    visibility = 0 if kind in ("point", "pair") else 1
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=visibility)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"{kind} {box}: {error:.5f}")
    assert expected.max() > 0.0
    assert error < 0.002


@pytest.mark.parametrize("density", ["plume", "layer"])
def test_final_quality_through_a_field_is_within_one_percent(density):
    # The acceptance: at Final, a plume lit by a spot and a point light, and a layer
    # (density 1 below y = 2.5, 0 above) lit by the spot, each within 1% of the reference.
    renderer, window, info, shafts = scene("pair" if density == "plume" else "spot", 96, 72)
    shafts.SetQualityToFinal()
    shafts.GetMedium().SetDensityField(plume_image() if density == "plume" else layer_image())
    image = rendered(window, shafts)
    visibility = 0 if density == "plume" else 1
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=visibility)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"{density} at Final: {error:.5f}")
    assert error < 0.01


def wide_layer_image(step=0.1, across=10.0):
    """Density 1 below y = 2.5 and 0 above over the whole [-HALF, HALF]^3 box, as point data a
    `step` apart along y (linear over one cell) and `across` apart along x and z."""
    image = vtkImageData()
    along = int(round(2.0 * HALF / step)) + 1
    lateral = int(round(2.0 * HALF / across)) + 1
    image.SetDimensions(lateral, along, lateral)
    image.SetSpacing(across, step, across)
    image.SetOrigin(-HALF, -HALF, -HALF)
    y = -HALF + step * np.arange(along)
    values = np.broadcast_to((y < 2.5)[None, :, None], (lateral, along, lateral))
    image.GetPointData().SetScalars(numpy_to_vtk(values.astype(float).ravel(), deep=True))
    return image


def test_a_sharp_layer_in_a_wide_box_at_final_quality():
    # The table's depth follows the field's sampling seen from the light: 64 texels over the
    # box's 104 units left the layer's edge (0.1 thick) 3 units wide, 1.2% from the reference
    # at Final (240x180); a texel per sample plane crossed brings it to the marched leg's.
    # Measured: 0.051% (the leg marched: 0.053%).
    renderer, window, info, shafts = scene("spot", 240, 180)
    shafts.SetQualityToFinal()
    shafts.GetMedium().SetDensityField(wide_layer_image())
    image = rendered(window, shafts)
    assert shafts.GetLastFrame().GetLightFieldShadowBytes(0) > 4 * 64 ** 3
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=1)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"wide layer at Final: {error:.5f}")
    assert expected.max() > 0.0
    assert error < 0.002


def test_the_table_is_built_when_the_field_or_the_light_moves_only():
    renderer, window, info, shafts = marching(width=48, height=36)
    image = plume_image(samples=16)
    shafts.GetMedium().SetDensityField(image)

    def built():
        shafts.GetMedium().SetTime(shafts.GetMedium().GetTime() + 0.1)  # (a new frame of the shafts each time)
        window.Render()
        return shafts.GetLastFrame().GetLightFieldShadowBuildTime(0) > 0.0

    assert built() and not built()
    shafts.GetMedium().SetDensityScale(2.0)   # applied in the shader: nothing to build
    shafts.GetMedium().SetBackgroundDensity(0.1)
    renderer.GetActiveCamera().Azimuth(10.0)
    assert not built()
    info.light.SetPosition(0.0, 6.0, 0.5)
    assert built() and not built()
    scalars = image.GetPointData().GetScalars()
    scalars.SetValue(0, 2.0)
    scalars.Modified()
    assert built() and not built()
    shafts.GetMedium().SetFieldShadowResolution(96)
    assert built()
    assert shafts.GetLastFrame().GetLightFieldShadowBytes(0) == 4 * 96 ** 3
    shafts.GetMedium().SetFieldShadowResolution(0)  # the leg marched: no table
    assert not built()
    assert shafts.GetLastFrame().GetLightFieldShadowBytes(0) == 0
    assert "field-shadow" not in shafts.GetLastFrame().GetShaderVariant()
    assert "field" in shafts.GetLastFrame().GetShaderVariant()


def test_a_pipeline_drives_the_field(messages):
    # SetMediumDensityConnection: the pipeline is brought up to date each frame, a change of a
    # source's parameter reaches the picture (uploaded and the light leg's table rebuilt), an
    # output that is not an image gets one error and the last field stays; SetMediumDensity
    # replaces the connection.
    from vtkmodules.vtkImagingCore import vtkImageShiftScale, vtkRTAnalyticSource
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    renderer, window, info, shafts = marching(width=48, height=36)
    log = messages(shafts)
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-8, 8, -1, 8, -8, 8)
    scale = vtkImageShiftScale()
    scale.SetInputConnection(wavelet.GetOutputPort())
    scale.SetShift(10.0)  # (the wavelet dips below 0 at the box's corners)
    scale.SetScale(0.01)
    scale.SetOutputScalarTypeToFloat()
    shafts.GetMedium().SetDensityFieldConnection(scale.GetOutputPort())
    assert shafts.GetMedium().GetDensityFieldConnection() is scale.GetOutputPort()
    first = rendered(window, shafts)
    assert first.max() > 0.0 and shafts.GetLastFrame().GetLightFieldShadowBuildTime(0) > 0.0
    assert shafts.GetMedium().GetDensityField() is scale.GetOutput()
    wavelet.SetMaximum(1000.0)  # (the pipeline's way: no call to the pass)
    denser = rendered(window, shafts)
    assert shafts.GetLastFrame().GetLightFieldShadowBuildTime(0) > 0.0
    assert not np.array_equal(denser, first)
    # The same as setting that pipeline's output image directly.
    direct = vtkImageData()
    direct.DeepCopy(scale.GetOutput())
    assert np.array_equal(rendered(window, shafts), denser) and not log.errors
    # An output that is not an image: one error, the last field kept.
    sphere = vtkSphereSource()
    shafts.GetMedium().SetDensityFieldConnection(sphere.GetOutputPort())
    kept = rendered(window, shafts)
    rendered(window, shafts)
    assert len(log.errors) == 1 and "vtkPolyData, not a vtkImageData" in log.errors[0]
    assert np.array_equal(kept, denser)
    shafts.GetMedium().SetDensityField(direct)
    assert shafts.GetMedium().GetDensityFieldConnection() is None
    assert np.array_equal(rendered(window, shafts), denser)


@pytest.mark.parametrize("kind, density", [
    ("spot", "plume"), ("pair", "plume"), ("directional", "plume"), ("spot", "layer")])
@pytest.mark.parametrize("method", ["SLICES", "EPIPOLAR"])
def test_slices_and_epipolar_through_a_field_against_the_reference(method, kind, density):
    # SLICES (each slab's fragment marches the view leg up to it, DensitySteps samples) and
    # EPIPOLAR (RAY_MARCH's march at its samples) render the field too. Measured at 96x72:
    # SLICES 256 slabs 0.04-0.10%; EPIPOLAR 64 steps, every 4th sample marched, 0.17-0.92%
    # (its interpolation along the lines across the layer's edge).
    renderer, window, info, shafts = marching(kind)
    if method == "SLICES":
        shafts.SetMethod(vtkLightShaftPass.SLICES)
        shafts.SetAutomaticSliceCount(False)
        shafts.SetNumberOfSlices(256)
        bound = 0.002
    else:
        shafts.SetMethod(vtkLightShaftPass.EPIPOLAR)
        shafts.SetNumberOfSteps(64)
        shafts.SetEpipolarStep(4)
        bound = 0.015
    shafts.GetMedium().SetDensityField(layer_image() if density == "layer" else plume_image())
    image = rendered(window, shafts)
    assert shafts.GetLastFrame().GetMethod() == getattr(vtkLightShaftPass, method)
    assert "field-shadow" in shafts.GetLastFrame().GetShaderVariant()
    visibility = 0 if kind == "pair" else 1
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=visibility)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"{method} {kind} {density}: {error:.5f}")
    assert error < bound


@pytest.mark.parametrize("density, target", [("plume", 0.02), ("layer", 0.02), ("layer", 0.01)])
def test_a_target_error_applies_to_a_field(messages, density, target):
    # The error model measures a field along view rays through the lit volume (its optical
    # depth, and its own quadrature error at each setting's samples: GetFieldError()): with a
    # field, TargetError chooses a setting that renders it, its prediction is reported, and
    # the picture meets it against the float64 reference. Measured at 96x72: the plume 0.024%
    # (M128 chosen for 2%, predicted 1.2%), the layer 0.014% (M128 for 2%, M256 for 1%).
    renderer, window, info, shafts = scene("pair" if density == "plume" else "spot", 96, 72)
    log = messages(shafts)
    shafts.SetTargetError(target)
    shafts.GetMedium().SetDensityField(plume_image() if density == "plume" else layer_image())
    image = rendered(window, shafts)
    frame = shafts.GetLastFrame()
    name = shafts.GetErrorModelSettingName(frame.GetErrorModelSetting())
    assert frame.GetMethod() in (vtkLightShaftPass.RAY_MARCH, vtkLightShaftPass.EPIPOLAR)
    assert 0.0 < frame.GetPredictedError() <= target, name
    assert frame.GetFieldError() >= 0.0
    visibility = 0 if density == "plume" else 1
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=visibility)
    error, _ = ref.relative_rms_error(image, expected)
    print(f"{density} target {target}: {name} predicted {frame.GetPredictedError():.4f}, "
          f"field {frame.GetFieldError():.4f}, measured {error:.5f}")
    assert error <= target
    assert not log.warnings and not log.errors
    # Without the field the model predicts as before; GetFieldError says there is none.
    shafts.GetMedium().SetDensityField(None)
    window.Render()
    assert shafts.GetLastFrame().GetPredictedError() > 0.0
    assert shafts.GetLastFrame().GetFieldError() == -1.0


def test_an_image_over_the_gl_3d_texture_size_is_resampled_with_one_warning(messages):
    # More samples along x than this GL's 3D textures hold: resampled to that many along x (one
    # warning per image), the reference integrates the image as it is. A linear field is
    # reproduced exactly by the resampling, so the picture stays within the usual bound.
    from vtkmodules.vtkRenderingOpenGL2 import vtkTextureObject
    renderer, window, info, shafts = marching()
    limit = vtkTextureObject.GetMaximumTextureSize3D(window)
    shafts.GetMedium().SetFieldResolution(16384)  # (the pass's own bound above the GL's)
    image = field_image(linear, samples=3)
    image.SetDimensions(2 * limit + 1, 3, 3)
    image.SetSpacing(2.0 * HALF / (2 * limit), 2.0 * HALF, 2.0 * HALF)
    image.SetOrigin(-HALF, -HALF, -HALF)
    image.SetDirectionMatrix(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    x = -HALF + image.GetSpacing()[0] * np.arange(2 * limit + 1)
    grid = np.meshgrid(x, [-HALF, 0.0, HALF], [-HALF, 0.0, HALF], indexing="ij")
    values = linear(*grid).transpose(2, 1, 0)  # (z, y, x): x fastest when raveled
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True))
    log = messages(shafts)
    shafts.GetMedium().SetDensityField(image)
    picture = rendered(window, shafts)
    rendered(window, shafts)
    assert len(log.warnings) == 1 and f"resampled to {limit} along that axis" in log.warnings[0]
    assert not log.errors
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=1)
    error, _ = ref.relative_rms_error(picture, expected)
    assert expected.max() > 0.0 and error < 0.002


def test_field_resolution_bounds_the_pass_s_grid_silently(messages):
    # A field with more samples along an axis than FieldResolution is resampled to that many,
    # without a message (the bound is the user's): a field that varies along x at 65 samples
    # gives another picture at FieldResolution 16, the same one at 65 and above.
    renderer, window, info, shafts = marching()
    image = field_image(lambda x, y, z: 1.0 + np.sin(3.0 * x), samples=65)
    log = messages(shafts)
    shafts.GetMedium().SetDensityField(image)
    pictures = {}
    assert shafts.GetMedium().GetFieldResolution() == 2048
    for resolution in (2048, 65, 16):
        shafts.GetMedium().SetFieldResolution(resolution)
        assert shafts.GetMedium().GetFieldResolution() == resolution
        pictures[resolution] = rendered(window, shafts)
    assert np.array_equal(pictures[2048], pictures[65])
    assert ref.relative_rms_error(pictures[16], pictures[2048])[0] > 1e-3
    assert not log.warnings and not log.errors
    shafts.GetMedium().SetFieldResolution(1)
    assert shafts.GetMedium().GetFieldResolution() == 16


def test_a_still_view_refines_the_light_leg_table(messages):
    # Refinement's estimates average what their shifted samples scatter, not the table's
    # interpolation, the same in each: a still view refines the table (or marches the leg)
    # where its term is over half of what the setting's samples make, from the frame where the
    # camera stops (a new history then replaces the moving frame's one estimate). A sharp layer
    # over the whole box, lit by a point light inside it (a cube of faces, their texels wide
    # far from the light), seen level (the rays that hit nothing end on the box's far face):
    # measured at 96x72, Final, 0.222% with the table, 0.003% with the leg marched. The floor's box is flat: the error model's probe rays see the air above it (they
    # used to be cut to the box, and saw nothing).
    renderer, window, info, shafts = scene("point", 96, 72, level=True)
    log = messages(shafts)
    shafts.SetQualityToFinal()
    shafts.ProgressiveRefinementOn()
    shafts.GetMedium().SetDensityField(wide_layer_image())
    window.Render()
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=0)

    def frame():
        image = rendered(window, shafts)
        report = shafts.GetLastFrame()
        return (ref.relative_rms_error(image, expected)[0], report.GetLightFieldShadowBytes(0),
                report.GetLightFieldShadowBuildTime(0), report.GetPredictedError(),
                report.GetFieldError())

    camera = renderer.GetActiveCamera()
    camera.Azimuth(1.0)
    window.Render()
    camera.Azimuth(-1.0)  # (back where the reference saw it)
    moving = frame()
    assert moving[1] > 0 and moving[4] > 0.0  # the table, and the error model sees it
    stopped = frame()
    assert stopped[1] != moving[1]  # refined (0 bytes: marched)
    assert stopped[3] < moving[3] and stopped[4] < moving[4]
    assert stopped[0] <= 0.5 * moving[0]
    print(f"table {100 * moving[0]:.3f}%, refined {100 * stopped[0]:.3f}% "
          f"({stopped[1]:.0f} bytes), predicted {100 * moving[3]:.2f}% then "
          f"{100 * stopped[3]:.2f}%")
    assert frame()[0] <= stopped[0] * 1.01
    # Moving again: the table set is used again, and was kept (nothing built); so is the
    # refined one when the view stops again.
    camera.Azimuth(2.0)
    again = frame()
    assert again[1] == moving[1] and again[2] == 0.0
    assert frame()[1:3] == (stopped[1], 0.0)
    # Without refinement a still view keeps the table set.
    shafts.ProgressiveRefinementOff()
    for _ in range(3):
        assert frame()[1] == moving[1]
    assert not log.warnings and not log.errors


def test_refining_a_dense_field_improves_on_the_first_estimate(messages):
    # Each estimate samples a medium from data at its pieces' midpoints (the pieces shifted):
    # looking it up off the centre, as the shadow is, made a dense plume's second estimate
    # worse than its first (0.60% then 1.46% on a random scene at 240x180). The plume's density
    # scaled up (optical depth about 10 through it), 32 steps.
    renderer, window, info, shafts = scene("pair", 96, 72)
    log = messages(shafts)
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetNumberOfSteps(32)
    shafts.SetInterleaveSize(1)
    shafts.SetBlurRadius(0)
    shafts.ProgressiveRefinementOn()
    shafts.SetRefinementFrames(8)
    shafts.GetMedium().SetDensityField(plume_image())
    shafts.GetMedium().SetDensityScale(10.0)
    window.Render()
    expected, _, _ = cpp_reference(renderer, shafts, VisibilityMode=0)
    errors = []
    for _ in range(8):
        errors.append(ref.relative_rms_error(rendered(window, shafts), expected)[0])
    print("errors over the estimates:", " ".join(f"{100 * e:.3f}%" for e in errors))
    assert all(later <= 1.02 * errors[0] for later in errors[1:])
    assert errors[-1] < errors[0]
    assert not log.warnings and not log.errors
