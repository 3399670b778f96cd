"""Parameters: defaults, round trips, clamping, and refusal of non-finite values."""

import math

import pytest

import lightshafts
from lightshafts import parameter_owner, vtkLightShaftMedium, vtkLightShaftPass
from vtkmodules.vtkRenderingCore import vtkLight
from vtkmodules.vtkRenderingOpenGL2 import vtkImageProcessingPass, vtkRenderStepsPass


def test_import_and_type():
    p = vtkLightShaftPass()
    assert isinstance(p, vtkImageProcessingPass)
    assert p.GetClassName() == "vtkLightShaftPass"
    assert "vtkLightShaftPass" in lightshafts.__all__


def test_defaults():
    p = vtkLightShaftPass()
    assert p.GetMedium().GetScatteringCoefficient() == (0.1, 0.1, 0.1)
    assert p.GetMedium().GetAbsorptionCoefficient() == (0.0, 0.0, 0.0)
    assert p.GetMedium().GetPhaseFunction() == vtkLightShaftMedium.ISOTROPIC
    assert p.GetMedium().GetAnisotropy() == 0.0
    assert p.GetExposure() == 1.0
    assert p.GetAttenuateScene() is True or p.GetAttenuateScene() == 1
    assert not p.GetShadowSurfaces()
    assert p.GetAttenuateSurfaceLight()
    assert p.GetNumberOfSlices() == 64
    assert p.GetShadowMapSize() == 1024
    assert p.GetLight() is None
    assert p.GetDelegatePass() is None
    assert p.GetCookie() is None
    assert p.GetMedium().GetNoiseTexture() is None
    assert p.GetMedium().GetNoiseAmplitude() == 0.0
    assert p.GetMedium().GetNoiseScale() == 3.0
    assert p.GetMedium().GetNoiseVelocity1() == (0.04, 0.01)
    assert p.GetMedium().GetNoiseVelocity2() == (-0.015, 0.03)
    assert p.GetMedium().GetTime() == 0.0
    assert not p.GetAutomaticSliceCount()
    assert p.GetMaximumNumberOfSlices() == 512
    assert p.GetJitter()
    assert p.GetBlurRadius() == 2
    assert p.GetDownsampleFactor() == 1
    assert p.GetAccumulationPrecision() == vtkLightShaftPass.ACCUMULATE_FLOAT32
    assert p.GetTargetError() == 0.0
    assert p.GetLastFrame().GetPredictedError() == -1.0 and p.GetLastFrame().GetErrorModelSetting() == -1


@pytest.mark.parametrize("name,value", [
    ("NumberOfSlices", 512),
    ("ShadowMapSize", 2048),
    ("Exposure", 3.5),
    ("Anisotropy", -0.4),
    ("PhaseFunction", vtkLightShaftMedium.RAYLEIGH),
    ("NoiseAmplitude", 0.6),
    ("NoiseScale", 7.5),
    ("Time", -12.25),
    ("MaximumNumberOfSlices", 64),
    ("BlurRadius", 5),
    ("DownsampleFactor", 4),
    ("AccumulationPrecision", vtkLightShaftPass.ACCUMULATE_8BIT),
    ("TargetError", 0.02),
    ("TimeBudget", 0.05),
    ("RefinementFrames", 64),
])
def test_scalar_round_trip(name, value):
    p = vtkLightShaftPass()
    getattr(parameter_owner(p, name), "Set" + name)(value)
    assert getattr(parameter_owner(p, name), "Get" + name)() == value


@pytest.mark.parametrize("name", ["ScatteringCoefficient", "AbsorptionCoefficient"])
def test_vector_round_trip(name):
    p = vtkLightShaftPass()
    getattr(parameter_owner(p, name), "Set" + name)(0.25, 0.5, 0.75)
    assert getattr(parameter_owner(p, name), "Get" + name)() == (0.25, 0.5, 0.75)
    getattr(parameter_owner(p, name), "Set" + name)((1.0, 2.0, 3.0))
    assert getattr(parameter_owner(p, name), "Get" + name)() == (1.0, 2.0, 3.0)
    getattr(parameter_owner(p, name), "Set" + name)(0.125)
    assert getattr(parameter_owner(p, name), "Get" + name)() == (0.125, 0.125, 0.125)


