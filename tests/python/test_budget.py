"""The frame budget (SetTimeBudget, and the renderer's AllocatedRenderTime while an interactor
drags): the most accurate sampling the cost model predicts will fit, learnt from the frames.

No test asserts a duration (a busy machine would fail it): they check the choice against the
pass's own predictions, which budget applies when, and that a still view keeps its choice. The
measured frame times are printed (`pytest -s`) and measured in tests/benchmarks/budget.py.
"""

import statistics

import numpy as np
import pytest

import vtkmodules.vtkInteractionStyle  # noqa: F401  (the interactor's default style)
from lightshafts import parameter_owner, scenes, vtkLightShaftPass
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingUI import vtkGenericRenderWindowInteractor

import lightshaft_reference as ref
import render_helpers as rh

WIDTH, HEIGHT = 200, 150


def budget_scene(**params):
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    renderer.SetPass(shafts)
    return renderer, window, info, shafts


def setting_name(shafts):
    return vtkLightShaftPass.GetErrorModelSettingName(shafts.GetLastFrame().GetErrorModelSetting())


def test_defaults_and_no_budget_without_an_interaction():
    shafts = vtkLightShaftPass()
    assert shafts.GetTimeBudget() == 0.0 and shafts.GetUseAllocatedRenderTime()
    renderer, window, info, shafts = budget_scene()
    window.Render()  # VTK allocates 10000 s to a renderer at rest: no budget
    assert renderer.GetAllocatedRenderTime() >= 10.0
    assert shafts.GetLastFrame().GetTimeBudget() == 0.0
    assert shafts.GetLastFrame().GetPredictedFrameTime() == -1.0 and shafts.GetLastFrame().GetFrameTime() == -1.0
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.SLICES  # the parameters set
    assert shafts.GetLastFrame().GetDownsampleFactor() == 1


def test_which_budget_applies():
    renderer, window, info, shafts = budget_scene()
    try:
        window.SetDesiredUpdateRate(15.0)  # what an interactor sets while the user drags
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(1.0 / 15.0)
        shafts.SetTimeBudget(0.02)
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(0.02)  # the smaller
        shafts.SetTimeBudget(0.5)
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(1.0 / 15.0)
        shafts.UseAllocatedRenderTimeOff()
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(0.5)
        shafts.SetTimeBudget(0.0)
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == 0.0
        assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.SLICES
    finally:
        window.SetDesiredUpdateRate(0.0001)


def test_a_budget_nothing_fits_gets_the_cheapest_at_quarter_resolution():
    renderer, window, info, shafts = budget_scene(TimeBudget=1e-9)
    window.Render()
    assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(1e-9)
    assert shafts.GetLastFrame().GetDownsampleFactor() == 4
    assert shafts.GetLastFrame().GetPredictedFrameTime() > 1e-9
    assert shafts.GetLastFrame().GetFrameTime() > 0.0  # measured
    assert shafts.GetLastFrame().GetPredictedError() == -1.0  # the model knows full resolution only
    assert np.all(np.isfinite(rh.in_scatter(shafts)))


def test_an_ample_budget_gets_the_most_accurate_setting_at_full_resolution():
    renderer, window, info, shafts = budget_scene()
    predicted = {}
    for preset in ("Draft", "Interactive", "Final"):
        getattr(shafts, "SetQualityTo" + preset)()
        window.Render()
        predicted[preset] = shafts.GetLastFrame().GetPredictedError()
    shafts.SetTimeBudget(3600.0)
    window.Render()
    assert shafts.GetLastFrame().GetDownsampleFactor() == 1
    assert shafts.GetLastFrame().GetPredictedFrameTime() <= 3600.0
    assert 0.0 < shafts.GetLastFrame().GetPredictedError() <= min(predicted.values())


def test_a_target_error_under_a_budget_takes_the_cheapest_setting_that_meets_it():
    renderer, window, info, shafts = budget_scene(TimeBudget=3600.0)
    window.Render()
    most_accurate = shafts.GetLastFrame().GetPredictedError()
    shafts.SetTargetError(0.05)
    window.Render()
    assert most_accurate <= shafts.GetLastFrame().GetPredictedError() <= 0.05
    assert shafts.GetLastFrame().GetDownsampleFactor() == 1


