"""vtkLightShaftReference, the C++ float64 reference: against the independent numpy reference,
its closed forms against its quadrature, known limits and scalings, and the pass against it."""

import time

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass, vtkLightShaftReference
from vtkmodules.util.numpy_support import vtk_to_numpy

import lightshaft_reference as ref
import render_helpers as rh


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
    shafts.SetScatteringCoefficient(*medium.get("sigma_s", (0.05, 0.04, 0.03)))
    shafts.SetAbsorptionCoefficient(*medium.get("sigma_a", (0.02, 0.01, 0.03)))
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
    shafts.SetScatteringCoefficient(0.0)
    zero, _, _ = cpp_reference(renderer, shafts)
    assert np.all(zero == 0.0)


def test_the_pass_against_the_cpp_reference_and_its_speed():
    renderer, window, info, shafts = scene(640, 480)
    shafts.SetNumberOfSlices(512)
    shafts.SetShadowMapSize(2048)
    window.Render()
    start = time.time()
    values, errors, _ = cpp_reference(renderer, shafts)
    seconds = time.time() - start
    assert seconds < 60.0, f"640x480 reference took {seconds:.1f} s"
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
    shafts.SetNoiseAmplitude(1.0)
    shafts.SetNoiseScale(1.5)
    shafts.SetTime(4.0)
    window.Render()
    # Noise makes every ray's integrand wiggle: a looser tolerance keeps the reference quick.
    values, _, _ = cpp_reference(renderer, shafts, RelativeTolerance=1e-5)
    error, _ = ref.relative_rms_error(rh.in_scatter(shafts), values)
    assert error < 0.05


def test_shadow_map_visibility_separates_shadow_map_error():
    # A coarse shadow map (16^2): the pass is far from the exact reference near the sphere's
    # shadow (3.3% measured), close to the reference that uses its own shadow map (0.08%: the
    # integration error, the same as with a 2048^2 map).
    renderer, window, info, shafts = scene(200, 150)
    shafts.SetNumberOfSlices(512)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    shafts.SetShadowMapSize(16)
    window.Render()
    assert shafts.GetLastShadowMapRendered()
    measured = rh.in_scatter(shafts)
    exact, _, _ = cpp_reference(renderer, shafts)
    same_map, _, reference = cpp_reference(renderer, shafts, VisibilityMode=1,
                                           VisibilitySamples=256)
    assert reference.GetVisibilityMode() == vtkLightShaftReference.SHADOW_MAP
    error_exact, _ = ref.relative_rms_error(measured, exact)
    error_same_map, _ = ref.relative_rms_error(measured, same_map)
    assert error_exact > 0.02
    assert error_same_map < 0.1 * error_exact
    assert error_same_map < 0.005


def test_shadow_map_visibility_needs_a_shadow_map(messages, vtk_messages):
    renderer, window, info, shafts = scene(40, 30)
    shafts.SetScatteringCoefficient(0.0)  # nothing scatters: no shadow map is rendered
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
