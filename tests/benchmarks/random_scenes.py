#!/usr/bin/python3
"""Randomised scene benchmark: error against the float64 reference and cost, per preset and
method, over seeded random scenes from the families users have.

    PYTHONPATH=build/lib/python3.11/dist-packages \
        xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 \
        tests/benchmarks/random_scenes.py --seed 0 --scenes 50 --output-dir docs

Each scene is drawn from its own generator (seeded with --seed, the scene's index and an attempt
number): occluders (a few spheres, a few rotated boxes, a grid of thin bars across the beam, an
isosurface of VTK's wavelet as scenes.isosurface, or many small props), a floor or none, one
light (a spot with cone 5-80 degrees and exponent 0-32, a point light, or a directional light
given to the pass with SetLight), attenuation (1,0,0), (0,0,1) or (1,0,c2), a medium whose
optical depth along the lit region is 0.01-3 (log-uniform), a phase function (isotropic,
Henyey-Greenstein with g in [-0.5, 0.8], Rayleigh), a camera outside, grazing or inside the beam,
perspective or parallel, and a resolution from 240p to 1080p (--max-height caps it). A scene
whose reference has no lit pixel in view (peak 0, or fewer than --min-lit-fraction of the pixels
above 1% of the peak), or whose view holds nothing (every prop behind the camera: VTK's clipping
range collapses), is drawn again (next attempt), not reported.

For every scene and setting (the Draft, Interactive and Final presets; the defaults of RAY_MARCH,
RADIAL_BLUR and ANALYTIC; or those of --ladder, --downsampled, --epipolar or --light-volume;
--validation adds the fitted ladder's): the relative RMS
error of the pass's in-scatter against vtkLightShaftReference (exact surfaces and shadows, float64; pixels above
1% of the reference's peak), and the time ratio: median frame time with the pass over the median
frame time of the same scene without it, measured in the same run (--frames frames after a warm-up
frame, glFinish).

Writes random-scenes.csv (one row per scene and setting, the scene as JSON), random-scenes.md
(median and 90th percentile per setting, the worst scenes), images/random-pareto.png and
images/random-worst-K.png (the three worst scenes of the Interactive preset) into --output-dir.
--only-scene K re-runs scene K of --seed alone. --smoke: 3 scenes at 96x72, 3 settings,
2 frames. --ladder: the settings tests/benchmarks/fit_error_model.py fits the TargetError model
on (with --smoke its cheapest and dearest), instead of the presets, methods and targets.
--downsampled: settings that compute the in-scatter at a reduced resolution (ANALYTIC and
RAY_MARCH at DownsampleFactor 2 and 4) against ANALYTIC, the RAY_MARCH defaults and
Interactive, instead of the presets, methods and targets (with --smoke: Interactive and one).
--epipolar: EPIPOLAR's settings (steps, lines, samples, marching step, shadow map) against the
cheapest setting of --downsampled, the RAY_MARCH defaults and Interactive. --light-volume:
LIGHT_VOLUME's (mesh cells, shadow map, downsampling) against the same and one of EPIPOLAR's.

VTK warnings and errors are captured per setting; the pass's documented warnings (ANALYTIC
ignoring shadows) are counted as expected, anything else is listed as unexpected.
"""

import argparse
import csv
import dataclasses
import json
import math
import os
import platform
import re
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
sys.path.insert(0, HERE)

import lightshaft_reference as ref  # noqa: E402
import progress  # noqa: E402
import render_helpers as rh  # noqa: E402
from benchmark import reference_image  # noqa: E402  (tests/benchmarks/benchmark.py)
from lightshafts import parameter_owner, vtkLightShaftMedium, vtkLightShaftPass  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow  # noqa: E402
from vtkmodules.vtkCommonMath import vtkMatrix4x4  # noqa: E402
from vtkmodules.vtkFiltersSources import (  # noqa: E402
    vtkCubeSource, vtkPlaneSource, vtkSphereSource)
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper  # noqa: E402

SETTINGS = [
    ("Draft", dict(Quality="Draft")),
    ("Interactive", dict(Quality="Interactive")),
    ("Final", dict(Quality="Final")),
    ("RAY_MARCH defaults", dict(Method=vtkLightShaftPass.RAY_MARCH)),
    ("RADIAL_BLUR defaults", dict(Method=vtkLightShaftPass.RADIAL_BLUR)),
    ("ANALYTIC", dict(Method=vtkLightShaftPass.ANALYTIC)),
    ("Target 5%", dict(TargetError=0.05)),
    ("Target 2%", dict(TargetError=0.02)),
    ("Target 1%", dict(TargetError=0.01)),
    ("Target 0.5%", dict(TargetError=0.005)),
]
SMOKE_SETTINGS = ("Interactive", "Final", "Target 2%")


def _rung(slices, jitter, blur, downsample, shadow_map):
    return dict(Method=vtkLightShaftPass.SLICES, AutomaticSliceCount=False,
                NumberOfSlices=slices, Jitter=jitter, BlurRadius=blur,
                DownsampleFactor=downsample, ShadowMapSize=shadow_map,
                AccumulationPrecision=vtkLightShaftPass.ACCUMULATE_FLOAT32)


def _march(steps, interleave, shadow_map, downsample=1):
    return dict(Method=vtkLightShaftPass.RAY_MARCH, NumberOfSteps=steps,
                InterleaveSize=interleave, BlurRadius=0, DownsampleFactor=downsample,
                ShadowMapSize=shadow_map,
                AccumulationPrecision=vtkLightShaftPass.ACCUMULATE_FLOAT32)


# --downsampled: today's cheapest ways (the in-scatter at a reduced resolution, depth-aware
# upsampling), against ANALYTIC, the RAY_MARCH defaults and Interactive: the baseline that
# cheaper methods (epipolar sampling, light volumes) are measured against.
DOWNSAMPLED_SETTINGS = [
    ("Interactive", dict(Quality="Interactive")),
    ("RAY_MARCH defaults", dict(Method=vtkLightShaftPass.RAY_MARCH)),
    ("ANALYTIC", dict(Method=vtkLightShaftPass.ANALYTIC)),
    ("ANALYTIC d2", dict(Method=vtkLightShaftPass.ANALYTIC, DownsampleFactor=2, BlurRadius=0)),
    ("M8 i2 d2 m512", _march(8, 2, 512, downsample=2)),
    ("M16 i2 d2 m1024", _march(16, 2, 1024, downsample=2)),
    ("M32 i1 d2 m1024", _march(32, 1, 1024, downsample=2)),
    ("M16 i1 d4 m1024", _march(16, 1, 1024, downsample=4)),
]
DOWNSAMPLED_SMOKE_SETTINGS = ("Interactive", "M8 i2 d2 m512")


