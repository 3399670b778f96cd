"""vtkLightShaftReference, the C++ float64 reference: against the independent numpy reference,
its closed forms against its quadrature, known limits and scalings, and the pass against it."""

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass, vtkLightShaftReference
from vtkmodules.util.numpy_support import vtk_to_numpy

import lightshaft_reference as ref
import render_helpers as rh

# A sweep (conftest.py): the float64 references against each other and the pass (LightShaftAccuracy
# checks the pass against it on every release).
pytestmark = pytest.mark.sweep


def cpp_reference(renderer, shafts, **params):
    reference = vtkLightShaftReference()
    reference.SetRenderer(renderer)
    reference.SetLightShaftPass(shafts)
    for name, value in params.items():
        getattr(reference, "Set" + name)(value)
    reference.Update()
    image = reference.GetOutput()
    w, h, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetArray("InScatteredRadiance")).reshape(h, w, 3)
    errors = vtk_to_numpy(image.GetPointData().GetArray("ErrorEstimate")).reshape(h, w, 3)
    return values.copy(), errors.copy(), reference


def scene(width=120, height=90, sphere=True, **medium):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=256)
    if not sphere:
        renderer.RemoveActor(info.actors[0])
        info.spheres = []
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(*medium.get("sigma_s", (0.05, 0.04, 0.03)))
    shafts.GetMedium().SetAbsorptionCoefficient(*medium.get("sigma_a", (0.02, 0.01, 0.03)))
    renderer.SetPass(shafts)
    window.Render()  # VTK resets the clipping range; both references read it afterwards
    return renderer, window, info, shafts


def test_layout_matches_the_pass_readback():
    renderer, window, info, shafts = scene()
    values, errors, reference = cpp_reference(renderer, shafts)
    assert values.shape == rh.in_scatter(shafts).shape
    assert reference.GetOutput().GetPointData().GetScalars().GetName() == "InScatteredRadiance"
    assert np.all(errors >= 0.0)


def test_agrees_with_the_numpy_reference_on_exact_geometry():
    # Floor only: a plane is exact in both (no tessellation), so the two float64 integrators
    # must agree to quadrature tolerance.
    renderer, window, info, shafts = scene(sphere=False)
    values, _, _ = cpp_reference(renderer, shafts)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8)
    assert np.abs(values - numpy_values).max() <= 1e-8 * numpy_values.max()


def test_agrees_with_the_numpy_reference_with_the_sphere_shadow():
    # The C++ reference shadows with the tessellated sphere (256x256 facets), the numpy one with
    # the analytic sphere: they differ only at shadow and silhouette edges.
    renderer, window, info, shafts = scene()
    values, _, _ = cpp_reference(renderer, shafts)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8)
    error, _ = ref.relative_rms_error(values, numpy_values)
    assert error < 2e-3
    assert ref.energy_error(values, numpy_values) < 5e-4


def test_closed_form_b_matches_quadrature():
    # A = 1/r^2, isotropic, plain cone (exponent 0), nothing in the light: the closed form (B),
    # homogeneous extinction, against the adaptive quadrature.
    renderer, window, info, shafts = scene(sphere=False, sigma_s=(0.05,) * 3,
                                           sigma_a=(0.02, 0.0, 0.1))
    info.light.SetAttenuationValues(0.0, 0.0, 1.0)
    info.light.SetExponent(0.0)
    renderer.RemoveActor(info.actors[1])  # no floor: nothing shadows, no surface
    rh.scene_extent(shafts)
    window.Render()
    closed, _, reference = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    assert reference.GetLastClosedFormPixels() > 0
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert np.abs(closed - quadrature).max() <= 1e-9 * quadrature.max()


def test_small_extinction_limit():
    # As sigma_t -> 0 with sigma_s fixed, (B) tends to (A) * (no extinction): compare the closed
    # form at sigma_a = 0, sigma_s = 1e-9 (optical depths ~1e-8) with the quadrature.
    renderer, window, info, shafts = scene(sphere=False, sigma_s=(1e-9,) * 3,
                                           sigma_a=(0.0, 0.0, 0.0))
    info.light.SetAttenuationValues(0.0, 0.0, 1.0)
    info.light.SetExponent(0.0)
    renderer.RemoveActor(info.actors[1])
    rh.scene_extent(shafts)
    window.Render()
    closed, _, _ = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert np.abs(closed - quadrature).max() <= 1e-7 * quadrature.max()


