"""Surfaces lit as the shafts are lit (ShadowSurfaces).

- No acne, no peter-panning: a sphere, a torus and a tilted plane that nothing occludes keep
  their light under a spot, a point and a directional light at 512^2 to 8192^2 maps (and
  multisampled); the README's sphere keeps it at 1024^2 and 4096^2; the contact shadow under a
  box resting on the floor starts at the contact line.
- The light leg's transmittance: the floor under an absorbing medium (optical depth 1 between
  light and floor) and under the smoke plume of examples/smoke_plume.py has the float64
  reference's surface term (vtkLightShaftReference's SurfaceLight); AttenuateSurfaceLight off
  keeps VTK's own lighting.
- No clipped shares: a floor lit beyond white keeps its whole shadow.
"""

import os
import sys

import numpy as np
import pytest
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import (vtkCubeSource, vtkParametricFunctionSource,
                                          vtkPlaneSource, vtkSphereSource)
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper

from lightshafts import add_light_shafts, vtkLightShaftPass

import render_helpers as rh

WIDTH, HEIGHT = 320, 240


def add_surface(renderer, source, color=(1.0, 1.0, 1.0), opacity=1.0):
    """A diffuse actor of `source` (no ambient or specular light: the lights' shares alone)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(*color)
    prop.SetOpacity(opacity)
    prop.SetAmbient(0.0)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(0.0)
    renderer.AddActor(actor)
    return actor


def plane(origin, point1, point2):
    source = vtkPlaneSource()
    source.SetOrigin(*origin)
    source.SetPoint1(*point1)
    source.SetPoint2(*point2)
    return source


def floor(half=6.0):
    return plane((-half, 0.0, -half), (half, 0.0, -half), (-half, 0.0, half))


def look(renderer, position, focal_point):
    """Put the renderer's camera at `position`, looking at `focal_point`."""
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal_point)
    renderer.ResetCameraClippingRange()


def shape_source(shape):
    """The test shapes, centred 3 units above the floor."""
    if shape == "sphere":
        source = vtkSphereSource()
        source.SetCenter(0.0, 3.0, 0.0)
        source.SetRadius(0.8)
        source.SetThetaResolution(48)
        source.SetPhiResolution(48)
        return source
    if shape == "torus":
        torus = vtkParametricTorus()
        torus.SetRingRadius(0.9)
        torus.SetCrossSectionRadius(0.3)
        source = vtkParametricFunctionSource()
        source.SetParametricFunction(torus)
        source.SetUResolution(64)
        source.SetVResolution(32)
        lying = vtkTransform()
        lying.Translate(0.0, 3.0, 0.0)
        lying.RotateX(90.0)
        moved = vtkTransformPolyDataFilter()
        moved.SetTransform(lying)
        moved.SetInputConnection(source.GetOutputPort())
        return moved
    source = plane((-1.0, 0.0, -1.0), (1.0, 0.0, -1.0), (-1.0, 0.0, 1.0))
    source.SetCenter(0.0, 3.0, 0.0)
    source.SetNormal(0.5, 1.0, 0.3)  # tilted about 30 degrees
    return source


def make_light(kind, position=(0.0, 6.0, 0.0), focal=(0.0, 0.0, 0.0), cone=30.0):
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(*position)
    light.SetFocalPoint(*focal)
    if kind == "directional":
        light.SetPositional(False)
    else:
        light.SetPositional(True)
        light.SetConeAngle(cone if kind == "spot" else 180.0)
    return light