def _epipolar(steps, lines, samples, step, shadow_map, downsample=1):
    return dict(Method=vtkLightShaftPass.EPIPOLAR, NumberOfSteps=steps, EpipolarLines=lines,
                EpipolarSamples=samples, EpipolarStep=step, BlurRadius=0,
                DownsampleFactor=downsample, ShadowMapSize=shadow_map,
                AccumulationPrecision=vtkLightShaftPass.ACCUMULATE_FLOAT32)


# --epipolar: EPIPOLAR's settings against today's cheapest (--downsampled's best) and dearest.
EPIPOLAR_SETTINGS = [
    ("Interactive", dict(Quality="Interactive")),
    ("RAY_MARCH defaults", dict(Method=vtkLightShaftPass.RAY_MARCH)),
    ("M8 i2 d2 m512", _march(8, 2, 512, downsample=2)),
    ("E128 l1024 s512 k16 m2048", _epipolar(128, 1024, 512, 16, 2048)),
    ("E64 l512 s512 k16 m2048", _epipolar(64, 512, 512, 16, 2048)),
    ("E32 l512 s512 k16 m1024", _epipolar(32, 512, 512, 16, 1024)),
    ("E32 l256 s512 k16 m1024", _epipolar(32, 256, 512, 16, 1024)),
    ("E32 l256 s256 k8 m1024", _epipolar(32, 256, 256, 8, 1024)),
    ("E16 l128 s256 k8 m512", _epipolar(16, 128, 256, 8, 512)),
]
EPIPOLAR_SMOKE_SETTINGS = ("Interactive", "E32 l256 s256 k8 m1024")


def _light_volume(cells, shadow_map, downsample=1):
    return dict(Method=vtkLightShaftPass.LIGHT_VOLUME, LightVolumeResolution=cells,
                BlurRadius=0, DownsampleFactor=downsample, ShadowMapSize=shadow_map,
                AccumulationPrecision=vtkLightShaftPass.ACCUMULATE_FLOAT32)


# --light-volume: LIGHT_VOLUME's settings (mesh cells, shadow map, downsampling) against
# EPIPOLAR's and today's cheapest and dearest.
LIGHT_VOLUME_SETTINGS = [
    ("Interactive", dict(Quality="Interactive")),
    ("RAY_MARCH defaults", dict(Method=vtkLightShaftPass.RAY_MARCH)),
    ("M8 i2 d2 m512", _march(8, 2, 512, downsample=2)),
    ("E32 l256 s256 k8 m1024", _epipolar(32, 256, 256, 8, 1024)),
    ("V1024 m2048", _light_volume(1024, 2048)),
    ("V512 m2048", _light_volume(512, 2048)),
    ("V256 m1024", _light_volume(256, 1024)),
    ("V128 m512", _light_volume(128, 512)),
    ("V64 m256", _light_volume(64, 256)),
    ("V128 m512 d2", _light_volume(128, 512, downsample=2)),
    ("V1024 m1024", _light_volume(1024, 1024)),
    ("V512 m512", _light_volume(512, 512)),
]
LIGHT_VOLUME_SMOKE_SETTINGS = ("Interactive", "V256 m1024")


# The settings the error model is fitted on (--ladder), cheapest first: by the median time
# ratios of their training runs (docs/error-model-training.csv).
LADDER = [
    ("E16 l128 s256 k8 m512", _epipolar(16, 128, 256, 8, 512)),
    ("E32 l256 s256 k8 m1024", _epipolar(32, 256, 256, 8, 1024)),
    ("V64 m256", _light_volume(64, 256)),
    ("V128 m512", _light_volume(128, 512)),
    ("S16 j b2 d2 m512", _rung(16, True, 2, 2, 512)),
    ("V256 m1024", _light_volume(256, 1024)),
    ("S32 j b2 d2 m512", _rung(32, True, 2, 2, 512)),
    ("S32 j b1 d2 m1024", _rung(32, True, 1, 2, 1024)),
    ("S64 b0 d2 m1024", _rung(64, False, 0, 2, 1024)),
    ("V512 m2048", _light_volume(512, 2048)),
    ("S32 b0 d1 m1024", _rung(32, False, 0, 1, 1024)),
    ("S32 j b1 d1 m1024", _rung(32, True, 1, 1, 1024)),
    ("V1024 m2048", _light_volume(1024, 2048)),
    ("M32 i2 m2048", _march(32, 2, 2048)),
    ("S64 b0 d1 m1024", _rung(64, False, 0, 1, 1024)),
    ("S64 j b2 d1 m1024", _rung(64, True, 2, 1, 1024)),
    ("S64 j b1 d1 m2048", _rung(64, True, 1, 1, 2048)),
    ("M64 i1 m2048", _march(64, 1, 2048)),
    ("M64 i2 m2048", _march(64, 2, 2048)),
    ("S128 j b1 d1 m2048", _rung(128, True, 1, 1, 2048)),
    ("S128 b0 d1 m2048", _rung(128, False, 0, 1, 2048)),
    ("M128 i1 m2048", _march(128, 1, 2048)),
    ("S256 b0 d1 m2048", _rung(256, False, 0, 1, 2048)),
    ("M256 i1 m2048", _march(256, 1, 2048)),
    ("S512 b0 d1 m2048", _rung(512, False, 0, 1, 2048)),
]

def _fitted_table():
    with open(os.path.join(HERE, "..", "..", "plugin", "core", "vtkLightShaftErrorModelTable.h")) as f:
        return f.read()


def fitted_ladder():
    """The names of the ladder's settings in the fitted table (plugin/core/)."""
    return re.findall(r'^\s*\{ \{ "([^"]+)"', _fitted_table(), re.M)


