"""The hooks distributed rendering uses (ParaView under MPI): ShadowMapRenderedEvent with
GetShadowMapTexture(), SetShadowCasterBounds(), and PaintBackground with PaintedBackground."""

import math

import numpy as np

from lightshafts import scenes, vtkLightShaftPass
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLFramebufferObject

import render_helpers as rh


def clear_depth(window, texture, value):
    """Overwrite a depth texture with one value (what a combining observer would upload)."""
    fbo = vtkOpenGLFramebufferObject()
    fbo.SetContext(window)
    state = window.GetState()
    state.PushFramebufferBindings()
    fbo.Bind()
    fbo.AddDepthAttachment(texture)
    fbo.StartNonOrtho(texture.GetWidth(), texture.GetHeight())
    state.vtkglDepthMask(True)
    state.vtkglClearDepth(value)
    state.vtkglClear(0x100)  # GL_DEPTH_BUFFER_BIT
    state.vtkglClearDepth(1.0)
    fbo.RemoveDepthAttachment()
    state.PopFramebufferBindings()
    fbo.ReleaseGraphicsResources(window)


def test_the_shadow_map_event_lets_an_observer_rewrite_the_map():
    renderer, window = rh.make_window(160, 120)
    scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = rh.plain_slab_pass(slices=64, shadow_map=512)
    renderer.SetPass(shafts)
    window.Render()
    original = rh.in_scatter(shafts)
    seen = []

    def occlude_everything(pass_, _event):
        texture = pass_.GetShadowMapTexture()
        seen.append((texture.GetWidth(), texture.GetHeight()))
        clear_depth(window, texture, 0.0)  # an occluder at the near plane everywhere

    shafts.AddObserver(vtkLightShaftPass.ShadowMapRenderedEvent, occlude_everything)
    window.Render()
    assert seen == [(512, 512)]  # once per frame, during the frame
    assert shafts.GetShadowMapTexture() is None  # only valid inside the event
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    occluded = rh.in_scatter(shafts)
    # Only the part of the beam nearer the light than the light camera's near plane (the
    # nearest caster) stays lit.
    assert occluded.sum() < 0.5 * original.sum()
    assert np.all(occluded <= original * (1 + 1e-5) + 1e-12)


def test_shadow_caster_bounds_make_every_process_take_the_same_path():
    renderer, window = rh.make_window(160, 120)
    info = scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = rh.plain_slab_pass(slices=64, Method=vtkLightShaftPass.AUTOMATIC)
    renderer.SetPass(shafts)
    window.Render()
    global_range = shafts.GetLastFrame().GetLightDepthRange()
    bounds = [0.0] * 6
    assert not shafts.GetShadowCasterBounds(bounds)

    # A process that holds no caster: alone it would take ANALYTIC and render no shadow map.
    world_bounds = renderer.ComputeVisiblePropBounds()
    renderer.RemoveAllViewProps()
    rh.add_extent_marker(renderer)  # its own piece: a prop outside the light's volume
    window.Render()
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.ANALYTIC
    assert not shafts.GetLastFrame().GetShadowMapRendered()
    # With the global casters' bounds it renders a (cleared) map with the common light camera.
    shafts.SetShadowCasterBounds(world_bounds)
    assert shafts.GetShadowCasterBounds(bounds) and bounds == list(world_bounds)
    window.Render()
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.SLICES
    assert shafts.GetLastFrame().GetShadowMapRendered()
    assert shafts.GetLastFrame().GetNumberOfShadowCasters() == 0
    near, far = shafts.GetLastFrame().GetLightDepthRange()
    assert far >= global_range[1] * 0.999 and near <= global_range[0] * 1.001
    assert shafts.GetLastFrame().GetGLErrorCount() == 0
    shafts.UnsetShadowCasterBounds()
    window.Render()
    assert shafts.GetLastFrame().GetMethod() == vtkLightShaftPass.ANALYTIC


def test_non_finite_shadow_caster_bounds_are_refused(messages):
    shafts = vtkLightShaftPass()
    log = messages(shafts)
    shafts.SetShadowCasterBounds([0.0, 1.0, 0.0, math.nan, 0.0, 1.0])
    assert not shafts.GetShadowCasterBounds([0.0] * 6)
    assert len(log.errors) == 1 and "ShadowCasterBounds" in log.errors[0]


