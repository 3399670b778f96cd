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
