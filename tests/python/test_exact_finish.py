"""The exact finish of a still view (SetExactFinish with SetProgressiveRefinement): worker
threads integrate the float64 reference tile by tile; each frame shows the finished tiles in
place of the estimate, and the picture ends at the reference.

Scene: scenes.window_room at 160x120 (the README's window, σ_s 0.05), Interactive preset.
- once complete, the in-scatter is the reference's to float32 rounding (relative 1e-6 of the
  peak), the report says COMPLETE, fraction 1, predicted error 0, converged;
- a finished still view renders the same picture again, bit for bit;
- while it runs, refinement goes on and the finished tiles replace its estimates; the first
  still frame after frames under a budget shows their picture again (no long frame);
- any change (camera, medium, light, a prop, the viewport's size) stops it and starts again from
  the new view's estimate;
- a scene the reference cannot model (an actor drawn as wireframe) is refined as without it,
  the report saying why; the pass deleted or released while workers run neither hangs nor leaks.
"""

import time

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftFrameReport, vtkLightShaftPass

import lightshaft_reference as ref
import render_helpers as rh
from vtk_output import VTK_OUTPUT  # noqa: F401  (fails a test on any VTK message)

WIDTH, HEIGHT = 160, 120
COMPLETE = vtkLightShaftFrameReport.EXACT_FINISH_COMPLETE
RUNNING = vtkLightShaftFrameReport.EXACT_FINISH_RUNNING
OFF = vtkLightShaftFrameReport.EXACT_FINISH_OFF
UNSUPPORTED = vtkLightShaftFrameReport.EXACT_FINISH_UNSUPPORTED


def finishing_scene(width=WIDTH, height=HEIGHT):
    renderer, window = rh.make_window(width, height)
    info = scenes.window_room(renderer)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(40.0)
    shafts.SetQualityToInteractive()
    shafts.ProgressiveRefinementOn()
    shafts.ExactFinishOn()
    renderer.SetPass(shafts)
    return renderer, window, shafts, info


def render_until_complete(window, shafts, seconds=120.0):
    start = time.monotonic()
    frames = 0
    while time.monotonic() - start < seconds:
        window.Render()
        frames += 1
        frame = shafts.GetLastFrame()
        if frame.GetExactFinishState() != RUNNING and frames > 1:
            return frame
        time.sleep(0.02)
    raise AssertionError("the exact finish did not complete in %s s" % seconds)


def test_complete_picture_is_the_reference_and_stays():
    renderer, window, shafts, _ = finishing_scene()
    window.Render()
    estimate = rh.in_scatter(shafts)
    window.Render()  # the same view: the finish starts
    frame = shafts.GetLastFrame()
    assert frame.GetExactFinishState() in (RUNNING, COMPLETE)
    assert frame.GetInScatterReused()
    frame = render_until_complete(window, shafts)
    assert frame.GetExactFinishState() == COMPLETE
    assert frame.GetExactFinishFraction() == 1.0
    assert frame.GetRefinementConverged()
    assert frame.GetPredictedError() == 0.0
    exact = rh.scene_reference(renderer, shafts)
    image = rh.in_scatter(shafts)
    assert np.abs(image - exact).max() <= 1e-6 * exact.max()
    error, _ = ref.relative_rms_error(estimate, exact)
    assert error > 1e-3  # the estimate was not already the answer
    picture = rh.screenshot(window)
    window.Render()
    assert np.array_equal(rh.screenshot(window), picture)
    assert np.array_equal(rh.in_scatter(shafts), image)


@pytest.mark.parametrize("change", ["camera", "medium", "light", "prop", "size"])
def test_any_change_stops_the_finish(change):
    renderer, window, shafts, info = finishing_scene()
    window.Render()
    window.Render()
    render_until_complete(window, shafts)
    if change == "camera":
        renderer.GetActiveCamera().Azimuth(3.0)
    elif change == "medium":
        shafts.GetMedium().SetScatteringCoefficient(0.08)
    elif change == "light":
        info.light.SetConeAngle(18.0)
    elif change == "prop":
        info.actors[-1].SetPosition(0.0, 0.3, 0.0)
    else:
        window.SetSize(WIDTH + 16, HEIGHT)
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetExactFinishState() == OFF
    assert frame.GetExactFinishFraction() == 0.0
    assert not frame.GetInScatterReused()
    assert frame.GetRefinementEstimates() == 1
    frame = render_until_complete(window, shafts)
    assert frame.GetExactFinishState() == COMPLETE
    exact = rh.scene_reference(renderer, shafts)
    assert np.abs(rh.in_scatter(shafts) - exact).max() <= 1e-6 * exact.max()


def test_partial_picture_mixes_tiles_and_estimate():
    renderer, window, shafts, _ = finishing_scene(320, 240)
    window.Render()
    estimate = rh.in_scatter(shafts)
    exact = rh.scene_reference(renderer, shafts)
    window.Render()
    seen_partial = False
    for _ in range(2000):
        frame = shafts.GetLastFrame()
        image = rh.in_scatter(shafts)
        # every pixel is the estimate's or the reference's
        from_estimate = np.all(image == estimate, axis=-1)
        from_exact = np.all(np.abs(image - exact) <= 1e-6 * exact.max(), axis=-1)
        assert np.all(from_estimate | from_exact)
        if frame.GetExactFinishState() == COMPLETE:
            break
        seen_partial = seen_partial or 0.0 < frame.GetExactFinishFraction() < 1.0
        time.sleep(0.01)
        window.Render()
    assert frame.GetExactFinishState() == COMPLETE
    assert seen_partial