def fitted_presets():
    """The presets' settings in the fitted table: {"Draft": "E16 l128 s256 k8 m512", ...}."""
    return dict(re.findall(r"constexpr int (\w+)Setting = \d+; // (.+), aim", _fitted_table()))


FAMILIES = ("spheres", "boxes", "bars", "isosurface", "props")
HEIGHTS = (240, 360, 480, 720, 1080)
# Warnings the pass documents; anything else VTK prints is a finding.
EXPECTED_WARNINGS = [re.compile(r"Method ANALYTIC ignores shadows"),
                     re.compile(r"Method LIGHT_VOLUME has no closed form")]


@dataclasses.dataclass
class Scene:
    """Everything needed to rebuild a scene (recorded in the CSV as JSON)."""
    index: int
    attempt: int
    width: int
    height: int
    family: str
    occluders: list  # family-specific dicts
    floor: bool
    light_kind: str  # spot, point, directional
    light_position: list
    light_focal_point: list
    cone_angle: float
    exponent: float
    attenuation: list
    optical_depth: float
    lit_length: float  # the length the optical depth is measured over
    sigma_s: list
    sigma_a: list
    phase: str  # isotropic, hg, rayleigh
    anisotropy: float
    camera_kind: str  # outside, grazing, inside
    parallel: bool
    camera_position: list
    camera_focal_point: list
    camera_view_up: list
    view_angle: float
    parallel_scale: float

    def summary(self):
        light = self.light_kind
        if light == "spot":
            light += f" {self.cone_angle:.0f}deg exp {self.exponent:.1f}"
        if light != "directional":
            light += " att (" + ",".join(f"{a:g}" for a in self.attenuation) + ")"
        phase = {"hg": f"HG g={self.anisotropy:.2f}"}.get(self.phase, self.phase)
        return (f"{self.width}x{self.height}, {self.family}{'' if self.floor else ' (no floor)'}, "
                f"{light}, tau {self.optical_depth:.3g}, {phase}, camera {self.camera_kind} "
                f"{'parallel' if self.parallel else 'perspective'}")


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _perpendicular(axis, rng):
    """A random unit vector perpendicular to `axis`."""
    while True:
        v = np.cross(axis, rng.normal(size=3))
        if np.linalg.norm(v) > 1e-3:
            return _unit(v)


def _direction(elevation_deg, azimuth_deg):
    e, a = math.radians(elevation_deg), math.radians(azimuth_deg)
    return np.array([math.cos(e) * math.cos(a), math.sin(e), math.cos(e) * math.sin(a)])


def _r(x):
    return [round(float(v), 6) for v in x]


