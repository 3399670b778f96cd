"""lightshafts.pyvista: the shafts in a pyvista.Plotter, beside PyVista's own render passes.

PyVista keeps a chain of render passes per renderer and rebuilds it whenever one of its passes
is switched on or off; a pass set by hand with SetPass is lost at the next change. The entry
point joins that chain. Measured here: the shafts are there (in-scatter on the cone's axis above
the sphere, none in its shadow), PyVista's pass is there too (the picture differs from the
shafts alone), the order of switching does not matter (pixel-identical pictures), and switching
the shafts off gives back PyVista's picture exactly. Runs where apt has PyVista (Debian 13:
0.44, unstable: 0.49); skipped on Debian 12, which has none."""

import numpy as np
import pytest

pv = pytest.importorskip("pyvista")

from vtkmodules.vtkCommonCore import vtkOutputWindow  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkLight  # noqa: E402

import lightshafts  # noqa: E402
from lightshafts import vtkLightShaftPass  # noqa: E402
from lightshafts.pyvista import (  # noqa: E402
    disable_light_shafts, enable_light_shafts, get_light_shafts)

SIZE = (240, 180)
LIGHT_POSITION = (0.0, 6.0, 0.0)
SPHERE_CENTER = (0.0, 3.0, 0.0)
LIT_POINT = (0.0, 4.6, 0.0)      # on the cone's axis between the light and the sphere
SHADOW_POINT = (0.0, 1.2, 0.0)   # on the axis below the sphere
SHAFTS = dict(ScatteringCoefficient=(0.08, 0.08, 0.08), Exposure=50.0, NumberOfSlices=96,
              ShadowMapSize=1024)

MULTI_SAMPLES = 8  # PyVista's default (its theme's "msaa")


def _disable_anti_aliasing(plotter):
    # PyVista's disable_anti_aliasing also switches the window's multisampling off: back to the
    # plotter's own, so that the picture can be compared with the one before.
    plotter.disable_anti_aliasing()
    plotter.ren_win.SetMultiSamples(MULTI_SAMPLES)


def _enable_fxaa(plotter):
    # Through EGL or OSMesa (VTK_DEFAULT_OPENGL_WINDOW, tools/test-headless.sh) PyVista replaces
    # FXAA by SSAA and says so with a UserWarning: expected there, an error anywhere else.
    from pyvista.plotting.utilities.gl_checks import uses_egl
    if uses_egl():
        with pytest.warns(UserWarning, match="FXAA"):
            plotter.enable_anti_aliasing("fxaa")
    else:
        plotter.enable_anti_aliasing("fxaa")


# PyVista's passes, switched on and off as users do. (FXAA is the renderer's own, not a pass.)
PYVISTA_PASSES = {
    "ssao": (lambda p: p.enable_ssao(radius=1.0, kernel_size=32), lambda p: p.disable_ssao()),
    "eye_dome_lighting": (lambda p: p.enable_eye_dome_lighting(),
                          lambda p: p.disable_eye_dome_lighting()),
    "shadows": (lambda p: p.enable_shadows(), lambda p: p.disable_shadows()),
    "ssaa": (lambda p: p.enable_anti_aliasing("ssaa"), _disable_anti_aliasing),
    "fxaa": (_enable_fxaa, _disable_anti_aliasing),
    "depth_of_field": (lambda p: p.enable_depth_of_field(),
                       lambda p: p.disable_depth_of_field()),
    "blur": (lambda p: p.add_blurring(), lambda p: p.remove_blurring()),
}


def make_plotter(multi_samples=MULTI_SAMPLES):
    """A sphere over a floor under a spotlight, seen from the side: PyVista's defaults but the
    lights (the spotlight alone) and, where asked, the multisampling."""
    plotter = pv.Plotter(off_screen=True, window_size=SIZE, lighting="none")
    plotter.ren_win.SetMultiSamples(multi_samples)
    plotter.set_background("black")
    plotter.add_mesh(pv.Plane(center=(0, 0, 0), direction=(0, 1, 0), i_size=12, j_size=12,
                              i_resolution=32, j_resolution=32), color="lightgrey")
    plotter.add_mesh(pv.Sphere(radius=1.0, center=SPHERE_CENTER, theta_resolution=48,
                               phi_resolution=48), color="white")
    spot = pv.Light(position=LIGHT_POSITION, focal_point=(0, 0, 0), light_type="scene light",
                    positional=True, cone_angle=20.0, intensity=1.0)
    plotter.add_light(spot)
    plotter.camera.position = (0.0, 3.0, 14.0)
    plotter.camera.focal_point = (0.0, 3.0, 0.0)
    plotter.camera.up = (0.0, 1.0, 0.0)
    plotter.camera.view_angle = 40.0
    plotter.camera.clipping_range = (1.0, 40.0)
    return plotter, spot