def test_a_still_view_keeps_its_choice_and_refines():
    renderer, window, info, shafts = budget_scene(TimeBudget=0.05, RefinementFrames=4)
    shafts.SetCookie(rh.uniform_cookie())  # no LIGHT_VOLUME (nothing to refine): a sampled one
    shafts.ProgressiveRefinementOn()
    renderer.GetActiveCamera().Azimuth(1.0)
    window.Render()
    chosen = (setting_name(shafts), shafts.GetLastFrame().GetDownsampleFactor())
    for estimates in range(2, 5):
        window.Render()  # nothing changed: the same choice, one more estimate
        assert (setting_name(shafts), shafts.GetLastFrame().GetDownsampleFactor()) == chosen
        assert shafts.GetLastFrame().GetRefinementEstimates() == estimates
    assert shafts.GetLastFrame().GetRefinementConverged()


def test_the_predictions_follow_the_budget_along_an_interactive_camera_path():
    """An interactor rotates the camera (VTK's trackball style: DesiredUpdateRate 15 while the
    button is down); each frame's predicted time fits the budget once the model has measured
    a frame, and the view at rest has no budget."""
    renderer, window, info, shafts = budget_scene()
    window.SetSize(320, 240)
    interactor = vtkGenericRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    interactor.Initialize()
    interactor.Enable()
    budgets, predicted, measured, names = [], [], [], []

    def record(*_):
        budgets.append(shafts.GetLastFrame().GetTimeBudget())
        predicted.append(shafts.GetLastFrame().GetPredictedFrameTime())
        measured.append(shafts.GetLastFrame().GetFrameTime())
        names.append((setting_name(shafts), shafts.GetLastFrame().GetDownsampleFactor()))

    window.AddObserver(vtkCommand.EndEvent, record)
    try:
        interactor.SetEventInformation(160, 120)
        interactor.InvokeEvent(vtkCommand.LeftButtonPressEvent)
        for step in range(1, 25):
            interactor.SetEventInformation(160 + 4 * step, 120 + step)
            interactor.InvokeEvent(vtkCommand.MouseMoveEvent)
        interactor.InvokeEvent(vtkCommand.LeftButtonReleaseEvent)
    finally:
        window.SetDesiredUpdateRate(0.0001)
    moving = [i for i, b in enumerate(budgets) if b > 0.0]
    assert len(moving) >= 20
    assert all(b == pytest.approx(1.0 / 15.0) for b in (budgets[i] for i in moving))
    assert budgets[-1] == 0.0  # released: the still render has no budget
    # After the first measured frame, every choice is predicted to fit (or is the cheapest).
    for i in moving[1:]:
        assert predicted[i] <= budgets[i] or names[i][1] == 4, (i, names[i], predicted[i])
    times = [measured[i] for i in moving[2:]]
    print(f"budget {1000 / 15:.0f} ms: measured median {1000 * statistics.median(times):.0f} ms,"
          f" max {1000 * max(times):.0f} ms; choices {sorted(set(names[i] for i in moving))}")


def test_a_new_budget_for_a_still_view_chooses_again():
    renderer, window, info, shafts = budget_scene(TimeBudget=3600.0)
    window.Render()
    ample = (setting_name(shafts), shafts.GetLastFrame().GetDownsampleFactor())
    assert ample[1] == 1
    shafts.SetTimeBudget(1e-9)  # the same view, a budget nothing fits
    window.Render()
    assert shafts.GetLastFrame().GetDownsampleFactor() == 4
    assert (setting_name(shafts), shafts.GetLastFrame().GetDownsampleFactor()) != ample
    try:
        shafts.SetTimeBudget(0.0)
        window.SetDesiredUpdateRate(5.0)  # an interactor's rate: a budget of 0.2 s
        window.Render()
        first = shafts.GetLastFrame().GetTimeBudget()
        window.SetDesiredUpdateRate(1e6)  # the view still, a new rate: a new choice
        window.Render()
        assert shafts.GetLastFrame().GetTimeBudget() == pytest.approx(1e-6)
        assert first != shafts.GetLastFrame().GetTimeBudget()
        assert shafts.GetLastFrame().GetDownsampleFactor() == 4
    finally:
        window.SetDesiredUpdateRate(0.0001)


CHEAPEST = dict(Method=vtkLightShaftPass.EPIPOLAR, NumberOfSteps=16, Jitter=False, BlurRadius=0,
                DownsampleFactor=1, ShadowMapSize=512, InterleaveSize=1, EpipolarLines=128,
                EpipolarSamples=256, EpipolarStep=8)  # the ladder's "E16 l128 s256 k8 m512"