def draw_scene(seed, index, attempt, max_height, size=None):
    """Scene `index` of `seed` (its `attempt`-th draw)."""
    rng = np.random.default_rng([seed, index, attempt])
    heights = [h for h in HEIGHTS if h <= max_height] or [max_height]
    height = int(rng.choice(heights))
    width = int(round(height * (4 / 3 if rng.random() < 0.5 else 16 / 9)))
    width += width % 2
    if size:
        width, height = size
    family = str(rng.choice(FAMILIES))
    centre = np.array([rng.uniform(-1, 1), rng.uniform(1.5, 3.0), rng.uniform(-1, 1)])
    floor = bool(rng.random() < 0.85)

    kind = str(rng.choice(["spot", "point", "directional"], p=[0.5, 0.25, 0.25]))
    cone, exponent = 90.0, 0.0
    if kind == "spot":
        elevation, distance = rng.uniform(35, 90), rng.uniform(5, 10)
    elif kind == "point":
        elevation, distance = rng.uniform(60, 90), rng.uniform(2.5, 5)
    else:
        elevation, distance = rng.uniform(30, 90), 8.0
    up = _direction(elevation, rng.uniform(0, 360))
    axis = -up  # from the light towards the occluders
    position = centre + distance * up

    # Occluders around the centre, kept clear of the light.
    occluders = []
    if family == "spheres":
        for _ in range(int(rng.integers(1, 4))):
            occluders.append(dict(shape="sphere", centre=_r(centre + rng.uniform(-1.0, 1.0, 3)
                                                              * [1, 0.5, 1]),
                                  radius=float(rng.uniform(0.3, 1.1))))
    elif family == "boxes":
        for _ in range(int(rng.integers(1, 4))):
            occluders.append(dict(shape="box", centre=_r(centre + rng.uniform(-1.0, 1.0, 3)
                                                           * [1, 0.5, 1]),
                                  lengths=_r(rng.uniform(0.3, 1.6, 3)),
                                  orientation=_r(rng.uniform(0, 90, 3))))
    elif family == "bars":
        # A grid of thin bars across the beam, in the plane through the centre.
        u = _perpendicular(axis, rng)
        v = np.cross(axis, u)
        n, thickness = int(rng.integers(3, 9)), float(rng.uniform(0.04, 0.2))
        length, spacing = float(rng.uniform(2.0, 4.0)), float(rng.uniform(0.25, 0.7))
        for i in range(n):
            offset = (i - (n - 1) / 2) * spacing
            occluders.append(dict(shape="bar", centre=_r(centre + offset * v), along=_r(u),
                                  across=_r(v), length=length, thickness=thickness))
        if rng.random() < 0.5:  # a cross bar
            occluders.append(dict(shape="bar", centre=_r(centre), along=_r(v), across=_r(u),
                                  length=n * spacing, thickness=thickness))
    elif family == "isosurface":
        occluders.append(dict(shape="isosurface", centre=_r(centre),
                              scale=float(rng.uniform(0.1, 0.22)),
                              iso_value=float(rng.uniform(140, 200))))
    else:
        for _ in range(int(rng.integers(20, 81))):
            occluders.append(dict(shape=str(rng.choice(["sphere", "box"])),
                                  centre=_r(centre + rng.uniform(-1.5, 1.5, 3) * [1, 0.7, 1]),
                                  radius=float(rng.uniform(0.04, 0.18)),
                                  lengths=_r(rng.uniform(0.06, 0.3, 3)),
                                  orientation=_r(rng.uniform(0, 90, 3))))
    extent = {"spheres": 2.2, "boxes": 2.4, "bars": 2.5, "isosurface": 2.5, "props": 2.2}[family]

    attenuation = [1.0, 0.0, 0.0]
    if kind == "spot":
        cone = float(rng.uniform(5, 80))
        exponent = float(0.0 if rng.random() < 0.3 else rng.uniform(0, 32))
    if kind != "directional":
        choice = rng.integers(3)
        attenuation = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
                       [1.0, 0.0, float(rng.uniform(0.01, 0.5))])[choice]
    # The lit region's length: from the light (a sun: its plane) to the floor along the axis
    # (or twice the distance to the occluders without a floor).
    lit_length = (position[1] / -axis[1]) if floor and axis[1] < -0.05 else 2 * distance
    tau = float(math.exp(rng.uniform(math.log(0.01), math.log(3.0))))
    sigma_t = tau / lit_length
    albedo = rng.uniform(0.5, 1.0)
    tint = rng.uniform(0.8, 1.2, 3)
    sigma_s = sigma_t * albedo * tint
    sigma_a = np.maximum(sigma_t * tint - sigma_s, 0.0)
    phase = str(rng.choice(["isotropic", "hg", "rayleigh"]))
    g = float(rng.uniform(-0.5, 0.8)) if phase == "hg" else 0.0

    # The camera: the beam's nominal radius at a point on its axis.
    def radius_at(s):
        if kind == "spot":
            return s * math.tan(math.radians(min(cone, 80.0)))
        return 1.5

    camera_kind = str(rng.choice(["outside", "grazing", "inside"]))
    parallel = bool(rng.random() < 0.25)
    view_angle = float(rng.uniform(20, 60))
    clear = max(distance - extent, 0.6)  # light to the occluders' bound
    if camera_kind == "outside":
        s = rng.uniform(0.3, 0.9) * distance
        focal = position + s * axis
        look = _direction(rng.uniform(-5, 30), rng.uniform(0, 360))
        camera = focal + rng.uniform(8, 16) * look
    elif camera_kind == "grazing":
        s = rng.uniform(0.3, 0.8) * distance
        mid = position + s * axis
        side = _perpendicular(axis, rng)
        r = radius_at(s) * rng.uniform(1.1, 1.6) + 0.3
        camera = mid + r * side
        if floor and camera[1] < 0.3:
            camera = mid - r * side
        sign = 1.0 if rng.random() < 0.5 else -1.0
        focal = camera + 5.0 * sign * axis - 0.5 * r * side
    else:
        s = rng.uniform(0.25, 0.75) * clear
        camera = position + s * axis + 0.3 * radius_at(s) * rng.uniform(-1, 1) \
            * _perpendicular(axis, rng)
        target = rng.integers(3)
        if target == 0:
            focal = centre
        elif target == 1:
            focal = camera + _direction(rng.uniform(-60, 10), rng.uniform(0, 360))
        else:
            focal = camera + axis
    if floor:
        camera[1] = max(camera[1], 0.3)
    forward = _unit(focal - camera)
    view_up = np.array([0.0, 1.0, 0.0])
    if abs(forward[1]) > 0.98:
        view_up = np.array([1.0, 0.0, 0.0])
    parallel_scale = float(np.linalg.norm(focal - camera) * math.tan(math.radians(view_angle / 2)))
    if parallel:
        parallel_scale = max(parallel_scale, 2.0)

    return Scene(index=index, attempt=attempt, width=width, height=height, family=family,
                 occluders=occluders, floor=floor, light_kind=kind, light_position=_r(position),
                 light_focal_point=_r(centre), cone_angle=cone, exponent=exponent,
                 attenuation=attenuation, optical_depth=tau, lit_length=float(lit_length),
                 sigma_s=_r(sigma_s), sigma_a=_r(sigma_a), phase=phase, anisotropy=g,
                 camera_kind=camera_kind, parallel=parallel, camera_position=_r(camera),
                 camera_focal_point=_r(focal), camera_view_up=_r(view_up),
                 view_angle=view_angle, parallel_scale=parallel_scale)


def _actor(source, color, renderer):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    renderer.AddActor(actor)
    return actor


def build(renderer, scene):
    """Add the scene's props and light to `renderer`, set its camera; return the light."""
    from vtkmodules.vtkFiltersCore import vtkContourFilter
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
    colours = [(0.9, 0.5, 0.3), (0.35, 0.6, 0.9), (0.6, 0.8, 0.4), (0.8, 0.75, 0.6)]
    for i, o in enumerate(scene.occluders):
        colour = colours[i % len(colours)]
        if o["shape"] == "sphere":
            source = vtkSphereSource()
            source.SetCenter(*o["centre"])
            source.SetRadius(o["radius"])
            resolution = 16 if scene.family == "props" else 48
            source.SetThetaResolution(resolution)
            source.SetPhiResolution(resolution)
            _actor(source, colour, renderer)
        elif o["shape"] == "box":
            source = vtkCubeSource()
            source.SetXLength(o["lengths"][0])
            source.SetYLength(o["lengths"][1])
            source.SetZLength(o["lengths"][2])
            actor = _actor(source, colour, renderer)
            actor.SetOrientation(*o["orientation"])
            actor.SetPosition(*o["centre"])
        elif o["shape"] == "bar":
            source = vtkCubeSource()
            source.SetXLength(o["length"])
            source.SetYLength(o["thickness"])
            source.SetZLength(o["thickness"])
            actor = _actor(source, colour, renderer)
            along, across = np.array(o["along"]), np.array(o["across"])
            third = np.cross(along, across)
            matrix = vtkMatrix4x4()
            for row in range(3):
                matrix.SetElement(row, 0, along[row])
                matrix.SetElement(row, 1, across[row])
                matrix.SetElement(row, 2, third[row])
                matrix.SetElement(row, 3, o["centre"][row])
            actor.SetUserMatrix(matrix)
        else:
            wavelet = vtkRTAnalyticSource()
            wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
            contour = vtkContourFilter()
            contour.SetInputConnection(wavelet.GetOutputPort())
            contour.SetValue(0, o["iso_value"])
            contour.ComputeNormalsOn()
            contour.ComputeScalarsOff()
            actor = _actor(contour, colour, renderer)
            actor.SetScale(o["scale"], o["scale"], o["scale"])
            actor.SetPosition(*o["centre"])
    if scene.floor:
        floor = vtkPlaneSource()
        s = 12.0
        floor.SetOrigin(-s, 0.0, -s)
        floor.SetPoint1(-s, 0.0, s)
        floor.SetPoint2(s, 0.0, -s)
        _actor(floor, (0.75, 0.7, 0.65), renderer)

    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(scene.light_kind != "directional")
    light.SetPosition(*scene.light_position)
    light.SetFocalPoint(*scene.light_focal_point)
    light.SetConeAngle(scene.cone_angle if scene.light_kind == "spot" else 180.0)
    light.SetExponent(scene.exponent)
    light.SetAttenuationValues(*scene.attenuation)
    light.SetIntensity(1.0)
    light.SetColor(1.0, 0.95, 0.85)
    renderer.AddLight(light)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(*scene.camera_position)
    camera.SetFocalPoint(*scene.camera_focal_point)
    camera.SetViewUp(*scene.camera_view_up)
    camera.SetViewAngle(scene.view_angle)
    camera.SetParallelProjection(scene.parallel)
    camera.SetParallelScale(scene.parallel_scale)
    renderer.ResetCameraClippingRange()
    return light


