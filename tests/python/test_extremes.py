"""Numerical stability at the extremes: every case renders finite values with no GL error, and
agrees with the float64 reference within the bound stated per case (or degrades as documented).

Every case runs for every method (the `method` fixture). SLICES, RAY_MARCH and EPIPOLAR (256
slices or steps, no jitter/interleave/blur; EPIPOLAR's default lines and samples) and
LIGHT_VOLUME (1024 cells) share the bounds; ANALYTIC is compared with the unshadowed
reference (what it computes), at the same bounds; RADIAL_BLUR's screen-space shadows are
approximate, so its bound is RADIAL_BLUR_BOUND against the shadowed reference, and the case is
also required to stay finite and GL-error free.
"""

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import lightshaft_reference as ref
import render_helpers as rh
from vtk_output import ANALYTIC_IGNORES_SHADOWS, VTK_OUTPUT

# A sweep (conftest.py): numerical stability at the extremes: the shaders' arithmetic, which no VTK
# version changes (the GL limits: LightShaftContexts, on every release).
pytestmark = pytest.mark.sweep


METHODS = ["slices", "ray-march", "radial-blur", "analytic", "epipolar", "light-volume"]
# RADIAL_BLUR measures 6% on the test scene's default view (docs/methods.md); at the extremes (eye in
# the beam, light behind the camera, pencil cones) its screen-space shadows are worse.
RADIAL_BLUR_BOUND = 0.3
_method = "slices"


@pytest.fixture(params=METHODS, autouse=True)
def method(request):
    global _method
    _method = request.param
    # ANALYTIC says once that it ignores the scene's shadows: documented, expected here.
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)
    yield request.param
    _method = "slices"


def use_method(shafts, method=None):
    """Switch a pass set up for plain slabs to `method` with comparable settings."""
    method = method or _method
    if method == "ray-march":
        shafts.SetMethodToRayMarch()
        shafts.SetNumberOfSteps(shafts.GetNumberOfSlices())
        shafts.SetInterleaveSize(1)
    elif method == "radial-blur":
        shafts.SetMethodToRadialBlur()
    elif method == "analytic":
        shafts.SetMethodToAnalytic()
    elif method == "epipolar":
        shafts.SetMethodToEpipolar()
        shafts.SetNumberOfSteps(shafts.GetNumberOfSlices())
    elif method == "light-volume":
        shafts.SetMethodToLightVolume()
        shafts.SetLightVolumeResolution(1024)


def bound(value):
    """The case's stated bound for the current method."""
    return max(value, RADIAL_BLUR_BOUND) if _method == "radial-blur" else value


