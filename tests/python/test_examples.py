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


@pytest.mark.parametrize("script", ["window_shafts.py", "isosurface_shafts.py"])
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