def test_named_phase_setters():
    p = vtkLightShaftPass()
    p.GetMedium().SetPhaseFunctionToHenyeyGreenstein()
    assert p.GetMedium().GetPhaseFunction() == vtkLightShaftMedium.HENYEY_GREENSTEIN == 1
    p.GetMedium().SetPhaseFunctionToRayleigh()
    assert p.GetMedium().GetPhaseFunction() == vtkLightShaftMedium.RAYLEIGH == 2
    p.GetMedium().SetPhaseFunctionToIsotropic()
    assert p.GetMedium().GetPhaseFunction() == vtkLightShaftMedium.ISOTROPIC == 0


def test_boolean_macros():
    p = vtkLightShaftPass()
    p.AttenuateSceneOff()
    assert not p.GetAttenuateScene()
    p.AttenuateSceneOn()
    assert p.GetAttenuateScene()
    p.ShadowSurfacesOn()
    assert p.GetShadowSurfaces()
    p.SetShadowSurfaces(False)
    assert not p.GetShadowSurfaces()
    assert p.GetSplitLongFrames()
    p.SplitLongFramesOff()
    assert not p.GetSplitLongFrames()
    p.SetSplitLongFrames(True)
    assert p.GetSplitLongFrames()
    p.AttenuateSurfaceLightOff()
    assert not p.GetAttenuateSurfaceLight()
    p.SetAttenuateSurfaceLight(True)
    assert p.GetAttenuateSurfaceLight()


@pytest.mark.parametrize("name,low,high,expect_low,expect_high", [
    ("NumberOfSlices", 0, 10 ** 6, 1, 4096),
    ("ShadowMapSize", 1, 10 ** 6, 16, 16384),
    ("Exposure", -1.0, 1e9, 0.0, 1e6),
    ("Anisotropy", -5.0, 5.0, -0.99, 0.99),
    ("PhaseFunction", -3, 17, 0, 2),
    ("NoiseAmplitude", -1.0, 3.0, 0.0, 1.0),
    ("NoiseScale", 0.0, 1e9, 0.01, 1000.0),
    ("MaximumNumberOfSlices", 0, 10 ** 6, 1, 4096),
    ("BlurRadius", -2, 100, 0, 32),
    ("DownsampleFactor", 0, 100, 1, 4),
    ("AccumulationPrecision", -1, 7, 0, 2),
    ("TargetError", -0.5, 3.0, 0.0, 1.0),
    ("TimeBudget", -1.0, 1e9, 0.0, 3600.0),
    ("RefinementFrames", 0, 10 ** 6, 1, 4096),
])
def test_scalar_clamping(name, low, high, expect_low, expect_high):
    p = vtkLightShaftPass()
    getattr(parameter_owner(p, name), "Set" + name)(low)
    assert getattr(parameter_owner(p, name), "Get" + name)() == expect_low
    getattr(parameter_owner(p, name), "Set" + name)(high)
    assert getattr(parameter_owner(p, name), "Get" + name)() == expect_high


@pytest.mark.parametrize("name,high", [("ScatteringCoefficient", 1e6),
                                       ("AbsorptionCoefficient", 1e6),
                                       ("PaintedBackground", 1.0)])
def test_vector_clamping(name, high):
    p = vtkLightShaftPass()
    getattr(parameter_owner(p, name), "Set" + name)(-1.0, 0.5, 1e9)
    assert getattr(parameter_owner(p, name), "Get" + name)() == (0.0, 0.5, high)