def render(width=160, height=120, prepare=None, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
    shafts = rh.plain_slab_pass(**params)
    use_method(shafts)
    if prepare:
        prepare(renderer, info, shafts)
        renderer.ResetCameraClippingRange()
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    image = rh.in_scatter(shafts)
    assert np.all(np.isfinite(image)), "non-finite in-scatter"
    assert np.all(image >= 0.0)
    pixels = rh.screenshot(window)
    return renderer, window, info, shafts, image, pixels


def error_against_reference(renderer, window, info, shafts, image, threshold=0.01, lights=None):
    reference = rh.reference_for(renderer, window, info, shafts,
                                 shadows=_method != "analytic", lights=lights)
    assert np.all(np.isfinite(reference))
    if reference.max() == 0.0:
        return 0.0 if image.max() == 0.0 else np.inf
    error = ref.relative_rms_error(image, reference, threshold)[0]
    return error


def move_camera(position, focal_point, view_up=(0.0, 1.0, 0.0)):
    def prepare(renderer, info, shafts):
        camera = renderer.GetActiveCamera()
        camera.SetPosition(*position)
        camera.SetFocalPoint(*focal_point)
        camera.SetViewUp(*view_up)
    return prepare


@pytest.mark.parametrize("offset", [1e-4, 1e-2])
def test_eye_next_to_the_light(offset):
    # The eye sits at the apex: every ray starts inside (or at the tip of) the cone.
    light = np.array([0.5, 6.0, 0.0])
    args = render(prepare=move_camera(light + [offset, 0.0, 0.0], (0.0, 0.0, 0.3)))
    assert error_against_reference(*args[:5]) < bound(0.02)


@pytest.mark.parametrize("direction", ["into", "away"])
def test_view_along_the_cone_axis(direction):
    light = np.array([0.5, 6.0, 0.0])
    axis = -light / np.linalg.norm(light)
    if direction == "into":  # inside the cone, between the sphere and the light, facing the light
        eye = light + 3.5 * axis
        focal = light
    else:  # from behind the light, looking along the beam
        eye = light - 2.0 * axis
        focal = light + axis
    args = render(prepare=move_camera(eye + [0.0, 0.0, 1e-3], focal, (0.0, 0.0, 1.0)))
    assert error_against_reference(*args[:5]) < bound(0.02)


def test_light_far_behind_the_camera():
    def prepare(renderer, info, shafts):
        info.light.SetPosition(0.0, 3.5, 60.0)  # behind the camera (at z = 12), off-screen
        info.light.SetFocalPoint(0.0, 1.5, 0.0)
        info.light.SetConeAngle(4.0)
    args = render(prepare=prepare)
    assert args[4].max() > 0.0
    assert error_against_reference(*args[:5]) < bound(0.02)


@pytest.mark.parametrize("angle", [0.5, 89.0])
def test_extreme_cone_angles(angle):
    def prepare(renderer, info, shafts):
        info.light.SetConeAngle(angle)
    args = render(prepare=prepare)
    renderer, window, info, shafts, image, _ = args
    if angle < 1.0:
        # A 0.5 degree cone is a pencil about 5 cm wide at the floor: a few pixels; the
        # comparison is over those pixels. EPIPOLAR interpolates each pixel from samples at
        # their exact places on lines under a pixel apart, and across a 2-3 pixel pencil the
        # in-scatter changes by its whole value within a pixel: measured 6.1% (the same with
        # every sample marched), bound 8%.
        assert image.max() > 0.0
        assert error_against_reference(*args[:5]) < bound(0.08 if _method == "epipolar" else 0.05)
    else:
        # 89 degrees: the shadow-map frustum is 178 degrees wide, so a texel covers a large
        # solid angle near the edge of the cone; the error stays bounded.
        assert error_against_reference(*args[:5]) < bound(0.05)


@pytest.mark.parametrize("sigma", [0.0, 1e-6, 1.0, 1e3])
def test_extinction_from_none_to_opaque(sigma):
    args = render(ScatteringCoefficient=sigma, AbsorptionCoefficient=0.0)
    renderer, window, info, shafts, image, pixels = args
    if sigma == 0.0:
        assert image.max() == 0.0
    elif sigma >= 1e3:
        # Optical depth ~1e4 along every ray: transmittance underflows to 0 in float; black
        # shafts and a black (fully fogged) scene, no NaN.
        assert image.max() < 1e-30
        assert pixels.max() == 0
    else:
        assert error_against_reference(*args[:5]) < bound(0.02)


@pytest.mark.parametrize("intensity", [1e-6, 1e6])
def test_extreme_intensities(intensity):
    def prepare(renderer, info, shafts):
        info.light.SetIntensity(intensity)
    args = render(prepare=prepare)
    assert error_against_reference(*args[:5]) < bound(0.01)


@pytest.mark.parametrize("slices", [1, 4096])
def test_one_slice_and_the_maximum(method, slices):
    if method not in ("slices", "ray-march", "epipolar"):
        pytest.skip("slices / steps are SLICES, RAY_MARCH and EPIPOLAR parameters")
    args = render(NumberOfSlices=slices)
    renderer, window, info, shafts, image, _ = args
    # RAY_MARCH and EPIPOLAR: one slab over the lit range, `slices` steps per pixel or sample.
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == (slices if method == "slices" else 1)
    error = error_against_reference(*args[:5])
    # One slab: the whole lit depth range in one product-rule segment per pixel (a documented
    # degradation: about 30% RMS, the energy within 10%); 4096: converged.
    assert error < (0.35 if slices == 1 else 0.01)
    if slices == 1:
        assert ref.energy_error(image, rh.reference_for(renderer, window, info, shafts)) < 0.1


@pytest.mark.parametrize("size", [64, 16384])
def test_smallest_and_largest_shadow_map(method, size):
    if method not in ("slices", "ray-march", "epipolar", "light-volume"):
        pytest.skip("only SLICES, RAY_MARCH, EPIPOLAR and LIGHT_VOLUME use a shadow map")
    args = render(ShadowMapSize=size)
    renderer, window, info, shafts, image, _ = args
    error = error_against_reference(*args[:5])
    # 64 texels: the sphere's shadow edges are blocky (a documented degradation); the maximum is
    # limited to the GL implementation's largest texture.
    assert error < (0.15 if size == 64 else 0.01)


def test_far_to_near_ratio_of_a_million():
    renderer, window = rh.make_window(160, 120)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=128)
    camera = renderer.GetActiveCamera()
    far = camera.GetClippingRange()[1] * 2.0
    camera.SetClippingRange(far * 1e-6, far)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetNumberOfSlices(256)
    use_method(shafts)
    renderer.SetPass(shafts)
    window.Render()
    near_used, far_used = camera.GetClippingRange()
    assert far_used / near_used > 0.99e6
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    image = rh.in_scatter(shafts)
    assert np.all(np.isfinite(image))
    # 24-bit-like depth at near = 1e-6 far resolves the floor and sphere only coarsely; the
    # pass reconstructs surface distances from that depth buffer, the reference is exact.
    assert error_against_reference(renderer, window, info, shafts, image) < bound(0.05)


