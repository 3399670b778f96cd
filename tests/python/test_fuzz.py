"""Seeded fuzz: the pass driven the way users drive it, at random.

A random sequence of what users do between frames: parameters set in range, at their bounds
and to junk (NaN, +-inf, negative, huge), methods and presets switched, cookie and noise
textures set, replaced by empty ones and removed, the light moved, widened past a spotlight
(a point light), made directional, switched off; other lights (a point light, a sun, a second
spot) switched on and off, given to the pass and taken away (several lights); the camera moved (into the beam too), perspective and parallel; the window
resized down to 1x1, viewports, multisampling changed, a hardware selection now and then.
After every frame:
  - no GL error, and no VTK message but the pass's documented ones (an error naming the
    parameter right after a junk value; the documented warnings);
  - the in-scatter finite and non-negative;
  - the frame did not run away (under FRAME_CPU_LIMIT of CPU time), and the process stays under
    MEMORY_LIMIT.
The ranges are read from the pass itself (each setter clamps). `--fuzz-frames N` and
`--fuzz-seed S|random` (pytest options) set the length and the seed; a failure prints the
seed and the steps that led to it.
"""

import math
import random
import resource
import time

import numpy as np
import pytest

from lightshafts import parameter_owner, scenes, vtkLightShaftMedium, vtkLightShaftPass
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import vtkVolume, vtkVolumeProperty
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkHardwareSelector, vtkLight,
                                         vtkPolyDataMapper, vtkTexture)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonMath import vtkMatrix4x4

import render_helpers as rh
from vtk_output import VTK_OUTPUT, Messages

# A sweep (conftest.py): random parameter sequences through the same calls the other tests make.
pytestmark = pytest.mark.sweep

# A run-away frame, not a slow one: the process's CPU time (every thread's: llvmpipe renders on
# all cores), which a busy machine does not inflate as it does the wall time. Measured here
# (llvmpipe, 2 cores, windows up to 200 x 150): the slowest frames take about 12 s of wall time,
# under 25 s of CPU time (ShadowSurfaces with 16384^2 shadow maps, VTK's baker allocating them).
FRAME_CPU_LIMIT = 120.0
MEMORY_LIMIT_MIB = 8192

# (name, integer?, sampled log-uniformly?) for the scalar setters.
SCALARS = [
    ("NumberOfSlices", True, True), ("ShadowMapSize", True, True), ("PhaseFunction", True, False),
    ("MaximumNumberOfSlices", True, True), ("BlurRadius", True, False),
    ("DownsampleFactor", True, False), ("AccumulationPrecision", True, False),
    ("Method", True, False), ("LatticeResolution", True, True), ("NumberOfSteps", True, True),
    ("InterleaveSize", True, False), ("RadialSamples", True, True),
    ("EpipolarLines", True, True), ("EpipolarSamples", True, True), ("EpipolarStep", True, True),
    ("LightVolumeResolution", True, True), ("RefinementFrames", True, True),
    ("TimeBudget", False, True),
    ("Exposure", False, True), ("Anisotropy", False, False), ("NoiseAmplitude", False, False),
    ("NoiseScale", False, True), ("Time", False, False), ("Decay", False, False),
    ("Density", False, False), ("Weight", False, False), ("RadialGuardBand", False, False),
    ("DensityScale", False, True), ("BackgroundDensity", False, True),
    ("FieldShadowResolution", True, False), ("TranslucentShadowLayers", True, False),
]
VECTORS = [("ScatteringCoefficient", 3), ("AbsorptionCoefficient", 3),
           ("NoiseVelocity1", 2), ("NoiseVelocity2", 2)]
BOOLEANS = ["AttenuateScene", "ShadowSurfaces", "AutomaticSliceCount", "Jitter", "RadialJitter",
            "ProgressiveRefinement", "UseAllocatedRenderTime", "TranslucentShadows", "ExactFinish",
            "FitMediumToScene", "AttenuateSurfaceLight", "SplitLongFrames"]
# Setters that refuse non-finite values (with an error naming the parameter).
REFUSING = {"Exposure", "Anisotropy", "NoiseAmplitude", "NoiseScale", "Time", "Decay",
            "Density", "Weight", "RadialGuardBand", "ScatteringCoefficient",
            "DensityScale", "BackgroundDensity",
            "AbsorptionCoefficient", "NoiseVelocity1", "NoiseVelocity2", "TimeBudget"}