def move_under_rate(renderer, window, shafts, rate, frames=4):
    """The camera turned `frames` times while an interactor's rate holds; then the rate back to
    rest. Returns the last moving frame's (setting, factor, predicted error, in-scatter)."""
    try:
        window.SetDesiredUpdateRate(rate)
        for _ in range(frames):
            renderer.GetActiveCamera().Azimuth(0.5)
            window.Render()
    finally:
        window.SetDesiredUpdateRate(0.0001)
    frame = shafts.GetLastFrame()
    return (setting_name(shafts), frame.GetDownsampleFactor(), frame.GetPredictedError(),
            rh.in_scatter(shafts))


@pytest.mark.parametrize("refine", [False, True], ids=["plain", "refined"])
def test_a_still_view_is_never_worse_than_the_moving_frames(refine):
    # The still setting is the ladder's cheapest; a generous budget chose better while moving.
    # When the camera stops, the still view keeps the budget's setting (the model predicts it
    # better): its picture is the moving frame's accuracy, not the cheap setting's.
    renderer, window, info, shafts = budget_scene(**CHEAPEST)
    shafts.SetProgressiveRefinement(refine)
    name, factor, predicted, moving = move_under_rate(renderer, window, shafts, rate=0.5)
    assert factor == 1 and name != "E16 l128 s256 k8 m512" and predicted > 0.0
    window.Render()  # the camera stopped
    frame = shafts.GetLastFrame()
    assert frame.GetTimeBudget() == 0.0
    assert (setting_name(shafts), frame.GetDownsampleFactor()) == (name, 1)
    assert frame.GetPredictedError() == predicted
    exact = rh.scene_reference(renderer, shafts)
    still_error = ref.relative_rms_error(rh.in_scatter(shafts), exact)[0]
    moving_error = ref.relative_rms_error(moving, exact)[0]
    assert still_error <= moving_error * 1.0001
    # The cheap setting itself, on the same view, is worse: keeping the choice mattered.
    cheap = vtkLightShaftPass()
    cheap.GetMedium().SetScatteringCoefficient(0.05)
    for key, value in CHEAPEST.items():
        getattr(parameter_owner(cheap, key), "Set" + key)(value)
    renderer.SetPass(cheap)
    window.Render()
    assert ref.relative_rms_error(rh.in_scatter(cheap), exact)[0] > 1.2 * still_error


def test_a_still_view_takes_its_own_setting_where_the_model_cannot_compare():
    # Moving under a budget nothing fits (quarter resolution: the model predicts nothing), the
    # still view gets the setting asked for, as it would without a budget.
    renderer, window, info, shafts = budget_scene(**CHEAPEST)
    shafts.SetNumberOfSteps(256)
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)
    shafts.SetShadowMapSize(2048)  # the ladder's "M256 i1 m2048"
    name, factor, _, _ = move_under_rate(renderer, window, shafts, rate=1e6)
    assert factor == 4
    window.Render()
    assert setting_name(shafts) == "M256 i1 m2048"
    assert shafts.GetLastFrame().GetDownsampleFactor() == 1


FINAL_STEPS = 256  # the Final preset's ray march ("M256 i1 m2048")


def final_after_moving(rate, refinement_frames=2):
    """The sphere scene at the Final preset, refined while still, after frames under `rate`
    (an interactor's DesiredUpdateRate) and one still frame."""
    renderer, window, info, shafts = budget_scene(RefinementFrames=refinement_frames)
    shafts.SetQualityToFinal()
    shafts.ProgressiveRefinementOn()
    moving = move_under_rate(renderer, window, shafts, rate)
    window.Render()  # the camera stopped
    return renderer, window, shafts, moving


