"""Offscreen rendering helpers shared by the Python tests and the accuracy measurement."""

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import lightshaft_reference as ref
from lightshafts import parameter_owner


_shared_window = None


def make_window(width=320, height=240):
    """A fresh renderer in the session's one offscreen window.

    One window serves every test, so the tests do not close and reopen X connections one after
    another: an Xvfb started without -noreset (xvfb-run's default) resets when its last client
    disconnects and drops a client that connected just before, and VTK then aborts with
    `bad X server connection` (see docs/known-issues.md).
    """
    global _shared_window
    if _shared_window is None:
        _shared_window = vtkRenderWindow()
        _shared_window.SetOffScreenRendering(1)
        _shared_window.SetMultiSamples(0)
    window = _shared_window
    renderers = window.GetRenderers()
    while renderers.GetNumberOfItems() > 0:
        window.RemoveRenderer(renderers.GetFirstRenderer())
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    window.SetSize(width, height)
    return renderer, window


def plain_slab_pass(sigma_s=(0.05, 0.04, 0.03), sigma_a=(0.01, 0.01, 0.01), slices=256,
                    shadow_map=2048, **params):
    """A vtkLightShaftPass measuring the slab integration itself (no jitter, no blur), then
    Set<name>(value) for each keyword."""
    from lightshafts import vtkLightShaftPass
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(*sigma_s)
    shafts.GetMedium().SetAbsorptionCoefficient(*sigma_a)
    shafts.SetNumberOfSlices(slices)
    shafts.SetShadowMapSize(shadow_map)
    shafts.JitterOff()
    shafts.SetBlurRadius(0)
    for name, value in params.items():
        getattr(parameter_owner(shafts, name), "Set" + name)(value)
    return shafts


def in_scatter(shaft_pass):
    """The pass's last L_in as (height, width, 3), row 0 at the bottom."""
    image = vtkImageData()
    assert shaft_pass.GetInScatteredRadiance(image)
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3).astype(np.float64)


def scene_reference(renderer, shaft_pass, array="InScatteredRadiance"):
    """vtkLightShaftReference's image of the renderer's own props (float64 reference, exact
    visibility) with the pass's light and medium, as (height, width, components), row 0 at the
    bottom: its in-scatter, or another of its arrays (SurfaceLight: 3 per light)."""
    from lightshafts import vtkLightShaftReference
    reference = vtkLightShaftReference()
    reference.SetRenderer(renderer)
    reference.SetLightShaftPass(shaft_pass)
    reference.Update()
    image = reference.GetOutput()
    w, h, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetArray(array))
    return values.reshape(h, w, -1).astype(np.float64)


def add_sphere(renderer, centre, radius, color, resolution=32):
    """Add a sphere actor to `renderer` and return it."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    sphere = vtkSphereSource()
    sphere.SetCenter(*centre)
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    renderer.AddActor(actor)
    return actor


def add_box(renderer, lengths, centre=(0.0, 0.0, 0.0)):
    """Add a box actor (`lengths` along x, y, z about `centre`) to `renderer` and return it."""
    from vtkmodules.vtkFiltersSources import vtkCubeSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    box = vtkCubeSource()
    box.SetCenter(*centre)
    box.SetXLength(lengths[0])
    box.SetYLength(lengths[1])
    box.SetZLength(lengths[2])
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(box.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    return actor


def screenshot(window, front=False):
    """The window's RGB pixels as (height, width, 3) uint8, row 0 at the bottom: the back buffer
    (as rendered), or with front=True the front buffer (as displayed, without re-rendering)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.SetReadFrontBuffer(front)
    grab.SetShouldRerender(not front)
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3).copy()


