"""The Python examples run as a user runs them and draw light shafts."""

import os
import subprocess
import sys

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)


@pytest.mark.parametrize("script", ["window_shafts.py", "isosurface_shafts.py",
                                    "stained_glass.py"])
def test_example_renders(tmp_path, script):
    output = tmp_path / "out.png"
    result = subprocess.run(
        [sys.executable, os.path.join(EXAMPLES, script), "-o", str(output), "--size", "320", "200"],
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
            [sys.executable, os.path.join(EXAMPLES, "dusty_room.py"), "--frames", str(frames),
             "--size", "240", "136", "--output-dir", str(directory)],
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
