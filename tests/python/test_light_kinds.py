"""Every kind of VTK light, and several at once: which lights scatter, what each kind lights,
several lights adding up, the shadow maps kept between frames, every method with every kind,
and the surfaces shadowed by the same maps.

Scenes: scenes.sphere_and_floor with its spotlight turned into a point or a directional light
(or joined by others), plain slabs (no jitter or blur) unless a test says otherwise.
"""

import numpy as np
import pytest

from lightshafts import parameter_owner, scenes, vtkLightShaftPass
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

import render_helpers as rh
from vtk_output import ANALYTIC_IGNORES_SHADOWS, VTK_OUTPUT

SPOT, POINT, DIRECTIONAL = (vtkLightShaftPass.SPOT_LIGHT, vtkLightShaftPass.POINT_LIGHT,
                            vtkLightShaftPass.DIRECTIONAL_LIGHT)
KIND_NAMES = {SPOT: "spot", POINT: "point", DIRECTIONAL: "directional"}
METHODS = {"slices": vtkLightShaftPass.SLICES, "ray-march": vtkLightShaftPass.RAY_MARCH,
           "radial-blur": vtkLightShaftPass.RADIAL_BLUR, "analytic": vtkLightShaftPass.ANALYTIC,
           "epipolar": vtkLightShaftPass.EPIPOLAR, "light-volume": vtkLightShaftPass.LIGHT_VOLUME}


def make_kind(light, kind):
    """Turn sphere_and_floor's spotlight (at (0.5, 6, 0), aiming at the origin) into `kind`."""
    if kind == POINT:
        light.SetConeAngle(180.0)
        light.SetPosition(0.4, 3.4, 0.3)  # below the top of the view: the whole sphere of
        light.SetAttenuationValues(1.0, 0.0, 0.05)  # directions is in use
    elif kind == DIRECTIONAL:
        light.SetPositional(False)  # the plane through (0.5, 6, 0), light travelling down
    return light


def kind_scene(kind, width=200, height=150, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    make_kind(info.light, kind)
    shafts = rh.plain_slab_pass(slices=128, **params)
    shafts.SetLight(info.light)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return renderer, window, info, shafts


# --- which lights scatter -------------------------------------------------------------------

def test_automatic_choice_takes_spot_and_point_lights_not_directional_ones():
    renderer, window = rh.make_window(120, 90)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=32)
    point = scenes.add_point_light(renderer, (2.0, 3.0, 1.0), color=(0.2, 0.4, 1.0))
    sun = scenes.add_directional_light(renderer, (0.0, 8.0, 0.0), (0.3, 0.0, 0.2))
    scenes.add_fill_light(renderer)  # a headlight: directional
    shafts = vtkLightShaftPass()
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    assert shafts.GetLastFrame().GetUsedLight(0) is info.light and shafts.GetLastFrame().GetUsedLight(1) is point
    assert [shafts.GetLastFrame().GetLightKind(i) for i in range(2)] == [SPOT, POINT]
    assert shafts.GetLastFrame().GetUsedLight(2) is None and shafts.GetLastFrame().GetLightKind(2) == -1
    # Given lights: any kind, in the order given; duplicates ignored.
    shafts.SetLight(sun)
    shafts.AddLight(point)
    shafts.AddLight(point)
    assert shafts.GetNumberOfLights() == 2 and shafts.GetLight() is sun
    assert shafts.GetLight(1) is point and shafts.GetLight(2) is None
    window.Render()
    assert [shafts.GetLastFrame().GetLightKind(i) for i in range(2)] == [DIRECTIONAL, POINT]
    shafts.RemoveLight(sun)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 1 and shafts.GetLastFrame().GetUsedLight() is point
    shafts.RemoveAllLights()
    assert shafts.GetNumberOfLights() == 0 and shafts.GetLight() is None
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    shafts.SetLight(sun)
    shafts.SetLight(None)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2


def test_modified_time_follows_the_light_list():
    shafts = vtkLightShaftPass()
    light = scenes.add_point_light(rh.make_window(8, 8)[0], (0.0, 1.0, 0.0))
    for change in (lambda: shafts.AddLight(light), lambda: shafts.RemoveLight(light),
                   lambda: shafts.SetLight(light), lambda: shafts.RemoveAllLights()):
        before = shafts.GetMTime()
        change()
        assert shafts.GetMTime() > before
    before = shafts.GetMTime()
    shafts.RemoveLight(light)  # not given: nothing changes
    shafts.RemoveAllLights()
    assert shafts.GetMTime() == before


