"""Junk on the VTK objects the pass reads (issue 24): values VTK takes that the shafts cannot
use. Each gives a finite picture: the light (or prop, or image) is left out for the frame, or
the frame renders without shafts (the camera), with one warning that names the object and its
value, not repeated while the value stays, said again when it changes. The rest renders.
"""

import math

import numpy as np
import pytest

from lightshafts import parameter_owner, scenes, vtkLightShaftPass
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkRenderingCore import vtkTexture

import render_helpers as rh
from vtk_output import Messages

WIDTH, HEIGHT = 160, 120


def junk_scene():
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=24)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.3)
    renderer.SetPass(shafts)
    return renderer, window, info, shafts, Messages(shafts)


def render(window, shafts):
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    image = rh.in_scatter(shafts)
    assert np.all(np.isfinite(image))
    return image


def nan_transform():
    matrix = vtkMatrix4x4()
    matrix.SetElement(0, 3, math.nan)
    return matrix


LIGHT_JUNK = {
    "exponent": (lambda light: light.SetExponent(math.nan), "its exponent is nan"),
    "intensity": (lambda light: light.SetIntensity(math.nan), "its intensity is nan"),
    "negative intensity": (lambda light: light.SetIntensity(-1.0), "its intensity is -1"),
    "colour": (lambda light: light.SetDiffuseColor(1.0, math.nan, 1.0),
               "its diffuse colour is (1, nan, 1)"),
    "attenuation": (lambda light: light.SetAttenuationValues(math.nan, 0.0, 0.0),
                    "its attenuation is (nan, 0, 0)"),
    "negative attenuation": (lambda light: light.SetAttenuationValues(1.0, -2.0, 0.0),
                             "its attenuation is (1, -2, 0)"),
    "cone angle": (lambda light: light.SetConeAngle(math.nan), "its cone angle is nan"),
    "no direction": (lambda light: light.SetPosition(*light.GetFocalPoint()),
                     "its position equals its focal point"),
    "transform": (lambda light: light.SetTransformMatrix(nan_transform()), "its position is (nan"),
}


@pytest.mark.parametrize("junk", LIGHT_JUNK)
def test_a_light_with_junk_is_left_out_with_one_warning(junk):
    renderer, window, info, shafts, log = junk_scene()
    shafted = render(window, shafts)
    assert shafted.max() > 0.0 and not log.warnings
    apply, value = LIGHT_JUNK[junk]
    apply(info.light)
    for _ in range(3):
        image = render(window, shafts)
        assert image.max() == 0.0  # the only light, left out
        assert shafts.GetLastFrame().GetNumberOfUsedLights() == 0
    assert len(log.warnings) == 1, log.warnings
    assert "is left out of the shafts" in log.warnings[0] and value in log.warnings[0]
    assert "): Light 0x" in log.warnings[0]  # the object, by its address


def test_a_light_back_to_usable_values_comes_back_and_new_junk_is_said_again():
    renderer, window, info, shafts, log = junk_scene()
    shafted = render(window, shafts)
    info.light.SetExponent(math.nan)
    render(window, shafts)
    info.light.SetExponent(1.0)
    assert np.array_equal(render(window, shafts), shafted)
    info.light.SetExponent(math.nan)
    render(window, shafts)
    info.light.SetIntensity(math.nan)  # another value: said
    render(window, shafts)
    assert len(log.warnings) == 3
    assert ["exponent" in log.warnings[0], "exponent" in log.warnings[1],
            "intensity" in log.warnings[2]] == [True, True, True]


def test_the_other_lights_keep_their_shafts():
    renderer, window, info, shafts, log = junk_scene()
    point = scenes.add_point_light(renderer, (-1.5, 3.2, 1.0), intensity=0.8)
    alone = vtkLightShaftPass()
    alone.GetMedium().SetScatteringCoefficient(0.3)
    alone.SetLight(point)
    renderer.SetPass(alone)
    expected = render(window, alone)
    renderer.SetPass(shafts)
    info.light.SetDiffuseColor(math.nan, 1.0, 1.0)
    image = render(window, shafts)
    assert shafts.GetLastFrame().GetNumberOfUsedLights() == 1 and shafts.GetLastFrame().GetUsedLight(0) is point
    assert np.allclose(image, expected, rtol=1e-5, atol=1e-9)
    assert len(log.warnings) == 1


