"""Picking and selection through the pass give exactly the answers they give without it.

VTK's hardware selector renders ids, not colours: while it renders, the pass draws the plain
scene as the renderer would without it (GetLastFrame().GetPlainScene()), and the next frame has its shafts
again. Compared with the same scene and camera with no pass: vtkHardwareSelector (cells,
points; the whole window, boxes and single pixels), vtkPropPicker (with and without a pick
list), vtkCellPicker (software),
vtkRenderer.PickProp, and vtkRenderer.GetZ after a frame.
"""

import numpy as np
import pytest

from lightshafts import scenes, vtkLightShaftPass
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkRenderingCore import vtkCellPicker, vtkHardwareSelector, vtkPropPicker

import render_helpers as rh

WIDTH, HEIGHT = 200, 150


def scene(with_pass, multisamples=0):
    renderer, window = rh.make_window(WIDTH, HEIGHT)
    window.SetMultiSamples(multisamples)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=24)
    shafts = None
    if with_pass:
        shafts = vtkLightShaftPass()
        shafts.GetMedium().SetScatteringCoefficient(0.08)
        renderer.SetPass(shafts)
    window.Render()
    return renderer, window, info, shafts


def select(renderer, area, field):
    """{actor index: sorted ids} of a hardware selection over `area` (x0, y0, x1, y1)."""
    selector = vtkHardwareSelector()
    selector.SetRenderer(renderer)
    selector.SetArea(*area)
    selector.SetFieldAssociation(field)
    selection = selector.Select()
    actors = list(renderer.GetActors())
    result = {}
    for i in range(selection.GetNumberOfNodes()):
        node = selection.GetNode(i)
        prop = node.GetProperties().Get(node.PROP())
        ids = node.GetSelectionList()
        result[actors.index(prop)] = sorted(ids.GetValue(j) for j in range(ids.GetNumberOfTuples()))
    return result


def both(check):
    """Run `check(renderer, window, info, shafts)` on the scene without and with the pass."""
    results = []
    for with_pass in (False, True):
        renderer, window, info, shafts = scene(with_pass)
        results.append(check(renderer, window, info, shafts))
        window.SetMultiSamples(0)
    return results


FIELDS = {"cells": vtkDataObject.FIELD_ASSOCIATION_CELLS,
          "points": vtkDataObject.FIELD_ASSOCIATION_POINTS}


@pytest.mark.parametrize("field", sorted(FIELDS))
@pytest.mark.parametrize("area", [(0, 0, WIDTH - 1, HEIGHT - 1), (100, 70, 100, 70),
                                  (70, 30, 130, 60)], ids=["window", "pixel", "box"])
def test_hardware_selection_is_unchanged(field, area):
    plain, shafted = both(lambda r, w, i, s: select(r, area, FIELDS[field]))
    assert plain, "the selection should hit something"
    assert shafted == plain


def test_selection_then_the_shafts_come_back():
    renderer, window, info, shafts = scene(True)
    before = rh.screenshot(window)
    slabs = shafts.GetLastFrame().GetNumberOfSlicesDrawn()
    assert slabs > 0 and not shafts.GetLastFrame().GetPlainScene()
    hits = select(renderer, (0, 0, WIDTH - 1, HEIGHT - 1), FIELDS["cells"])
    assert len(hits) == 2
    assert shafts.GetLastFrame().GetPlainScene()
    window.Render()
    assert not shafts.GetLastFrame().GetPlainScene()
    assert shafts.GetLastFrame().GetNumberOfSlicesDrawn() == slabs
    np.testing.assert_array_equal(rh.screenshot(window), before)


def test_prop_picker_is_unchanged():
    def pick(renderer, window, info, shafts):
        picker = vtkPropPicker()
        found = []
        for x, y in [(100, 75), (100, 20), (5, 145), (150, 60)]:
            hit = picker.Pick(x, y, 0, renderer)
            prop = picker.GetViewProp()
            found.append((hit, info.actors.index(prop) if prop else None,
                          tuple(np.round(picker.GetPickPosition(), 4))))
        return found
    plain, shafted = both(pick)
    assert plain[0][1] == 0  # the sphere at the centre
    assert shafted == plain


