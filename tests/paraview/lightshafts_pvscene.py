"""The ParaView tests' scene and measurements, for pvbatch (ParaView's own Python).

A spotlight above a floor, a sphere that nearly fills the cone (the occluder), a side camera.
Run by tests/paraview/test_*.py under pvbatch with PYTHONPATH giving paraview.simple (see
tools/pvbatch); the plugin is found from LIGHTSHAFTS_PARAVIEW_PLUGIN or the build tree's
LightShaftsPluginPath.txt.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
WIDTH, HEIGHT = 400, 300

LIGHT_POSITION = (0.0, 6.0, 0.0)
CONE_ANGLE = 20.0                  # half-angle, degrees
SPHERE_CENTER = (0.0, 3.0, 0.0)
SPHERE_RADIUS = 1.0                # asin(1/3) = 19.5 degrees: its shadow fills most of the cone
LIT_POINT = (0.0, 4.6, 0.0)        # on the axis between the light and the sphere
SHADOW_POINT = (0.0, 1.0, 0.0)     # on the axis below the sphere


def plugin_path():
    """The built (or installed) LightShafts.so."""
    path = os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN")
    if path:
        return path
    listings = [os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST", "")]
    listings += [os.path.join(ROOT, build, "LightShaftsPluginPath.txt")
                 for build in ("build/paraview-plugin", "build-pv")]
    for listing in listings:
        if listing and os.path.exists(listing):
            with open(listing) as f:
                return f.read().strip()
    sys.exit("LightShafts.so not found: build the plugin or set LIGHTSHAFTS_PARAVIEW_PLUGIN")


def load_plugin():
    from paraview import simple
    simple.LoadPlugin(plugin_path(), remote=False, ns=globals())


def window_class(view):
    """The class of the window ParaView renders through. (From ParaView 6.0 a view draws into an
    offscreen window sharing the context of the process's window, whose class is the one VTK
    chose: X, EGL or OSMesa.)"""
    try:
        from paraview.modules.vtkRemotingViews import vtkPVProcessWindow
        window = vtkPVProcessWindow.GetRenderWindow()
        if window is not None:
            return window.GetClassName()
    except ImportError:  # (before ParaView 6.0)
        pass
    return view.GetRenderWindow().GetClassName()


def make_scene(view=None, occluder=True, medium=True, **shaft_properties):
    """The test scene in a LightShaftsRenderView (created when `view` is None); `medium`: its
    coefficients and exposure set (else the view chooses them from the scene). Returns
    (view, light, sphere display)."""
    from paraview import simple
    if view is None:
        view = simple.CreateView("LightShaftsRenderView")
    expected = os.environ.get("LIGHTSHAFTS_EXPECTED_RENDER_WINDOW")
    if expected and window_class(view) != expected:
        # (tools/test-headless.sh: ParaView must render through the window class it names.)
        print(f"FAIL: ParaView renders through {window_class(view)}, not {expected} "
              f"(LIGHTSHAFTS_EXPECTED_RENDER_WINDOW)")
        finish(1)
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseLight = 0                      # no light kit / headlight: the spotlight alone
    floor = simple.Plane(Origin=[-6, 0, -6], Point1=[6, 0, -6], Point2=[-6, 0, 6],
                         XResolution=64, YResolution=64)
    ball = simple.Sphere(Center=list(SPHERE_CENTER), Radius=SPHERE_RADIUS,
                         ThetaResolution=64, PhiResolution=64)
    simple.Show(floor, view)
    ball_display = simple.Show(ball, view)
    ball_display.Visibility = 1 if occluder else 0
    light = simple.AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = list(LIGHT_POSITION)
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.ConeAngle = CONE_ANGLE
    light.Intensity = 1.0
    if view.GetXMLName() == "LightShaftsRenderView":
        if medium:
            view.ScatteringCoefficient = [0.08, 0.08, 0.08]
            view.ShaftExposure = 12.0
        view.ShaftQuality = 0
        view.NumberOfSlices = 128
        view.ShadowMapSize = 1024
        for name, value in shaft_properties.items():
            setattr(view, name, value)
    view.CameraPosition = [0.0, 3.0, 14.0]
    view.CameraFocalPoint = [0.0, 3.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 40.0
    return view, light, ball_display


def process_ids(source):
    """A filter giving `source` each point's process id, and that array's name. (ParaView 5.12
    deprecated ProcessIdScalars, array "ProcessId", for ProcessIds, array "PointProcessIds".)"""
    from paraview import simple
    if hasattr(simple, "ProcessIds"):
        return simple.ProcessIds(Input=source), "PointProcessIds"
    return simple.ProcessIdScalars(Input=source), "ProcessId"


def read_png(path):
    """A PNG as (height, width, 3) floats, row 0 at the top."""
    import numpy as np
    from vtkmodules.vtkIOImage import vtkPNGReader
    from paraview.vtk.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    w, h, _ = data.GetDimensions()
    c = data.GetPointData().GetScalars().GetNumberOfComponents()
    pixels = vtk_to_numpy(data.GetPointData().GetScalars()).reshape(h, w, c)[:, :, :3]
    return pixels[::-1].astype(np.float64)


def screenshot(view, path):
    """SaveScreenshot at the test size; returns the image as (height, width, 3) floats."""
    from paraview import simple
    simple.SaveScreenshot(path, view, ImageResolution=[WIDTH, HEIGHT])
    return read_png(path)


def report(failures):
    """Print the failures; the test's exit status."""
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


def to_pixel(view, point):
    """Screen pixel (column, row from the top) of a world point, for the test size."""
    camera = view.GetActiveCamera()
    matrix = camera.GetCompositeProjectionTransformMatrix(WIDTH / HEIGHT, -1, 1)
    p = [point[0], point[1], point[2], 1.0]
    clip = [sum(matrix.GetElement(i, j) * p[j] for j in range(4)) for i in range(4)]
    x, y = clip[0] / clip[3], clip[1] / clip[3]
    return int(round((x + 1) / 2 * WIDTH - 0.5)), int(round((1 - (y + 1) / 2) * HEIGHT - 0.5))


def patch_mean(image, pixel, radius=3):
    """Mean grey level of a (2 radius + 1)^2 patch around pixel (column, row from the top)."""
    col, row = pixel
    return float(image[row - radius:row + radius + 1, col - radius:col + radius + 1].mean())


def compare_images(actual, baseline, mean_tolerance, pixel_fraction, pixel_level):
    """(mean absolute difference, fraction of pixels off by more than pixel_level, ok)."""
    import numpy as np
    if actual.shape != baseline.shape:
        return float("inf"), 1.0, False
    diff = np.abs(actual - baseline).max(axis=2)
    mean = float(np.abs(actual - baseline).mean())
    fraction = float((diff > pixel_level).mean())
    return mean, fraction, mean <= mean_tolerance and fraction <= pixel_fraction


def finish(status):
    """End the pvbatch run with `status`, skipping pvbatch's teardown: ParaView 5.11 segfaults
    in it after sys.exit() from a script, and ParaView 6.1 (Debian's VTK 9.6) warns there that
    its own composite mappers left textures active ("There are still active textures when there
    should not be"), a plain RenderView too (docs/known-issues.md). What the script printed is
    flushed first: from 6.0 pvbatch's Python output goes through C stdio, which os._exit would
    drop."""
    import ctypes
    sys.stdout.flush()
    sys.stderr.flush()
    ctypes.CDLL(None).fflush(None)
    os._exit(status)