CAMERA_JUNK = {
    "parallel scale 0": (lambda c: (c.ParallelProjectionOn(), c.SetParallelScale(0.0)),
                         "its parallel scale is 0"),
    "parallel scale nan": (lambda c: (c.ParallelProjectionOn(), c.SetParallelScale(math.nan)),
                           "its parallel scale is nan"),
    "clipping range nan": (lambda c: c.SetClippingRange(math.nan, 10.0),
                           "its clipping range is (nan, 10)"),
}


@pytest.mark.parametrize("junk", CAMERA_JUNK)
def test_a_camera_with_junk_renders_the_scene_without_shafts(junk):
    renderer, window, info, shafts, log = junk_scene()
    renderer.ResetCameraClippingRange()
    apply, value = CAMERA_JUNK[junk]
    apply(renderer.GetActiveCamera())
    for _ in range(3):
        window.Render()
        assert shafts.GetLastFrame().GetGLErrorCount() == 0
        assert shafts.GetLastFrame().GetMethod() == -1
    assert len(log.warnings) == 1, log.warnings
    assert "The camera cannot be used for the shafts" in log.warnings[0]
    assert value in log.warnings[0]


@pytest.mark.parametrize("angle", [0.0, 180.0, 1e-12, 179.999])
def test_view_angles_at_their_limits_give_finite_pictures(angle):
    renderer, window, info, shafts, log = junk_scene()
    renderer.GetActiveCamera().SetViewAngle(angle)  # VTK clamps to [1e-8, 179]
    render(window, shafts)
    assert not log.warnings


def test_a_camera_on_its_focal_point_gives_a_finite_picture():
    renderer, window, info, shafts, log = junk_scene()
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*camera.GetFocalPoint())
    render(window, shafts)
    assert all("The camera cannot be used" in w for w in log.warnings)


def test_a_prop_with_a_nan_transform_casts_no_shadow_and_the_others_do():
    renderer, window, info, shafts, log = junk_scene()
    box = rh.add_box(renderer, (0.6, 0.6, 0.6), centre=(-1.5, 0.3, 1.0))
    render(window, shafts)
    casters = shafts.GetLastFrame().GetNumberOfShadowCasters()
    box.SetPosition(math.nan, 0.0, 0.0)
    for _ in range(2):
        render(window, shafts)
        assert shafts.GetLastFrame().GetNumberOfShadowCasters() == casters - 1
        assert shafts.GetLastFrame().GetShadowMapRendered() or shafts.GetLastFrame().GetNumberOfShadowCasters() > 0
    assert len(log.warnings) == 1, log.warnings
    assert "casts no shadow in the shafts" in log.warnings[0]
    assert "transform matrix holds nan" in log.warnings[0]
    box.SetPosition(0.0, 0.0, 0.0)
    render(window, shafts)
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() == casters and len(log.warnings) == 1


def test_a_prop_with_nan_points_gives_a_finite_picture():
    renderer, window, info, shafts, log = junk_scene()
    box = rh.add_box(renderer, (0.6, 0.6, 0.6), centre=(-1.5, 0.3, 1.0))
    source = box.GetMapper().GetInputAlgorithm()
    source.Update()
    polydata = source.GetOutput()
    bad = vtkPoints()
    bad.DeepCopy(polydata.GetPoints())
    bad.SetPoint(0, math.nan, 0.0, 0.0)
    copy = type(polydata)()
    copy.DeepCopy(polydata)
    copy.SetPoints(bad)
    box.GetMapper().SetInputData(copy)
    render(window, shafts)  # VTK's bounds skip NaN: the box still casts with its other faces
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() >= 1
    assert not log.warnings


def image_texture(values):
    image = vtkImageData()
    image.SetDimensions(len(values), 1, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(np.asarray(values, np.float32), deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


@pytest.mark.parametrize("which,said", [("Cookie", "no cookie is applied"),
                                        ("NoiseTexture", "using the generated noise")])
def test_images_with_non_finite_texels_are_left_out(which, said):
    renderer, window, info, shafts, log = junk_scene()
    shafts.GetMedium().SetNoiseAmplitude(0.5)
    getattr(parameter_owner(shafts, which), "Set" + which)(image_texture([1.0, 0.5, math.inf, 1.0]))
    for _ in range(2):
        render(window, shafts)
    assert len(log.warnings) == 1, log.warnings
    assert "cannot be used (texel 2 is inf)" in log.warnings[0] and said in log.warnings[0]