def test_a_still_setting_that_overruns_the_budget_is_split_among_estimates():
    # Moving under a budget nothing fits (a microsecond), the still Final frame would overrun
    # it: each estimate marches a power-of-two share of its steps, the fewest predicted to fit
    # and 16 steps a share at least (here: none fits, so 16 estimates a Final frame, each
    # marching every 16th of its 256 steps). The picture shown is the moving one, bit for bit,
    # until they add up to one Final frame.
    renderer, window, shafts, (_, factor, _, moving) = final_after_moving(rate=1e6)
    assert factor == 4
    split = FINAL_STEPS // 16
    for estimates in range(1, split):
        frame = shafts.GetLastFrame()
        assert (frame.GetRefinementSplit(), frame.GetNumberOfSteps()) == (split, FINAL_STEPS)
        assert setting_name(shafts) == "M256 i1 m2048"
        assert frame.GetRefinementEstimates() == estimates and frame.GetRefinementHeld()
        assert frame.GetPredictedError() == -1.0  # the moving picture's: at 1/4, unknown
        np.testing.assert_array_equal(rh.in_scatter(shafts), moving)
        window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetRefinementEstimates() == split and not frame.GetRefinementHeld()
    assert frame.GetPredictedError() > 0.0 and not frame.GetRefinementConverged()
    split_picture = rh.in_scatter(shafts)
    exact = rh.scene_reference(renderer, shafts)
    split_error = ref.relative_rms_error(split_picture, exact)[0]
    # The split estimates sample as one Final frame does.
    whole = vtkLightShaftPass()
    whole.GetMedium().SetScatteringCoefficient(0.05)
    whole.SetQualityToFinal()
    renderer.SetPass(whole)
    window.Render()
    whole_error = ref.relative_rms_error(rh.in_scatter(whole), exact)[0]
    print(f"split into {split}: {100 * split_error:.3f}%, one Final frame: "
          f"{100 * whole_error:.3f}%")
    assert split_error <= 1.1 * whole_error
    # Refinement goes on to RefinementFrames (2) Final frames' worth, showing the first one's
    # picture until the second is complete (a partial group looks up only part of each piece).
    renderer.SetPass(shafts)
    for estimates in range(split + 1, 2 * split):
        window.Render()
        frame = shafts.GetLastFrame()
        assert frame.GetRefinementEstimates() == estimates and frame.GetRefinementHeld()
        assert not frame.GetRefinementConverged()
        np.testing.assert_array_equal(rh.in_scatter(shafts), split_picture)
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetRefinementEstimates() == 2 * split and frame.GetRefinementConverged()
    assert not frame.GetRefinementHeld()
    assert ref.relative_rms_error(rh.in_scatter(shafts), exact)[0] < split_error


def test_a_still_setting_within_the_budget_is_not_split():
    # A budget of seconds: the moving frames ran Final themselves, and so does the still view.
    renderer, window, shafts, (name, factor, _, _) = final_after_moving(rate=0.2)
    assert (name, factor) == ("M256 i1 m2048", 1)
    frame = shafts.GetLastFrame()
    assert (frame.GetRefinementSplit(), frame.GetNumberOfSteps()) == (1, FINAL_STEPS)
    assert not frame.GetRefinementHeld()


def test_without_frames_under_a_budget_nothing_is_split():
    renderer, window, info, shafts = budget_scene(RefinementFrames=2)
    shafts.SetQualityToFinal()
    shafts.ProgressiveRefinementOn()
    for _ in range(2):
        window.Render()
        frame = shafts.GetLastFrame()
        assert (frame.GetRefinementSplit(), frame.GetNumberOfSteps()) == (1, FINAL_STEPS)
        assert not frame.GetRefinementHeld()


@pytest.mark.parametrize("change", ["camera", "time", "light", "off"])
def test_any_change_ends_a_split_still_view_and_its_held_picture(change):
    renderer, window, shafts, _ = final_after_moving(rate=1e6)
    window.Render()
    assert shafts.GetLastFrame().GetRefinementHeld()
    if change == "camera":
        renderer.GetActiveCamera().Azimuth(1.0)
    elif change == "time":
        parameter_owner(shafts, "Time").SetTime(1.0)
    elif change == "light":
        renderer.GetLights().GetItemAsObject(0).SetIntensity(0.5)
    else:
        shafts.ProgressiveRefinementOff()
    window.Render()
    frame = shafts.GetLastFrame()
    # No budget now: the setting asked for, whole, its own picture.
    assert (frame.GetRefinementSplit(), frame.GetNumberOfSteps()) == (1, FINAL_STEPS)
    assert not frame.GetRefinementHeld()
    assert frame.GetRefinementEstimates() == (0 if change == "off" else 1)


def test_behind_a_translucent_surface_in_view_nothing_is_split():
    # The camera leg through a pane is each piece's mean by length: split into longer pieces it
    # stays coarse whatever the estimates (measured: 0.24% from the reference where one Final
    # frame is 0.09%), so the still view keeps whole Final frames.
    from test_camera_leg import add_pane
    renderer, window, info, shafts = budget_scene(RefinementFrames=1)
    add_pane(renderer, 2.0, (0.2, 0.2, 0.2), 0.5, x_range=(-20.0, 0.5))
    shafts.SetQualityToFinal()
    shafts.ProgressiveRefinementOn()
    move_under_rate(renderer, window, shafts, rate=1e6)
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetCameraTranslucentLayers() == 1
    assert (frame.GetRefinementSplit(), frame.GetNumberOfSteps()) == (1, FINAL_STEPS)
    assert not frame.GetRefinementHeld()