@pytest.mark.parametrize("name,args", [
    ("ScatteringCoefficient", (math.nan, 0.1, 0.1)),
    ("ScatteringCoefficient", (0.1, math.inf, 0.1)),
    ("ScatteringCoefficient", (math.nan,)),
    ("AbsorptionCoefficient", (0.1, 0.1, -math.inf)),
    ("Anisotropy", (math.nan,)),
    ("Exposure", (math.inf,)),
    ("Exposure", (math.nan,)),
    ("NoiseAmplitude", (math.nan,)),
    ("NoiseScale", (math.inf,)),
    ("NoiseVelocity1", (math.nan, 0.0)),
    ("NoiseVelocity2", (0.0, -math.inf)),
    ("Time", (math.nan,)),
    ("Time", (math.inf,)),
    ("TargetError", (math.nan,)),
    ("TimeBudget", (math.nan,)),
    ("TimeBudget", (math.inf,)),
    ("PaintedBackground", (math.nan, 0.5, 0.5)),
    ("PaintedBackground", (0.5, 0.5, math.inf)),
])
def test_non_finite_refused(messages, name, args):
    p = vtkLightShaftPass()
    log = messages(parameter_owner(p, name))  # (the medium's setters report on the medium)
    before = getattr(parameter_owner(p, name), "Get" + name)()
    mtime = p.GetMTime()
    getattr(parameter_owner(p, name), "Set" + name)(*args)
    assert getattr(parameter_owner(p, name), "Get" + name)() == before
    assert p.GetMTime() == mtime
    assert len(log.errors) == 1
    assert name in log.errors[0]


def test_light_round_trip():
    p = vtkLightShaftPass()
    light = vtkLight()
    p.SetLight(light)
    assert p.GetLight() is light
    p.SetLight(None)
    assert p.GetLight() is None


def test_delegate_round_trip():
    p = vtkLightShaftPass()
    steps = vtkRenderStepsPass()
    p.SetDelegatePass(steps)
    assert p.GetDelegatePass() is steps


def test_readback_before_render_fails_cleanly(messages):
    from vtkmodules.vtkCommonDataModel import vtkImageData
    p = vtkLightShaftPass()
    log = messages(p)
    image = vtkImageData()
    assert not p.GetInScatteredRadiance(image)
    assert len(log.errors) == 1


def test_release_without_window_is_safe():
    p = vtkLightShaftPass()
    p.ReleaseGraphicsResources(None)
    p.ReleaseGraphicsResources(None)


def test_downsample_factor_rounds_down_to_a_power_of_two():
    p = vtkLightShaftPass()
    for requested, expected in [(1, 1), (2, 2), (3, 2), (4, 4), (5, 4)]:
        p.SetDownsampleFactor(requested)
        assert p.GetDownsampleFactor() == expected


def test_noise_velocities_and_textures_round_trip():
    from vtkmodules.vtkRenderingCore import vtkTexture
    p = vtkLightShaftPass()
    p.GetMedium().SetNoiseVelocity1(0.5, -0.25)
    p.GetMedium().SetNoiseVelocity2(-2.0, 3.0)
    assert p.GetMedium().GetNoiseVelocity1() == (0.5, -0.25)
    assert p.GetMedium().GetNoiseVelocity2() == (-2.0, 3.0)
    p.GetMedium().SetNoiseVelocity1(1e9, -1e9)
    assert p.GetMedium().GetNoiseVelocity1() == (1e3, -1e3)
    cookie, noise = vtkTexture(), vtkTexture()
    p.SetCookie(cookie)
    p.GetMedium().SetNoiseTexture(noise)
    assert p.GetCookie() is cookie and p.GetMedium().GetNoiseTexture() is noise
    p.SetCookie(None)
    p.GetMedium().SetNoiseTexture(None)
    assert p.GetCookie() is None and p.GetMedium().GetNoiseTexture() is None


def test_named_precision_setters_and_booleans():
    p = vtkLightShaftPass()
    p.SetAccumulationPrecisionTo8Bit()
    assert p.GetAccumulationPrecision() == 2
    p.SetAccumulationPrecisionToFloat16()
    assert p.GetAccumulationPrecision() == 1
    p.SetAccumulationPrecisionToFloat32()
    assert p.GetAccumulationPrecision() == 0
    p.JitterOn()
    p.AutomaticSliceCountOn()
    assert p.GetJitter() and p.GetAutomaticSliceCount()
    p.JitterOff()
    p.AutomaticSliceCountOff()
    assert not p.GetJitter() and not p.GetAutomaticSliceCount()


def _table_presets():
    """The presets the fitted table names: {"Draft": "S64 b0 d1 m1024", ...}."""
    import os
    import re
    path = os.path.join(os.path.dirname(__file__), "..", "..", "plugin", "core",
                        "vtkLightShaftErrorModelTable.h")
    with open(path) as table:
        return dict(re.findall(r"constexpr int (\w+)Setting = \d+; // (.+), aim", table.read()))