def depth_points(renderer, window):
    """The world points the window's depth buffer holds, as (height, width, 3) (row 0 at the
    bottom), and the depths (1: nothing drawn)."""
    from vtkmodules.vtkCommonCore import vtkFloatArray
    w, h = window.GetSize()
    values = vtkFloatArray()
    window.GetZbufferData(0, 0, w - 1, h - 1, values)
    depth = vtk_to_numpy(values).reshape(h, w).astype(np.float64)
    matrix = renderer.GetActiveCamera().GetCompositeProjectionTransformMatrix(
        renderer.GetTiledAspectRatio(), -1, 1)
    world_to_clip = np.array([[matrix.GetElement(i, j) for j in range(4)] for i in range(4)])
    ys, xs = np.mgrid[0:h, 0:w]
    ndc = np.stack([2.0 * (xs + 0.5) / w - 1.0, 2.0 * (ys + 0.5) / h - 1.0, 2.0 * depth - 1.0,
                    np.ones_like(depth)], -1)
    points = ndc @ np.linalg.inv(world_to_clip).T
    return points[..., :3] / points[..., 3:], depth


def scene_bounds(renderer, shafts=None):
    """The scene's box as the pass takes it (its rule, written again here): the visible props'
    bounds, grown to hold the pass's ShadowCasterBounds (when set) and its medium's density
    field; None when there is none."""
    boxes = [renderer.ComputeVisiblePropBounds()]
    if shafts is not None:
        given = [0.0] * 6
        if shafts.GetShadowCasterBounds(given):
            boxes.append(given)
        field = shafts.GetMedium().GetDensityField()
        if field is not None:
            boxes.append(field.GetBounds())
    boxes = [b for b in boxes if all(np.isfinite(b)) and b[0] <= b[1] and abs(b[0]) < 1e299]
    if not boxes:
        return None
    lows = np.min([b[0::2] for b in boxes], axis=0)
    highs = np.max([b[1::2] for b in boxes], axis=0)
    return [v for pair in zip(lows, highs) for v in pair]


def backdrop_depth(renderer, shafts=None):
    """Where the pass ends a ray that hits nothing: the view depth of the deepest corner of
    scene_bounds; 0 with no scene."""
    bounds = scene_bounds(renderer, shafts)
    if bounds is None:
        return 0.0
    view = renderer.GetActiveCamera().GetViewTransformMatrix()
    m = np.array([[view.GetElement(i, j) for j in range(4)] for i in range(4)])
    corners = np.array([[bounds[i & 1], bounds[2 + ((i >> 1) & 1)], bounds[4 + ((i >> 2) & 1)], 1.0]
                        for i in range(8)])
    return max(0.0, float(np.max(-(corners @ m.T)[:, 2])))


def scene_extent(shafts, bounds=(-6.0, 6.0, 0.0, 6.0, -6.0, 6.0)):
    """Give a scene with no prop (or a small one) an extent: rays that hit nothing end at the
    scene's far side, and a renderer with no 3D prop is left as it is. The pass's
    ShadowCasterBounds (the distributed scene's bounds) are part of the scene's box; the
    default is scenes.sphere_and_floor's floor up to its light."""
    shafts.SetShadowCasterBounds(bounds)


