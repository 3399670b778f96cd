"""vtkLightShaftMedium: what the medium is, apart from how the pass computes the shafts.

Its own ranges, defaults and refusals are checked with the pass's (test_api.py,
test_parameter_sources.py); here: that every pass has one, that several passes share one (a
change shows in each at its next frame and restarts their refinement), that SetMedium(None)
gives a fresh one, that a medium holds no GL and outlives its passes, and that a shared medium
renders what a medium of one's own with the same values renders, bit for bit.
"""

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

import lightshafts
from lightshafts import scenes, vtkLightShaftMedium, vtkLightShaftPass

import render_helpers as rh

WIDTH, HEIGHT = 96, 72


def rendered(shafts, size=(WIDTH, HEIGHT)):
    """The picture and in-scatter of `shafts` over the sphere-and-floor scene."""
    renderer, window = rh.make_window(*size)
    info = scenes.sphere_and_floor(renderer)
    shafts.SetLight(info.light)
    shafts.SetBlurRadius(0)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    return rh.screenshot(window), rh.in_scatter(shafts)


def test_every_pass_has_a_medium_of_its_own():
    a, b = vtkLightShaftPass(), vtkLightShaftPass()
    assert isinstance(a.GetMedium(), vtkLightShaftMedium)
    assert a.GetMedium() is a.GetMedium()
    assert a.GetMedium() is not b.GetMedium()
    a.GetMedium().SetScatteringCoefficient(0.5)
    assert b.GetMedium().GetScatteringCoefficient() == (0.1, 0.1, 0.1)


def test_set_medium_none_gives_a_fresh_default_medium():
    shafts = vtkLightShaftPass()
    shared = vtkLightShaftMedium()
    shared.SetScatteringCoefficient(0.3)
    shafts.SetMedium(shared)
    assert shafts.GetMedium() is shared
    before = shafts.GetMTime()
    shafts.SetMedium(shared)  # the same one: nothing changes
    assert shafts.GetMTime() == before
    shafts.SetMedium(None)
    assert shafts.GetMedium() is not shared
    assert shafts.GetMedium().GetScatteringCoefficient() == (0.1, 0.1, 0.1)
    assert shafts.GetMTime() > before


def test_a_change_of_the_medium_is_a_change_of_every_pass_sharing_it():
    medium = vtkLightShaftMedium()
    passes = [vtkLightShaftPass(), vtkLightShaftPass()]
    for shafts in passes:
        shafts.SetMedium(medium)
    times = [shafts.GetMTime() for shafts in passes]
    medium.SetAnisotropy(0.5)
    assert all(shafts.GetMTime() > t for shafts, t in zip(passes, times))
    times = [shafts.GetMTime() for shafts in passes]
    medium.SetAnisotropy(0.5)  # unchanged value: no change
    assert [shafts.GetMTime() for shafts in passes] == times


def test_the_medium_outlives_its_pass_and_holds_no_graphics():
    shafts = vtkLightShaftPass()
    medium = shafts.GetMedium()
    medium.SetScatteringCoefficient(0.07)
    rendered(shafts)
    del shafts
    assert medium.GetScatteringCoefficient() == (0.07, 0.07, 0.07)
    other = vtkLightShaftPass()
    other.SetMedium(medium)
    image, radiance = rendered(other)
    assert radiance.max() > 0.0


def test_a_shared_medium_renders_as_a_medium_of_ones_own():
    medium = vtkLightShaftMedium()
    medium.SetScatteringCoefficient(0.05, 0.04, 0.03)
    medium.SetAbsorptionCoefficient(0.01)
    medium.SetPhaseFunctionToHenyeyGreenstein()
    medium.SetAnisotropy(0.4)
    medium.SetNoiseAmplitude(0.5)
    medium.SetTime(1.5)
    first, second = vtkLightShaftPass(), vtkLightShaftPass()
    first.SetMedium(medium)
    second.SetMedium(medium)
    own = vtkLightShaftPass()
    lightshafts.configure(own, None, ScatteringCoefficient=(0.05, 0.04, 0.03),
                          AbsorptionCoefficient=0.01,
                          PhaseFunction=vtkLightShaftMedium.HENYEY_GREENSTEIN, Anisotropy=0.4,
                          NoiseAmplitude=0.5, Time=1.5)
    pictures = [rendered(shafts) for shafts in (first, second, own)]
    assert pictures[0][1].max() > 0.0
    for image, radiance in pictures[1:]:
        assert np.array_equal(image, pictures[0][0])
        assert np.array_equal(radiance, pictures[0][1])


def test_a_change_of_a_shared_medium_restarts_refinement():
    medium = vtkLightShaftMedium()
    shafts = vtkLightShaftPass()
    shafts.SetMedium(medium)
    shafts.SetMethodToRayMarch()
    shafts.SetNumberOfSteps(4)
    shafts.ProgressiveRefinementOn()
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer)
    shafts.SetLight(info.light)
    renderer.SetPass(shafts)
    for _ in range(3):
        window.Render()
    assert shafts.GetLastFrame().GetRefinementEstimates() == 3
    medium.SetScatteringCoefficient(0.2)  # through the medium, not the pass
    window.Render()
    assert shafts.GetLastFrame().GetRefinementEstimates() == 1


def test_a_shared_density_field_renders_in_each_pass():
    field = vtkImageData()  # a density rising along x, 8^3 samples over the scene
    field.SetDimensions(8, 8, 8)
    field.SetOrigin(-4.0, -1.0, -4.0)
    field.SetSpacing(8.0 / 7, 8.0 / 7, 8.0 / 7)
    values = numpy_to_vtk(np.tile(np.linspace(0.0, 2.0, 8), 64), deep=True)
    values.SetName("density")
    field.GetPointData().SetScalars(values)
    medium = vtkLightShaftMedium()
    medium.SetDensityField(field)
    first, second = vtkLightShaftPass(), vtkLightShaftPass()
    for shafts in (first, second):
        shafts.SetMedium(medium)
        shafts.SetMethodToRayMarch()
    one = rendered(first)
    two = rendered(second)  # (reads the image itself: the first pass took the setter's read)
    assert first.GetLastFrame().GetMethod() == vtkLightShaftPass.RAY_MARCH
    assert one[1].max() > 0.0
    assert np.array_equal(one[0], two[0])
    assert np.array_equal(one[1], two[1])


def test_add_light_shafts_keywords_reach_the_medium():
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer)
    shafts = lightshafts.add_light_shafts(renderer, light=info.light, quality="draft",
                                          ScatteringCoefficient=0.05, NoiseAmplitude=0.3,
                                          Exposure=2.0, AttenuateScene=False)
    assert shafts.GetMedium().GetScatteringCoefficient() == (0.05, 0.05, 0.05)
    assert shafts.GetMedium().GetNoiseAmplitude() == 0.3
    assert shafts.GetExposure() == 2.0 and not shafts.GetAttenuateScene()
    assert lightshafts.parameter_owner(shafts, "Time") is shafts.GetMedium()
    assert lightshafts.parameter_owner(shafts, "NumberOfSteps") is shafts
    try:
        lightshafts.configure(shafts, renderer, Fog=1.0)
    except TypeError as error:
        assert "Fog" in str(error)
    else:
        raise AssertionError("an unknown keyword was accepted")
    renderer.SetPass(None)
