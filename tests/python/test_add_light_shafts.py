"""lightshafts.add_light_shafts: the one-line convenience for plain VTK scripts."""

import numpy as np
import pytest

import lightshafts
from lightshafts import add_light_shafts, scenes, vtkLightShaftPass
from vtkmodules.vtkRenderingCore import vtkLight
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

import render_helpers as rh


def test_one_line_renders_the_same_as_the_pass_set_up_by_hand():
    renderer, window = rh.make_window(160, 120)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = add_light_shafts(renderer, light=info.light, quality="final", method="ray-march",
                              ScatteringCoefficient=(0.05, 0.04, 0.03), Exposure=30.0,
                              NumberOfSteps=64, Jitter=False)
    assert "add_light_shafts" in lightshafts.__all__
    assert renderer.GetPass() is shafts
    assert shafts.GetLight() is info.light
    assert shafts.GetMethod() == vtkLightShaftPass.RAY_MARCH
    # The Final preset (256 ray-march steps, no interleaving, 2048^2 map), applied before the
    # keywords: they override its steps.
    assert (shafts.GetInterleaveSize(), shafts.GetShadowMapSize()) == (1, 2048)
    assert shafts.GetMedium().GetScatteringCoefficient() == (0.05, 0.04, 0.03)
    assert (shafts.GetExposure(), shafts.GetNumberOfSteps(), shafts.GetJitter()) == (30, 64, 0)
    window.Render()
    one_line = rh.in_scatter(shafts)
    by_hand = vtkLightShaftPass()
    by_hand.SetQualityToFinal()
    by_hand.SetMethodToRayMarch()
    by_hand.GetMedium().SetScatteringCoefficient(0.05, 0.04, 0.03)
    by_hand.SetExposure(30.0)
    by_hand.SetNumberOfSteps(64)
    by_hand.JitterOff()
    by_hand.SetLight(info.light)
    renderer.SetPass(by_hand)
    window.Render()
    np.testing.assert_array_equal(one_line, rh.in_scatter(by_hand))


def test_a_new_light_is_added_and_an_existing_pass_becomes_the_delegate():
    renderer, window = rh.make_window(160, 120)
    scenes.sphere_and_floor(renderer, sphere_resolution=32)
    renderer.RemoveAllLights()
    spot = vtkLight()
    spot.SetPositional(True)
    spot.SetPosition(0.5, 6.0, 0.0)
    spot.SetFocalPoint(0.0, 0.0, 0.0)
    spot.SetConeAngle(25.0)
    steps = vtkRenderStepsPass()
    renderer.SetPass(steps)
    shafts = add_light_shafts(renderer, light=spot)
    assert renderer.GetLights().GetNumberOfItems() == 1
    assert shafts.GetDelegatePass() is steps
    window.Render()
    assert shafts.GetLastFrame().GetUsedLight() is spot
    assert rh.in_scatter(shafts).max() > 0.0
    add_light_shafts(renderer, light=spot)  # the light is not added twice
    assert renderer.GetLights().GetNumberOfItems() == 1


@pytest.mark.parametrize("method", [vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH,
                                    vtkLightShaftPass.RADIAL_BLUR, vtkLightShaftPass.ANALYTIC,
                                    vtkLightShaftPass.AUTOMATIC, vtkLightShaftPass.EPIPOLAR,
                                    vtkLightShaftPass.LIGHT_VOLUME])
def test_every_method_is_chosen_by_the_name_the_pass_gives_it(method):
    renderer, _ = rh.make_window(32, 32)
    name = vtkLightShaftPass.GetMethodName(method)
    assert add_light_shafts(renderer, method=name).GetMethod() == method
    assert add_light_shafts(renderer, method=name.upper()).GetMethod() == method


def test_bad_arguments_are_refused_with_their_name():
    renderer, _ = rh.make_window(32, 32)
    with pytest.raises(TypeError, match="Exposur"):
        add_light_shafts(renderer, Exposur=3)
    with pytest.raises(ValueError, match="method"):
        add_light_shafts(renderer, method="photon-mapping")
    with pytest.raises(ValueError, match="quality"):
        add_light_shafts(renderer, quality="ultra")