def light_in_view(renderer, scene):
    """Whether the light (a sun: its direction) projects inside the picture, in front of the
    camera: then pixels near its image hold most of the in-scatter (with inverse-square
    attenuation a few pixels can hold most of the reference's energy)."""
    camera = renderer.GetActiveCamera()
    matrix = camera.GetCompositeProjectionTransformMatrix(scene.width / scene.height, -1, 1)
    if scene.light_kind == "directional":
        point = list(np.subtract(scene.light_position, scene.light_focal_point)) + [0.0]
    else:
        point = list(scene.light_position) + [1.0]
    x, y, _, w = matrix.MultiplyPoint(point)
    # In front of the camera (a parallel projection's w is 1 behind it too).
    ahead = np.dot(np.subtract(point[:3], point[3] * np.asarray(camera.GetPosition())),
                   camera.GetDirectionOfProjection()) > 0
    return bool(ahead and w > 0 and abs(x / w) <= 1 and abs(y / w) <= 1)


def error_model_columns(shafts, scene):
    """What the pass's error model saw in the last frame (its features of the first lit light)
    and predicted (-1: no prediction), as CSV columns (tests/benchmarks/fit_error_model.py)."""
    falling = scene.light_kind != "directional" and any(a != 0 for a in scene.attenuation[1:])
    return dict(depth_range_in_beam_widths=shafts.GetLastFrame().GetDepthRangeInBeamWidths(),
                beam_width_in_pixels=shafts.GetLastFrame().GetBeamWidthInPixels(),
                model_optical_depth=shafts.GetLastFrame().GetOpticalDepth(),
                shadow_texel_in_pixels=shafts.GetLastFrame().GetShadowTexelInPixels(),
                model_light_in_view=int(shafts.GetLastFrame().GetLightInView()),
                falling_attenuation=int(falling), kind=scene.light_kind,
                predicted_error=shafts.GetLastFrame().GetPredictedError(),
                model_setting=shafts.GetErrorModelSettingName(shafts.GetLastFrame().GetErrorModelSetting()))


def configure(shafts, scene, light, params):
    shafts.GetMedium().SetScatteringCoefficient(*scene.sigma_s)
    shafts.GetMedium().SetAbsorptionCoefficient(*scene.sigma_a)
    shafts.GetMedium().SetPhaseFunction({"isotropic": vtkLightShaftMedium.ISOTROPIC,
                             "hg": vtkLightShaftMedium.HENYEY_GREENSTEIN,
                             "rayleigh": vtkLightShaftMedium.RAYLEIGH}[scene.phase])
    shafts.GetMedium().SetAnisotropy(scene.anisotropy)
    if scene.light_kind == "directional":
        shafts.SetLight(light)  # directional lights scatter only when given
    for key, value in params.items():
        if key == "Quality":
            getattr(shafts, f"SetQualityTo{value}")()
        else:
            getattr(parameter_owner(shafts, key), "Set" + key)(value)


class WarningLog:
    """Every message VTK prints, captured (vtkStringOutputWindow) and split into messages."""

    def __init__(self):
        self.window = vtkStringOutputWindow()
        self.seen = 0
        vtkOutputWindow.SetInstance(self.window)

    def take(self):
        """(expected, unexpected) messages since the last call."""
        output = self.window.GetOutput()  # all of it (vtkStringOutputWindow keeps appending)
        text, self.seen = output[self.seen:], len(output)
        messages = [m.strip() for m in re.split(r"\n(?=(?:Warning|ERROR|Generic Warning):)",
                                                 text) if m.strip()]
        expected = [m for m in messages if any(p.search(m) for p in EXPECTED_WARNINGS)]
        unexpected = [m for m in messages if m not in expected]
        return expected, unexpected


def percentile(values, q):
    return float(np.percentile(np.asarray(values, float), q)) if values else float("nan")


def _single_frame(window):
    """One render's wall time, no warm-up (--frames 0: errors only, times indicative)."""
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return time.perf_counter() - start


