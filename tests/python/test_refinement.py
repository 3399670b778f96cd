"""Progressive refinement of a still view (SetProgressiveRefinement): each still frame is one
more estimate with its samples shifted, averaged into the picture; any change starts again.

Scene: scenes.sphere_and_floor at 160x120 with a 2048^2 shadow map, no blur; errors against the
float64 reference (exact surfaces and shadows; relative RMS over the pixels above 1% of its
peak). Bounds, with what was
measured on llvmpipe (`pytest -s` prints the figures):
- the first estimate is the picture without refinement, bit for bit;
- RAY_MARCH (4 steps), SLICES (8 jittered slabs) and EPIPOLAR (4 steps): the error never grows
  by more than 5% from 1 to 2, 4, 8, 16 and 32 estimates, and 32 estimates end below a quarter
  of one's (measured 4.63% -> 0.30%, 4.57% -> 0.30%, 4.42% -> 0.71%: EPIPOLAR keeps the error
  of its interpolation between samples);
- 16 estimates of 4 steps are within twice the error of one frame of 64 steps, 32 within 1.25
  times (measured 0.47% and 0.30% against 0.30%): the estimates also shift the shadow map's
  texel grid, which costs a little early and leaves less of the map's staircase late.
"""

import numpy as np
import pytest

import lightshafts
from lightshafts import parameter_owner, scenes, vtkLightShaftPass
import vtkmodules.vtkInteractionStyle  # noqa: F401  (the interactor's default style)
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkPropPicker
from vtkmodules.vtkRenderingUI import vtkGenericRenderWindowInteractor

import lightshaft_reference as ref
import render_helpers as rh
from vtk_output import ANALYTIC_IGNORES_SHADOWS, VTK_OUTPUT

WIDTH, HEIGHT = 160, 120
SAMPLED = {
    "ray-march": dict(Method=vtkLightShaftPass.RAY_MARCH, NumberOfSteps=4, InterleaveSize=1),
    "slices": dict(Method=vtkLightShaftPass.SLICES, NumberOfSlices=8, Jitter=True),
    "epipolar": dict(Method=vtkLightShaftPass.EPIPOLAR, NumberOfSteps=4),
}


def still_scene(width=WIDTH, height=HEIGHT, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer)
    shafts = rh.plain_slab_pass(shadow_map=2048)
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    shafts.SetLight(info.light)
    renderer.SetPass(shafts)
    return renderer, window, info, shafts


_references = {}


def reference(renderer, window, info, shafts):
    """The float64 reference (exact surfaces and shadows) for the scene as set up."""
    key = tuple(window.GetSize())
    if key not in _references:
        _references[key] = rh.reference_for(renderer, window, info, shafts)
    return _references[key]


def error(image, expected):
    assert np.all(np.isfinite(image))
    relative, pixels = ref.relative_rms_error(image, expected)
    assert pixels > 300
    return relative


def render(window, shafts):
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return rh.in_scatter(shafts)


# --- parameters -----------------------------------------------------------------------------

def test_defaults_ranges_and_read_outs_when_off():
    shafts = vtkLightShaftPass()
    assert not shafts.GetProgressiveRefinement()
    assert shafts.GetRefinementFrames() == 16
    shafts.SetRefinementFrames(0)
    assert shafts.GetRefinementFrames() == 1
    shafts.SetRefinementFrames(10 ** 6)
    assert shafts.GetRefinementFrames() == 4096
    renderer, window, info, shafts = still_scene()
    render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementEstimates() == 0
    assert not shafts.GetLastFrame().GetRefinementConverged()
    assert not shafts.GetLastFrame().GetInScatterReused()


# --- convergence ----------------------------------------------------------------------------

@pytest.mark.parametrize("method", SAMPLED)
def test_the_first_estimate_is_the_picture_without_refinement(method):
    renderer, window, info, shafts = still_scene(**SAMPLED[method])
    plain = render(window, shafts)
    shafts.ProgressiveRefinementOn()
    first = render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementEstimates() == 1
    assert "refine" not in shafts.GetLastFrame().GetShaderVariant()
    assert np.array_equal(first, plain)