def add_extent_marker(renderer, info=None, centre=(-6.0, 0.25, -6.0), radius=0.25):
    """A small sphere at the far corner of scenes.sphere_and_floor's floor, outside its spot's
    volume (it casts nothing): a scene emptied of its props keeps the floor's extent with it
    (rays that hit nothing end at the scene's far side, and a renderer with no 3D prop is left
    as it is). Added to info.spheres for the numpy reference when `info` is given."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    sphere = vtkSphereSource()
    sphere.SetCenter(*centre)
    sphere.SetRadius(radius)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    if info is not None:
        info.spheres = list(info.spheres) + [(tuple(centre), radius)]
    return actor


def hold_bounds(renderer, bounds):
    """Add a box of opacity 0 (VTK draws none of it and it passes all the light, but it is a
    translucent prop: LIGHT_VOLUME gives way where it is a caster) that spans `bounds`, and
    return it. Rays that hit nothing end at the scene's far side (the backdrop), so scenes
    compared with and without a prop inside `bounds` keep one backdrop with it."""
    from vtkmodules.vtkFiltersSources import vtkCubeSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    box = vtkCubeSource()
    box.SetBounds(*bounds)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(box.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(0.0)
    renderer.AddActor(actor)
    return actor


def reference_camera(renderer, window, size=None, shafts=None):
    """The renderer's camera, for the reference (size: the viewport's, default the window's);
    its far depth is the backdrop's (backdrop_depth, with `shafts`' extent and field), as the
    pass takes it."""
    cam = renderer.GetActiveCamera()
    w, h = size or window.GetSize()
    return ref.Camera(cam.GetPosition(), cam.GetFocalPoint(), cam.GetViewUp(),
                      cam.GetViewAngle(),
                      (cam.GetClippingRange()[0], backdrop_depth(renderer, shafts)),
                      w, h,
                      parallel=bool(cam.GetParallelProjection()),
                      parallel_scale=cam.GetParallelScale())


def reference_light(light, cookie=None):
    """A vtkLight of any kind, for the reference (optionally with a cookie function): a spot
    (positional, cone angle below 90 degrees), a point light (positional, 90 or more; it takes
    no cookie, as in the pass, so `cookie` is ignored) or a directional light (not positional).
    Position and focal point are the transformed ones, as the pass reads them (a scene light's
    are its own)."""
    position = light.GetTransformedPosition()
    focal_point = light.GetTransformedFocalPoint()
    colour = tuple(light.GetDiffuseColor())
    intensity = light.GetIntensity() if light.GetSwitch() else 0.0
    if not light.GetPositional():
        return ref.DirectionalLight(position, focal_point, intensity, colour, cookie=cookie)
    if light.GetConeAngle() >= 90.0:
        return ref.PointLight(position, light.GetAttenuationValues(), intensity, colour)
    return ref.Spotlight(position, focal_point, light.GetConeAngle(), light.GetExponent(),
                         light.GetAttenuationValues(), intensity, colour, cookie=cookie)


def reference_lights(lights, cookie=None):
    """A vtkLight or a list of them, for the reference (a list of reference lights)."""
    if not isinstance(lights, (list, tuple)):
        lights = [lights]
    return [reference_light(light, cookie) for light in lights]


def reference_medium(shaft_pass):
    return ref.Medium(shaft_pass.GetMedium().GetScatteringCoefficient(),
                      shaft_pass.GetMedium().GetAbsorptionCoefficient(), shaft_pass.GetMedium().GetPhaseFunction(),
                      shaft_pass.GetMedium().GetAnisotropy())


def reference_for(renderer, window, info, shaft_pass, panels=4, cookie=None, with_props=True,
                  size=None, shadows=True, lights=None):
    """The float64 reference L_in for a scenes.* scene as the pass is set up (shadows=False:
    surfaces stop the rays but cast no shadow). The lights: `lights` (a vtkLight or a list),
    else info.lights when the scene has several, else info.light (which may be a list)."""
    scene = ref.Scene(spheres=info.spheres, floors=info.floors) if with_props else ref.Scene()
    if lights is None:
        lights = getattr(info, "lights", None) or info.light
    return ref.in_scattered_radiance(reference_camera(renderer, window, size, shaft_pass),
                                     reference_lights(lights, cookie),
                                     reference_medium(shaft_pass), scene, panels=panels,
                                     shadows=shadows)


def surface_points(renderer, window, info):
    """World points the pixel-centre rays hit (the backdrop where nothing), and which are
    floor."""
    camera = reference_camera(renderer, window)
    eye, dirs, forward = ref.camera_rays(camera)
    d = dirs.reshape(-1, 3)
    origins = np.broadcast_to(eye, dirs.shape).reshape(-1, 3)
    t = ref.surface_distance(origins, d, forward, camera,
                             ref.Scene(spheres=info.spheres, floors=info.floors))
    hit = origins + t[:, None] * d
    return hit, np.abs(hit[:, 1]) < 1e-9


POINT_ATTENUATION = {"point": (1.0, 0.0, 0.05), "point-constant": (1.0, 0.0, 0.0),
                     "point-inverse-square": (0.0, 0.0, 1.0)}


def make_light_kind(renderer, info, kind, point_position):
    """Turn scenes.sphere_and_floor's spotlight (at (0.5, 6, 0), aiming at the origin) into
    `kind` and return the lights to give the pass: "spot" (unchanged); a point light at
    `point_position` with A = 1 / (1 + 0.05 r^2) ("point"), A = 1 ("point-constant") or A = 1 / r^2
    ("point-inverse-square"); "directional" (the plane through (0.5, 6, 0), light travelling
    down to the origin); "pair" (the spot, orange, and a blue point light)."""
    from lightshafts import scenes
    light = info.light
    if kind in POINT_ATTENUATION:
        light.SetConeAngle(180.0)
        light.SetPosition(*point_position)
        light.SetAttenuationValues(*POINT_ATTENUATION[kind])
    elif kind == "directional":
        light.SetPositional(False)
    elif kind == "pair":
        light.SetColor(1.0, 0.6, 0.3)
        point = scenes.add_point_light(renderer, (-1.5, 3.2, 1.0), intensity=0.8,
                                       color=(0.3, 0.6, 1.0), attenuation=(1.0, 0.0, 0.1))
        return [light, point]
    return [light]


def floor_shadow_masks(renderer, window, info, erode=2):
    """Analytic floor masks (lit by info.light, of any kind / in the sphere's shadow from it), as
    (height, width) booleans eroded by `erode` pixels."""
    w, h = window.GetSize()
    hit, on_floor = surface_points(renderer, window, info)
    light = info.light
    position = np.asarray(light.GetPosition(), float)
    axis = np.asarray(light.GetFocalPoint(), float) - position
    axis /= np.linalg.norm(axis)
    (centre, radius), = info.spheres
    centre = np.asarray(centre, float)
    if not light.GetPositional():  # directional: the half-space, a cylinder of shadow
        lit_here = (hit - position) @ axis >= 0.0
        offset = hit - centre
        along = offset @ axis
        across = np.linalg.norm(offset - along[:, None] * axis, axis=1)
        shadowed = (along > 0.0) & (across < radius)
    else:  # spot (its cone) or point: a cone of shadow from the light
        to_hit = hit - position
        r = np.linalg.norm(to_hit, axis=1)
        lit_here = np.ones(len(hit), bool)
        if light.GetConeAngle() < 90.0:
            lit_here = (to_hit @ axis) / r >= np.cos(np.radians(light.GetConeAngle()))
        u = to_hit / r[:, None]
        m = position - centre
        b = u @ m
        disc = b * b - (m @ m - radius * radius)
        shadowed = (disc > 0) & (-b - np.sqrt(np.maximum(disc, 0)) < r)

    def erode_mask(mask):
        mask = mask.reshape(h, w)
        out = mask.copy()
        for dy in range(-erode, erode + 1):
            for dx in range(-erode, erode + 1):
                out &= np.roll(np.roll(mask, dy, 0), dx, 1)
        return out

    return erode_mask(on_floor & lit_here & ~shadowed), erode_mask(on_floor & lit_here & shadowed)


def median_frame_time(window, frames, warm_up=1, warm_up_seconds=0.0):
    """Median wall time of `frames` renders, each finished with glFinish, after `warm_up`
    frames, or more until `warm_up_seconds` have passed. A fresh scene's first frames can be
    slow for a while (docs/known-issues.md: 23 frames for the sphere scene's sphere)."""
    import statistics
    import time
    start = time.perf_counter()
    done = 0
    while done < warm_up or (time.perf_counter() - start < warm_up_seconds and done < 100):
        window.Render()
        window.WaitForCompletion()
        done += 1
    samples = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def window_scene(width, height):
    """The README picture's window scene (scenes.window_room) at width x height, its settled plain
    frame time (median of 5 after 30 frames and 2 s), and a vtkLightShaftPass with the README's
    medium (σ_s 0.05, exposure 40), not yet set on the renderer:
    (renderer, window, plain_seconds, shafts)."""
    from lightshafts import scenes, vtkLightShaftPass
    renderer, window = make_window(width, height)
    scenes.window_room(renderer)
    plain = median_frame_time(window, 5, warm_up=30, warm_up_seconds=2.0)
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    shafts.SetExposure(40.0)
    return renderer, window, plain, shafts


def uniform_cookie(size=64, value=255):
    """A vtkTexture of one uniform grey level (a cookie that changes nothing but the cost)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkRenderingCore import vtkTexture
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    image.GetPointData().SetScalars(
        numpy_to_vtk(np.full((size * size, 3), value, np.uint8), deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture
