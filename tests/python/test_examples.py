"""The Python examples run as a user runs them and draw light shafts."""

import os
import subprocess
import sys

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def python(script, *args):
    """The command that runs an example as a user runs it, a deprecated VTK call in it (or in
    the lightshafts package) an error."""
    return [sys.executable, "-W", "error::DeprecationWarning:__main__", "-W",
            "error::DeprecationWarning:lightshafts", os.path.join(EXAMPLES, script), *args]


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)


@pytest.mark.parametrize("script", ["window_shafts.py", "isosurface_shafts.py",
                                    "stained_glass.py", "sun_through_window.py",
                                    "lamp_over_table.py", "crossing_spotlights.py",
                                    "pyvista_shafts.py", "smoke_plume.py", "ct_phantom.py",
                                    "glass_window.py", "smoke_in_beam.py"])
def test_example_renders(tmp_path, script):
    output = tmp_path / "out.png"
    if script == "pyvista_shafts.py":
        pytest.importorskip("pyvista")
    result = subprocess.run(python(script, "-o", str(output), "--size", "320", "200"),
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "ERR|" not in result.stderr, result.stderr
    pixels = read_png(str(output))
    assert pixels.shape[:2] == (200, 320)
    # A lit, non-trivial picture: a good part of it is neither black nor saturated.
    luminance = pixels[..., :3].mean(axis=-1)
    assert np.mean((luminance > 10) & (luminance < 250)) > 0.1


def test_dusty_room_frames_are_reproducible(tmp_path):
    def run(directory, frames):
        result = subprocess.run(
            python("dusty_room.py", "--frames", str(frames), "--size", "240", "136",
                   "--output-dir", str(directory)),
            capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, result.stderr
        assert "ERR|" not in result.stderr, result.stderr

    run(tmp_path / "a", 3)
    run(tmp_path / "b", 2)
    first = [read_png(str(tmp_path / "a" / f"frame_{k:04d}.png")) for k in range(3)]
    again = read_png(str(tmp_path / "b" / "frame_0001.png"))
    np.testing.assert_array_equal(first[1], again)  # same time, same image
    assert np.abs(first[0].astype(int) - first[2].astype(int)).max() > 0  # the dust moves
    assert (tmp_path / "a" / "dusty_room.ogv").stat().st_size > 1000


def test_interactive_demo_replays_recorded_keys(tmp_path):
    output = tmp_path / "last.png"
    result = subprocess.run(
        python("interactive_shafts.py", "--play", os.path.join(EXAMPLES, "interactive_shafts.keys"),
               "-o", str(output), "--size", "240", "180"),
        capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "ERR|" not in result.stderr, result.stderr
    reports = [line for line in result.stdout.splitlines() if line.startswith("[")]
    stats = [line for line in result.stdout.splitlines() if "last frame:" in line]
    assert len(reports) == len(stats) == 25  # the start and the 24 key presses
    assert "next / previous method" in result.stdout  # h printed the help
    assert all("GL errors 0" in line for line in stats)
    methods = [line.split("method=")[1].split()[0] for line in reports]
    assert set(methods) == {"slices", "ray-march", "radial-blur", "analytic", "automatic",
                            "epipolar", "light-volume"}
    assert methods[19] == "analytic"  # M stepped back from automatic
    assert methods[-1] == "light-volume"
    by_key = {}  # each key's first press
    for line, stat in zip(reports, stats):
        by_key.setdefault(line.split("]")[0][1:], (line, stat))
    # The last presses: ] doubled EPIPOLAR's steps, [ halved LIGHT_VOLUME's cells, which gave
    # way to RAY_MARCH (the noise is on: no closed form) with one warning.
    assert "steps=16" in reports[-3] and "cells=128" in reports[-1]
    assert "(used ray-march)" in reports[-1]
    assert result.stderr.count("Method LIGHT_VOLUME has no closed form") == 1
    assert "light=(0.25, 6.0, -0.25)" in by_key["Up"][0]
    assert "light=(0.25, 6.25, -0.25)" in by_key["Prior"][0]
    assert "exposure=50" in by_key["plus"][0]
    assert "slices=128" in by_key["bracketright"][0]  # SLICES: the slice count doubled
    assert "steps=8" in by_key["bracketleft"][0]  # RAY_MARCH: the steps halved
    assert "decay=0.99" in by_key["d"][0] and "weight=0.9" in by_key["w"][0]
    assert "density=1" in by_key["Y"][0]  # clamped at its maximum
    assert "noise=0.8" in by_key["n"][0] and "time=1" in by_key["t"][0]
    shadow = dict(zip(methods, stats))  # each method's last frame
    assert "shadow map yes" in shadow["slices"] and "shadow map yes" in shadow["ray-march"]
    assert "shadow map no" in shadow["radial-blur"] and "shadow map no" in shadow["analytic"]
    pixels = read_png(str(output))
    assert pixels.shape[:2] == (180, 240)
    assert pixels[..., :3].mean() > 5