@pytest.mark.parametrize("size", [(1, 1), (4096, 4096)])
def test_tiny_and_huge_windows(size):
    renderer, window = rh.make_window(*size)
    scenes.sphere_and_floor(renderer, sphere_resolution=64)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetNumberOfSlices(32)
    use_method(shafts)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert tuple(shafts.GetLastFrame().GetViewportSize()) == size
    image = rh.in_scatter(shafts)
    assert image.shape == (size[1], size[0], 3)
    assert np.all(np.isfinite(image))
    window.SetSize(160, 120)  # leave the shared window small


def test_occluder_touching_the_light():
    def prepare(renderer, info, shafts):
        # A plate just under the light, touching it, covering one side of the cone.
        plate = vtkPlaneSource()
        plate.SetOrigin(0.5, 6.0, -1.0)
        plate.SetPoint1(2.0, 6.0, -1.0)
        plate.SetPoint2(0.5, 6.0, 1.0)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(plate.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    renderer, window, info, shafts, image, _ = render(prepare=prepare)
    assert shafts.GetLastFrame().GetShadowMapRendered() == (
        _method in ("slices", "ray-march", "epipolar", "light-volume"))
    assert image.max() > 0.0


def test_degenerate_scene():
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    renderer, window = rh.make_window(160, 120)
    # Zero-area geometry: a triangle collapsed to a line, and the light.
    points = vtkPoints()
    for x in (0.0, 1.0, 2.0):
        points.InsertNextPoint(x, 0.0, 0.0)
    triangles = vtkCellArray()
    triangles.InsertNextCell(3, (0, 1, 2))
    plate = vtkPolyData()
    plate.SetPoints(points)
    plate.SetPolys(triangles)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(plate)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    scenes.add_spotlight(renderer, (0.5, 6.0, 0.0), (0.0, 0.0, 0.0))
    renderer.ResetCamera()
    shafts = vtkLightShaftPass()
    use_method(shafts)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    assert np.all(np.isfinite(rh.in_scatter(shafts)))


# --- point and directional lights, several lights -----------------------------------------

def point_light(position, attenuation=(1.0, 0.0, 0.05)):
    """prepare(): sphere_and_floor's spotlight becomes a point light at `position`."""
    def prepare(renderer, info, shafts):
        info.light.SetConeAngle(180.0)
        info.light.SetPosition(*position)
        info.light.SetAttenuationValues(*attenuation)
    return prepare


def directional_light(position, focal_point):
    """prepare(): sphere_and_floor's spotlight becomes a directional light, given to the pass
    (directional lights scatter only when given)."""
    def prepare(renderer, info, shafts):
        shafts.SetLight(info.light)
        info.light.SetPositional(False)
        info.light.SetPosition(*position)
        info.light.SetFocalPoint(*focal_point)
    return prepare


def then(*prepares):
    def prepare(renderer, info, shafts):
        for step in prepares:
            step(renderer, info, shafts)
    return prepare


@pytest.mark.parametrize("case", ["eye next to it", "inside the sphere", "far away",
                                  "largest shadow map"])
def test_point_light_extremes(method, case):
    params = {}
    if case == "eye next to it":
        light = (0.4, 3.4, 0.3)
        prepare = then(point_light(light), move_camera((0.4 + 1e-3, 3.4, 0.3), (0.0, 0.0, 0.0)))
    elif case == "inside the sphere":  # every direction blocked a radius 0.8 away
        prepare = point_light((0.0, 1.5, 0.0))
    elif case == "far away":  # 1000 units up: nearly parallel light, 1/r^2 = 1e-6
        prepare = point_light((0.3, 1000.0, 0.2), attenuation=(0.0, 0.0, 1.0))
    else:
        if method not in ("slices", "ray-march", "epipolar", "light-volume"):
            pytest.skip("only SLICES, RAY_MARCH, EPIPOLAR and LIGHT_VOLUME use a shadow map")
        prepare = point_light((0.4, 3.4, 0.3))
        params["ShadowMapSize"] = 16384  # faces limited to a third of the largest texture
    args = render(prepare=prepare, **params)
    renderer, window, info, shafts, image, _ = args
    assert shafts.GetLastFrame().GetLightKind(0) == vtkLightShaftPass.POINT_LIGHT
    if case == "inside the sphere" and method != "analytic":
        # Only the inside of the sphere is lit; the camera sees its outside: nothing, but for the
        # shell the shadow bias lets through where rays graze the sphere (a few texels thick).
        unshadowed = rh.reference_for(renderer, window, info, shafts, shadows=False).max()
        print(f"{method}: leak {image.max() / unshadowed:.2e} of the unshadowed peak")
        # Measured: SLICES 1.1%, RAY_MARCH 0.93% (RADIAL_BLUR has no shadow map: 59%);
        # EPIPOLAR 3.9% (2.7% with 512 samples per line; 400 here, two per pixel of the
        # diagonal): its samples lie anywhere on their lines, some nearer the silhouette (where
        # the grazing rays leak most) than any pixel centre, and the pixels beside them take
        # their value.
        leak_bound = 0.06 if _method == "epipolar" else 0.02
        assert image.max() < bound(leak_bound) * unshadowed or _method == "radial-blur"
        return
    assert error_against_reference(*args[:5]) < bound(0.03)


@pytest.mark.parametrize("case", ["eye on its plane", "grazing", "along the view",
                                  "tiny focal distance"])
def test_directional_light_extremes(method, case):
    if case == "eye on its plane":  # the camera on the plane the light starts from
        prepare = then(directional_light((0.0, 4.0, 12.0), (0.0, 0.0, 12.0)),
                       move_camera((0.0, 4.0, 12.0), (0.0, 2.0, 0.0)))
    elif case == "grazing":  # 0.6 degrees above the floor's plane
        prepare = directional_light((-10.0, 1.6, 0.0), (10.0, 1.4, 0.0))
    elif case == "along the view":  # light travelling towards the camera, from behind the scene
        prepare = directional_light((0.0, 2.0, -20.0), (0.0, 2.0, 0.0))
    else:  # focal point 1e-4 from the position: only the direction matters
        prepare = directional_light((0.5, 6.0, 0.0), (0.5, 6.0 - 1e-4, 0.0))
    args = render(prepare=prepare)
    shafts = args[3]
    assert shafts.GetLastFrame().GetLightKind(0) == vtkLightShaftPass.DIRECTIONAL_LIGHT
    assert error_against_reference(*args[:5]) < bound(0.03)


def test_eight_lights_at_once(method):
    colours = [(1, 0.2, 0.2), (0.2, 1, 0.2), (0.2, 0.2, 1), (1, 1, 0.2)]

    def prepare(renderer, info, shafts):
        for k, colour in enumerate(colours):
            angle = 2.0 * np.pi * k / len(colours)
            x, z = 4.0 * np.cos(angle), 4.0 * np.sin(angle)
            scenes.add_spotlight(renderer, (x, 5.0, z), (0.0, 0.5, 0.0), cone_angle=15.0,
                                 color=colour, intensity=0.5)
            scenes.add_point_light(renderer, (0.5 * x, 3.2, 0.5 * z), intensity=0.1,
                                   color=colour, attenuation=(1.0, 0.0, 0.2))
        info.light.SwitchOff()
    args = render(prepare=prepare, ShadowMapSize=1024)
    renderer, window, info, shafts, image, _ = args
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 8
    lights = [shafts.GetLastFrame().GetUsedLight(i) for i in range(8)]
    assert error_against_reference(*args[:5], lights=lights) < bound(0.03)