@pytest.mark.parametrize("method", SAMPLED)
def test_the_estimates_converge_to_the_reference(method):
    renderer, window, info, shafts = still_scene(RefinementFrames=32, **SAMPLED[method])
    shafts.ProgressiveRefinementOn()
    errors = {}
    expected = None
    for estimates in range(1, 33):
        image = render(window, shafts)
        expected = reference(renderer, window, info, shafts) if expected is None else expected
        assert shafts.GetLastFrame().GetRefinementEstimates() == estimates
        if estimates in (1, 2, 4, 8, 16, 32):
            errors[estimates] = error(image, expected)
    print(method, {k: f"{100 * v:.3f}%" for k, v in errors.items()})
    counts = sorted(errors)
    for fewer, more in zip(counts, counts[1:]):
        assert errors[more] <= 1.05 * errors[fewer]
    assert errors[32] < errors[1] / 4
    assert shafts.GetLastFrame().GetRefinementConverged()
    assert "refine" in shafts.GetLastFrame().GetShaderVariant()


def test_estimates_of_four_steps_come_close_to_one_frame_of_sixty_four():
    renderer, window, info, shafts = still_scene(RefinementFrames=32, **SAMPLED["ray-march"])
    shafts.SetNumberOfSteps(64)
    one_frame = render(window, shafts)
    expected = reference(renderer, window, info, shafts)
    shafts.SetNumberOfSteps(4)
    shafts.ProgressiveRefinementOn()
    refined = {}
    for estimates in range(1, 33):
        image = render(window, shafts)
        if estimates in (16, 32):
            refined[estimates] = error(image, expected)
    one_frame = error(one_frame, expected)
    print(f"64 steps {100 * one_frame:.3f}%; 4 steps, 16 estimates {100 * refined[16]:.3f}%, "
          f"32 estimates {100 * refined[32]:.3f}%")
    assert refined[16] < 2.0 * one_frame
    assert refined[32] < 1.25 * one_frame


@pytest.mark.parametrize("kind", ["point", "directional", "pair"])
def test_every_light_kind_refines(kind):
    renderer, window, info, shafts = still_scene(RefinementFrames=16, **SAMPLED["ray-march"])
    lights = rh.make_light_kind(renderer, info, kind, (0.5, 3.5, 0.5))
    shafts.SetLight(lights[0])
    for light in lights[1:]:
        shafts.AddLight(light)
    renderer.ResetCameraClippingRange()
    baseline = render(window, shafts)
    shafts.SetNumberOfSteps(256)
    fine = render(window, shafts)
    shafts.SetNumberOfSteps(4)
    assert np.array_equal(render(window, shafts), baseline)
    frames = lightshafts.render_converged(window, shafts)
    refined = rh.in_scatter(shafts)
    assert frames == 16 and shafts.GetLastFrame().GetNumberOfUsedLights() == len(lights)
    before, _ = ref.relative_rms_error(baseline, fine)
    after, _ = ref.relative_rms_error(refined, fine)
    print(kind, f"{100 * before:.3f}% -> {100 * after:.3f}% against 256 steps")
    assert after < before / 3


# --- the filters of a refined picture ------------------------------------------------------

FILTERED = {
    "slices, blur 2": dict(Method=vtkLightShaftPass.SLICES, NumberOfSlices=32, Jitter=True,
                           BlurRadius=2),
    "ray-march, interleaved 2, blur 2": dict(Method=vtkLightShaftPass.RAY_MARCH,
                                             NumberOfSteps=16, InterleaveSize=2, BlurRadius=2),
}


def gaussian_weights(sigma, radius):
    return np.exp(-0.5 * np.arange(-radius, radius + 1) ** 2 / np.float32(sigma) ** 2)