# The pass's documented warnings (docs/any-scene.md).
DOCUMENTED_WARNINGS = ["No spot or point light in the renderer", "given to the pass are switched off",
                       "The cookie shapes spot and directional lights only",
                       "cookie texture has no image", "noise texture has no image",
                       "Method ANALYTIC ignores shadows", "lattice cells in a frame",
                       "segments in a frame",
                       "Method LIGHT_VOLUME has no closed form",
                       "is rendered by SLICES, RAY_MARCH and EPIPOLAR",
                       # junk on the VTK objects the pass reads (junk_vtk)
                       "is left out of the shafts", "The camera cannot be used for the shafts",
                       "casts no shadow in the shafts", "image cannot be used (texel",
                       # several volumes: the first dims the shafts (volumes)
                       "The shafts are dimmed and shadowed by one vtkVolume"]
INT_PROBE = 2 ** 31 - 1
FLOAT_PROBE = 1e300


def probe_ranges():
    """{name: (low, high)} read from the pass's clamping setters."""
    shafts = vtkLightShaftPass()
    ranges = {}
    for name, integer, _ in SCALARS:
        setter, getter = getattr(parameter_owner(shafts, name), "Set" + name), getattr(parameter_owner(shafts, name), "Get" + name)
        probe = INT_PROBE if integer else FLOAT_PROBE
        setter(-probe)
        low = getter()
        setter(probe)
        ranges[name] = (low, getter())
    for name, n in VECTORS:
        setter, getter = getattr(parameter_owner(shafts, name), "Set" + name), getattr(parameter_owner(shafts, name), "Get" + name)
        setter(*([-FLOAT_PROBE] * n))
        low = getter()[0]
        setter(*([FLOAT_PROBE] * n))
        ranges[name] = (low, getter()[0])
    ranges["Time"] = (-1e6, 1e6)  # any finite value: fuzz a wide span
    return ranges


def nan_matrix(value):
    matrix = vtkMatrix4x4()
    matrix.SetElement(1, 3, value)
    return matrix