def _setting_of(p):
    """The ladder's name of the pass's parameters (tests/benchmarks/random_scenes.LADDER)."""
    if p.GetMethod() == vtkLightShaftPass.RAY_MARCH:
        return f"M{p.GetNumberOfSteps()} i{p.GetInterleaveSize()} m{p.GetShadowMapSize()}"
    if p.GetMethod() == vtkLightShaftPass.LIGHT_VOLUME:
        return f"V{p.GetLightVolumeResolution()} m{p.GetShadowMapSize()}"
    if p.GetMethod() == vtkLightShaftPass.EPIPOLAR:
        return (f"E{p.GetNumberOfSteps()} l{p.GetEpipolarLines()} s{p.GetEpipolarSamples()} "
                f"k{p.GetEpipolarStep()} m{p.GetShadowMapSize()}")
    jitter = " j" if p.GetJitter() else ""
    return (f"S{p.GetNumberOfSlices()}{jitter} b{p.GetBlurRadius()} d{p.GetDownsampleFactor()} "
            f"m{p.GetShadowMapSize()}")


def test_quality_presets():
    # Each preset is the setting of the error model's ladder that the fit chose for it, with a
    # fixed count and 32-bit float accumulation; the defaults are not a preset.
    presets = _table_presets()
    assert set(presets) == {"Draft", "Interactive", "Final"}
    p = vtkLightShaftPass()
    assert _setting_of(p) == "S64 j b2 d1 m1024"  # the defaults
    for name in ("Final", "Draft", "Interactive"):
        p.SetAutomaticSliceCount(True)
        p.SetAccumulationPrecision(vtkLightShaftPass.ACCUMULATE_8BIT)
        getattr(p, "SetQualityTo" + name)()
        assert _setting_of(p) == presets[name], name
        assert not p.GetAutomaticSliceCount()
        assert p.GetAccumulationPrecision() == vtkLightShaftPass.ACCUMULATE_FLOAT32


def test_reference_parameters(messages, vtk_messages):
    from lightshafts import vtkLightShaftReference
    r = vtkLightShaftReference()
    assert r.GetRelativeTolerance() == 1e-9
    assert r.GetVisibilitySamples() == 32
    assert r.GetUseClosedForms()
    assert r.GetRenderer() is None and r.GetLightShaftPass() is None
    r.SetRelativeTolerance(1.0)
    assert r.GetRelativeTolerance() == 1e-2
    r.SetRelativeTolerance(0.0)
    assert r.GetRelativeTolerance() == 1e-14
    r.SetVisibilitySamples(0)
    assert r.GetVisibilitySamples() == 2
    r.SetVisibilitySamples(10 ** 9)
    assert r.GetVisibilitySamples() == 100000
    r.UseClosedFormsOff()
    assert not r.GetUseClosedForms()
    assert r.GetVisibilityMode() == vtkLightShaftReference.EXACT
    r.SetVisibilityModeToShadowMap()
    assert r.GetVisibilityMode() == vtkLightShaftReference.SHADOW_MAP
    r.SetVisibilityMode(7)
    assert r.GetVisibilityMode() == vtkLightShaftReference.SHADOW_MAP
    r.SetVisibilityModeToExact()
    log = messages(r)
    r.SetRelativeTolerance(math.nan)
    assert r.GetRelativeTolerance() == 1e-14
    assert len(log.errors) == 1 and "RelativeTolerance" in log.errors[0]
    # Without a renderer and a pass, Update() reports the missing inputs (and VTK's executive
    # that the algorithm failed).
    vtk_messages.expect("vtkLightShaftReference.*returned failure for request")
    r.Update()
    assert any("SetRenderer" in e for e in log.errors)


def test_fetch_floor_measures_more_for_more_fetches(vtk_messages):
    import render_helpers as rh
    from lightshafts import vtkLightShaftFetchFloor
    renderer, window = rh.make_window(64, 48)
    window.Render()
    floor = vtkLightShaftFetchFloor()
    few = floor.Measure(window, 256, 256, 1, 3)
    many = floor.Measure(window, 256, 256, 400, 3)
    assert 0.0 < few < many
    vtk_messages.expect("vtkLightShaftFetchFloor.*window")
    assert floor.Measure(None, 16, 16, 1, 1) == -1.0
    assert len(vtk_messages.messages) == 1