def effective_samples(weights):
    return weights.sum() ** 2 / (weights ** 2).sum()


def picture_width(first_samples, estimates):
    """The Gaussian the refined picture of `estimates` is filtered by, found as the pass does:
    the one that averages first_samples * estimates^(-1/4) samples along an axis."""
    needed = first_samples / estimates ** 0.25
    if needed <= 1.01:
        return 0.0
    low, high = 0.25, 64.0
    while high - low > 1e-3 * high:
        mid = 0.5 * (low + high)
        samples = effective_samples(gaussian_weights(mid, max(1, int(np.ceil(2 * mid)))))
        low, high = (mid, high) if samples < needed else (low, mid)
    return high


@pytest.mark.parametrize("setting", FILTERED)
def test_later_estimates_leave_the_filters_to_the_picture(setting):
    # The first estimate is the filtered picture without refinement; the second is computed but
    # not shown; from the third the unfiltered estimates' average is filtered by a Gaussian
    # narrowing as n^(-1/4), so refinement goes below the filters' floor (their blur), and no
    # picture is worse than the first. Measured (160x120, 16 estimates): slices 32 with blur 2
    # 1.095% -> 0.483%, falling at every estimate after the second (each estimate blurred, as
    # before: 1.043%); ray-march 16, 2x2 interleaved, blur 2: 1.375% -> 0.641% (each estimate
    # filtered: 1.338%).
    params = FILTERED[setting]
    renderer, window, info, shafts = still_scene(RefinementFrames=16, **params)
    plain = render(window, shafts)
    shafts.ProgressiveRefinementOn()
    expected = reference(renderer, window, info, shafts)
    blur = gaussian_weights(max(0.5 * params["BlurRadius"], 0.5), params["BlurRadius"])
    first = blur
    if params.get("InterleaveSize", 1) > 1:
        first = np.convolve(np.array([0.5, 1.0, 0.5]), blur)
    first_samples = effective_samples(first)
    errors, widths, pictures = [], [], []
    for estimates in range(1, 17):
        pictures.append(render(window, shafts))
        frame = shafts.GetLastFrame()
        assert frame.GetRefinementEstimates() == estimates
        widths.append(frame.GetRefinementFilterWidth())
        errors.append(error(pictures[-1], expected))
    print(setting, " ".join(f"{100 * e:.3f}%" for e in errors),
          "widths", " ".join(f"{w:.2f}" for w in widths))
    assert np.array_equal(pictures[0], plain) and widths[0] == 0.0
    assert np.array_equal(pictures[1], pictures[0]) and widths[1] == 0.0
    for estimates, width in enumerate(widths[2:], start=3):
        assert width == pytest.approx(picture_width(first_samples, estimates), rel=2e-3)
    assert max(errors) <= errors[0]
    assert errors[-1] < 0.5 * errors[0]
    assert shafts.GetLastFrame().GetRefinementConverged()


def test_a_downsampled_picture_is_filtered_in_reduced_pixels():
    # The filter's width is in full-resolution pixels: a reduced pixel is DownsampleFactor wide.
    widths = {}
    for factor in (1, 2):
        renderer, window, info, shafts = still_scene(
            RefinementFrames=4, DownsampleFactor=factor, **FILTERED["slices, blur 2"])
        shafts.ProgressiveRefinementOn()
        for _ in range(3):
            render(window, shafts)
        widths[factor] = shafts.GetLastFrame().GetRefinementFilterWidth()
        assert np.all(np.isfinite(rh.in_scatter(shafts)))
    assert widths[1] > 0.0 and widths[2] == pytest.approx(2.0 * widths[1], rel=1e-9)


def test_a_refinement_of_two_estimates_shows_their_average():
    # RefinementFrames 2: the second estimate is the last, so the picture is their average.
    renderer, window, info, shafts = still_scene(RefinementFrames=2, **SAMPLED["ray-march"])
    shafts.ProgressiveRefinementOn()
    first = render(window, shafts)
    second = render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementConverged()
    assert not np.array_equal(first, second)


