"""Ready-made scenes for examples, tests and benchmarks.

Each builder adds props and a spotlight to a renderer, sets its camera, and returns a
`SceneInfo` that describes the scene analytically (for the float64 reference in tests/).
"""

from dataclasses import dataclass, field

from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper


@dataclass
class SceneInfo:
    light: vtkLight
    spheres: list = field(default_factory=list)  # (centre, radius)
    floors: list = field(default_factory=list)  # (height, xmin, xmax, zmin, zmax)
    actors: list = field(default_factory=list)
    lights: list = field(default_factory=list)  # several lights (empty: `light` alone)


def _actor(source, color=(0.8, 0.8, 0.8)):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def add_spotlight(renderer, position, focal_point, cone_angle=30.0, intensity=1.0,
                  color=(1.0, 1.0, 1.0), exponent=1.0, attenuation=(1.0, 0.0, 0.0)):
    """Add a positional spotlight (VTK's conventions) to `renderer` and return it."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(*position)
    light.SetFocalPoint(*focal_point)
    light.SetConeAngle(cone_angle)
    light.SetExponent(exponent)
    light.SetAttenuationValues(*attenuation)
    light.SetIntensity(intensity)
    light.SetColor(*color)
    renderer.AddLight(light)
    return light


def add_point_light(renderer, position, intensity=1.0, color=(1.0, 1.0, 1.0),
                    attenuation=(1.0, 0.0, 0.0)):
    """Add a point light (positional, cone angle 180: no cone) to `renderer` and return it."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(*position)
    light.SetFocalPoint(position[0], position[1] - 1.0, position[2])
    light.SetConeAngle(180.0)
    light.SetAttenuationValues(*attenuation)
    light.SetIntensity(intensity)
    light.SetColor(*color)
    renderer.AddLight(light)
    return light