def run_scene(scene, settings, frames, log, keep_pictures):
    """The rows of one scene, or None when its reference has no lit pixel in view."""
    renderer, window = rh.make_window(scene.width, scene.height)
    light = build(renderer, scene)
    camera = renderer.GetActiveCamera()
    if camera.GetClippingRange()[1] < 1e-6 * camera.GetDistance():
        # Every prop behind the camera: VTK's clipping range collapses (far ~1e-18) and the
        # view holds no medium, only rounding (the reference's peak was 1e-22 in one such scene).
        return None, None
    log.take()
    # The plain frame after the scene's first frames have settled (30 frames, or 2 s:
    # docs/known-issues.md); the settings' frames come after it, settled too.
    plain = rh.median_frame_time(window, max(frames, 1), warm_up=30, warm_up_seconds=2.0)
    _, unexpected = log.take()
    if unexpected:
        print("\n".join(unexpected), file=sys.stderr)
    rows, pictures, reference = [], {}, None
    in_view = light_in_view(renderer, scene)
    for label, params in settings:
        shafts = vtkLightShaftPass()
        configure(shafts, scene, light, params)
        if reference is None:
            # The medium and light are the same for every setting; the reference reads them
            # from the pass (its visibility is exact, independent of the pass's frames).
            reference = reference_image(renderer, shafts)
            _, ref_unexpected = log.take()
            luminance = reference.mean(-1)
            peak = float(luminance.max())
            lit = int(np.sum(luminance > 0.01 * peak)) if peak > 0 else 0
            if lit < keep_pictures["min_lit"] * luminance.size:
                return None, None
        renderer.SetPass(shafts)
        start = time.perf_counter()
        frame = rh.median_frame_time(window, frames) if frames > 0 else _single_frame(window)
        image = rh.in_scatter(shafts)
        expected, unexpected = log.take()
        if label == settings[0][0]:
            unexpected = ref_unexpected + unexpected
        error, pixels = ref.relative_rms_error(image, reference)
        row = dict(scene=scene.index, attempt=scene.attempt, setting=label,
                   relative_rmse=error, time_ratio=frame / plain, plain_ms=1000 * plain,
                   pass_ms=1000 * frame, lit_pixels=pixels, width=scene.width,
                   height=scene.height, family=scene.family, light=scene.light_kind,
                   camera=scene.camera_kind, parallel=int(scene.parallel),
                   optical_depth=scene.optical_depth, phase=scene.phase,
                   light_in_view=int(in_view),
                   slice_near=shafts.GetLastFrame().GetSliceDepthRange()[0],
                   slice_far=shafts.GetLastFrame().GetSliceDepthRange()[1],
                   gl_errors=shafts.GetLastFrame().GetGLErrorCount(), expected_warnings=len(expected),
                   unexpected_warnings=" | ".join(" ".join(m.split()) for m in unexpected),
                   seconds=time.perf_counter() - start,
                   **error_model_columns(shafts, scene),
                   scene_json=json.dumps(dataclasses.asdict(scene), separators=(",", ":")))
        rows.append(row)
        flag = "  UNEXPECTED: " + row["unexpected_warnings"] if unexpected else ""
        print(f"scene {scene.index:3d} {label:22s} ratio {row['time_ratio']:7.2f} "
              f"error {100 * error:7.2f}%{flag}", flush=True)
        if unexpected:
            print("\n".join(unexpected), file=sys.stderr)
        if label == "Interactive" and keep_pictures["on"]:
            frame_rgb = rh.screenshot(window)
            pictures = dict(frame=frame_rgb, image=image.mean(-1).astype(np.float32),
                            reference=reference.mean(-1).astype(np.float32), error=error)
        renderer.SetPass(None)
        del shafts
    return rows, pictures


def worst_picture(path, scene, pictures):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    peak = float(pictures["reference"].max())
    error_map = np.abs(pictures["image"] - pictures["reference"]) / peak
    mask = pictures["reference"] > 0.01 * peak
    scale = max(float(np.percentile(pictures["reference"][mask], 99)), 1e-30)
    figure, axes = plt.subplots(1, 4, figsize=(20, 4.4))
    axes[0].imshow(pictures["frame"], origin="lower")
    axes[0].set_title("the pass's frame (Interactive)")
    for axis, key, title in ((axes[1], "image", "the pass's in-scatter"),
                             (axes[2], "reference", "reference in-scatter")):
        axis.imshow(1 - np.exp(-pictures[key] / scale), origin="lower", cmap="gray",
                    vmin=0, vmax=1)
        axis.set_title(title + " (tone-mapped alike)")
    shown = axes[3].imshow(np.where(mask, error_map, np.nan), origin="lower", cmap="magma",
                           vmin=0, vmax=max(float(np.nanpercentile(
                               np.where(mask, error_map, np.nan), 99.5)), 1e-6))
    axes[3].set_title(f"|pass - reference| / peak, lit pixels\n(relative RMS "
                      f"{100 * pictures['error']:.2f}%)")
    figure.colorbar(shown, ax=axes[3], fraction=0.046)
    for axis in axes:
        axis.set_xticks([])
        axis.set_yticks([])
    figure.suptitle(f"scene {scene.index}: {scene.summary()}", fontsize=9)
    figure.tight_layout()
    figure.savefig(path, dpi=90)
    plt.close(figure)


def summarise(rows, settings):
    table = []
    for label, _ in settings:
        sub = [r for r in rows if r["setting"] == label]
        if not sub:
            continue
        errors = [r["relative_rmse"] for r in sub]
        ratios = [r["time_ratio"] for r in sub]
        table.append(dict(setting=label, n=len(sub), error_median=percentile(errors, 50),
                          error_p90=percentile(errors, 90), error_max=max(errors),
                          ratio_median=percentile(ratios, 50), ratio_p90=percentile(ratios, 90)))
    return table


def pareto_plot(table, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axis = plt.subplots(figsize=(7, 5))
    colours = plt.cm.tab10.colors
    for index, t in enumerate(table):
        colour = colours[index % 10]
        axis.plot([t["ratio_median"], t["ratio_p90"]],
                  [100 * t["error_median"], 100 * t["error_p90"]], "-", color=colour, alpha=0.5)
        axis.plot(t["ratio_median"], 100 * t["error_median"], "o", color=colour,
                  label=f"{t['setting']} (o median, ^ p90)")
        axis.plot(t["ratio_p90"], 100 * t["error_p90"], "^", color=colour)
    axis.set_xscale("log")
    axis.set_yscale("log")
    axis.set_xlabel("frame time / without the pass")
    axis.set_ylabel("relative RMS error (%)")
    axis.set_title(f"random scenes (n = {table[0]['n']}): median and 90th percentile")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)


PRESET_AIMS = (("Draft", 0.05), ("Interactive", 0.02), ("Final", 0.005))
FIXED_SETTINGS = ("Draft", "Interactive", "Final")