def test_scalings_and_zero_scattering():
    renderer, window, info, shafts = scene()
    base, _, _ = cpp_reference(renderer, shafts)
    info.light.SetIntensity(2.0)
    doubled, _, _ = cpp_reference(renderer, shafts)
    np.testing.assert_allclose(doubled, 2.0 * base, rtol=1e-9, atol=1e-300)
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    zero, _, _ = cpp_reference(renderer, shafts)
    assert np.all(zero == 0.0)


def test_the_pass_against_the_cpp_reference():
    # (How long the reference takes is a benchmark figure, not a test: tools/measure.sh
    # reference-speed.)
    renderer, window, info, shafts = scene(640, 480)
    shafts.SetNumberOfSlices(512)
    shafts.SetShadowMapSize(2048)
    window.Render()
    values, errors, _ = cpp_reference(renderer, shafts)
    assert errors.max() <= 1e-6 * values.max()
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), values)
    assert error < 0.01


def test_cookie_and_noise_against_the_pass():
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkRenderingCore import vtkTexture
    renderer, window, info, shafts = scene(100, 75)
    shafts.SetNumberOfSlices(256)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    shafts.SetShadowMapSize(2048)
    # A smooth coloured cookie: a horizontal ramp in red, a vertical one in blue.
    size = 32
    v, u = np.mgrid[0:size, 0:size] / (size - 1)
    rgb = np.dstack([u, np.full_like(u, 0.5), v]) * 255
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(rgb.astype(np.uint8).reshape(-1, 3), deep=1))
    cookie = vtkTexture()
    cookie.SetInputData(image)
    shafts.SetCookie(cookie)
    window.Render()
    values, _, _ = cpp_reference(renderer, shafts, RelativeTolerance=1e-6)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), values)
    assert error < 0.02
    shafts.SetCookie(None)
    shafts.GetMedium().SetNoiseAmplitude(1.0)
    shafts.GetMedium().SetNoiseScale(1.5)
    shafts.GetMedium().SetTime(4.0)
    window.Render()
    # Noise makes every ray's integrand wiggle: a looser tolerance keeps the reference quick.
    values, _, _ = cpp_reference(renderer, shafts, RelativeTolerance=1e-5)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), values)
    assert error < 0.05


@pytest.mark.parametrize("size", [16, 32, 64, 2048])
def test_shadow_map_visibility_separates_shadow_map_error(size):
    # The pass against the exact reference and against the reference that uses the pass's own
    # shadow map: a coarse map (16^2) is far from the exact one near the sphere's shadow (3.3%
    # measured), close to its own (0.08%: the integration error, the same for every size;
    # docs/reference-and-benchmarks.md quotes what this prints).
    renderer, window, info, shafts = scene(200, 150)
    shafts.SetNumberOfSlices(512)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    shafts.SetShadowMapSize(size)
    window.Render()
    assert shafts.GetLastFrame().GetShadowMapRendered()
    measured = rh.in_scatter(shafts)
    exact, _, _ = cpp_reference(renderer, shafts)
    same_map, _, reference = cpp_reference(renderer, shafts, VisibilityMode=1,
                                           VisibilitySamples=256)
    assert reference.GetVisibilityMode() == vtkLightShaftReference.SHADOW_MAP
    error_exact, _ = ref.relative_rms_error(measured, exact)
    error_same_map, _ = ref.relative_rms_error(measured, same_map)
    print(f"{size}^2 map: {error_exact:.3%} against the exact reference, {error_same_map:.3%} "
          "against the one using the pass's map")
    assert error_same_map < 0.005
    if size == 16:
        assert error_exact > 0.02
        assert error_same_map < 0.1 * error_exact


def test_shadow_map_visibility_needs_a_shadow_map(messages, vtk_messages):
    renderer, window, info, shafts = scene(40, 30)
    shafts.GetMedium().SetScatteringCoefficient(0.0)  # nothing scatters: no shadow map is rendered
    window.Render()
    reference = vtkLightShaftReference()
    log = messages(reference)
    reference.SetRenderer(renderer)
    reference.SetLightShaftPass(shafts)
    reference.SetVisibilityModeToShadowMap()
    vtk_messages.expect("vtkLightShaftReference.*returned failure for request")
    reference.Update()
    assert any("shadow map" in e for e in log.errors)