def add_directional_light(renderer, position, focal_point, intensity=1.0,
                          color=(1.0, 1.0, 1.0)):
    """Add a directional light (a sun) to `renderer` and return it: parallel light travelling
    from `position` towards `focal_point`, lighting the half-space beyond the plane through
    `position` perpendicular to that direction. The pass uses it when given (SetLight or
    AddLight): directional lights do not scatter by default."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(*position)
    light.SetFocalPoint(*focal_point)
    light.SetIntensity(intensity)
    light.SetColor(*color)
    renderer.AddLight(light)
    return light


def add_fill_light(renderer, intensity=0.12):
    """A dim headlight so a room is not pitch black; it is no spotlight, so it makes no shafts."""
    light = vtkLight()
    light.SetLightTypeToHeadlight()
    light.SetIntensity(intensity)
    renderer.AddLight(light)
    return light


def sphere_and_floor(renderer, sphere_resolution=256, floor_half_size=6.0):
    """A spotlight above a sphere over a square floor: the core test scene.

    Light at (0.5, 6, 0) aiming at the origin, 30 degree half-angle; sphere of radius 0.8 at
    (0, 1.5, 0); floor y = 0, |x|, |z| <= floor_half_size; camera at (0, 3, 12) looking at
    (0, 2, 0), 30 degree view angle.
    """
    centre, radius = (0.0, 1.5, 0.0), 0.8
    sphere = vtkSphereSource()
    sphere.SetCenter(*centre)
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(sphere_resolution)
    sphere.SetPhiResolution(sphere_resolution)
    floor = vtkPlaneSource()
    s = floor_half_size
    floor.SetOrigin(-s, 0.0, -s)
    floor.SetPoint1(-s, 0.0, s)
    floor.SetPoint2(s, 0.0, -s)
    actors = [_actor(sphere, (0.9, 0.5, 0.3)), _actor(floor, (0.8, 0.8, 0.8))]
    for actor in actors:
        renderer.AddActor(actor)
    light = add_spotlight(renderer, (0.5, 6.0, 0.0), (0.0, 0.0, 0.0), cone_angle=30.0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 3.0, 12.0)
    camera.SetFocalPoint(0.0, 2.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(30.0)
    renderer.ResetCameraClippingRange()
    return SceneInfo(light=light, spheres=[(centre, radius)],
                     floors=[(0.0, -s, s, -s, s)], actors=actors)


def window_room(renderer):
    """A spotlight shining through a window frame (four bars) onto a floor."""
    actors = []
    floor = vtkPlaneSource()
    floor.SetOrigin(-8.0, 0.0, -8.0)
    floor.SetPoint1(-8.0, 0.0, 8.0)
    floor.SetPoint2(8.0, 0.0, -8.0)
    actors.append(_actor(floor, (0.75, 0.7, 0.65)))
    # A wall at x = -3 with a window split into four panes by a cross of bars.
    pieces = [
        # centre (x, y, z), lengths (dx, dy, dz)
        ((-3.0, 0.75, 0.0), (0.2, 1.5, 9.0)),  # below the window
        ((-3.0, 6.25, 0.0), (0.2, 2.5, 9.0)),  # above the window
        ((-3.0, 3.25, -3.0), (0.2, 3.5, 3.0)),  # left
        ((-3.0, 3.25, 3.0), (0.2, 3.5, 3.0)),  # right
        ((-3.0, 3.25, 0.0), (0.2, 3.5, 0.25)),  # vertical bar
        ((-3.0, 3.25, 0.0), (0.2, 0.25, 3.0)),  # horizontal bar
    ]
    for (cx, cy, cz), (dx, dy, dz) in pieces:
        cube = vtkCubeSource()
        cube.SetCenter(cx, cy, cz)
        cube.SetXLength(dx)
        cube.SetYLength(dy)
        cube.SetZLength(dz)
        actors.append(_actor(cube, (0.55, 0.45, 0.35)))
    for actor in actors:
        renderer.AddActor(actor)
    light = add_spotlight(renderer, (-9.0, 8.0, 1.0), (0.5, 0.0, -0.5), cone_angle=22.0,
                          intensity=1.0, color=(1.0, 0.93, 0.8))
    camera = renderer.GetActiveCamera()
    camera.SetPosition(7.0, 2.2, 8.0)
    camera.SetFocalPoint(-3.0, 3.0, -1.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(40.0)
    renderer.ResetCameraClippingRange()
    return SceneInfo(light=light, floors=[(0.0, -8.0, 8.0, -8.0, 8.0)], actors=actors)


def isosurface(renderer, iso_value=160.0):
    """A scientific-visualisation scene: an isosurface of VTK's wavelet source lit from above.

    The isosurface (extent +-10, scaled to about 4 units, centred 3 units above a floor) casts
    its holes and lobes as shafts onto the floor; colour by the scalar for the usual look.
    """
    from vtkmodules.vtkFiltersCore import vtkContourFilter
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, iso_value)
    contour.ComputeNormalsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.SetScalarRange(iso_value - 1.0, iso_value + 1.0)
    mapper.ScalarVisibilityOff()
    surface = vtkActor()
    surface.SetMapper(mapper)
    surface.GetProperty().SetColor(0.35, 0.6, 0.9)
    surface.SetScale(0.2, 0.2, 0.2)
    surface.SetPosition(0.0, 3.0, 0.0)
    floor = vtkPlaneSource()
    floor.SetOrigin(-8.0, 0.0, -8.0)
    floor.SetPoint1(-8.0, 0.0, 8.0)
    floor.SetPoint2(8.0, 0.0, -8.0)
    actors = [surface, _actor(floor, (0.8, 0.8, 0.8))]
    for actor in actors:
        renderer.AddActor(actor)
    light = add_spotlight(renderer, (1.0, 10.0, 1.0), (0.0, 0.0, 0.0), cone_angle=24.0,
                          color=(1.0, 0.97, 0.9))
    camera = renderer.GetActiveCamera()
    camera.SetPosition(9.0, 4.0, 11.0)
    camera.SetFocalPoint(0.0, 3.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(35.0)
    renderer.ResetCameraClippingRange()
    return SceneInfo(light=light, floors=[(0.0, -8.0, 8.0, -8.0, 8.0)], actors=actors)


def _box(centre, lengths, color):
    cube = vtkCubeSource()
    cube.SetCenter(*centre)
    cube.SetXLength(lengths[0])
    cube.SetYLength(lengths[1])
    cube.SetZLength(lengths[2])
    return _actor(cube, color)


def _floor(half_size, color=(0.75, 0.7, 0.65)):
    floor = vtkPlaneSource()
    floor.SetOrigin(-half_size, 0.0, -half_size)
    floor.SetPoint1(-half_size, 0.0, half_size)
    floor.SetPoint2(half_size, 0.0, -half_size)
    return _actor(floor, color)


def _set_camera(renderer, position, focal_point, view_angle):
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal_point)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(view_angle)
    renderer.ResetCameraClippingRange()


def sun_room(renderer):
    """Sunlight through a window: a closed room (a long wall with a four-pane window, a ceiling)
    lit from outside by a directional light (a sun).

    The sun's plane passes through (-12, 10, 1.5) (the light travels from there towards
    (0.5, 0, -0.5)): everything lies beyond it, and the medium's depth the light crosses before
    reaching the window is explicit. Returns the SceneInfo with the sun as light; give it to the
    pass (SetLight), since directional lights scatter only when given.
    """
    actors = [_floor(15.0)]
    wall = (0.55, 0.45, 0.35)
    pieces = [
        # centre (x, y, z), lengths (dx, dy, dz): the wall at x = -3, the window in its middle
        ((-3.0, 0.75, 0.0), (0.2, 1.5, 30.0)),  # below the window
        ((-3.0, 6.25, 0.0), (0.2, 2.5, 30.0)),  # above the window
        ((-3.0, 3.25, -8.25), (0.2, 3.5, 13.5)),  # left
        ((-3.0, 3.25, 8.25), (0.2, 3.5, 13.5)),  # right
        ((-3.0, 3.25, 0.0), (0.2, 3.5, 0.25)),  # vertical bar
        ((-3.0, 3.25, 0.0), (0.2, 0.25, 3.0)),  # horizontal bar
        ((4.5, 7.6, 0.0), (15.2, 0.2, 30.0)),  # ceiling
    ]
    actors += [_box(centre, lengths, wall) for centre, lengths in pieces]
    for actor in actors:
        renderer.AddActor(actor)
    light = add_directional_light(renderer, (-12.0, 10.0, 1.5), (0.5, 0.0, -0.5),
                                  intensity=1.0, color=(1.0, 0.92, 0.78))
    _set_camera(renderer, (7.0, 2.2, 8.0), (-3.0, 3.0, -1.0), 40.0)
    return SceneInfo(light=light, floors=[(0.0, -15.0, 15.0, -15.0, 15.0)], actors=actors)


def lamp_over_table(renderer):
    """A bare lamp (a point light) in an open shade over a table with things on it.

    The shade (an open cylinder) lets the light out upwards, onto the ceiling, and downwards,
    in two cones; the
    table top, its legs, a vase, a bowl and a book cut shadow volumes out of the lower cone;
    attenuation 1 / (1 + 0.05 r^2).
    """
    from vtkmodules.vtkFiltersSources import vtkCylinderSource
    actors = [_floor(8.0, (0.6, 0.55, 0.5))]
    wood = (0.45, 0.3, 0.2)
    actors.append(_box((0.0, 1.5, 0.0), (3.2, 0.08, 1.8), wood))  # table top
    for x in (-1.45, 1.45):
        for z in (-0.75, 0.75):
            actors.append(_box((x, 0.75, z), (0.12, 1.5, 0.12), wood))
    vase = vtkSphereSource()
    vase.SetCenter(-0.7, 1.9, 0.1)
    vase.SetRadius(0.35)
    vase.SetThetaResolution(64)
    vase.SetPhiResolution(64)
    actors.append(_actor(vase, (0.3, 0.45, 0.7)))
    bowl = vtkSphereSource()
    bowl.SetCenter(0.6, 1.55, -0.2)
    bowl.SetRadius(0.3)
    bowl.SetStartTheta(0.0)
    bowl.SetThetaResolution(64)
    bowl.SetPhiResolution(64)
    actors.append(_actor(bowl, (0.8, 0.75, 0.6)))
    actors.append(_box((0.5, 1.6, 0.5), (0.6, 0.12, 0.45), (0.6, 0.15, 0.1)))  # book
    shade = vtkCylinderSource()
    shade.SetCenter(0.0, 3.6, 0.0)
    shade.SetRadius(0.45)
    shade.SetHeight(1.1)
    shade.SetResolution(64)
    shade.CappingOff()
    actors.append(_actor(shade, (0.9, 0.85, 0.7)))
    actors.append(_box((0.0, 5.6, 0.0), (16.0, 0.2, 16.0), (0.6, 0.55, 0.5)))  # ceiling
    for actor in actors:
        renderer.AddActor(actor)
    light = add_point_light(renderer, (0.0, 3.6, 0.0), intensity=1.0, color=(1.0, 0.85, 0.6),
                            attenuation=(1.0, 0.0, 0.05))
    _set_camera(renderer, (6.5, 3.2, 7.5), (0.0, 2.0, 0.0), 40.0)
    return SceneInfo(light=light, floors=[(0.0, -8.0, 8.0, -8.0, 8.0)], actors=actors)


def crossing_spotlights(renderer):
    """Two coloured spotlights crossing over a stage, with pillars and a ball in their beams.

    A red-orange spot from the left and a blue one from the right, both 18 degree half-angle,
    meet above the centre of the stage; where their beams overlap their colours add.
    Returns the SceneInfo with the first spot as light and both in `lights`.
    """
    actors = [_floor(8.0, (0.5, 0.5, 0.5))]
    for x in (-1.6, 0.0, 1.6):
        actors.append(_box((x, 1.2, -1.5), (0.3, 2.4, 0.3), (0.7, 0.7, 0.7)))
    ball = vtkSphereSource()
    ball.SetCenter(0.0, 2.6, 0.3)
    ball.SetRadius(0.45)
    ball.SetThetaResolution(64)
    ball.SetPhiResolution(64)
    actors.append(_actor(ball, (0.8, 0.8, 0.8)))
    for actor in actors:
        renderer.AddActor(actor)
    warm = add_spotlight(renderer, (-5.5, 7.0, 0.5), (1.5, 0.0, -0.8), cone_angle=18.0,
                         color=(1.0, 0.35, 0.12))
    cool = add_spotlight(renderer, (5.5, 7.0, 0.5), (-1.5, 0.0, -0.8), cone_angle=18.0,
                         color=(0.15, 0.4, 1.0))
    _set_camera(renderer, (0.0, 3.0, 12.0), (0.0, 2.6, -0.5), 42.0)
    return SceneInfo(light=warm, floors=[(0.0, -8.0, 8.0, -8.0, 8.0)], actors=actors,
                     lights=[warm, cool])