# --- a converged picture --------------------------------------------------------------------

def test_a_converged_picture_is_reused_and_does_not_change():
    renderer, window, info, shafts = still_scene(RefinementFrames=6, **SAMPLED["ray-march"])
    needed = []
    shafts.AddObserver(vtkLightShaftPass.RefinementNeededEvent, lambda *_: needed.append(1))
    assert lightshafts.render_converged(window, shafts) == 6
    assert len(needed) == 5  # after every frame but the converged one
    converged = rh.in_scatter(shafts)
    picture = rh.screenshot(window)
    for _ in range(3):
        assert np.array_equal(render(window, shafts), converged)
        assert np.array_equal(rh.screenshot(window), picture)
        assert shafts.GetLastFrame().GetInScatterReused() and shafts.GetLastFrame().GetRefinementConverged()
        assert shafts.GetLastFrame().GetRefinementEstimates() == 6
        assert shafts.GetLastFrame().GetNumberOfUsedLights() == 1
        assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.RAY_MARCH
    assert len(needed) == 5
    assert lightshafts.render_converged(window, shafts) == 1


def test_surfaces_shadowed_keep_their_light_computed_and_the_picture_stays():
    renderer, window, info, shafts = still_scene(RefinementFrames=3, **SAMPLED["ray-march"])
    shafts.ShadowSurfacesOn()
    lightshafts.render_converged(window, shafts)
    converged, picture = rh.in_scatter(shafts), rh.screenshot(window)
    render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementConverged() and not shafts.GetLastFrame().GetInScatterReused()
    assert np.array_equal(rh.in_scatter(shafts), converged)
    assert np.array_equal(rh.screenshot(window), picture)


# LIGHT_VOLUME has no samples to shift; its shadow map's grid alone would gain little (0.39% ->
# 0.36% in 32 estimates on the sphere scene at 320x240 with a 512^2 map).
@pytest.mark.parametrize("method", ["analytic", "light-volume", "radial-blur", "unjittered"])
def test_methods_with_nothing_to_shift_converge_at_once(method):
    VTK_OUTPUT.expect(ANALYTIC_IGNORES_SHADOWS)
    if method == "unjittered":
        params = dict(Method=vtkLightShaftPass.SLICES, Jitter=False)
    else:
        params = dict(Method=getattr(vtkLightShaftPass, method.upper().replace("-", "_")))
    renderer, window, info, shafts = still_scene(**params)
    plain = render(window, shafts)
    needed = []
    shafts.AddObserver(vtkLightShaftPass.RefinementNeededEvent, lambda *_: needed.append(1))
    assert lightshafts.render_converged(window, shafts) == 1
    assert shafts.GetLastFrame().GetRefinementEstimates() == 1 and not needed
    assert np.array_equal(rh.in_scatter(shafts), plain)
    render(window, shafts)
    assert shafts.GetLastFrame().GetInScatterReused()


# --- what starts a new picture --------------------------------------------------------------

def _move_actor(renderer, info, shafts, window):
    renderer.GetActors().GetLastActor().AddPosition(0.0, 0.01, 0.0)


def _sphere_data(renderer, info, shafts, window):
    actors = list(renderer.GetActors())
    sphere = [a for a in actors if a.GetMapper().GetInputAlgorithm().GetClassName()
              == "vtkSphereSource"][0]
    source = sphere.GetMapper().GetInputAlgorithm()
    source.SetThetaResolution(source.GetThetaResolution() + 1)