def shape_pictures(shape, kind, sizes, samples):
    """The shape over the floor under the light: VTK's picture, the shape's pixels, and the
    picture with ShadowSurfaces at each map size (empty medium: the surfaces alone)."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    window.SetMultiSamples(samples)
    add_surface(renderer, shape_source(shape), (0.9, 0.9, 0.9))
    add_surface(renderer, floor(), (0.7, 0.7, 0.7))
    light = make_light(kind, position=(0.3, 6.0, 0.2) if kind == "directional" else (0, 6, 0))
    renderer.AddLight(light)
    look(renderer, (2.0, 5.0, 10.0), (0.0, 2.5, 0.0))
    try:
        window.Render()
        plain = rh.screenshot(window).astype(float)
        points, depth = rh.depth_points(renderer, window)
        shafts = vtkLightShaftPass()
        shafts.AddLight(light)
        shafts.GetMedium().SetScatteringCoefficient(0.0)
        shafts.ShadowSurfacesOn()
        renderer.SetPass(shafts)
        pictures = {}
        for size in sizes:
            shafts.SetShadowMapSize(size)
            window.Render()
            assert shafts.GetLastFrame().GetGLErrorCount() == 0
            pictures[size] = rh.screenshot(window).astype(float)
    finally:
        window.SetMultiSamples(0)
    return plain, (depth < 1.0) & (points[..., 1] > 0.05), pictures


def assert_keeps_its_light(plain, mask, shadowed, what):
    ratio = shadowed[mask].mean() / plain[mask].mean()
    assert 0.98 <= ratio <= 1.0005, f"{what}: {ratio:.4f} of its light"
    lit = mask & (plain.sum(-1) > 60.0)
    darkened = (shadowed[lit].sum(-1) < 0.9 * plain[lit].sum(-1)).mean()
    assert darkened < 0.002, f"{what}: {100 * darkened:.2f}% of its lit pixels darkened (acne)"


@pytest.mark.parametrize("kind", ["spot", "point", "directional"])
@pytest.mark.parametrize("shape", ["sphere", "torus", "tilted-plane"])
def test_unoccluded_surfaces_keep_their_light(shape, kind):
    plain, mask, pictures = shape_pictures(shape, kind, (512, 2048, 8192), samples=0)
    for size, shadowed in pictures.items():
        assert_keeps_its_light(plain, mask, shadowed, f"{shape}, {kind}, {size}^2")


@pytest.mark.parametrize("kind", ["spot", "point", "directional"])
def test_a_multisampled_sphere_keeps_its_light(kind):
    # Each sample's surface point is where that sample lies in its pixel (taken at the pixel's
    # centre, a sloped surface's points were half a pixel's slope off: acne at fine maps).
    plain, mask, pictures = shape_pictures("sphere", kind, (512, 8192), samples=4)
    for size, shadowed in pictures.items():
        assert_keeps_its_light(plain, mask, shadowed, f"sphere, {kind}, {size}^2, 4 samples")


def readme_scene(map_size, shadow_surfaces, attenuate_surface_light=True):
    """The README's Python example (its window's own multisampling), with ShadowSurfaces."""
    renderer, window = rh.make_window(640, 480)
    window.SetMultiSamples(8)
    sphere = shape_source("sphere")
    for source in (sphere, floor()):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    spot = make_light("spot", cone=25.0)
    shafts = add_light_shafts(renderer, light=spot, quality="interactive",
                              ScatteringCoefficient=0.05, Exposure=40)
    shafts.SetShadowMapSize(map_size)
    shafts.SetShadowSurfaces(shadow_surfaces)
    shafts.SetAttenuateSurfaceLight(attenuate_surface_light)
    look(renderer, (2.0, 3.5, 14.0), (0.0, 2.5, 0.0))
    try:
        window.Render()
        picture = rh.screenshot(window).astype(float)
        points, depth = rh.depth_points(renderer, window)
    finally:
        window.SetMultiSamples(0)
    upper_half = ((depth < 1.0) & (np.linalg.norm(points - (0.0, 3.0, 0.0), axis=-1) < 0.85)
                  & (points[..., 1] > 3.0))
    return picture, upper_half


@pytest.mark.parametrize("map_size", [1024, 4096])
def test_the_readme_sphere_keeps_its_light(map_size):
    plain, upper_half = readme_scene(map_size, False)
    # VTK's light on the surfaces but for the shadows: no acne.
    shadowed, _ = readme_scene(map_size, True, attenuate_surface_light=False)
    ratio = shadowed[upper_half].mean() / plain[upper_half].mean()
    assert abs(ratio - 1.0) < 0.02, ratio  # (0.90 and 0.70 before)
    # And dimmed by the medium on the light's way, by e^(-0.05 r) for r from 2.2 to 3.8 (its
    # shafts and unlit parts are the same in both pictures: the ratio is a little above).
    dimmed, _ = readme_scene(map_size, True)
    ratio = dimmed[upper_half].mean() / plain[upper_half].mean()
    assert np.exp(-0.05 * 3.8) < ratio < 0.95, ratio


def box_shadow(points, light, low, high):
    """Whether the segment from each point to the light passes through the box [low, high]."""
    d = np.asarray(light, float) - points
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (np.asarray(low) - points) / d
        t1 = (np.asarray(high) - points) / d
    enter = np.nanmax(np.minimum(t0, t1), axis=-1)
    leave = np.nanmin(np.maximum(t0, t1), axis=-1)
    return (leave > np.maximum(enter, 0.0)) & (enter < 1.0)


def erode(mask, pixels):
    out = mask.copy()
    for dy in range(-pixels, pixels + 1):
        for dx in range(-pixels, pixels + 1):
            out &= np.roll(np.roll(mask, dy, 0), dx, 1)
    return out


def test_the_contact_shadow_starts_at_the_contact_line():
    renderer, window = rh.make_window(640, 480)
    low, high = (-0.75, 0.0, -0.75), (0.75, 1.0, 0.75)
    box = vtkCubeSource()
    box.SetBounds(low[0], high[0], low[1], high[1], low[2], high[2])
    add_surface(renderer, box, (0.9, 0.6, 0.4))
    add_surface(renderer, floor(), (0.8, 0.8, 0.8))
    position = (3.0, 6.0, 1.0)
    spot = make_light("spot", position=position, cone=40.0)
    renderer.AddLight(spot)
    shafts = vtkLightShaftPass()
    shafts.AddLight(spot)
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    shafts.ShadowSurfacesOn()
    renderer.SetPass(shafts)
    look(renderer, (-7.0, 4.0, 5.0), (0.0, 0.5, 0.0))
    window.Render()
    picture = rh.screenshot(window).astype(float).sum(-1)
    points, depth = rh.depth_points(renderer, window)
    on_floor = (depth < 1.0) & (np.abs(points[..., 1]) < 0.01)
    shadowed = on_floor & box_shadow(points, position, low, high)
    to_floor = points - position
    axis = -np.asarray(position) / np.linalg.norm(position)
    in_cone = (to_floor @ axis) / np.linalg.norm(to_floor, axis=-1) > np.cos(np.radians(38.0))
    lit = on_floor & in_cone & ~box_shadow(points, position, low, high)
    # Floor pixels more than 2 pixels inside the shadow (up to the contact line) are dark,
    # those more than 2 pixels outside it lit.
    inside = erode(shadowed | ~on_floor, 2) & shadowed
    outside = erode(lit, 2)
    assert inside.sum() > 2000
    assert picture[inside].max() <= 3.0, "light inside the shadow (peter-panning)"
    assert picture[outside].min() > 0.5 * np.median(picture[outside]), "a lit floor shadowed"
    # Next to the box (its silhouette over the floor) the floor is in its shadow too.
    box_edge = (depth < 1.0) & ~on_floor
    touching = inside & ~erode(~box_edge, 3)
    assert touching.sum() > 20
    assert picture[touching].max() <= 3.0


def surface_against_reference(renderer, window, light, shafts):
    """The floor lit through the medium: the pass's picture and what the reference's surface
    term makes of VTK's own pictures with and without the light, unlit + F (lit - unlit)."""
    renderer.SetPass(None)
    window.Render()
    lit = rh.screenshot(window).astype(float)
    intensity = light.GetIntensity()
    light.SetIntensity(0.0)
    window.Render()
    unlit = rh.screenshot(window).astype(float)
    light.SetIntensity(intensity)
    renderer.SetPass(shafts)
    window.Render()
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    picture = rh.screenshot(window).astype(float)
    factor = rh.scene_reference(renderer, shafts, "SurfaceLight")[..., :3]  # first light
    expected = unlit + factor * (lit - unlit)
    points, depth = rh.depth_points(renderer, window)
    on_floor = (depth < 1.0) & (np.abs(points[..., 1]) < 0.01)
    # Away from shadow edges (where the map's texels and the exact visibility differ by a
    # pixel) and where the light's share is large enough to measure.
    visible = factor.max(-1) > 1e-3
    steady = erode(visible, 2) | erode(~visible, 2)
    region = on_floor & steady & ((lit - unlit).max(-1) > 40.0)
    return picture, expected, lit, region