def shot(plotter):
    """The plotter's picture, rendered now, as floats, row 0 at the top. (A plotter renders on
    render(), show() or its first screenshot; a later screenshot reads the last picture.)"""
    plotter.render()
    return np.asarray(plotter.screenshot(return_img=True), dtype=np.float64)[:, :, :3]


def pixel(plotter, point):
    """(row from the top, column) of a world point in the picture."""
    renderer = plotter.renderer
    renderer.SetWorldPoint(*point, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return SIZE[1] - 1 - int(round(y)), int(round(x))


def patch(image, where, radius=3):
    row, col = where
    return float(image[row - radius:row + radius + 1, col - radius:col + radius + 1].mean())


def assert_shafts(plotter, with_shafts, without_shafts):
    """The shafts are in the picture: grey levels added on the axis above the sphere, and at
    least three times fewer in its shadow below."""
    lit = patch(with_shafts, pixel(plotter, LIT_POINT)) - patch(without_shafts,
                                                                pixel(plotter, LIT_POINT))
    shadowed = patch(with_shafts, pixel(plotter, SHADOW_POINT)) - patch(
        without_shafts, pixel(plotter, SHADOW_POINT))
    assert lit > 10.0, f"no shafts: {lit:.1f} levels added above the sphere"
    assert shadowed < lit / 3.0, f"no shadow: {shadowed:.1f} below against {lit:.1f} above"
    return lit


def chain(plotter):
    """The renderer's passes from the outermost in, by class name, down to PyVista's camera
    pass."""
    names = []
    current = plotter.renderer.GetPass()
    while current is not None and current.GetClassName() != "vtkCameraPass":
        names.append(current.GetClassName())
        current = current.GetDelegatePass() if hasattr(current, "GetDelegatePass") else None
    return names


def test_messages_are_still_caught_after_pyvista_replaced_vtks_output_window(vtk_messages):
    # `import pyvista` sends VTK's messages to Python's logging through an output window of
    # its own: the tests' capture must follow it.
    vtkOutputWindow.GetInstance().DisplayWarningText("a warning after import pyvista")
    assert any("a warning after import pyvista" in text for _, text in vtk_messages.messages)
    vtk_messages.expect("a warning after import pyvista")


def test_enable_renders_the_shafts_and_disable_gives_pyvistas_picture_back():
    plotter, spot = make_plotter()
    plain = shot(plotter)
    shafts = enable_light_shafts(plotter, light=spot, **SHAFTS)
    assert isinstance(shafts, vtkLightShaftPass)
    assert get_light_shafts(plotter) is shafts and shafts.GetLight() is spot
    assert chain(plotter) == ["vtkLightShaftPass"]
    assert_shafts(plotter, shot(plotter), plain)
    disable_light_shafts(plotter)
    assert get_light_shafts(plotter) is None and plotter.renderer.GetPass() is None
    np.testing.assert_array_equal(shot(plotter), plain)
    disable_light_shafts(plotter)  # nothing to do
    plotter.close()


def test_the_picture_is_the_pass_set_up_by_hand():
    plotter, spot = make_plotter()
    enable_light_shafts(plotter, light=spot, quality="interactive", **SHAFTS)
    entry_point = shot(plotter)
    disable_light_shafts(plotter)
    by_hand = lightshafts.add_light_shafts(plotter.renderer, light=spot, quality="interactive",
                                           **SHAFTS)
    assert plotter.renderer.GetPass() is by_hand
    np.testing.assert_array_equal(shot(plotter), entry_point)
    plotter.close()


def test_no_medium_is_pixel_identical_to_pyvistas_picture():
    plotter, spot = make_plotter()
    plain = shot(plotter)
    enable_light_shafts(plotter, light=spot, ScatteringCoefficient=(0, 0, 0),
                        AbsorptionCoefficient=(0, 0, 0))
    np.testing.assert_array_equal(shot(plotter), plain)
    plotter.close()


def test_enabling_again_sets_up_the_same_pass():
    plotter, spot = make_plotter()
    first = enable_light_shafts(plotter, light=spot, **SHAFTS)
    again = enable_light_shafts(plotter, method="ray-march", Exposure=20.0)
    assert again is first and chain(plotter) == ["vtkLightShaftPass"]
    assert (again.GetMethod(), again.GetExposure(), again.GetLight()) == (
        vtkLightShaftPass.RAY_MARCH, 20.0, spot)
    plotter.close()


def test_a_vtk_light_and_no_light_at_all():
    plotter, spot = make_plotter()
    plotter.renderer.RemoveAllLights()
    plain_spot = vtkLight()
    plain_spot.DeepCopy(spot)
    plain = shot(plotter)
    shafts = enable_light_shafts(plotter, light=plain_spot, **SHAFTS)
    lights = plotter.renderer.GetLights()
    assert lights.GetNumberOfItems() == 1 and lights.GetItemAsObject(0) is plain_spot
    assert shafts.GetLight() is plain_spot
    with_plain_spot = shot(plotter)
    assert_shafts(plotter, with_plain_spot, plain)
    # No light named: the pass's own choice, the renderer's spotlight.
    shafts.SetLight(None)
    np.testing.assert_array_equal(shot(plotter), with_plain_spot)
    plotter.close()


def test_a_pyvista_light_not_yet_added_is_added_once():
    plotter, spot = make_plotter()
    plotter.remove_all_lights()
    plain = shot(plotter)
    new_spot = pv.Light(position=LIGHT_POSITION, focal_point=(0, 0, 0), positional=True,
                        cone_angle=20.0, light_type="scene light")
    enable_light_shafts(plotter, light=new_spot, **SHAFTS)
    enable_light_shafts(plotter, light=new_spot)
    assert [light for light in plotter.renderer.lights if light is new_spot] == [new_spot]
    assert len(plotter.renderer.lights) == 1
    assert_shafts(plotter, shot(plotter), plain)
    plotter.close()


def test_bad_arguments_are_refused():
    plotter, spot = make_plotter()
    with pytest.raises(TypeError, match="pyvista.Plotter"):
        enable_light_shafts(object())
    with pytest.raises(TypeError, match="NoSuchParameter"):
        enable_light_shafts(plotter, NoSuchParameter=1)
    with pytest.raises(ValueError, match="quality"):
        enable_light_shafts(plotter, quality="best")
    plotter.close()


def expect_pyvistas_unreleased_passes(vtk_messages):
    """PyVista 0.44 drops a pass it switches off without freeing its GL objects; VTK's EDL, blur,
    depth of field and shadow passes say so when they are deleted (0.49 frees them first)."""
    from pyvista.plotting.render_passes import RenderPasses
    if not hasattr(RenderPasses, "_release_graphics_resources"):
        vtk_messages.expect(r"should have been deleted in ReleaseGraphicsResources")


@pytest.mark.parametrize("name", sorted(PYVISTA_PASSES))
def test_with_pyvistas_pass_in_either_order(name, vtk_messages):
    expect_pyvistas_unreleased_passes(vtk_messages)
    enable, disable = PYVISTA_PASSES[name]
    # PyVista's pass first, then the shafts; each switched off again.
    plotter, spot = make_plotter()
    plain = shot(plotter)
    enable(plotter)
    other_alone = shot(plotter)
    shafts = enable_light_shafts(plotter, light=spot, **SHAFTS)
    both = shot(plotter)
    assert get_light_shafts(plotter) is shafts
    assert_shafts(plotter, both, other_alone)
    disable_light_shafts(plotter)
    np.testing.assert_array_equal(shot(plotter), other_alone)
    disable(plotter)
    np.testing.assert_array_equal(shot(plotter), plain)
    plotter.close()
    # The shafts first, then PyVista's pass, in another plotter: the same picture. (Not the
    # same plotter: PyVista 0.44 re-enables its shadows with another picture, shafts or not.)
    plotter, spot = make_plotter()
    enable_light_shafts(plotter, light=spot, **SHAFTS)
    shafts_alone = shot(plotter)
    enable(plotter)
    np.testing.assert_array_equal(shot(plotter), both)
    # PyVista's pass did something (its picture is not the plain one), and still does with
    # the shafts (their picture is not the shafts alone).
    assert np.abs(other_alone - plain).mean() > 0.05, f"{name} changed nothing"
    assert np.abs(both - shafts_alone).mean() > 0.05, f"{name} is gone with the shafts"
    # PyVista's pass off again: the shafts stay, as they were alone.
    disable(plotter)
    np.testing.assert_array_equal(shot(plotter), shafts_alone)
    plotter.close()


def test_the_chain_reads_geometry_inside_the_shafts_and_filters_outside(vtk_messages):
    expect_pyvistas_unreleased_passes(vtk_messages)
    plotter, spot = make_plotter()
    plotter.enable_eye_dome_lighting()
    plotter.enable_ssao(kernel_size=32)
    enable_light_shafts(plotter, light=spot, **SHAFTS)
    plotter.enable_anti_aliasing("ssaa")
    assert chain(plotter) == ["vtkSSAAPass", "vtkLightShaftPass", "vtkSSAOPass", "vtkEDLShading"]
    plotter.disable_ssao()
    plotter.enable_depth_of_field()
    plotter.add_blurring()
    assert chain(plotter) == ["vtkSSAAPass", "vtkGaussianBlurPass", "vtkDepthOfFieldPass",
                              "vtkLightShaftPass", "vtkEDLShading"]
    disable_light_shafts(plotter)
    # Without shafts, PyVista's own order, untouched.
    assert chain(plotter) == ["vtkSSAAPass", "vtkGaussianBlurPass", "vtkDepthOfFieldPass",
                              "vtkEDLShading"]
    plotter.close()


def test_text_and_scalar_bar_stay_on_top_unfogged():
    # PyVista's overlays (its text, its scalar bars) are drawn after the shafts, as VTK's own
    # steps draw them after the scene: where they are opaque, the pixels are the same.
    plotter, spot = make_plotter(multi_samples=0)
    plotter.add_text("SHAFTS", position=(60, 100), font_size=24, color="red")
    plotter.add_scalar_bar(title="", mapper=plotter.add_mesh(
        pv.Sphere(center=(-3.0, 0.5, 0.0), radius=0.4), scalars=np.arange(842),
        show_scalar_bar=False).mapper, vertical=False, position_x=0.1, position_y=0.02,
        width=0.8, height=0.1, n_labels=0)
    plain = shot(plotter)
    enable_light_shafts(plotter, light=spot, **SHAFTS, AttenuateScene=False)
    with_shafts = shot(plotter)
    red = np.all(plain == [255, 0, 0], axis=-1)
    bar = np.zeros(red.shape, dtype=bool)
    bar[int(0.9 * SIZE[1]) + 2:SIZE[1] - 2, int(0.12 * SIZE[0]):int(0.88 * SIZE[0])] = True
    assert red.sum() > 30 and np.abs(plain[bar] - plain[bar].mean(axis=0)).max() > 50
    np.testing.assert_array_equal(with_shafts[red], plain[red])
    np.testing.assert_array_equal(with_shafts[bar], plain[bar])
    assert_shafts(plotter, with_shafts, plain)  # while the shafts are there
    plotter.close()


def test_multisampling_off_and_on():
    for samples in (0, 4):
        plotter, spot = make_plotter(multi_samples=samples)
        plain = shot(plotter)
        enable_light_shafts(plotter, light=spot, **SHAFTS)
        assert_shafts(plotter, shot(plotter), plain)
        plotter.close()


def test_the_shafts_survive_ssao_switched_on_and_off(vtk_messages):
    expect_pyvistas_unreleased_passes(vtk_messages)
    # The session: the pass was lost when PyVista rebuilt its chain for SSAO.
    plotter, spot = make_plotter()
    plain = shot(plotter)
    enable_light_shafts(plotter, light=spot, **SHAFTS)
    shafts_alone = shot(plotter)
    plotter.enable_ssao(kernel_size=32)
    assert_shafts(plotter, shot(plotter), plain)
    plotter.disable_ssao()
    np.testing.assert_array_equal(shot(plotter), shafts_alone)
    plotter.close()
