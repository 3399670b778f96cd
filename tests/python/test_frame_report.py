"""vtkLightShaftFrameReport: what the pass's last frame did, in one read-only object.

Each read-out's meaning is tested where its feature is (methods, budget, refinement, light
kinds, ...); here: the object itself (one per pass, the same after every frame, updated by
each), its documented values before any frame and out of range, that it has no setters, and
that it agrees with what the frame did.
"""

import pytest

from lightshafts import scenes, vtkLightShaftFrameReport, vtkLightShaftPass

import render_helpers as rh

WIDTH, HEIGHT = 96, 72

# Read-out -> its documented value before the first frame.
BEFORE_ANY_FRAME = {
    "Method": -1, "ViewportSize": (0, 0), "NumberOfSceneRenders": 0, "MultiSamples": 0,
    "PlainScene": False, "RendererFXAA": False, "GLErrorCount": 0, "NumberOfSlicesDrawn": 0,
    "SliceDepthRange": (0.0, 0.0), "NumberOfSlabBatches": 0, "LatticeResolution": 0,
    "NumberOfSteps": 0, "LightVolumeResolution": 0, "NumberOfPostPasses": 0, "RadialGuardBand": 0.0, "DownsampleFactor": 1,
    "ShaderVariant": "", "SliceShaderSource": "", "ShadowMapRendered": False,
    "NumberOfShadowCasters": 0, "LightDepthRange": (0.0, 0.0), "ShadowBias": 0.0,
    "PredictedError": -1.0, "ErrorModelSetting": -1, "DepthRangeInBeamWidths": 0.0,
    "BeamWidthInPixels": 0.0, "OpticalDepth": 0.0, "ShadowTexelInPixels": 0.0,
    "LightInView": False, "TimeBudget": 0.0, "PredictedFrameTime": -1.0, "FrameTime": -1.0,
    "RefinementEstimates": 0, "RefinementConverged": False, "InScatterReused": False,
    "RefinementFilterWidth": 0.0, "RefinementSplit": 1, "RefinementHeld": False,
    "NumberOfUsedLights": 0,
}
# Per-light read-out -> its documented value out of range.
OUT_OF_RANGE = {
    "UsedLight": None, "LightKind": -1, "LightMethod": -1, "LightSlicesDrawn": 0,
    "LightShadowMapRendered": False, "LightShadowMapReused": False, "LightShadowCasters": 0,
    "LightTime": -1.0, "LightFieldShadowBytes": 0.0, "LightFieldShadowBuildTime": 0.0,
    "LightTranslucentLayers": 0, "LightTranslucentBytes": 0.0,
}


@pytest.mark.parametrize("name", sorted(BEFORE_ANY_FRAME))
def test_values_before_any_frame(name):
    value = getattr(vtkLightShaftPass().GetLastFrame(), "Get" + name)()
    assert value == BEFORE_ANY_FRAME[name]


@pytest.mark.parametrize("name", sorted(OUT_OF_RANGE))
@pytest.mark.parametrize("index", [-1, 0, 7])
def test_per_light_values_out_of_range(name, index):
    value = getattr(vtkLightShaftPass().GetLastFrame(), "Get" + name)(index)
    assert value == OUT_OF_RANGE[name]


def test_it_is_read_only():
    own = {n for n in dir(vtkLightShaftFrameReport) if n.startswith("Set")}
    inherited = {n for n in dir(vtkLightShaftFrameReport.__mro__[1]) if n.startswith("Set")}
    assert own == inherited, own - inherited


def test_one_object_updated_by_every_frame():
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer)
    shafts = vtkLightShaftPass()
    shafts.SetLight(info.light)
    shafts.SetMethodToRayMarch()
    shafts.SetNumberOfSteps(8)
    renderer.SetPass(shafts)
    report = shafts.GetLastFrame()
    window.Render()
    assert shafts.GetLastFrame() is report
    stamp = report.GetMTime()
    assert report.GetMethod() == vtkLightShaftPass.RAY_MARCH
    assert report.GetViewportSize() == (WIDTH, HEIGHT)
    assert report.GetNumberOfSteps() == 8
    assert report.GetNumberOfUsedLights() == 1
    assert report.GetUsedLight(0) is info.light
    assert report.GetLightKind(0) == vtkLightShaftPass.SPOT_LIGHT
    assert report.GetLightMethod(0) == vtkLightShaftPass.RAY_MARCH
    assert report.GetShadowMapRendered() and report.GetLightShadowMapRendered(0)
    assert report.GetNumberOfShadowCasters() == report.GetLightShadowCasters(0) > 0
    assert "method=ray-march" in report.GetShaderVariant()
    assert "void main" in report.GetSliceShaderSource()
    shafts.SetMethodToSlices()
    window.Render()
    assert report.GetMTime() > stamp
    assert report.GetMethod() == vtkLightShaftPass.SLICES
    assert report.GetLightShadowMapReused(0)  # nothing that decides the map changed
    assert report.GetNumberOfSlicesDrawn() == report.GetLightSlicesDrawn(0) > 0
    renderer.SetPass(None)


def test_each_pass_has_its_own_report():
    a, b = vtkLightShaftPass(), vtkLightShaftPass()
    assert a.GetLastFrame() is not b.GetLastFrame()
    assert isinstance(a.GetLastFrame(), vtkLightShaftFrameReport)