def target_validation(rows):
    """Per TargetError setting: the share of scenes meeting the target, the errors, the cost,
    and the cheapest fixed preset that meets the same target on 90% of the scenes."""
    table = []
    for label in sorted({r["setting"] for r in rows if r["setting"].startswith("Target ")},
                        key=lambda label: -float(label.split()[1].rstrip("%"))):
        target = float(label.split()[1].rstrip("%")) / 100
        sub = [r for r in rows if r["setting"] == label]
        errors = [r["relative_rmse"] for r in sub]
        fixed = []
        for preset in FIXED_SETTINGS:
            preset_rows = [r for r in rows if r["setting"] == preset]
            if preset_rows and np.mean([r["relative_rmse"] <= target
                                        for r in preset_rows]) >= 0.9:
                fixed.append((percentile([r["time_ratio"] for r in preset_rows], 50), preset))
        best = min(fixed) if fixed else None
        # The oracle: per scene, the cheapest ladder setting that met the target there (in
        # hindsight, in the same run); the target's time over the oracle's.
        ladder = {name for name, _ in LADDER} | set(fitted_presets())
        over_oracle = []
        for r in sub:
            met = [o["time_ratio"] for o in rows if o["scene"] == r["scene"] and
                   o["setting"] in ladder and o["relative_rmse"] <= target]
            if met:
                over_oracle.append(r["time_ratio"] / min(met))
        table.append(dict(setting=label, target=target, n=len(sub),
                          oracle_scenes=len(over_oracle),
                          over_oracle_median=percentile(over_oracle, 50) if over_oracle
                          else float("nan"),
                          over_oracle_p90=percentile(over_oracle, 90) if over_oracle
                          else float("nan"),
                          met=float(np.mean([e <= target for e in errors])),
                          error_median=percentile(errors, 50), error_p90=percentile(errors, 90),
                          predicted_median=percentile([r["predicted_error"] for r in sub], 50),
                          ratio_median=percentile([r["time_ratio"] for r in sub], 50),
                          best_fixed=best[1] if best else None,
                          best_fixed_ratio=best[0] if best else float("nan")))
    return table


def validation_lines(rows):
    lines = []
    presets = [(name, aim, [r["relative_rmse"] for r in rows if r["setting"] == name])
               for name, aim in PRESET_AIMS]
    presets = [p for p in presets if p[2]]
    if presets:
        lines += ["## The presets against their aims", "",
                  "| preset | aim (p90) | p90 error | scenes within the aim | met |",
                  "|---|---:|---:|---:|---|"]
        for name, aim, errors in presets:
            p90 = percentile(errors, 90)
            within = np.mean([e <= aim for e in errors])
            lines.append(f"| {name} | {100 * aim:g}% | {100 * p90:.2f}% | {100 * within:.0f}% | "
                         f"{'yes' if p90 <= aim else 'no'} |")
        lines.append("")
    targets = target_validation(rows)
    if targets:
        lines += ["## TargetError validation", "",
                  "| target | scenes | achieved <= target | median error | p90 error | median "
                  "prediction | median time ratio | cheapest preset meeting it on 90% | its "
                  "median time ratio | time over the oracle's: median, p90 (scenes) |",
                  "|---|---:|---:|---:|---:|---:|---:|---|---:|---|"]
        for t in targets:
            best = (f"{t['best_fixed']} | {t['best_fixed_ratio']:.1f}" if t["best_fixed"]
                    else "none | -")
            oracle = (f"{t['over_oracle_median']:.2f}, {t['over_oracle_p90']:.2f} "
                      f"({t['oracle_scenes']})" if t["oracle_scenes"] else "-")
            lines.append(f"| {100 * t['target']:g}% | {t['n']} | {100 * t['met']:.0f}% | "
                         f"{100 * t['error_median']:.2f}% | {100 * t['error_p90']:.2f}% | "
                         f"{100 * t['predicted_median']:.2f}% | {t['ratio_median']:.1f} | "
                         f"{best} | {oracle} |")
        lines += ["", "The oracle of a scene is the cheapest setting of the ladder that met the "
                  "target on it, in hindsight, in the same run (only the ladder settings run "
                  "here: --validation runs those of the fitted table)."]
        lines.append("")
    return lines