def test_the_floor_under_an_absorbing_medium_has_the_reference_surface_term():
    # A slab over the floor in a thick homogeneous medium (optical depth 1 from light to floor).
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    add_surface(renderer, floor(), (0.9, 0.9, 0.9))
    slab = vtkCubeSource()
    slab.SetBounds(-0.8, 0.8, 2.9, 3.1, -0.8, 0.8)
    add_surface(renderer, slab, (0.8, 0.5, 0.3))
    spot = make_light("spot", cone=35.0)
    renderer.AddLight(spot)
    shafts = vtkLightShaftPass()
    shafts.AddLight(spot)
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    shafts.GetMedium().SetAbsorptionCoefficient(1.0 / 6.0)  # optical depth 1 light -> floor
    shafts.AttenuateSceneOff()
    shafts.ShadowSurfacesOn()
    look(renderer, (2.0, 6.0, 10.0), (0.0, 1.0, 0.0))
    picture, expected, lit, region = surface_against_reference(renderer, window, spot, shafts)
    assert region.sum() > 3000
    # Below the light the floor gets e^-1 of VTK's light.
    points = rh.depth_points(renderer, window)[0]
    r = np.linalg.norm(points - (0.0, 6.0, 0.0), axis=-1)
    beside = region & (np.abs(points[..., [0, 2]]).max(-1) > 2.0)  # (not the slab's shadow)
    dimmed = lit[beside] * np.exp(-r[beside] / 6.0)[:, None]
    assert np.allclose(picture[beside].sum() / dimmed.sum(), 1.0, atol=0.02)
    error = np.abs(picture[region].mean(0) - expected[region].mean(0)) / expected[region].mean(0)
    assert error.max() < 0.02, error
    assert np.percentile(np.abs(picture - expected)[region], 99) <= 3.0

    # AttenuateSurfaceLight off: VTK's own light (but for the shadows) as before.
    shafts.AttenuateSurfaceLightOff()
    window.Render()
    vtk_light = rh.screenshot(window).astype(float)
    shafts.GetMedium().SetAbsorptionCoefficient(0.0)
    window.Render()
    assert np.abs(vtk_light - rh.screenshot(window).astype(float)).max() <= 1.0