def test_a_painted_background_is_dimmed_as_the_renderer_s_own():
    """A compositor (ParaView's IceT) renders the scene over a transparent background and blends
    the background in after the pass: with PaintBackground the pass paints it behind the scene's
    uncovered part before the medium dims it, as it dims a background the renderer cleared to."""
    background = (0.2, 0.3, 0.4)
    shots = {}
    for case in ("cleared", "painted", "unpainted"):
        renderer, window = rh.make_window(160, 120)
        scenes.sphere_and_floor(renderer, sphere_resolution=32)
        shafts = rh.plain_slab_pass(slices=64, shadow_map=512, sigma_a=(0.05, 0.05, 0.05))
        if case == "cleared":
            renderer.SetBackground(*background)
        else:
            renderer.SetBackground(0.0, 0.0, 0.0)
            renderer.SetBackgroundAlpha(0.0)  # the scene image: nothing where nothing is drawn
            shafts.SetPaintBackground(case == "painted")
            shafts.SetPaintedBackground(*background)
        renderer.SetPass(shafts)
        window.Render()
        shots[case] = rh.screenshot(window).astype(float)
        assert shafts.GetLastFrame().GetGLErrorCount() == 0
    difference = np.abs(shots["painted"] - shots["cleared"])
    assert difference.max() <= 1.0 and difference.mean() < 0.05, (difference.max(),
                                                                  difference.mean())
    # Unpainted, the sky lacks the background: the test sees the difference.
    assert np.abs(shots["unpainted"] - shots["cleared"]).mean() > 3.0