def write_markdown(path, rows, table, scenes_by_index, args, command, worst):
    lines = ["# Randomised scene benchmark", "",
             __doc__.split("\n\n")[2].replace("\n", " "), "",
             __doc__.split("\n\n")[3].replace("\n", " "), "",
             f"Seed {args.seed}, {len(scenes_by_index)} scenes, median of {args.frames} frames.",
             "", "![median and p90 per setting](images/random-pareto.png)", "",
             "| setting | scenes | median error | p90 error | max error | median time ratio | "
             "p90 time ratio |", "|---|---:|---:|---:|---:|---:|---:|"]
    for t in table:
        lines.append(f"| {t['setting']} | {t['n']} | {100 * t['error_median']:.2f}% | "
                     f"{100 * t['error_p90']:.2f}% | {100 * t['error_max']:.2f}% | "
                     f"{t['ratio_median']:.2f} | {t['ratio_p90']:.2f} |")
    in_view = sorted({r["scene"] for r in rows if r["light_in_view"]})
    hidden = [r for r in rows if not r["light_in_view"]]
    lines += ["", f"The light (a sun: its direction) is in the picture in {len(in_view)} of "
              f"{len(scenes_by_index)} scenes; there a few pixels around its image can hold most "
              "of the reference's energy (inverse-square attenuation), and the blur of the "
              "fast settings spreads them. Without those scenes:", ""]
    if hidden:
        lines += ["| setting | scenes | median error | p90 error | max error |",
                  "|---|---:|---:|---:|---:|"]
        for t in summarise(hidden, [(t["setting"], None) for t in table]):
            lines.append(f"| {t['setting']} | {t['n']} | {100 * t['error_median']:.2f}% | "
                         f"{100 * t['error_p90']:.2f}% | {100 * t['error_max']:.2f}% |")
    lines += [""] + validation_lines(rows)
    lines += ["## Worst scenes per setting", ""]
    for t in table:
        sub = sorted((r for r in rows if r["setting"] == t["setting"]),
                     key=lambda r: -r["relative_rmse"])[:5]
        lines.append(f"**{t['setting']}**")
        lines.append("")
        for r in sub:
            lines.append(f"- {100 * r['relative_rmse']:.2f}% (time ratio {r['time_ratio']:.2f}): "
                         f"scene {r['scene']} — {scenes_by_index[r['scene']].summary()}"
                         f"{', light in view' if r['light_in_view'] else ''}")
        lines.append("")
    if worst:
        lines += ["## The three worst scenes of the Interactive preset", ""]
        for k, index in enumerate(worst, 1):
            lines.append(f"![worst {k}: scene {index}](images/random-worst-{k}.png)")
        lines.append("")
    unexpected = [r for r in rows if r["unexpected_warnings"] or r["gl_errors"]]
    lines += ["## VTK warnings and GL errors", "",
              f"Expected warnings (documented: ANALYTIC ignoring shadows): "
              f"{sum(r['expected_warnings'] for r in rows)}. Unexpected messages or GL errors: "
              f"{len(unexpected)} rows.", ""]
    for r in unexpected:
        lines.append(f"- scene {r['scene']} {r['setting']}: GL errors {r['gl_errors']}; "
                     f"{r['unexpected_warnings'][:400]}")
    lines += ["", f"Machine: {platform.machine()}, {os.cpu_count()} cores; only the ratios carry "
              "over to other machines.", "", f"Command: `{command}`", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", default="docs")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--scenes", type=int, default=50)
    parser.add_argument("--frames", type=int, default=7)
    parser.add_argument("--max-height", type=int, default=1080)
    parser.add_argument("--only-scene", type=int)
    parser.add_argument("--settings", nargs="+", help="only these settings (labels)")
    parser.add_argument("--min-lit-fraction", type=float, default=0.001,
                        help="redraw a scene with fewer lit pixels (above 1%% of the peak)")
    parser.add_argument("--max-attempts", type=int, default=20)
    parser.add_argument("--smoke", action="store_true")
    parser.add_argument("--ladder", action="store_true",
                        help="the error model's SLICES settings instead of the presets")
    parser.add_argument("--downsampled", action="store_true",
                        help="reduced-resolution settings against ANALYTIC, the RAY_MARCH "
                        "defaults and Interactive instead of the presets")
    parser.add_argument("--epipolar", action="store_true",
                        help="EPIPOLAR's settings against the cheapest of --downsampled, the "
                        "RAY_MARCH defaults and Interactive instead of the presets")
    parser.add_argument("--validation", action="store_true",
                        help="the presets, methods and targets, and the fitted ladder's "
                        "settings (TargetError's cost against the oracle)")
    parser.add_argument("--light-volume", action="store_true",
                        help="LIGHT_VOLUME's settings against EPIPOLAR's, the RAY_MARCH "
                        "defaults and Interactive instead of the presets")
    args = parser.parse_args()
    settings = SETTINGS
    size = None
    if args.smoke:
        args.scenes, args.frames, size = 3, 2, (96, 72)
        settings = [s for s in SETTINGS if s[0] in SMOKE_SETTINGS]
    if args.ladder:
        settings = [LADDER[0], LADDER[-1]] if args.smoke else LADDER
    if args.downsampled:
        settings = [s for s in DOWNSAMPLED_SETTINGS
                    if not args.smoke or s[0] in DOWNSAMPLED_SMOKE_SETTINGS]
    if args.epipolar:
        settings = [s for s in EPIPOLAR_SETTINGS
                    if not args.smoke or s[0] in EPIPOLAR_SMOKE_SETTINGS]
    if args.validation:
        # The presets are ladder settings: those run once, under the preset's name.
        presets = fitted_presets()
        settings = SETTINGS + [s for s in LADDER
                               if s[0] in fitted_ladder() and s[0] not in presets.values()]
    if args.light_volume:
        settings = [s for s in LIGHT_VOLUME_SETTINGS
                    if not args.smoke or s[0] in LIGHT_VOLUME_SMOKE_SETTINGS]
    if args.settings:
        settings = [s for s in settings if s[0] in args.settings]
    indices = [args.only_scene] if args.only_scene is not None else range(args.scenes)
    os.makedirs(os.path.join(args.output_dir, "images"), exist_ok=True)
    log = WarningLog()

    rows, scenes_by_index, pictures = [], {}, {}
    keep = dict(on=any(s[0] == "Interactive" for s in settings),
                min_lit=args.min_lit_fraction)
    for index in progress.steps(indices, "scenes"):
        for attempt in range(args.max_attempts):
            scene = draw_scene(args.seed, index, attempt, args.max_height, size)
            scene_rows, scene_pictures = run_scene(scene, settings, args.frames, log, keep)
            if scene_rows is not None:
                break
            print(f"scene {index}: attempt {attempt} has no lit pixel in view (or no view), "
                  "drawn again", flush=True)
        else:
            raise RuntimeError(f"scene {index}: no lit view in {args.max_attempts} attempts")
        rows += scene_rows
        scenes_by_index[index] = scene
        if scene_pictures:
            pictures[index] = scene_pictures
            # Keep the pictures of the three worst Interactive scenes only.
            for i in sorted(pictures, key=lambda i: -pictures[i]["error"])[3:]:
                del pictures[i]

    with open(os.path.join(args.output_dir, "random-scenes.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    table = summarise(rows, settings)
    pareto_plot(table, os.path.join(args.output_dir, "images", "random-pareto.png"))
    worst = sorted(pictures, key=lambda i: -pictures[i]["error"])
    for k, index in enumerate(worst, 1):
        worst_picture(os.path.join(args.output_dir, "images", f"random-worst-{k}.png"),
                      scenes_by_index[index], pictures[index])
    command = ("PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s \"-screen 0 "
               "1280x1024x24 -noreset\" /usr/bin/python3 tests/benchmarks/random_scenes.py "
               + " ".join(a for a in sys.argv[1:]))
    write_markdown(os.path.join(args.output_dir, "random-scenes.md"), rows, table,
                   scenes_by_index, args, command, worst)
    for t in table:
        print(f"{t['setting']:22s} n {t['n']:3d} error median {100 * t['error_median']:6.2f}% "
              f"p90 {100 * t['error_p90']:6.2f}%  ratio median {t['ratio_median']:6.2f} "
              f"p90 {t['ratio_p90']:6.2f}")
    print("\n".join(validation_lines(rows)))


if __name__ == "__main__":
    main()