# --- several lights ---------------------------------------------------------------------------

def two_light_scene(method, **params):
    renderer, window = rh.make_window(200, 150)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    info.light.SetColor(1.0, 0.6, 0.3)
    point = scenes.add_point_light(renderer, (-1.5, 3.2, 1.0), intensity=0.8,
                                   color=(0.3, 0.6, 1.0), attenuation=(1.0, 0.0, 0.1))
    shafts = rh.plain_slab_pass(slices=96, Method=method, **params)
    renderer.SetPass(shafts)
    window.Render()
    return renderer, window, info, point, shafts


@pytest.mark.parametrize("method", list(METHODS))
def test_several_lights_add_up_to_the_sum_of_each_alone(method):
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)
    renderer, window, info, point, shafts = two_light_scene(METHODS[method])
    both = rh.in_scatter(shafts)
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    alone = []
    for light in (info.light, point):
        shafts.SetLight(light)
        window.Render()
        assert shafts.GetLastFrame().GetNumberOfUsedLights() == 1
        alone.append(rh.in_scatter(shafts))
    total = alone[0] + alone[1]
    assert alone[0].max() > 0.0 and alone[1].max() > 0.0
    # Colours: the spot is orange, the point light blue: neither hides in the other.
    assert alone[0][..., 0].sum() > 1.5 * alone[0][..., 2].sum()
    assert alone[1][..., 2].sum() > 1.5 * alone[1][..., 0].sum()
    relative = np.sqrt(np.sum((both - total) ** 2) / np.sum(total ** 2))
    print(f"{method}: two lights against the sum of each alone: {relative:.2e}")
    assert relative <= 5e-3


def test_several_lights_with_jitter_blur_and_downsampling_add_up():
    renderer, window, info, point, shafts = two_light_scene(
        vtkLightShaftPass.SLICES, Jitter=True, BlurRadius=2, DownsampleFactor=2)
    both = rh.in_scatter(shafts)
    total = 0.0
    for light in (info.light, point):
        shafts.SetLight(light)
        window.Render()
        total = total + rh.in_scatter(shafts)
    relative = np.sqrt(np.sum((both - total) ** 2) / np.sum(total ** 2))
    assert relative <= 5e-3


def test_mixed_methods_per_light_add_up():
    # AUTOMATIC: SLICES for the spot the sphere shadows, ANALYTIC for a second spot aiming up,
    # where nothing can shadow it; then 8-bit SLICES and interleaved RAY_MARCH, which add
    # through a sum: every combination must add up.
    renderer, window = rh.make_window(200, 150)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=64)
    up = scenes.add_spotlight(renderer, (-1.5, 3.2, 1.0), (-1.5, 10.0, 1.0), cone_angle=20.0,
                              color=(0.3, 0.6, 1.0))
    shafts = rh.plain_slab_pass(slices=96, Method=vtkLightShaftPass.AUTOMATIC)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetLightMethod(0) == vtkLightShaftPass.SLICES
    assert shafts.GetLastFrame().GetLightMethod(1) == vtkLightShaftPass.ANALYTIC
    for settings in ({}, {"AccumulationPrecision": vtkLightShaftPass.ACCUMULATE_8BIT,
                          "Exposure": 40.0},
                     {"Method": vtkLightShaftPass.RAY_MARCH, "InterleaveSize": 2,
                      "NumberOfSteps": 96}):
        for name, value in settings.items():
            getattr(parameter_owner(shafts, name), "Set" + name)(value)
        shafts.RemoveAllLights()
        window.Render()
        mixed = rh.in_scatter(shafts)
        total = 0.0
        for light in (info.light, up):
            shafts.SetLight(light)
            window.Render()
            assert rh.in_scatter(shafts).max() > 0.0
            total = total + rh.in_scatter(shafts)
        relative = np.sqrt(np.sum((mixed - total) ** 2) / np.sum(total ** 2))
        print(f"{settings}: two lights against the sum of each alone: {relative:.2e}")
        assert relative <= 5e-3, settings


def test_a_switched_off_light_contributes_nothing():
    renderer, window, info, point, shafts = two_light_scene(vtkLightShaftPass.SLICES)
    shafts.SetLight(info.light)
    window.Render()
    spot_alone = rh.in_scatter(shafts)
    shafts.AddLight(point)
    point.SwitchOff()
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 1
    np.testing.assert_array_equal(rh.in_scatter(shafts), spot_alone)
    # Switched on with zero intensity: used, but adds nothing.
    point.SwitchOn()
    point.SetIntensity(0.0)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    assert shafts.GetLastFrame().GetLightMethod(1) == -1
    np.testing.assert_allclose(rh.in_scatter(shafts), spot_alone, rtol=1e-6, atol=0.0)


