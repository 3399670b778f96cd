"""A smoke-sized run of the benchmark (tests/benchmarks/benchmark.py --smoke): it runs, and
writes the CSV, the markdown table and the Pareto plot."""

import csv
import os
import subprocess
import sys

import pytest

# A sweep (conftest.py): the benchmark scripts.
pytestmark = pytest.mark.sweep

BENCHMARK = os.path.join(os.path.dirname(__file__), "..", "benchmarks", "benchmark.py")


def test_benchmark_smoke(tmp_path):
    result = subprocess.run([sys.executable, BENCHMARK, "--smoke", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "benchmark.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 8
    families = {r["family"] for r in rows}
    for method in ("slices", "ray march, interleaved", "radial blur", "analytic (no shadows)",
                   "lattice"):
        assert method in families  # every method is on the Pareto plot
    assert any(r["over_fetch_floor"] for r in rows)  # the fetch floor was measured
    for row in rows:
        assert float(row["time_ratio"]) > 0.0
    measured = [r for r in rows if r["relative_rmse"]]
    # The shadowed methods are within 20% even at this tiny size; the unshadowed ones are not
    # meant to be close (their error is the shadow they leave out).
    shadowed = [r for r in measured if r["family"] not in ("radial blur", "analytic (no shadows)")]
    assert shadowed and all(0.0 <= float(r["relative_rmse"]) < 0.2 for r in shadowed)
    assert all(0.0 <= float(r["relative_rmse"]) < 1.0 for r in measured)
    assert all(0.0 < float(r["ssim"]) <= 1.0 for r in measured)
    assert (tmp_path / "images" / "pareto.png").stat().st_size > 10000
    assert "| setting | time ratio |" in (tmp_path / "benchmark.md").read_text()


def test_light_kinds_benchmark_smoke(tmp_path):
    script = os.path.join(os.path.dirname(BENCHMARK), "light_kinds.py")
    result = subprocess.run([sys.executable, script, "--smoke", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "light-kinds.csv") as f:
        rows = list(csv.DictReader(f))
    assert {r["lights"] for r in rows} == {"spot", "point", "directional", "spot + point",
                                           "2 spots + 2 points"}
    for row in rows:
        assert float(row["time_ratio"]) > 0.0
        lights = 4 if row["lights"].startswith("2 spots") else 2 if "+" in row["lights"] else 1
        assert len(row["gpu_ms_per_light"].split(" / ")) == lights
        assert 0.0 <= float(row["relative_rmse"]) < 0.2  # shadowed, at 96x72
    assert "| lights | setting |" in (tmp_path / "light-kinds.md").read_text()


def test_random_scenes_smoke(tmp_path):
    import json
    import math
    script = os.path.join(os.path.dirname(BENCHMARK), "random_scenes.py")
    result = subprocess.run([sys.executable, script, "--smoke", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "random-scenes.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3 * 3  # 3 scenes x (Interactive, Final, Target 2%)
    assert {r["setting"] for r in rows} == {"Interactive", "Final", "Target 2%"}
    for row in rows:
        assert math.isfinite(float(row["relative_rmse"])) and float(row["relative_rmse"]) >= 0
        assert float(row["time_ratio"]) > 0.0
        assert int(row["gl_errors"]) == 0
        assert row["unexpected_warnings"] == ""  # every VTK message is a documented one
        scene = json.loads(row["scene_json"])
        assert (scene["width"], scene["height"]) == (96, 72)
        if row["setting"] == "Final":
            assert float(row["relative_rmse"]) < 0.2
        if row["setting"] != "Final" or float(row["predicted_error"]) != -1.0:
            # Interactive and Final are settings of the model's ladder; the target chose one.
            assert float(row["predicted_error"]) > 0.0 and row["model_setting"] != "none"
    text = (tmp_path / "random-scenes.md").read_text()
    assert "| setting | scenes | median error | p90 error |" in text
    assert "## TargetError validation" in text and "## The presets against their aims" in text
    assert (tmp_path / "images" / "random-pareto.png").stat().st_size > 10000
    for k in (1, 2, 3):
        assert (tmp_path / "images" / f"random-worst-{k}.png").stat().st_size > 10000


def test_random_scenes_downsampled_smoke(tmp_path):
    """--downsampled: the reduced-resolution settings run on the same scenes, their rows and
    table written like the presets'."""
    script = os.path.join(os.path.dirname(BENCHMARK), "random_scenes.py")
    result = subprocess.run([sys.executable, script, "--smoke", "--downsampled", "--output-dir",
                             str(tmp_path)], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "random-scenes.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3 * 2
    assert {r["setting"] for r in rows} == {"Interactive", "M8 i2 d2 m512"}
    for row in rows:
        assert 0.0 <= float(row["relative_rmse"]) < 1.0 and float(row["time_ratio"]) > 0.0
        assert int(row["gl_errors"]) == 0 and row["unexpected_warnings"] == ""
    assert "| M8 i2 d2 m512 | 3 |" in (tmp_path / "random-scenes.md").read_text()


def test_error_model_fit_smoke(tmp_path):
    """The TargetError model's pipeline: a --ladder run, then fit_error_model.py writes a table
    the pass's format reads, its markdown and the training CSV with the features."""
    script = os.path.join(os.path.dirname(BENCHMARK), "random_scenes.py")
    result = subprocess.run([sys.executable, script, "--smoke", "--ladder", "--frames", "0",
                             "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    fit = os.path.join(os.path.dirname(BENCHMARK), "fit_error_model.py")
    table = tmp_path / "table.h"
    result = subprocess.run([sys.executable, fit, str(tmp_path / "random-scenes.csv"),
                             "--table", str(table), "--docs", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    text = table.read_text()
    # The smoke ladder: its cheapest setting (EPIPOLAR) and its dearest (SLICES).
    assert text.count("{ { \"") == 2 and "constexpr Row Rows[]" in text
    assert "vtkLightShaftEnums::EPIPOLAR, 16" in text and "vtkLightShaftEnums::SLICES, 512" in text
    assert "| setting | n | median error |" in (tmp_path / "error-model.md").read_text()
    with open(tmp_path / "error-model-training.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3 * 2 and all(float(r["beam_width_in_pixels"]) > 0 for r in rows)


def test_reference_speed_smoke():
    import re
    script = os.path.join(os.path.dirname(BENCHMARK), "reference_speed.py")
    result = subprocess.run([sys.executable, script, "--runs", "1", "--frames", "1", "--width",
                             "80", "--height", "60"], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    figures = dict(re.findall(r"^(reference|pass frame|pass against)[^\n]*?([0-9.]+)",
                              result.stdout, re.M))
    assert set(figures) == {"reference", "pass frame", "pass against"}, result.stdout
    assert float(figures["pass against"]) < 5.0  # percent, at 80x60


def test_fixed_cost_smoke():
    import re
    script = os.path.join(os.path.dirname(BENCHMARK), "fixed_cost.py")
    result = subprocess.run([sys.executable, script, "--scenes", "1", "--frames", "1", "--size",
                             "96", "72"], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    ratios = re.findall(r"^  (ANALYTIC[^\n]*?) +frame +[0-9.]+ ms +ratio +([0-9.]+)", result.stdout,
                        re.M)
    assert [label for label, _ in ratios] == [
        "ANALYTIC", "ANALYTIC d8", "ANALYTIC d8, no AttenuateScene"], result.stdout
    assert all(float(ratio) > 0.0 for _, ratio in ratios)


def test_refinement_benchmark_smoke(tmp_path):
    script = os.path.join(os.path.dirname(BENCHMARK), "refinement.py")
    result = subprocess.run([sys.executable, script, "--size", "96", "54", "--estimates", "4",
                             "--frames", "1", "--output-dir", str(tmp_path),
                             "--settings", "RAY_MARCH 4 steps, 1024² map"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "refinement.md").read_text()
    rows = [line for line in text.splitlines() if line.startswith("| ") and "%" in line]
    assert [row.split("|")[1].strip() for row in rows] == ["1", "2", "4"]
    errors = [float(row.split("|")[4].strip().rstrip("%")) for row in rows]
    assert all(0.0 <= e < 100.0 for e in errors) and errors[-1] < errors[0]


def test_refinement_filters_benchmark_smoke(tmp_path):
    # Refinement with and without filters, estimate by estimate: it runs, writes its page with a
    # row per setting asked for, and no picture is worse than the first.
    script = os.path.join(os.path.dirname(BENCHMARK), "refinement_filters.py")
    result = subprocess.run([sys.executable, script, "--size", "64", "36", "--estimates", "4",
                             "--only", "RAY_MARCH 16", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    page = (tmp_path / "refinement-filters.md").read_text()
    rows = [line.split("|") for line in page.splitlines() if line.startswith("| sphere")
            or line.startswith("| window")]
    assert [row[2].strip() for row in rows] == ["RAY_MARCH 16, 2x2, blur 2"] * 2
    assert all(float(row[-3]) == 1.0 for row in rows)  # worst / first
    assert "Before" not in page  # (the figures of another size are not shown)


def test_budget_benchmark_smoke(tmp_path):
    script = os.path.join(os.path.dirname(BENCHMARK), "budget.py")
    result = subprocess.run([sys.executable, script, "--size", "96", "54", "--frames", "4",
                             "--every", "2", "--estimates", "2", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "budget.md").read_text()
    assert "Budget: 1/15 s = 67 ms" in text
    frames = [line for line in text.splitlines() if line.startswith("| ") and " ms |" in line]
    assert len(frames) == 4 and all(" ms | " in row for row in frames)
    assert "| estimates | seconds since the camera stopped | error |" in text


def test_reprojection_bound_smoke(tmp_path):
    script = os.path.join(os.path.dirname(BENCHMARK), "reprojection_bound.py")
    result = subprocess.run([sys.executable, script, "--size", "96", "54", "--output",
                             str(tmp_path / "reprojection.md")],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "reprojection.md").read_text()
    rows = [line for line in text.splitlines() if line.startswith("| ") and "%" in line]
    assert len(rows) == 4
    for row in rows:
        errors = [float(cell.strip().rstrip("%")) for cell in row.split("|")[2:5]]
        assert all(0.0 <= e < 100.0 for e in errors)


def test_resolution_cost_smoke():
    script = os.path.join(os.path.dirname(BENCHMARK), "resolution_cost.py")
    result = subprocess.run([sys.executable, script, "--size", "96", "54", "--frames", "1"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    rows = [line for line in result.stdout.splitlines() if line.startswith("| ") and " ms |" in line]
    assert len(rows) == 4


def test_medium_field_benchmarks_smoke(tmp_path):
    # The cost of a field (with the light leg marched and tabulated) and the methods' speed
    # against error through a plume: they run, and every method that renders a field is on
    # the Pareto plot.
    here = os.path.dirname(BENCHMARK)
    result = subprocess.run([sys.executable, os.path.join(here, "medium_field_cost.py"),
                             "--size", "64x48", "--frames", "1", "--samples", "16",
                             "--resolutions", "0", "16"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    assert "| wavelet 16³ | marched |" in result.stdout
    assert "| wavelet 16³ | table 16 |" in result.stdout
    result = subprocess.run([sys.executable, os.path.join(here, "medium_field_pareto.py"),
                             "--size", "48", "36", "--frames", "1",
                             "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "medium-field-pareto.csv") as f:
        rows = list(csv.DictReader(f))
    assert {r["family"] for r in rows} == {"RAY_MARCH", "RAY_MARCH, light leg marched",
                                           "SLICES", "EPIPOLAR"}
    assert all(0.0 < float(r["time_ratio"]) and 0.0 <= float(r["relative_rmse"]) < 0.5
               for r in rows)
    assert (tmp_path / "images" / "medium_field_pareto.png").stat().st_size > 10000


def test_field_still_benchmarks_smoke():
    # A still view refining the light leg's table on a random field scene, and a converged
    # still frame's cost through a field: they run and report each frame.
    here = os.path.dirname(BENCHMARK)
    result = subprocess.run([sys.executable, os.path.join(here, "field_still_refinement.py"),
                             "--scenes", "17", "--size", "64", "48", "--frames", "1"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    assert "scene 17 (" in result.stdout
    assert "moving" in result.stdout and "still 1" in result.stdout
    result = subprocess.run([sys.executable, os.path.join(here, "field_still_frame_cost.py"),
                             "--size", "48", "36", "--frames", "2", "--moving", "1"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    assert "a 48^3 plume: converged still frame median" in result.stdout
    assert "homogeneous : converged still frame median" in result.stdout


def test_translucent_cost_smoke():
    # The cost per layer of translucent casters: it runs and prints a row per pane count, the
    # layers peeled as many as the panes.
    script = os.path.join(os.path.dirname(BENCHMARK), "translucent_cost.py")
    result = subprocess.run([sys.executable, script, "--size", "64x48", "--frames", "1",
                             "--layers", "2"], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    rows = [line.split("|") for line in result.stdout.splitlines()
            if line.startswith("| ") and not line.startswith("| panes")]
    assert [int(row[1]) for row in rows] == [0, 1, 2]
    assert [int(row[2]) for row in rows] == [0, 1, 2]


def test_still_final_benchmark_smoke(tmp_path):
    # The Final preset still, whole and split: under a budget nothing fits (an interactor's
    # rate of a million) the still view splits Final into 16 estimates of 16 steps, shows the
    # moving picture until they add up to one Final frame, and then reaches its error.
    script = os.path.join(os.path.dirname(BENCHMARK), "still_final.py")
    result = subprocess.run([sys.executable, script, "--size", "96", "54", "--frames", "3",
                             "--rate", "1e6", "--seconds", "60", "--output-dir", str(tmp_path)],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "still-final.md").read_text()
    whole, split = [line for line in text.splitlines() if line.startswith(("- Whole", "- Split"))]
    assert "split 1)" in whole and "split 16)" in split
    assert "not within the run" not in split
    rows = [line.split("|") for line in text.splitlines() if line.startswith("| ") and " ms |" in line]
    held = [row for row in rows if row[8].strip() == "yes"]
    assert held and all(int(row[7]) < 16 for row in held)


def test_any_scene_figures_smoke():
    script = os.path.join(os.path.dirname(BENCHMARK), "any_scene.py")
    result = subprocess.run([sys.executable, script, "--scales", "1", "10"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("| 1") >= 1 and "far plane 1000.0" in result.stdout


def test_surface_light_cost_smoke():
    script = os.path.join(os.path.dirname(BENCHMARK), "surface_light_cost.py")
    result = subprocess.run([sys.executable, script, "--size", "160", "90", "--frames", "2"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    rows = [line for line in result.stdout.splitlines() if line.startswith("| ") and "ms" not in line]
    assert len(rows) == 3 and rows[0].endswith("| 1.00 |")


def test_responsiveness_smoke():
    script = os.path.join(os.path.dirname(BENCHMARK), "responsiveness.py")
    result = subprocess.run([sys.executable, script, "--changes", "3", "--abort-after", "0.5"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    assert "3 changes" in result.stdout and "after the abort" in result.stdout


def test_frame_bound_smoke():
    script = os.path.join(os.path.dirname(BENCHMARK), "frame_bound.py")
    result = subprocess.run([sys.executable, script, "--size", "32", "24", "--lights", "1",
                             "--methods", "ray-march"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    rows = [line for line in result.stdout.splitlines() if line.startswith("| ray-march")]
    assert len(rows) == 1