def test_the_floor_under_the_plume_has_the_reference_surface_term():
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
    try:
        import smoke_plume
    finally:
        sys.path.pop(0)
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    add_surface(renderer, plane((-8.0, 0.0, -8.0), (-8.0, 0.0, 8.0), (8.0, 0.0, -8.0)),
                (0.7, 0.68, 0.65))
    spot = make_light("spot", position=(-4.5, 9.0, 1.5), focal=(0.5, 1.0, 0.0), cone=24.0)
    renderer.AddLight(spot)
    shafts = vtkLightShaftPass()
    shafts.AddLight(spot)
    medium = shafts.GetMedium()
    medium.SetScatteringCoefficient(0.0)
    medium.SetAbsorptionCoefficient(0.35)  # the example's extinction, all of it absorbed
    medium.SetDensityField(smoke_plume.plume())
    medium.SetDensityScale(3.0)
    medium.SetBackgroundDensity(0.08)
    shafts.AttenuateSceneOff()
    shafts.ShadowSurfacesOn()
    look(renderer, (0.5, 7.0, 14.0), (1.0, 0.0, 0.0))
    picture, expected, lit, region = surface_against_reference(renderer, window, spot, shafts)
    assert region.sum() > 1000
    # The plume takes a good part of the light (the test means something).
    assert expected[region].mean() < 0.8 * lit[region].mean()
    error = np.abs(picture[region].mean(0) - expected[region].mean(0)) / expected[region].mean(0)
    assert error.max() < 0.02, error


@pytest.mark.parametrize("samples", [0, 4])
def test_a_floor_lit_beyond_white_keeps_its_whole_shadow(samples):
    """A dark translucent square (passing half the light) over a white floor: at 1.6 times the
    light, the floor in its shadow is 1.6 times as bright as at 1 while the lit floor clips."""
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    window.SetMultiSamples(samples)
    add_surface(renderer, floor(), (1.0, 1.0, 1.0))
    add_surface(renderer, plane((-1.0, 3.0, -1.0), (1.0, 3.0, -1.0), (-1.0, 3.0, 1.0)),
                (0.0, 0.0, 0.0), opacity=0.5)
    spot = make_light("spot", cone=40.0)
    renderer.AddLight(spot)
    shafts = vtkLightShaftPass()
    shafts.AddLight(spot)
    shafts.GetMedium().SetScatteringCoefficient(0.0)
    shafts.ShadowSurfacesOn()
    renderer.SetPass(shafts)
    look(renderer, (0.0, 2.0, 12.0), (0.0, 0.0, 0.0))  # below the square: the floor seen past it
    levels = {}
    try:
        for intensity in (1.0, 1.6):
            spot.SetIntensity(intensity)
            window.Render()
            picture = rh.screenshot(window).astype(float)[..., 0]
            points, depth = rh.depth_points(renderer, window)
            on_floor = (depth < 1.0) & (np.abs(points[..., 1]) < 0.01)
            across = np.abs(points[..., [0, 2]]).max(-1)
            shadow = on_floor & (across < 1.7)          # the square's shadow: |x|, |z| < 2
            lit = on_floor & (across > 2.3) & (across < 2.8)
            levels[intensity] = (picture[lit].mean(), picture[shadow].mean())
    finally:
        window.SetMultiSamples(0)
    (lit1, shadow1), (lit16, shadow16) = levels[1.0], levels[1.6]
    assert lit16 == 255.0 and lit1 < 230.0  # clipped, and not at 1
    assert abs(shadow16 - 1.6 * shadow1) <= 0.02 * 1.6 * shadow1, (shadow1, shadow16)