@pytest.mark.parametrize("offset", [1e-3, 1e-6])
def test_closed_forms_near_the_light_line(offset):
    # gamma -> 0 and h -> 0: the centre pixel's ray passes `offset` from the light (odd image
    # size, camera aimed just beside the light). Closed form and quadrature agree per pixel.
    renderer, window, info, shafts = scene(41, 31, sphere=False, sigma_s=(0.05,) * 3,
                                           sigma_a=(0.01, 0.0, 0.02))
    info.light.SetAttenuationValues(0.0, 0.0, 1.0)
    info.light.SetExponent(0.0)
    renderer.RemoveActor(info.actors[1])
    rh.scene_extent(shafts)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.5, 6.0, 10.0)
    camera.SetFocalPoint(0.5 + offset, 6.0, 0.0)
    window.Render()
    closed, _, reference = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert np.all(np.isfinite(closed)) and np.all(np.isfinite(quadrature))
    lit = quadrature > 0
    assert lit.sum() > 100
    assert np.max(np.abs(closed[lit] / quadrature[lit] - 1.0)) < 1e-7


# --- point and directional lights, several lights ------------------------------------------------

POINT_POSITION = (0.4, 3.4, 0.3)  # below the top of the view, beside the sphere: in the picture
ABSORPTION = (0.02, 0.01, 0.03)


def kind_scene(kind, width=120, height=90, sphere=True, phase="isotropic", **medium):
    """scene() with its light turned into `kind` (rh.make_light_kind), the lights given to the pass."""
    renderer, window, info, shafts = scene(width, height, sphere, **medium)
    lights = rh.make_light_kind(renderer, info, kind, POINT_POSITION)
    for light in lights:
        shafts.AddLight(light)
    if phase == "hg":
        shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
        shafts.GetMedium().SetAnisotropy(0.6)
    window.Render()
    return renderer, window, info, shafts, lights


def max_relative(values, expected):
    return float(np.abs(values - expected).max() / expected.max())


@pytest.mark.parametrize("absorption", [(0.0, 0.0, 0.0), ABSORPTION], ids=["no-abs", "abs"])
@pytest.mark.parametrize("phase", ["isotropic", "hg"])
@pytest.mark.parametrize("kind", ["point", "point-inverse-square", "directional", "pair"])
def test_kinds_agree_with_the_numpy_reference_on_exact_geometry(kind, phase, absorption):
    # Floor only (exact in both): the C++ quadrature (or closed forms: the 1/r^2 point light
    # when isotropic, the directional light always) against numpy's Gauss-Legendre. Measured:
    # 1e-15 to 1e-14.
    renderer, window, info, shafts, lights = kind_scene(kind, sphere=False, phase=phase,
                                                        sigma_a=absorption)
    values, _, reference = cpp_reference(renderer, shafts)
    assert reference.GetLastNumberOfLights() == len(lights)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8, lights=lights)
    assert numpy_values.max() > 0.0
    assert max_relative(values, numpy_values) <= 1e-8


@pytest.mark.parametrize("phase,absorption", [("isotropic", (0.0, 0.0, 0.0)),
                                              ("hg", ABSORPTION)], ids=["iso-no-abs", "hg-abs"])
@pytest.mark.parametrize("kind", ["point", "directional", "pair"])
def test_kinds_agree_with_the_numpy_reference_with_the_sphere_shadow(kind, phase, absorption):
    # The tessellated sphere (C++) against the analytic one (numpy: the tangent cone of a
    # positional light, the cylinder of a directional one). Measured: relative RMS 1.4e-5 to
    # 2e-4, energy 3e-7 to 4e-6.
    renderer, window, info, shafts, lights = kind_scene(kind, 80, 60, phase=phase,
                                                        sigma_a=absorption)
    values, _, _ = cpp_reference(renderer, shafts)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8, lights=lights)
    error, _ = ref.relative_rms_error(values, numpy_values)
    assert error < 2e-3
    assert ref.energy_error(values, numpy_values) < 5e-4