def render_pieces(method, pieces, downsample=1, **params):
    """The in-scatter of the whole image and of each image piece (SetImagePiece), the frame
    reports' rows and fragments, and what the pieces' events saw."""
    renderer, window = rh.make_window(160, 120)
    scenes.sphere_and_floor(renderer, sphere_resolution=32)
    shafts = rh.plain_slab_pass(slices=64, shadow_map=512, Method=method,
                                DownsampleFactor=downsample, **params)
    renderer.SetPass(shafts)
    window.Render()
    whole = rh.in_scatter(shafts)
    assert shafts.GetLastFrame().GetImagePieceRows() == 0
    assert shafts.GetLastFrame().GetInScatterFragments() == -1
    events = []

    def depth_ready(pass_, _event):
        texture = pass_.GetSceneDepthTexture()
        events.append(("depth", texture.GetWidth(), texture.GetHeight()))

    def piece_ready(pass_, _event):
        texture = pass_.GetInScatterPieceTexture()
        events.append(("in-scatter", texture.GetWidth(), texture.GetHeight()))

    shafts.AddObserver(vtkLightShaftPass.SceneDepthReadyEvent, depth_ready)
    shafts.AddObserver(vtkLightShaftPass.InScatterPieceEvent, piece_ready)
    images, rows, fragments = [], [], []
    for piece in range(pieces):
        shafts.SetImagePiece(piece, pieces)
        window.Render()
        report = shafts.GetLastFrame()
        assert report.GetGLErrorCount() == 0
        images.append(rh.in_scatter(shafts))
        rows.append(report.GetImagePieceRows())
        fragments.append(report.GetInScatterFragments())
    assert shafts.GetSceneDepthTexture() is None and shafts.GetInScatterPieceTexture() is None
    reduced = (-(-160 // downsample), -(-120 // downsample))
    assert events == [("depth", 160, 120), ("in-scatter", *reduced)] * pieces
    return whole, images, rows, fragments


def test_image_pieces_each_compute_their_rows_and_add_up_to_the_whole_image(vtk_messages):
    vtk_messages.expect("Method ANALYTIC ignores shadows")
    for method in (vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH,
                   vtkLightShaftPass.ANALYTIC):
        for pieces in (2, 3, 4):
            whole, images, rows, fragments = render_pieces(method, pieces, InterleaveSize=1)
            # Every row is one piece's: the others leave it at zero, so the pieces add up to the
            # whole image exactly.
            lit = [np.any(image != 0.0, axis=(1, 2)) for image in images]
            assert np.all(np.sum(lit, axis=0) <= 1)
            assert np.array_equal(np.sum(images, axis=0), whole), (method, pieces)
            assert sum(rows) == 120 and max(rows) - min(rows) <= 16
            # Each piece shades about its share of the fragments (rows all over the picture).
            assert min(fragments) > 0
            assert max(fragments) < 1.6 * sum(fragments) / pieces, (method, pieces, fragments)


def test_a_gathering_ray_march_computes_the_rows_its_gather_reads():
    # Interleaved sampling (InterleaveSize 2) averages neighbouring rows: each piece marches a
    # margin around its rows, so that every row of the whole image is exactly some piece's.
    whole, images, rows, _ = render_pieces(vtkLightShaftPass.RAY_MARCH, 3, InterleaveSize=2,
                                           BlurRadius=0)
    assert np.any(whole != 0.0)
    exact = np.array([[np.array_equal(image[y], whole[y]) for y in range(120)]
                      for image in images])
    assert np.all(exact.any(axis=0))
    assert sum(rows) == 120


def test_image_pieces_at_reduced_resolution_and_for_the_methods_that_do_not_split():
    # Half resolution: the pieces split the reduced in-scatter's rows (60), before upsampling.
    whole, images, rows, _ = render_pieces(vtkLightShaftPass.SLICES, 2, downsample=2)
    assert sum(rows) == 60
    # EPIPOLAR and RADIAL_BLUR compute the whole image on every piece (their samples are not
    # per pixel): each piece's picture is the whole one.
    for method in (vtkLightShaftPass.EPIPOLAR, vtkLightShaftPass.RADIAL_BLUR):
        whole, images, rows, fragments = render_pieces(method, 2)
        for image in images:
            assert np.array_equal(image, whole), method


def test_image_piece_arguments_are_clamped():
    shafts = vtkLightShaftPass()
    shafts.SetImagePiece(5, 2)
    assert (shafts.GetImagePiece(), shafts.GetNumberOfImagePieces()) == (1, 2)
    shafts.SetImagePiece(-1, 0)
    assert (shafts.GetImagePiece(), shafts.GetNumberOfImagePieces()) == (0, 1)


def keyed_scene(build):
    """The sphere-and-floor scene without its sphere under the vertical sun of test_volumes,
    with `build(renderer)` added: (renderer, window, pass) after one frame (Final)."""
    import test_volumes as tv
    renderer, window, shafts = tv.render("vertical", build)
    return renderer, window, shafts


def model_as(prop, modelled):
    """Set `prop`'s MODELLED_PROP key to `modelled` (what a distributed view does)."""
    from vtkmodules.vtkCommonCore import vtkInformation
    keys = prop.GetPropertyKeys() or vtkInformation()
    keys.Set(vtkLightShaftPass.MODELLED_PROP(), modelled)
    prop.SetPropertyKeys(keys)


def test_a_volume_keyed_to_another_is_modelled_as_that_one():
    import test_volumes as tv
    slab = {}

    def whole(renderer):
        slab["volume"] = tv.add_slab(renderer)

    _, _, direct = keyed_scene(whole)
    expected = rh.in_scatter(direct)

    def piece(renderer):
        # A volume drawn over the slab's box (the same bounds: the same clipping range, so the
        # same backdrop), transparent everywhere, that stands for the slab (in no renderer).
        drawn = tv.add_volume(renderer, tv.box_image((-30.0, 4.0, -30.0), (30.0, 4.4, 30.0)),
                              [(0.0, 0.0), (2.0, 0.0)])
        standing = tv.add_slab(renderer)
        renderer.RemoveVolume(standing)
        slab["standing"] = standing
        model_as(drawn, standing)

    _, _, keyed = keyed_scene(piece)
    assert keyed.GetLastFrame().GetVolume() is slab["standing"]
    got = rh.in_scatter(keyed)
    assert got.max() > 0.0
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-6 * expected.max())
    # Without the key the drawn volume, transparent, dims nothing: the slab's 0.5^0.4 is missing.
    _, _, unkeyed = keyed_scene(lambda renderer: tv.add_volume(
        renderer, tv.box_image((-30.0, 4.0, -30.0), (30.0, 4.4, 30.0)), [(0.0, 0.0), (2.0, 0.0)]))
    assert unkeyed.GetLastFrame().GetVolume() is None
    assert rh.in_scatter(unkeyed).sum() > 1.2 * expected.sum()


def test_a_translucent_actor_keyed_to_another_is_peeled_as_that_one():
    from vtkmodules.vtkFiltersSources import vtkPlaneSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    def pane(origin, point1, point2, color):
        source = vtkPlaneSource()
        source.SetOrigin(*origin)
        source.SetPoint1(*point1)
        source.SetPoint2(*point2)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*color)
        actor.GetProperty().SetOpacity(0.5)
        return actor

    across = ((-30.0, 4.0, -30.0), (30.0, 4.0, -30.0), (-30.0, 4.0, 30.0))

    def whole(renderer):
        renderer.AddActor(pane(*across, (1.0, 0.1, 0.1)))

    _, _, direct = keyed_scene(whole)
    expected = rh.in_scatter(direct)
    assert direct.GetLastFrame().GetLightTranslucentLayers(0) > 0

    def piece(renderer):
        # A green pane drawn in the red one's place (the same bounds), standing for it.
        drawn = pane(*across, (0.2, 0.9, 0.2))
        renderer.AddActor(drawn)
        model_as(drawn, pane(*across, (1.0, 0.1, 0.1)))

    _, _, keyed = keyed_scene(piece)
    got = rh.in_scatter(keyed)
    assert keyed.GetLastFrame().GetLightTranslucentLayers(0) > 0
    # Red passes, green and blue are dimmed, as by the pane itself.
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-5 * expected.max())
    # Without the key the green pane tints the shafts green: red dimmed, green passed.
    _, _, unkeyed = keyed_scene(lambda renderer: renderer.AddActor(pane(*across, (0.2, 0.9, 0.2))))
    green = rh.in_scatter(unkeyed).sum(axis=(0, 1))
    red = expected.sum(axis=(0, 1))
    assert green[0] < 0.8 * red[0] and green[1] > 1.2 * red[1]