# --- directional lights -------------------------------------------------------------------------

def directional_closed_form(renderer, window, info, shafts, light):
    """L_in of an unshadowed directional light in a homogeneous medium, per pixel, in closed
    form: along x = o + t d, r(t) = r_o + t k (k = d . a), and the integrand
    sigma_s p(-k) I exp(-sigma_t (r + t)) is integrated exactly over the part where r >= 0 in
    front of the surface (isotropic phase)."""
    camera = rh.reference_camera(renderer, window)
    eye, dirs, forward = rh.ref.camera_rays(camera)
    d = dirs.reshape(-1, 3)
    hit, _ = rh.surface_points(renderer, window, info)
    t_surface = np.linalg.norm(hit - eye, axis=1)
    position = np.asarray(light.GetPosition(), float)
    a = np.asarray(light.GetFocalPoint(), float) - position
    a /= np.linalg.norm(a)
    k = d @ a
    r_o = (eye - position) @ a
    with np.errstate(divide="ignore", invalid="ignore"):
        t_plane = np.where(k != 0.0, -r_o / k, np.inf)
    t0 = np.where(k > 0.0, np.maximum(t_plane, 0.0), 0.0)
    t1 = np.where(k < 0.0, np.minimum(t_plane, t_surface), t_surface)
    t0 = np.where((k == 0.0) & (r_o < 0.0), t1, t0)
    sigma_s = np.asarray(shafts.GetMedium().GetScatteringCoefficient())
    sigma_t = sigma_s + np.asarray(shafts.GetMedium().GetAbsorptionCoefficient())
    intensity = light.GetIntensity() * np.asarray(light.GetDiffuseColor())
    rate = sigma_t[None, :] * (1.0 + k[:, None])
    span = np.maximum(t1 - t0, 0.0)[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        integral = np.where(rate > 1e-12,
                            np.exp(-sigma_t * r_o - rate * t0[:, None])
                            * -np.expm1(-rate * span) / rate,
                            np.exp(-sigma_t * r_o) * span)
    radiance = sigma_s * intensity / (4.0 * np.pi) * integral
    w, h = window.GetSize()
    return radiance.reshape(h, w, 3)


def relative_rms(image, reference):
    return rh.ref.relative_rms_error(image, reference)[0]


def test_directional_light_lights_the_half_space_beyond_its_plane():
    # No sphere: nothing shadows, the closed form is exact. The camera above the plane (y = 6
    # at the light, tilted 5 degrees), looking level: the rays going up stay before the plane
    # and get nothing, those going down cross it.
    renderer, window, info, shafts = kind_scene(DIRECTIONAL, AbsorptionCoefficient=(0.02,) * 3)
    renderer.RemoveActor(info.actors[0])
    info.spheres = []
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 8.0, 16.0)
    camera.SetFocalPoint(0.0, 7.5, 0.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    assert shafts.GetLastFrame().GetLightKind(0) == DIRECTIONAL
    measured = rh.in_scatter(shafts)
    expected = directional_closed_form(renderer, window, info, shafts, info.light)
    error = relative_rms(measured, expected)
    print(f"directional, unshadowed, against the closed form: {error:.2e}")
    assert error < 2e-3
    before = expected.max(axis=-1) == 0.0
    assert 3000 < before.sum() < 0.9 * before.size
    assert measured[before].max() == 0.0
    # Camera below the plane: moving the plane up by D multiplies the radiance of the rays
    # that stay below the old plane (those ending on the floor) by exp(-sigma_t D): the depth of
    # medium the light crosses is explicit.
    camera.SetPosition(0.0, 3.0, 16.0)
    camera.SetFocalPoint(0.0, 2.5, 0.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    measured = rh.in_scatter(shafts)
    expected = directional_closed_form(renderer, window, info, shafts, info.light)
    assert relative_rms(measured, expected) < 2e-3
    sigma_t = np.asarray(shafts.GetMedium().GetScatteringCoefficient()) + np.asarray(
        shafts.GetMedium().GetAbsorptionCoefficient())
    _, on_floor = rh.surface_points(renderer, window, info)
    below = on_floor.reshape(measured.shape[:2]) & (expected.mean(axis=-1) > 0.0)
    assert below.sum() > 1000
    info.light.SetPosition(0.5, 9.0, 0.0)
    info.light.SetFocalPoint(0.0, 3.0, 0.0)
    window.Render()
    raised = rh.in_scatter(shafts)
    distance = 3.0 * 6.0 / np.sqrt(0.25 + 36.0)  # the plane's shift along its unit normal
    np.testing.assert_allclose(raised[below], measured[below] * np.exp(-sigma_t * distance),
                               rtol=2e-4)


def test_parallel_camera_looking_along_a_directional_light():
    # Every view ray runs along the light: its shadow lies exactly behind each surface, so the
    # unshadowed closed form (with the surfaces stopping the rays) is exact, a test of the
    # orthographic map at the sphere's silhouette.
    renderer, window, info, shafts = kind_scene(DIRECTIONAL, width=160, height=160,
                                                ShadowMapSize=2048)
    light = info.light
    light.SetPosition(0.0, 7.0, 0.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetPosition(0.0, 8.0, 0.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(0.0, 0.0, -1.0)
    camera.SetParallelScale(2.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    assert shafts.GetLastFrame().GetShadowMapRendered()
    measured = rh.in_scatter(shafts)
    parallel = rh.reference_camera(renderer, window)
    eye = np.asarray(camera.GetPosition())
    w, h = window.GetSize()
    # Rays straight down from the camera plane: x, z across the view, hitting sphere or floor.
    xs = (2.0 * (np.arange(w) + 0.5) / w - 1.0) * 2.0
    zs = -(2.0 * (np.arange(h) + 0.5) / h - 1.0) * 2.0
    x, z = np.meshgrid(xs, zs)
    (centre, radius), = info.spheres
    rho2 = (x - centre[0]) ** 2 + (z - centre[2]) ** 2
    top = np.where(rho2 <= radius ** 2, centre[1] + np.sqrt(np.maximum(radius ** 2 - rho2, 0)),
                   0.0)
    sigma_s = np.asarray(shafts.GetMedium().GetScatteringCoefficient())
    sigma_t = sigma_s + np.asarray(shafts.GetMedium().GetAbsorptionCoefficient())
    # r = 7 - y, t = 8 - y: integrand exp(-sigma_t (15 - 2 y)) over y from the surface to 7.
    y0, y1 = top[..., None], 7.0
    integral = (np.exp(-sigma_t * (15.0 - 2.0 * y1)) - np.exp(-sigma_t * (15.0 - 2.0 * y0))) / (
        2.0 * sigma_t)
    expected = sigma_s / (4.0 * np.pi) * integral
    assert parallel.width == w
    error = relative_rms(measured, expected)
    print(f"parallel camera along the light: {error:.2e}")
    assert error < 5e-3
    # No acne or spurious shadow next to the silhouette: the ring just outside the sphere gets
    # its full radiance.
    ring = (rho2 > (radius * 1.05) ** 2) & (rho2 < (radius * 1.3) ** 2)
    np.testing.assert_allclose(measured[ring], expected[ring], rtol=5e-3)


# --- point lights ------------------------------------------------------------------------------

def rotate_about(point, angle, vectors):
    """Rotate `vectors` (points, as (n, 3)) by `angle` degrees about the z axis through `point`."""
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    rotation = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return (np.asarray(vectors, float) - point) @ rotation.T + point


def test_point_light_shafts_show_no_cube_face_seam():
    # The point light's map is a cube of six world-aligned faces. Here the sphere, seen from the
    # light, straddles the seam between the +X and -Y faces (direction (1.3, -1.5, 0), 4 degrees
    # from the seam's 45). Turning the whole scene (props, light and camera) 41 degrees about
    # the light's z axis changes nothing physical, but puts the shadow in the middle of the -Y
    # face: the two pictures must agree, seam or not.
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)

    def render(angle, method=vtkLightShaftPass.RAY_MARCH):
        # A march per pixel up to its surface: the same samples on a surface's ray whatever
        # the scene's depth (SLICES spread their slabs over it, and the rotated props' axis-
        # aligned bounds, so the scene's far side, differ).
        renderer, window, info, shafts = kind_scene(POINT, width=240, height=180,
                                                    ShadowMapSize=2048, Method=method,
                                                    NumberOfSteps=128, InterleaveSize=1)
        light = info.light
        centre = np.array([-1.3, 3.0, 0.0])
        light.SetPosition(*centre)
        light.SetAttenuationValues(1.0, 0.0, 0.0)
        for actor in info.actors:
            actor.SetOrigin(*centre)
            actor.RotateZ(angle)
        camera = renderer.GetActiveCamera()
        position, focal = rotate_about(centre, angle, [camera.GetPosition(),
                                                       camera.GetFocalPoint()])
        up = rotate_about(np.zeros(3), angle, [camera.GetViewUp()])[0]
        camera.SetPosition(*position)
        camera.SetFocalPoint(*focal)
        camera.SetViewUp(*up)
        camera.SetClippingRange(0.1, 30.0)
        window.Render()
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkCommonCore import vtkFloatArray
        zbuffer = vtkFloatArray()
        window.GetZbufferData(0, 0, 239, 179, zbuffer)
        depth = vtk_to_numpy(zbuffer).reshape(180, 240)
        return rh.in_scatter(shafts), depth < 1.0

    seam, on_surfaces = render(0.0)
    centred, _ = render(41.0)
    unshadowed, _ = render(0.0, vtkLightShaftPass.ANALYTIC)
    shadowed = seam.mean(axis=-1) < 0.9 * unshadowed.mean(axis=-1)
    assert shadowed.sum() > 2000  # the sphere's shadow crosses the view
    # Over the rays that end on a surface: those that hit nothing end at the scene's far side,
    # the deepest corner of its axis-aligned bounds, which the rotation moves.
    assert on_surfaces.sum() > 0.3 * on_surfaces.size
    assert (shadowed & on_surfaces).sum() > 2000
    error = relative_rms(seam[on_surfaces], centred[on_surfaces])
    print(f"point light, shadow across a face seam against mid-face: {error:.2e}")
    assert error < 2e-3


# --- shadow maps kept between frames ------------------------------------------------------------

@pytest.mark.parametrize("kind", [SPOT, POINT, DIRECTIONAL])
def test_shadow_map_is_kept_while_nothing_changes(kind):
    renderer, window, info, shafts = kind_scene(kind)
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    first = rh.in_scatter(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0) and not shafts.GetLastFrame().GetLightShadowMapRendered(0)
    np.testing.assert_array_equal(rh.in_scatter(shafts), first)
    # A caster moves: rendered again, and the shafts follow.
    sphere = info.actors[0]
    sphere.SetPosition(0.3, 0.0, 0.0)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    assert not np.array_equal(rh.in_scatter(shafts), first)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0)
    # The caster's data changes (its source, not the actor): rendered again.
    sphere.GetMapper().GetInputAlgorithm().SetRadius(0.7)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    # The light moves; the map's size changes: rendered again.
    position = np.asarray(info.light.GetPosition())
    info.light.SetPosition(*(position + [0.1, 0.0, 0.0]))
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    shafts.SetShadowMapSize(512)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0)
    # The camera moves: spot and point maps do not depend on it.
    camera = renderer.GetActiveCamera()
    camera.Azimuth(5.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    if kind != DIRECTIONAL:
        assert shafts.GetLastFrame().GetLightShadowMapReused(0)
    # Someone observes the map (distributed processes combine theirs): rendered every frame.
    shafts.AddObserver(vtkLightShaftPass.ShadowMapRenderedEvent, lambda *args: None)
    for _ in range(2):
        window.Render()
        assert shafts.GetLastFrame().GetLightShadowMapRendered(0)


def test_each_light_keeps_its_own_map():
    renderer, window, info, point, shafts = two_light_scene(vtkLightShaftPass.SLICES)
    assert shafts.GetLastFrame().GetLightShadowMapRendered(0) and shafts.GetLastFrame().GetLightShadowMapRendered(1)
    point.SetPosition(-1.4, 3.2, 1.0)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0) and shafts.GetLastFrame().GetLightShadowMapRendered(1)
    window.Render()
    assert shafts.GetLastFrame().GetLightShadowMapReused(0) and shafts.GetLastFrame().GetLightShadowMapReused(1)


# --- every method with every kind --------------------------------------------------------------

@pytest.mark.parametrize("kind", [SPOT, POINT, DIRECTIONAL])
@pytest.mark.parametrize("method", list(METHODS))
def test_every_method_supports_every_kind(kind, method):
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)
    renderer, window, info, shafts = kind_scene(kind, Method=METHODS[method])
    image = rh.in_scatter(shafts)
    assert shafts.GetLastFrame().GetLightMethod(0) == METHODS[method]
    assert shafts.GetLastFrame().GetLightSlicesDrawn(0) >= 1
    assert np.all(np.isfinite(image)) and image.max() > 0.0
    assert f"light={KIND_NAMES[kind]}" in shafts.GetLastFrame().GetShaderVariant()
    assert f"method={method}" in shafts.GetLastFrame().GetShaderVariant()
    # The methods agree with each other (their accuracy against the reference is tested in
    # test_light_kind_accuracy.py): the unshadowed ones with slices everywhere the sphere
    # does not shadow, and the total within the shadow's share.
    shafts.SetMethod(vtkLightShaftPass.SLICES)
    window.Render()
    slices = rh.in_scatter(shafts)
    tolerance = {"slices": 1e-6, "ray-march": 0.05, "radial-blur": 0.5, "analytic": 0.5,
                 "epipolar": 0.05, "light-volume": 0.05}[method]
    assert abs(image.sum() - slices.sum()) <= tolerance * slices.sum()


# --- surfaces shadowed by the same maps ----------------------------------------------------------

@pytest.mark.parametrize("kind", [SPOT, POINT, DIRECTIONAL])
@pytest.mark.parametrize("delegate", ["default", "user"])
def test_floor_shadow_matches_the_analytic_shadow(kind, delegate):
    renderer, window = rh.make_window(320, 240)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
    make_kind(info.light, kind)
    if kind == POINT:
        info.light.SetAttenuationValues(1.0, 0.0, 0.0)
    shafts = vtkLightShaftPass()
    shafts.SetLight(info.light)
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(0.0)  # the surfaces alone
    shafts.AttenuateSceneOff()
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()
    if delegate == "user":
        shafts.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 2  # with and without the light
    pixels = rh.screenshot(window).max(axis=-1)
    lit, dark = rh.floor_shadow_masks(renderer, window, info)
    assert lit.sum() > 1000 and dark.sum() > 200
    # Dark exactly where the sphere shadows the floor from this light, lit elsewhere (no acne).
    print(f"{KIND_NAMES[kind]}, {delegate} delegate: dark {np.mean(pixels[dark] < 8):.4f}, "
          f"lit {np.mean(pixels[lit] > 40):.4f}")
    assert np.mean(pixels[dark] < 8) > 0.99
    assert np.mean(pixels[lit] > 40) > 0.99
    # Off: VTK's lighting, no shadow.
    shafts.ShadowSurfacesOff()
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 1
    assert np.mean(rh.screenshot(window).max(axis=-1)[dark] > 40) > 0.99


def test_surfaces_shadowed_for_each_of_several_lights():
    # Two lights, each with its own shadow of the sphere on the floor: where one light is
    # shadowed the floor keeps the other's light.
    renderer, window = rh.make_window(320, 240)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
    point = scenes.add_point_light(renderer, (-1.6, 3.0, 0.5))
    shafts = vtkLightShaftPass()
    shafts.SetExposure(0.0)
    shafts.AttenuateSceneOff()
    shafts.AttenuateSurfaceLightOff()  # VTK's light but for the shadows (compared below)
    shafts.SetShadowMapSize(2048)
    shafts.ShadowSurfacesOn()
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSceneRenders() == 3
    both = rh.screenshot(window).astype(float).max(axis=-1)
    spot_lit, spot_dark = rh.floor_shadow_masks(renderer, window, info)
    point_info = scenes.SceneInfo(light=point, spheres=info.spheres, floors=info.floors)
    point_lit, point_dark = rh.floor_shadow_masks(renderer, window, point_info)
    only_spot_dark = spot_dark & point_lit
    only_point_dark = point_dark & spot_lit
    neither = spot_lit & point_lit
    assert only_spot_dark.sum() > 100 and only_point_dark.sum() > 100
    # Each light alone, VTK's lighting without shadows, for the expected levels.
    shafts.ShadowSurfacesOff()
    levels = {}
    for light in (info.light, point):
        other = point if light is info.light else info.light
        other.SwitchOff()
        window.Render()
        levels[light] = rh.screenshot(window).astype(float).max(axis=-1)
        other.SwitchOn()
    # In one light's shadow the floor shows the other light only (8-bit rounding aside).
    assert np.median(np.abs(both[only_spot_dark] - levels[point][only_spot_dark])) <= 2.0
    assert np.median(np.abs(both[only_point_dark] - levels[info.light][only_point_dark])) <= 2.0
    assert both[neither].mean() > both[only_spot_dark].mean()