def no_props_scene(kind, **medium):
    """kind_scene without sphere or floor: nothing shadows, rays run to the backdrop of the
    floor's extent (rh.scene_extent)."""
    renderer, window, info, shafts, lights = kind_scene(kind, sphere=False, **medium)
    renderer.RemoveActor(info.actors[1])
    rh.scene_extent(shafts)
    info.floors = []
    window.Render()
    return renderer, window, info, shafts, lights


def test_point_light_closed_form_b_matches_quadrature():
    # A = 1/r^2, isotropic: (B), homogeneous extinction, with the light in the picture.
    renderer, window, info, shafts, lights = no_props_scene(
        "point-inverse-square", sigma_s=(0.05,) * 3, sigma_a=(0.02, 0.0, 0.1))
    closed, _, reference = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    assert reference.GetLastClosedFormPixels() == closed.shape[0] * closed.shape[1]
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert max_relative(closed, quadrature) <= 1e-9


def test_point_light_small_extinction_limit():
    # (B) as sigma_t -> 0 tends to (A) times no extinction (optical depths ~1e-8).
    renderer, window, info, shafts, lights = no_props_scene(
        "point-inverse-square", sigma_s=(1e-9,) * 3, sigma_a=(0.0, 0.0, 0.0))
    closed, _, reference = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    assert reference.GetLastClosedFormPixels() > 0
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert max_relative(closed, quadrature) <= 1e-7
    # (A) itself: a light at distance D from a whole ray (no extinction) gives
    # sigma_s I / (4 pi) (pi - gamma) / (D sin gamma); the numpy reference integrates the same.
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=16, lights=lights)
    assert max_relative(closed, numpy_values) <= 1e-7


@pytest.mark.parametrize("phase", ["isotropic", "hg"])
def test_directional_closed_form_matches_quadrature(phase):
    # Exact for any phase (theta is constant along the ray), on every lit piece between the
    # sphere's shadow boundaries.
    renderer, window, info, shafts, lights = kind_scene("directional", 80, 60, phase=phase)
    closed, _, reference = cpp_reference(renderer, shafts, RelativeTolerance=1e-12)
    assert reference.GetLastClosedFormPixels() > 0.5 * closed.shape[0] * closed.shape[1]
    quadrature, _, _ = cpp_reference(renderer, shafts, UseClosedForms=False,
                                     RelativeTolerance=1e-12)
    assert max_relative(closed, quadrature) <= 1e-9


def directional_plane_distance(renderer, window, info, light):
    """r = (x - P) . a at the surface each pixel's ray meets, (height, width)."""
    hit, _ = rh.surface_points(renderer, window, info)
    position = np.asarray(light.GetPosition(), float)
    axis = np.asarray(light.GetFocalPoint(), float) - position
    w, h = window.GetSize()
    return ((hit - position) @ (axis / np.linalg.norm(axis))).reshape(h, w)


def test_directional_light_gives_nothing_before_its_plane():
    # The eye above the plane, looking level: a ray that ends before the plane (r < 0 at its
    # surface, r linear along it) gets exactly nothing; one that crosses it gets light.
    renderer, window, info, shafts, lights = kind_scene("directional", sphere=False,
                                                        sigma_a=ABSORPTION)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 8.0, 16.0)
    camera.SetFocalPoint(0.0, 7.5, 0.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    values, _, _ = cpp_reference(renderer, shafts)
    r_end = directional_plane_distance(renderer, window, info, lights[0])
    before = r_end < 0.0
    assert 0.1 * before.size < before.sum() < 0.9 * before.size
    assert np.all(values[before] == 0.0)
    assert np.all(values[r_end > 0.05].min(axis=-1) > 0.0)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8, lights=lights)
    assert max_relative(values, numpy_values) <= 1e-8