def display_point(renderer, world):
    renderer.SetWorldPoint(*world, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return int(round(x)), int(round(y))


def test_prop_picker_honours_its_pick_list():
    # A pixel on the sphere's lower part, with the floor behind it: with the floor alone in the
    # pick list the picker finds the floor through the sphere.
    def pick(renderer, window, info, shafts):
        x, y = display_point(renderer, (0.0, 0.9, 0.5))
        found = []
        for listed in (None, 0, 1):
            picker = vtkPropPicker()
            if listed is not None:
                picker.PickFromListOn()
                picker.AddPickList(info.actors[listed])
            picker.Pick(x, y, 0, renderer)
            prop = picker.GetViewProp()
            found.append(info.actors.index(prop) if prop else None)
        return found
    plain, shafted = both(pick)
    assert plain == [0, 0, 1]
    assert shafted == plain


def test_renderer_pick_prop_is_unchanged():
    def pick(renderer, window, info, shafts):
        found = []
        for x, y in [(100, 75), (100, 20), (5, 145)]:
            path = renderer.PickProp(x, y)
            found.append(info.actors.index(path.GetFirstNode().GetViewProp()) if path else None)
        return found
    plain, shafted = both(pick)
    assert plain[0] == 0
    assert shafted == plain


def test_cell_picker_is_unchanged():
    def pick(renderer, window, info, shafts):
        picker = vtkCellPicker()
        picker.SetTolerance(0.0)
        picker.Pick(100, 75, 0, renderer)
        return picker.GetCellId(), tuple(np.round(picker.GetPickPosition(), 6))
    plain, shafted = both(pick)
    assert plain[0] >= 0
    assert shafted == plain


def test_depth_queries_are_unchanged():
    # GetZ reads the last frame's depth: the composite writes the scene's depth.
    def depths(renderer, window, info, shafts):
        return [renderer.GetZ(x, y) for x, y in [(100, 75), (100, 10), (5, 145), (199, 149)]]
    plain, shafted = both(depths)
    assert min(plain) < 1.0
    assert shafted == plain


@pytest.mark.parametrize("multisamples", [0, 4])
def test_selection_with_a_delegate_and_multisampling(multisamples):
    from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
    results = []
    for with_pass in (False, True):
        renderer, window, info, shafts = scene(with_pass, multisamples)
        if shafts:
            shafts.SetDelegatePass(vtkRenderStepsPass())
            window.Render()
        results.append(select(renderer, (0, 0, WIDTH - 1, HEIGHT - 1), FIELDS["cells"]))
        window.SetMultiSamples(0)
    assert results[0] and results[1] == results[0]


def test_depth_only_passes_get_the_plain_scene():
    # vtkShadowMapBakerPass renders its opaque sequence into a depth-only target from each
    # light: the pass nested there draws only what its delegate draws (no shafts), so the
    # surface shadows are the same as without it.
    from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkLightsPass, vtkOpaquePass,
                                                vtkRenderPassCollection, vtkRenderStepsPass,
                                                vtkSequencePass, vtkShadowMapPass)

    def sequence(*passes):
        collection = vtkRenderPassCollection()
        for p in passes:
            collection.AddItem(p)
        result = vtkSequencePass()
        result.SetPasses(collection)
        return result

    pictures = []
    for nest in (False, True):
        renderer, window = rh.make_window(WIDTH, HEIGHT)
        scenes.sphere_and_floor(renderer, sphere_resolution=24)
        shadows = vtkShadowMapPass()
        baker = shadows.GetShadowMapBakerPass()
        occluders = sequence(vtkLightsPass(), vtkOpaquePass())
        nested = vtkLightShaftPass()
        if nest:
            nested.SetDelegatePass(occluders)
            occluders = nested
        camera = vtkCameraPass()
        camera.SetDelegatePass(occluders)
        baker.SetOpaqueSequence(camera)
        steps = vtkRenderStepsPass()
        steps.SetOpaquePass(sequence(baker, shadows))
        renderer.SetPass(steps)
        window.Render()
        assert baker.GetHasShadows()
        pictures.append(rh.screenshot(window))
        if nest:
            assert nested.GetLastFrame().GetPlainScene()
            assert nested.GetLastFrame().GetMethod() == -1 and nested.GetLastFrame().GetNumberOfSlicesDrawn() == 0
    np.testing.assert_array_equal(pictures[1], pictures[0])
