"""The work a frame may do at the sampling maxima (issue 24): a frame's in-scatter integrates
at most 2^30 segments (steps or slabs per pixel, over the in-scatter's pixels), shared equally
by the lights that radiate. Beyond, RAY_MARCH takes fewer steps and SLICES fewer slabs, with
one warning until it fits again; the frame stays finite. The bound's time on llvmpipe (about
16 s a frame at 15 ns a segment) is measured in docs/robustness.md, not here.

The scenes keep the light's footprint small (a 3-degree cone): the budget counts every
in-scatter pixel, the work only the lit ones, so these frames are quick.
"""

import numpy as np
import pytest
from vtkmodules.vtkRenderingCore import vtkLight

from lightshafts import parameter_owner, scenes, vtkLightShaftPass

import render_helpers as rh
from vtk_output import Messages

BUDGET = 2 ** 30


def narrow_beam(width, height, **params):
    renderer, window = rh.make_window(width, height)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=16)
    info.light.SetConeAngle(3.0)
    shafts = vtkLightShaftPass()
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    renderer.SetPass(shafts)
    return renderer, window, shafts, Messages(shafts)


def test_ray_march_steps_beyond_the_budget_are_reduced_with_one_warning():
    renderer, window, shafts, log = narrow_beam(640, 480, Method=vtkLightShaftPass.RAY_MARCH,
                                                NumberOfSteps=4096, InterleaveSize=1)
    for _ in range(2):
        window.Render()
        assert shafts.GetLastFrame().GetNumberOfSteps() == BUDGET // (640 * 480) == 3495
        assert np.all(np.isfinite(rh.in_scatter(shafts)))
    assert len(log.warnings) == 1
    assert "NumberOfSteps 4096 over 307200 in-scatter pixels" in log.warnings[0]
    assert "using 3495" in log.warnings[0]
    # Half resolution fits: the steps asked for, and the next reduction is said again.
    shafts.SetDownsampleFactor(2)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSteps() == 4096
    shafts.SetDownsampleFactor(1)
    window.Render()
    assert len(log.warnings) == 2


def test_the_lights_of_a_frame_share_the_budget():
    renderer, window, shafts, log = narrow_beam(640, 480, Method=vtkLightShaftPass.RAY_MARCH,
                                                NumberOfSteps=4096, InterleaveSize=1)
    second = vtkLight()
    second.DeepCopy(renderer.GetLights().GetItemAsObject(0))
    second.SetPosition(np.add(second.GetPosition(), (0.5, 0.0, 0.0)))
    renderer.AddLight(second)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 2
    assert shafts.GetLastFrame().GetNumberOfSteps() == BUDGET // 2 // (640 * 480) == 1747
    assert np.all(np.isfinite(rh.in_scatter(shafts)))
    assert len(log.warnings) == 1
    assert "using 1747" in log.warnings[0] and "shared by 2 lights" in log.warnings[0]
    # Switched off, the second light leaves the first the whole budget.
    second.SwitchOff()
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSteps() == BUDGET // (640 * 480)


def test_slices_beyond_the_budget_are_reduced_with_one_warning():
    renderer, window, shafts, log = narrow_beam(640, 480, NumberOfSlices=4096, BlurRadius=0)
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() <= 3495 + 1
    assert np.all(np.isfinite(rh.in_scatter(shafts)))
    assert len(log.warnings) == 1 and "NumberOfSlices 4096" in log.warnings[0]


@pytest.mark.parametrize("size", [(320, 240), (1920, 1080)])
def test_the_presets_fit_the_budget_up_to_1080p(size):
    renderer, window, shafts, log = narrow_beam(*size)
    shafts.SetQualityToFinal()  # 256 steps: 530 M segments at 1080p
    window.Render()
    assert shafts.GetLastFrame().GetNumberOfSteps() == 256 and not log.warnings


def test_epipolar_steps_count_every_sample_it_may_march():
    renderer, window, shafts, log = narrow_beam(640, 480, Method=vtkLightShaftPass.EPIPOLAR,
                                                NumberOfSteps=4096, EpipolarLines=2048,
                                                EpipolarSamples=2048, EpipolarStep=1)
    window.Render()
    assert np.all(np.isfinite(rh.in_scatter(shafts)))
    # 2048 lines (of 2240 boundary pixels) x 1600 samples (two per pixel of the diagonal)
    # and the 307200 pixels: 3,584,000 rays afford 299 steps.
    assert len(log.warnings) == 1
    assert "NumberOfSteps 4096 over 3584000 rays" in log.warnings[0]
    assert "using 299" in log.warnings[0]
    assert shafts.GetLastFrame().GetNumberOfSteps() == 299