def test_directional_light_moved_back_dims_by_the_extinction_of_the_distance():
    # The eye beyond the plane: along a ray that ends on the floor r >= 0 throughout, so moving
    # P by D along -a (the lit interval unchanged) multiplies L by exp(-sigma_t D) per channel.
    renderer, window, info, shafts, lights = kind_scene("directional", sigma_a=ABSORPTION)
    light = lights[0]
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 3.0, 16.0)
    camera.SetFocalPoint(0.0, 2.5, 0.0)
    renderer.ResetCameraClippingRange()
    shafts.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    shafts.GetMedium().SetAnisotropy(-0.3)
    window.Render()
    base, _, _ = cpp_reference(renderer, shafts)
    _, on_floor = rh.surface_points(renderer, window, info)
    stays = on_floor.reshape(base.shape[:2]) & (base.max(axis=-1) > 0.0)
    assert stays.sum() > 0.2 * stays.size
    position = np.asarray(light.GetPosition(), float)
    axis = np.asarray(light.GetFocalPoint(), float) - position
    axis /= np.linalg.norm(axis)
    distance = 2.5
    light.SetPosition(*(position - distance * axis))
    light.SetFocalPoint(*(np.asarray(light.GetFocalPoint()) - distance * axis))
    moved, _, _ = cpp_reference(renderer, shafts)
    sigma_t = np.asarray(shafts.GetMedium().GetScatteringCoefficient()) + np.asarray(
        shafts.GetMedium().GetAbsorptionCoefficient())
    np.testing.assert_allclose(moved[stays], base[stays] * np.exp(-sigma_t * distance),
                               rtol=1e-10, atol=0.0)


@pytest.mark.parametrize("kind,sphere", [("directional", False), ("directional", True),
                                         ("point", False)])