def test_unmodelled_scene_is_refined_without_it():
    renderer, window, shafts, info = finishing_scene()
    info.actors[1].GetProperty().SetRepresentationToWireframe()
    shafts.SetMethod(vtkLightShaftPass.RAY_MARCH)  # estimates that shift: refined over frames
    shafts.SetNumberOfSteps(8)
    for _ in range(3):
        window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetExactFinishState() == UNSUPPORTED
    assert "lines" in frame.GetExactFinishProblem()
    assert frame.GetRefinementEstimates() == 3  # refinement goes on as without the finish


def test_off_without_refinement_and_when_released():
    renderer, window, shafts, _ = finishing_scene()
    shafts.ProgressiveRefinementOff()
    window.Render()
    window.Render()
    assert shafts.GetLastFrame().GetExactFinishState() == OFF
    shafts.ProgressiveRefinementOn()
    window.Render()
    window.Render()
    assert shafts.GetLastFrame().GetExactFinishState() == RUNNING
    shafts.ReleaseGraphicsResources(window)  # stops the workers
    window.Render()
    renderer.SetPass(None)
    del shafts  # a pass deleted while its workers run joins them
    window.Render()


def test_the_first_still_frame_after_a_budget_shows_the_moving_picture():
    # An interactor's rate while the camera turns, then rest: the frame that starts the finish
    # computes no estimate (the budget's picture again, bit for bit, at no shafts' cost), and
    # the next one refines from there.
    renderer, window, shafts, _ = finishing_scene()
    try:
        window.SetDesiredUpdateRate(15.0)
        for _ in range(3):
            renderer.GetActiveCamera().Azimuth(0.5)
            window.Render()
        moving = rh.in_scatter(shafts)
        assert shafts.GetLastFrame().GetTimeBudget() > 0.0
    finally:
        window.SetDesiredUpdateRate(0.0001)
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetExactFinishState() == RUNNING
    assert frame.GetInScatterReused()
    assert np.array_equal(rh.in_scatter(shafts), moving)
    render_until_complete(window, shafts)
    exact = rh.scene_reference(renderer, shafts)
    assert np.abs(rh.in_scatter(shafts) - exact).max() <= 1e-6 * exact.max()


def test_a_split_still_setting_holds_the_moving_picture_under_the_tiles():
    # Final after a budget nothing fits: the frame that starts the finish shows the moving
    # picture, the split estimates that follow hold it (with the finished tiles over it) until
    # they add up to a Final frame, and the finish completes at the reference.
    renderer, window, shafts, _ = finishing_scene()
    shafts.SetQualityToFinal()
    try:
        window.SetDesiredUpdateRate(1e6)
        for _ in range(3):
            renderer.GetActiveCamera().Azimuth(0.5)
            window.Render()
    finally:
        window.SetDesiredUpdateRate(0.0001)
    window.Render()
    assert shafts.GetLastFrame().GetExactFinishState() == RUNNING
    window.Render()
    frame = shafts.GetLastFrame()
    assert frame.GetRefinementSplit() == 16 and frame.GetRefinementEstimates() == 1
    assert frame.GetRefinementHeld() or frame.GetExactFinishState() == COMPLETE
    frame = render_until_complete(window, shafts)
    assert frame.GetExactFinishState() == COMPLETE
    exact = rh.scene_reference(renderer, shafts)
    assert np.abs(rh.in_scatter(shafts) - exact).max() <= 1e-6 * exact.max()


def test_render_converged_waits_for_the_finish():
    # The batch helper renders until the picture is final: with ExactFinish, the reference's.
    from lightshafts import render_converged
    renderer, window, shafts, _ = finishing_scene()
    frames = render_converged(window, shafts)
    frame = shafts.GetLastFrame()
    assert frame.GetExactFinishState() == COMPLETE and frame.GetRefinementConverged()
    assert frames >= 2
    exact = rh.scene_reference(renderer, shafts)
    assert np.abs(rh.in_scatter(shafts) - exact).max() <= 1e-6 * exact.max()


def test_a_composite_dataset_is_finished_as_its_pieces():
    # ParaView's representations draw a vtkMultiBlockDataSet through a composite mapper: the
    # reference (and so the finish) takes its polygonal leaves, and an actor that draws nothing
    # (an empty wireframe, as ParaView's selection outline) changes nothing.
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
    from vtkmodules.vtkRenderingCore import vtkActor
    from vtkmodules.vtkCommonCore import vtkVersion
    if (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) < (9, 3):
        from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2
    else:  # deprecated from VTK 9.3, where the Core class took its place
        from vtkmodules.vtkRenderingCore import vtkCompositePolyDataMapper as \
            vtkCompositePolyDataMapper2
    renderer, window, shafts, info = finishing_scene()
    window.Render()
    plain = rh.scene_reference(renderer, shafts)
    for actor in info.actors:
        polydata = actor.GetMapper().GetInputDataObject(0, 0)
        blocks = vtkMultiBlockDataSet()
        blocks.SetNumberOfBlocks(2)
        blocks.SetBlock(0, polydata)
        blocks.SetBlock(1, vtkPolyData())
        mapper = vtkCompositePolyDataMapper2()
        mapper.SetInputDataObject(blocks)
        actor.SetMapper(mapper)
    empty = vtkActor()
    empty.SetMapper(vtkCompositePolyDataMapper2())
    empty.GetMapper().SetInputDataObject(vtkMultiBlockDataSet())
    empty.GetProperty().SetRepresentationToWireframe()
    renderer.AddActor(empty)
    assert np.array_equal(rh.scene_reference(renderer, shafts), plain)
    window.Render()  # the new mappers' first render updates them: the view still after it
    frame = render_until_complete(window, shafts)
    assert frame.GetExactFinishState() == COMPLETE, frame.GetExactFinishProblem()
    assert np.abs(rh.in_scatter(shafts) - plain).max() <= 1e-6 * plain.max()