CHANGES = {
    "camera": lambda r, i, s, w: r.GetActiveCamera().Azimuth(0.01),
    "window size": lambda r, i, s, w: w.SetSize(WIDTH + 2, HEIGHT),
    "a parameter": lambda r, i, s, w: s.SetNumberOfSteps(5),
    "Time": lambda r, i, s, w: s.GetMedium().SetTime(0.5),
    "light intensity": lambda r, i, s, w: i.light.SetIntensity(0.9),
    "light position": lambda r, i, s, w: i.light.SetPosition(0.5, 6.01, 0.0),
    "a prop's transform": _move_actor,
    "a prop's data": _sphere_data,
    "a prop hidden": lambda r, i, s, w: r.GetActors().GetLastActor().VisibilityOff(),
    "a light added": lambda r, i, s, w: scenes.add_point_light(r, (1.0, 3.0, 1.0)),
}


@pytest.mark.parametrize("change", CHANGES)
def test_every_change_starts_a_new_picture(change):
    renderer, window, info, shafts = still_scene(RefinementFrames=4, **SAMPLED["ray-march"])
    shafts.SetLight(None)  # the renderer's spot and point lights: one more counts
    lightshafts.render_converged(window, shafts)
    assert shafts.GetLastFrame().GetRefinementConverged()
    CHANGES[change](renderer, info, shafts, window)
    image = render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementEstimates() == 1
    assert not shafts.GetLastFrame().GetInScatterReused() and not shafts.GetLastFrame().GetRefinementConverged()
    # The new first estimate is the new picture without refinement.
    shafts.ProgressiveRefinementOff()
    assert np.array_equal(render(window, shafts), image)


def test_setting_a_parameter_to_its_value_changes_nothing():
    renderer, window, info, shafts = still_scene(RefinementFrames=4, **SAMPLED["ray-march"])
    lightshafts.render_converged(window, shafts)
    shafts.SetNumberOfSteps(4)
    info.light.SetIntensity(info.light.GetIntensity())
    render(window, shafts)
    assert shafts.GetLastFrame().GetInScatterReused()


def test_picking_in_the_middle_of_refinement_picks_and_refinement_goes_on():
    renderer, window, info, shafts = still_scene(RefinementFrames=8, **SAMPLED["ray-march"])
    shafts.ProgressiveRefinementOn()
    for _ in range(3):
        render(window, shafts)
    picker = vtkPropPicker()
    assert picker.Pick(WIDTH // 2, HEIGHT // 2, 0.0, renderer)
    picked = picker.GetActor()
    assert picked is not None and picked.GetMapper().GetInputAlgorithm().GetClassName() in (
        "vtkSphereSource", "vtkPlaneSource")
    render(window, shafts)
    assert shafts.GetLastFrame().GetRefinementEstimates() == 4


def test_downsampled_and_multisampled_refinement():
    renderer, window, info, shafts = still_scene(DownsampleFactor=2, **SAMPLED["ray-march"])
    window.SetMultiSamples(4)
    try:
        frames = lightshafts.render_converged(window, shafts)
        assert frames == 16 and shafts.GetLastFrame().GetRefinementConverged()
        assert shafts.GetLastFrame().GetMultiSamples() in (0, 4)
        assert np.all(np.isfinite(rh.in_scatter(shafts)))
    finally:
        window.SetMultiSamples(0)


# --- the helpers ----------------------------------------------------------------------------

def test_refine_while_still_renders_from_timers_until_converged():
    renderer, window, info, shafts = still_scene(RefinementFrames=5, **SAMPLED["ray-march"])
    interactor = vtkGenericRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.Initialize()
    timers = []
    interactor.AddObserver(vtkCommand.CreateTimerEvent, lambda *_: timers.append(1))
    lightshafts.refine_while_still(interactor, shafts)
    window.Render()  # the application's render: one estimate, and a timer asked for
    for fired in range(1, 10):
        if len(timers) < fired:
            break
        interactor.InvokeEvent(vtkCommand.TimerEvent)  # the event loop fires the timer
    assert shafts.GetLastFrame().GetRefinementConverged()
    assert shafts.GetLastFrame().GetRefinementEstimates() == 5
    assert len(timers) == 4  # none once converged