def test_parallel_camera_against_numpy(kind, sphere):
    # Rays start on the plane through the camera's position and run along its view direction;
    # here obliquely through the light's shafts (not along a directional light).
    renderer, window, info, shafts, lights = kind_scene(kind, sphere=sphere, sigma_a=ABSORPTION)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(3.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    values, _, _ = cpp_reference(renderer, shafts)
    numpy_values = rh.reference_for(renderer, window, info, shafts, panels=8, lights=lights)
    assert rh.reference_camera(renderer, window).parallel
    if sphere:
        error, _ = ref.relative_rms_error(values, numpy_values)
        assert error < 2e-3
        assert ref.energy_error(values, numpy_values) < 5e-4
    else:
        assert max_relative(values, numpy_values) <= 1e-8


def test_several_lights_are_the_sum_of_each_alone():
    # A spot, a point light and a directional light, with the sphere's shadows: each light's
    # share is integrated on its own, so the sum is exact up to rounding.
    renderer, window, info, shafts, lights = kind_scene("pair", 64, 48, sigma_a=ABSORPTION)
    sun = scenes.add_directional_light(renderer, (2.0, 7.0, 1.0), (0.0, 0.0, 0.0),
                                       intensity=0.5, color=(0.9, 1.0, 0.8))
    lights.append(sun)
    shafts.AddLight(sun)
    window.Render()
    together, _, reference = cpp_reference(renderer, shafts)
    assert reference.GetLastNumberOfLights() == 3
    total = 0.0
    for light in lights:
        shafts.SetLight(light)
        alone, _, reference = cpp_reference(renderer, shafts)
        assert reference.GetLastNumberOfLights() == 1 and alone.max() > 0.0
        total = total + alone
    assert max_relative(together, total) <= 1e-12


def test_a_switched_off_light_contributes_nothing_to_the_reference():
    renderer, window, info, shafts, lights = kind_scene("pair", 80, 60)
    spot, point = lights
    shafts.SetLight(spot)
    spot_alone, _, _ = cpp_reference(renderer, shafts)
    shafts.AddLight(point)
    point.SwitchOff()
    values, _, reference = cpp_reference(renderer, shafts)
    assert reference.GetLastNumberOfLights() == 1
    np.testing.assert_array_equal(values, spot_alone)


def test_automatic_choice_takes_spot_and_point_lights_not_directional_ones():
    renderer, window, info, shafts, lights = kind_scene("pair", 80, 60, sphere=False)
    scenes.add_directional_light(renderer, (0.0, 8.0, 0.0), (0.3, 0.0, 0.2))
    scenes.add_fill_light(renderer)  # a headlight: directional
    shafts.RemoveAllLights()
    window.Render()
    automatic, _, reference = cpp_reference(renderer, shafts)
    assert reference.GetLastNumberOfLights() == 2
    for light in lights:
        shafts.AddLight(light)
    given, _, _ = cpp_reference(renderer, shafts)
    np.testing.assert_array_equal(automatic, given)


def test_shadow_map_visibility_of_a_directional_light():
    # The directional light's orthographic map, coarse (16^2; fitted to where the sphere and the
    # lit view volume overlap, so finer over the sphere than a spot's): the pass is further from
    # the exact reference than from the one using its own map (measured 3.7e-3 and 1.1e-4).
    renderer, window, info, shafts, lights = kind_scene("directional", 200, 150)
    shafts.SetNumberOfSlices(512)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    shafts.SetShadowMapSize(16)
    window.Render()
    assert shafts.GetLastFrame().GetShadowMapRendered()
    measured = rh.in_scatter(shafts)
    exact, _, _ = cpp_reference(renderer, shafts)
    same_map, _, reference = cpp_reference(renderer, shafts, VisibilityMode=1,
                                           VisibilitySamples=256)
    assert reference.GetVisibilityMode() == vtkLightShaftReference.SHADOW_MAP
    error_exact, _ = ref.relative_rms_error(measured, exact)
    error_same_map, _ = ref.relative_rms_error(measured, same_map)
    print(f"directional, 16^2 map: exact {error_exact:.2e}, same map {error_same_map:.2e}")
    assert error_exact > 0.002
    assert error_same_map < 0.1 * error_exact


@pytest.mark.parametrize("kind,message", [("point", "cube shadow map"),
                                          ("pair", "exactly one light")])
def test_shadow_map_visibility_refuses_point_lights_and_several(kind, message, messages,
                                                                 vtk_messages):
    renderer, window, info, shafts, lights = kind_scene(kind, 40, 30)
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == len(lights)
    reference = vtkLightShaftReference()
    log = messages(reference)
    reference.SetRenderer(renderer)
    reference.SetLightShaftPass(shafts)
    reference.SetVisibilityModeToShadowMap()
    vtk_messages.expect("vtkLightShaftReference.*returned failure for request")
    reference.Update()
    assert any(message in e for e in log.errors), log.errors


@pytest.mark.parametrize("kind", ["spot", "point", "directional"])
def test_exact_shadow_edges_equal_bisected_ones(kind):
    # Where only opaque surfaces shadow, the reference places each change of visibility along a
    # ray exactly (the ray clipped by the shadowing triangles' shadow volumes); with a
    # translucent surface in the scene it bisects them to 1e-12 of the interval. A translucent
    # triangle far out of the light and behind the view changes nothing else: the two must agree to
    # the bisection's precision, over the tessellated sphere's shared edges and the window
    # scene's wall. (Enough samples that neither misses a shadow thinner than their spacing:
    # at the default 32 a point light behind the window's bars is missed by both, in different
    # pixels, up to 6% of the peak.)
    for make in ("sphere", "window"):
        if make == "window":
            renderer, window, _, shafts = rh.window_scene(96, 54)
            renderer.SetPass(shafts)
            if kind != "spot":
                light = renderer.GetLights().GetItemAsObject(0)
                light.SetPositional(kind == "point")
                light.SetConeAngle(90.0 if kind == "point" else light.GetConeAngle())
                shafts.AddLight(light)  # the automatic choice leaves directional lights out
            window.Render()
        elif kind == "spot":
            renderer, window, _, shafts = scene(96, 72)
        else:
            renderer, window, _, shafts, _ = kind_scene(kind, 96, 72)
        exact, _, _ = cpp_reference(renderer, shafts, VisibilitySamples=512)
        assert exact.max() > 0.0
        # Behind the camera: it leaves the scene's far side, where rays that hit nothing end,
        # where it was.
        camera = renderer.GetActiveCamera()
        eye = np.asarray(camera.GetPosition())
        forward = np.asarray(camera.GetFocalPoint()) - eye
        far_away = rh.add_sphere(renderer, tuple(eye - 100.0 * forward / np.linalg.norm(forward)),
                                 1.0, (1.0, 1.0, 1.0), resolution=4)
        far_away.GetProperty().SetOpacity(0.5)
        bisected, _, _ = cpp_reference(renderer, shafts, VisibilitySamples=512)
        assert max_relative(exact, bisected) <= 1e-9, (make, kind)