def nan_image(value):
    image = vtkImageData()
    image.SetDimensions(4, 4, 1)
    texels = np.ones(16, np.float32)
    texels[5] = value
    image.GetPointData().SetScalars(numpy_to_vtk(texels, deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


def density_image(rng):
    """A small random density field over (or beside) the scene: point or cell data, placed,
    spaced and turned at random; or one the pass must refuse (a NaN or negative value, 2D, no
    scalars): (image, the words of the error expected or None)."""
    kind = rng.choice(["field"] * 6 + ["nan", "negative", "flat", "no scalars"])
    dims = [rng.choice([2, 3, 5, 9]) for _ in range(3)]
    if kind == "flat":
        dims[2] = 1
    image = vtkImageData()
    image.SetDimensions(*dims)
    image.SetSpacing(*[rng.choice([0.05, 0.5, 2.0, 40.0]) for _ in range(3)])
    image.SetOrigin(*[rng.uniform(-8.0, 4.0) for _ in range(3)])
    angle = math.radians(rng.uniform(0.0, 360.0))
    c, s = math.cos(angle), math.sin(angle)
    image.SetDirectionMatrix(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
    cells = rng.random() < 0.3 and kind != "flat"
    count = int(np.prod([d - 1 for d in dims])) if cells else int(np.prod(dims))
    values = np.array([rng.choice([0.0, 0.01, 1.0, rng.uniform(0.0, 20.0)])
                       for _ in range(count)])
    if kind in ("nan", "negative"):
        values[rng.randrange(count)] = math.nan if kind == "nan" else -1.0
    if kind != "no scalars":
        data = image.GetCellData() if cells else image.GetPointData()
        data.SetScalars(numpy_to_vtk(values, deep=1))
    expected = {"field": None, "nan": "finite and not negative",
                "negative": "finite and not negative", "flat": "is not a 3D image",
                "no scalars": "has no point or cell scalars"}[kind]
    return image, expected


def image_texture(rng, components=3):
    size = rng.choice([1, 2, 7, 64])
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    values = np.array([rng.randrange(256) for _ in range(size * size * components)], np.uint8)
    image.GetPointData().SetScalars(numpy_to_vtk(values.reshape(-1, components), deep=1))
    texture = vtkTexture()
    texture.SetInputData(image)
    return texture


class Fuzzer:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.ranges = probe_ranges()
        self.renderer, self.window = rh.make_window(120, 90)
        self.info = scenes.sphere_and_floor(self.renderer, sphere_resolution=24)
        scenes.add_fill_light(self.renderer)
        self.spot = self.info.light
        # Other lights of every kind, switched off until the fuzz switches them on.
        self.others = {
            "point": scenes.add_point_light(self.renderer, (1.0, 3.5, 1.0),
                                            attenuation=(1.0, 0.0, 0.05)),
            "sun": scenes.add_directional_light(self.renderer, (2.0, 9.0, -1.0),
                                                (0.0, 0.0, 0.0)),
            "spot2": scenes.add_spotlight(self.renderer, (-4.0, 5.0, 2.0), (0.0, 1.0, 0.0),
                                          cone_angle=20.0, color=(0.3, 0.5, 1.0)),
        }
        for light in self.others.values():
            light.SwitchOff()
        self.shafts = vtkLightShaftPass()
        self.renderer.SetPass(self.shafts)
        self.log = Messages(self.shafts, self.shafts.GetMedium())
        # Media to switch between: the pass's own, and one shared with a second pass (which
        # renders nothing); SetMedium(None) adds fresh ones.
        self.media = [self.shafts.GetMedium(), vtkLightShaftMedium()]
        self.log.observe(self.media[1])
        self.other_pass = vtkLightShaftPass()
        self.other_pass.SetMedium(self.media[1])
        self.errors, self.warnings = self.log.errors, self.log.warnings
        self.steps = []
        self.undo = []  # how to undo the junk set on VTK objects
        self.refused = set()  # parameters given a non-finite value this step
        self.expected_errors = []  # words of the errors this step's bad images must give
        self.frame_times = []
        self.shafted = 0  # frames that computed shafts
        self.translucent_actors = []
        self.volumes = []

    def value(self, name, integer, log):
        low, high = self.ranges[name]
        r = self.rng.random()
        if r < 0.1:
            return low
        if r < 0.2:
            return high
        if log and low >= 0 and high > 0:
            floor = max(low, 1 if integer else 1e-6)
            v = math.exp(self.rng.uniform(math.log(floor), math.log(high)))
            v = low if self.rng.random() < 0.05 else v
        else:
            v = self.rng.uniform(low, high)
        return int(round(v)) if integer else v

    def junk(self, integer):
        if integer:
            return self.rng.choice([-INT_PROBE, -1, INT_PROBE, 10 ** 6])
        return self.rng.choice([math.nan, math.inf, -math.inf, -1e300, 1e300, -1.0])

    # --- actions ----------------------------------------------------------------------------
    def set_scalar(self):
        name, integer, log = self.rng.choice(SCALARS)
        value = self.junk(integer) if self.rng.random() < 0.15 else self.value(name, integer, log)
        if not integer and not math.isfinite(value):
            self.refused.add(name)
        getattr(parameter_owner(self.shafts, name), "Set" + name)(value)
        return f"Set{name}({value!r})"

    def set_vector(self):
        name, n = self.rng.choice(VECTORS)
        low, high = self.ranges[name]
        if self.rng.random() < 0.15:
            values = [self.junk(False) if self.rng.random() < 0.5 else 0.1 for _ in range(n)]
        elif name.endswith("Coefficient"):
            values = [self.rng.choice([0.0, low, high, 10 ** self.rng.uniform(-9, 1)])
                      for _ in range(n)]
        else:
            values = [self.rng.uniform(low, high) for _ in range(n)]
        if not all(math.isfinite(v) for v in values):
            self.refused.add(name)
        getattr(parameter_owner(self.shafts, name), "Set" + name)(*values)
        return f"Set{name}{tuple(values)!r}"

    def set_boolean(self):
        name = self.rng.choice(BOOLEANS)
        value = self.rng.random() < 0.5
        getattr(parameter_owner(self.shafts, name), "Set" + name)(value)
        return f"Set{name}({value})"

    def preset(self):
        name = self.rng.choice(["Draft", "Interactive", "Final"])
        getattr(self.shafts, "SetQualityTo" + name)()
        return f"SetQualityTo{name}()"

    def textures(self):
        which = self.rng.choice(["Cookie", "NoiseTexture"])
        kind = self.rng.choice(["image", "empty", "none"])
        texture = {"image": lambda: image_texture(self.rng, self.rng.choice([1, 3])),
                   "empty": vtkTexture, "none": lambda: None}[kind]()
        getattr(parameter_owner(self.shafts, which), "Set" + which)(texture)
        return f"Set{which}({kind})"

    def medium(self):
        if self.rng.random() < 0.3:
            self.shafts.GetMedium().SetDensityField(None)
            return "SetDensityField(None)"
        image, expected = density_image(self.rng)
        if expected is None and self.rng.random() < 0.3:
            # The pipeline's way (its bad outputs' errors come with the frames: tested in
            # test_medium_field).
            producer = vtkTrivialProducer()
            producer.SetOutput(image)
            self.shafts.GetMedium().SetDensityFieldConnection(producer.GetOutputPort())
            return f"SetDensityFieldConnection({image.GetDimensions()})"
        if expected:
            self.expected_errors.append(expected)
        self.shafts.GetMedium().SetDensityField(image)
        return f"SetDensityField({image.GetDimensions()}, {expected or 'usable'})"

    def medium_object(self):
        # Another medium: one already used (its values, field and noise as they were left), or
        # a fresh default one.
        if self.rng.random() < 0.25:
            self.shafts.SetMedium(None)
            self.media.append(self.shafts.GetMedium())
            self.log.observe(self.media[-1])
            return "SetMedium(None)"
        index = self.rng.randrange(len(self.media))
        self.shafts.SetMedium(self.media[index])
        return f"SetMedium(media[{index}])"

    def translucent(self):
        # Translucent props: a pane across the spot's beam, a vertical pane between the camera
        # and the beam or behind it (the camera leg), a sphere shell around the scene's sphere
        # (two surfaces a ray crosses), or a cube: opacity anywhere in [0, 1] (0 and 1
        # included), any colour; or one taken out.
        rng = self.rng
        if self.translucent_actors and rng.random() < 0.3:
            actor = self.translucent_actors.pop(rng.randrange(len(self.translucent_actors)))
            self.renderer.RemoveActor(actor)
            return "translucent prop removed"
        kind = rng.choice(["pane", "front pane", "back pane", "shell", "cube"])
        if kind == "pane":
            source = vtkPlaneSource()
            y = rng.uniform(1.0, 5.5)
            source.SetOrigin(-2.0, y, -2.0)
            source.SetPoint1(2.0, y, -2.0)
            source.SetPoint2(-2.0, y, 2.0)
        elif kind in ("front pane", "back pane"):
            source = vtkPlaneSource()
            z = rng.uniform(2.5, 9.0) if kind == "front pane" else rng.uniform(-6.0, -2.5)
            x = rng.uniform(-3.0, 1.0)
            source.SetOrigin(x, -1.0, z)
            source.SetPoint1(x + rng.uniform(0.5, 6.0), -1.0, z)
            source.SetPoint2(x, 8.0, z)
        elif kind == "shell":
            source = vtkSphereSource()
            source.SetCenter(0.0, 1.5, 0.0)
            source.SetRadius(rng.uniform(0.9, 2.5))
        else:
            source = vtkCubeSource()
            source.SetCenter(rng.uniform(-2, 2), rng.uniform(0.5, 4.0), rng.uniform(-2, 2))
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        opacity = rng.choice([0.0, 1.0, rng.random(), rng.random()])
        actor.GetProperty().SetOpacity(opacity)
        actor.GetProperty().SetColor(rng.random(), rng.random(), rng.random())
        self.renderer.AddActor(actor)
        self.translucent_actors.append(actor)
        return f"translucent {kind} (opacity {opacity:.3f})"

    def volume(self):
        # Volumes: a slab or a puff of smoke, in front of, behind or across the beams, with an
        # opacity function anywhere in [0, 1] per unit distance in [0.01, 10]; one taken out,
        # made the medium (SetDensityVolume) or given back; its opacity changed.
        rng = self.rng
        medium = self.shafts.GetMedium()
        if self.volumes and rng.random() < 0.4:
            volume = rng.choice(self.volumes)
            choice = rng.choice(["remove", "medium", "opacity", "hide"])
            if choice == "remove":
                self.volumes.remove(volume)
                self.renderer.RemoveVolume(volume)
                return "volume removed"
            if choice == "medium":
                medium.SetDensityVolume(volume if medium.GetDensityVolume() is None else None)
                return f"SetDensityVolume({medium.GetDensityVolume() is not None})"
            if choice == "hide":
                volume.SetVisibility(not volume.GetVisibility())
                return f"volume visibility {volume.GetVisibility()}"
            opacity = volume.GetProperty().GetScalarOpacity()
            opacity.RemoveAllPoints()
            opacity.AddPoint(0.0, rng.choice([0.0, 1.0, rng.random()]))
            opacity.AddPoint(1.0, rng.choice([0.0, 1.0, rng.random()]))
            return "volume opacity changed"
        n = rng.randint(2, 12)
        image = vtkImageData()
        image.SetDimensions(n, rng.randint(2, 6), n)
        kind = rng.choice(["slab", "front", "puff"])
        if kind == "slab":
            image.SetOrigin(-4.0, rng.uniform(0.5, 5.0), -4.0)
            image.SetSpacing(8.0 / (n - 1), rng.uniform(0.02, 0.5), 8.0 / (n - 1))
        elif kind == "front":
            image.SetOrigin(rng.uniform(-3.0, 1.0), -1.0, rng.uniform(2.5, 9.0))
            image.SetSpacing(rng.uniform(0.1, 1.0), 2.0, rng.uniform(0.01, 0.2))
        else:
            image.SetOrigin(rng.uniform(-2, 1), rng.uniform(0.5, 3.0), rng.uniform(-2, 1))
            image.SetSpacing(*[rng.uniform(0.05, 0.5) for _ in range(3)])
        dims = image.GetDimensions()
        values = np.array([rng.random() for _ in range(dims[0] * dims[1] * dims[2])])
        scalars = numpy_to_vtk(values.astype(np.float32), deep=True)
        scalars.SetName("s")
        image.GetPointData().SetScalars(scalars)
        mapper = vtkOpenGLGPUVolumeRayCastMapper()
        mapper.SetInputData(image)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0.0, rng.choice([0.0, rng.random()]))
        opacity.AddPoint(1.0, rng.choice([1.0, rng.random()]))
        prop = vtkVolumeProperty()
        prop.SetScalarOpacity(opacity)
        prop.SetScalarOpacityUnitDistance(math.exp(rng.uniform(math.log(0.01), math.log(10.0))))
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        self.renderer.AddVolume(volume)
        self.volumes.append(volume)
        return f"volume {kind} {dims}"

    def light(self):
        rng, spot = self.rng, self.spot
        choice = rng.random()
        if choice < 0.4:
            spot.SetPosition(rng.uniform(-8, 8), rng.uniform(-2, 10), rng.uniform(-8, 8))
            spot.SetFocalPoint(rng.uniform(-3, 3), rng.uniform(-1, 2), rng.uniform(-3, 3))
            return f"light at {spot.GetPosition()} -> {spot.GetFocalPoint()}"
        if choice < 0.6:
            angle = rng.choice([0.01, 0.5, 89.9, 90.0, 180.0] + [rng.uniform(1, 89)] * 5)
            spot.SetConeAngle(angle)
            return f"SetConeAngle({angle})"
        if choice < 0.7:
            spot.SetExponent(rng.choice([0.0, 1.0, 128.0, rng.uniform(0, 32)]))
            spot.SetAttenuationValues(*[rng.choice([0.0, 1.0, rng.uniform(0, 2)])
                                        for _ in range(3)])
            spot.SetIntensity(rng.choice([0.0, 1e-6, 1.0, 1e3]))
            return (f"exponent {spot.GetExponent()}, attenuation {spot.GetAttenuationValues()},"
                    f" intensity {spot.GetIntensity()}")
        if choice < 0.8:
            spot.SetSwitch(rng.random() < 0.7)
            return f"spot switch {spot.GetSwitch()}"
        target = rng.choice(["none", "none", "spot", "point"])
        light = {"none": None, "spot": spot, "point": vtkLight()}[target]
        if target == "point":
            light.SetPositional(True)
            light.SetConeAngle(180.0)
        self.shafts.SetLight(light)
        return f"SetLight({target})"

    def several_lights(self):
        rng = self.rng
        name = rng.choice(sorted(self.others))
        light = self.others[name]
        choice = rng.random()
        if choice < 0.3:
            light.SetSwitch(not light.GetSwitch())
            return f"{name} switch {light.GetSwitch()}"
        if choice < 0.55:
            self.shafts.AddLight(light)
            return f"AddLight({name})"
        if choice < 0.7:
            self.shafts.RemoveLight(light)
            return f"RemoveLight({name})"
        if choice < 0.8:
            self.shafts.RemoveAllLights()
            return "RemoveAllLights()"
        if choice < 0.9:
            self.spot.SetPositional(not self.spot.GetPositional())
            return f"spot positional {self.spot.GetPositional()}"
        light.SetPosition(rng.uniform(-8, 8), rng.uniform(-2, 10), rng.uniform(-8, 8))
        light.SetFocalPoint(rng.uniform(-3, 3), rng.uniform(-1, 2), rng.uniform(-3, 3))
        return f"{name} at {light.GetPosition()} -> {light.GetFocalPoint()}"

    def usable_light(self):
        # Users switch lights back on: keep most frames computing shafts.
        self.spot.SetSwitch(True)
        self.spot.SetPositional(True)
        self.spot.SetConeAngle(self.rng.uniform(5, 60))
        self.spot.SetIntensity(1.0)
        self.shafts.SetLight(None)
        return "usable spotlight"

    def camera(self):
        rng = self.rng
        camera = self.renderer.GetActiveCamera()
        choice = rng.random()
        if choice < 0.5:
            camera.SetPosition(rng.uniform(-15, 15), rng.uniform(-3, 12), rng.uniform(-15, 15))
            camera.SetFocalPoint(rng.uniform(-2, 2), rng.uniform(0, 3), rng.uniform(-2, 2))
        elif choice < 0.65:
            # Inside the beam, next to the light.
            p = np.array(self.spot.GetPosition())
            f = np.array(self.spot.GetFocalPoint())
            camera.SetPosition(*(p + rng.uniform(0.001, 0.9) * (f - p)))
            camera.SetFocalPoint(*(f + np.array([rng.uniform(-1, 1), 0.0, rng.uniform(-1, 1)])))
        elif choice < 0.8:
            camera.SetParallelProjection(not camera.GetParallelProjection())
            camera.SetParallelScale(rng.choice([0.01, 1.0, 5.0, 100.0]))
        else:
            camera.SetViewAngle(rng.choice([1.0, 30.0, 120.0, 179.0]))
        camera.OrthogonalizeViewUp()
        self.renderer.ResetCameraClippingRange()
        return (f"camera {tuple(round(c, 3) for c in camera.GetPosition())}, parallel "
                f"{camera.GetParallelProjection()}, angle {camera.GetViewAngle()}")

    def window_size(self):
        rng = self.rng
        if rng.random() < 0.3:
            size = rng.choice([(1, 1), (1, 37), (53, 1), (2, 2)])
        else:
            size = (rng.randint(1, 200), rng.randint(1, 150))
        self.window.SetSize(*size)
        return f"window {size}"

    def viewport(self):
        rng = self.rng
        if rng.random() < 0.4:
            viewport = (0.0, 0.0, 1.0, 1.0)
        else:
            x0, y0 = rng.uniform(0, 0.9), rng.uniform(0, 0.9)
            viewport = (x0, y0, rng.uniform(x0 + 0.001, 1.0), rng.uniform(y0 + 0.001, 1.0))
        self.renderer.SetViewport(*viewport)
        return f"viewport {tuple(round(v, 3) for v in viewport)}"

    def multisamples(self):
        samples = self.rng.choice([0, 0, 2, 4, 8])
        self.window.SetMultiSamples(samples)
        return f"SetMultiSamples({samples})"

    def delegate(self):
        delegate = vtkRenderStepsPass() if self.rng.random() < 0.5 else None
        self.shafts.SetDelegatePass(delegate)
        return f"SetDelegatePass({'steps' if delegate else None})"

    def update_rate(self):
        # What an interactor does while the user drags (15) and at rest (0.0001).
        rate = self.rng.choice([0.0001, 0.0001, 0.5, 15.0, 60.0, 1000.0])
        self.window.SetDesiredUpdateRate(rate)
        return f"SetDesiredUpdateRate({rate})"

    def junk_vtk(self):
        """Junk VTK takes on the objects the pass reads (light, camera, prop, image); undone a
        few frames later (undo_junk) or by the actions that set those values."""
        rng = self.rng
        nan = rng.choice([math.nan, math.inf, -math.inf])
        spot, camera = self.spot, self.renderer.GetActiveCamera()
        actor = self.renderer.GetActors().GetLastActor()
        choices = {
            "exponent": (lambda: spot.SetExponent(nan), spot.SetExponent, spot.GetExponent()),
            "intensity": (lambda: spot.SetIntensity(nan), spot.SetIntensity,
                          spot.GetIntensity()),
            "colour": (lambda: spot.SetDiffuseColor(nan, 1.0, 1.0),
                       lambda v: spot.SetDiffuseColor(*v), spot.GetDiffuseColor()),
            "attenuation": (lambda: spot.SetAttenuationValues(1.0, nan, 0.0),
                            lambda v: spot.SetAttenuationValues(*v),
                            spot.GetAttenuationValues()),
            "cone": (lambda: spot.SetConeAngle(nan), spot.SetConeAngle, spot.GetConeAngle()),
            "light on its focal point": (lambda: spot.SetPosition(*spot.GetFocalPoint()),
                                         lambda v: spot.SetPosition(*v), spot.GetPosition()),
            "light transform": (lambda: spot.SetTransformMatrix(nan_matrix(nan)),
                                spot.SetTransformMatrix, spot.GetTransformMatrix()),
            "parallel scale": (lambda: camera.SetParallelScale(rng.choice([0.0, nan])),
                               camera.SetParallelScale, camera.GetParallelScale()),
            "view angle": (lambda: camera.SetViewAngle(rng.choice([0.0, 180.0, nan])),
                           camera.SetViewAngle, camera.GetViewAngle()),
            "prop transform": (lambda: actor.SetPosition(nan, 0.0, 0.0),
                               lambda v: actor.SetPosition(*v), actor.GetPosition()),
            "cookie": (lambda: self.shafts.SetCookie(nan_image(nan)), self.shafts.SetCookie,
                       self.shafts.GetCookie()),
            "noise": (lambda: self.shafts.GetMedium().SetNoiseTexture(nan_image(nan)),
                      self.shafts.GetMedium().SetNoiseTexture, self.shafts.GetMedium().GetNoiseTexture()),
        }
        name = rng.choice(sorted(choices))
        apply, restore, value = choices[name]
        apply()
        self.undo.append(lambda: restore(value))
        return f"junk {name} ({nan})"

    def undo_junk(self):
        for undo in reversed(self.undo):
            undo()
        self.undo.clear()
        return "junk undone"

    def still(self):
        # Nothing changes: with ProgressiveRefinement on, one more estimate (or the converged
        # picture again).
        return "still"

    def selection(self):
        w, h = self.window.GetSize()
        selector = vtkHardwareSelector()
        selector.SetRenderer(self.renderer)
        selector.SetArea(0, 0, w - 1, h - 1)
        selector.SetFieldAssociation(vtkDataObject.FIELD_ASSOCIATION_CELLS)
        selector.Select()
        return "hardware selection"

    ACTIONS = [(set_scalar, 30), (set_vector, 8), (set_boolean, 6), (preset, 2), (textures, 5),
               (light, 10), (several_lights, 8), (usable_light, 5), (camera, 10), (window_size, 6), (viewport, 4), (multisamples, 3),
               (delegate, 2), (selection, 2), (still, 6), (update_rate, 3), (junk_vtk, 6),
               (medium, 3), (medium_object, 2), (translucent, 4), (volume, 3)]

    # --- one frame --------------------------------------------------------------------------
    def step(self, index):
        self.errors.clear()
        self.warnings.clear()
        self.refused.clear()
        self.expected_errors.clear()
        actions, weights = zip(*self.ACTIONS)
        done = [action(self) for action in self.rng.choices(actions, weights,
                                                            k=self.rng.randint(1, 3))]
        if self.undo and self.rng.random() < 0.3:  # junk lasts a few frames
            done.append(self.undo_junk())
        self.steps.append(f"frame {index}: " + "; ".join(done))
        start, cpu_start = time.perf_counter(), time.process_time()
        self.window.Render()
        elapsed, cpu = time.perf_counter() - start, time.process_time() - cpu_start
        self.frame_times.append((elapsed, self.steps[-1]))
        if self.shafts.GetLastFrame().GetMethod() >= 0:
            self.shafted += 1
        return self.check(cpu)

    def check(self, cpu):
        problems = []
        if cpu > FRAME_CPU_LIMIT:
            problems.append(f"frame took {cpu:.1f} s of CPU time (limit {FRAME_CPU_LIMIT} s)")
        if self.shafts.GetLastFrame().GetGLErrorCount():
            problems.append(f"{self.shafts.GetLastFrame().GetGLErrorCount()} GL errors")
        for error in self.errors:
            if not any(name in error and "non-finite" in error for name in self.refused) and \
                    not any(words in error for words in self.expected_errors):
                problems.append(f"error: {error.strip()}")
        for words in self.expected_errors:
            if not any(words in e for e in self.errors):
                problems.append(f"no error for a density image that {words}")
        for name in self.refused:
            if not any(name in e for e in self.errors):
                problems.append(f"no error for the non-finite {name}")
        for warning in self.warnings:
            if not any(w in warning for w in DOCUMENTED_WARNINGS):
                problems.append(f"warning: {warning.strip()}")
        problems += [f"VTK {kind}: {text.strip()}" for kind, text in VTK_OUTPUT.unexpected()]
        VTK_OUTPUT.messages.clear()
        estimates = self.shafts.GetLastFrame().GetRefinementEstimates()
        split = self.shafts.GetLastFrame().GetRefinementSplit()  # (estimates a frame's share)
        if estimates > self.shafts.GetRefinementFrames() * split or (
                estimates and not self.shafts.GetProgressiveRefinement()):
            problems.append(f"{estimates} refinement estimates")
        w, h = self.shafts.GetLastFrame().GetViewportSize()
        if w > 0 and h > 0 and not self.shafts.GetLastFrame().GetPlainScene():
            image = rh.in_scatter(self.shafts)
            if not np.all(np.isfinite(image)):
                problems.append("non-finite in-scatter")
            elif image.min() < 0.0:
                problems.append(f"negative in-scatter {image.min()}")
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        if peak > MEMORY_LIMIT_MIB:
            problems.append(f"peak memory {peak:.0f} MiB (limit {MEMORY_LIMIT_MIB} MiB)")
        return problems


def test_fuzz(request):
    option = request.config.getoption("--fuzz-seed")
    seed = random.randrange(2 ** 32) if option == "random" else int(option)
    frames = request.config.getoption("--fuzz-frames")
    fuzzer = Fuzzer(seed)
    start = time.perf_counter()
    try:
        for index in range(frames):
            problems = fuzzer.step(index)
            assert not problems, (
                f"fuzz seed {seed}, frame {index}: " + "; ".join(problems) +
                "\nlast steps:\n  " + "\n  ".join(fuzzer.steps[-15:]) +
                f"\nreproduce: pytest tests/python/test_fuzz.py --fuzz-seed {seed} "
                f"--fuzz-frames {index + 1}")
    finally:
        fuzzer.window.SetMultiSamples(0)
        fuzzer.window.SetDesiredUpdateRate(0.0001)
        fuzzer.renderer.SetViewport(0.0, 0.0, 1.0, 1.0)
    slowest = max(fuzzer.frame_times)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"\nfuzz seed {seed}: {frames} frames ({fuzzer.shafted} with shafts) in "
          f"{time.perf_counter() - start:.0f} s; "
          f"median frame {np.median([t for t, _ in fuzzer.frame_times]) * 1000:.0f} ms, "
          f"slowest {slowest[0]:.2f} s ({slowest[1]}); peak memory {peak:.0f} MiB")
