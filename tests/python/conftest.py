"""pytest setup: the tests import the built `lightshafts` package (PYTHONPATH set by
tools/test.sh) and render offscreen (run under xvfb-run).

Every test runs with VTK's output captured: an error or warning that VTK (or the pass) prints
through its output window during a test fails that test, unless the test said it expects it
(`vtk_messages.expect(pattern)`) or caught it with an observer on the object (`messages`)."""

import os
import sys

sys.path.insert(0, os.path.dirname(__file__))

import pytest  # noqa: E402

from vtk_output import VTK_OUTPUT, Messages  # noqa: E402


def _check_vtk_output(phase):
    unexpected = VTK_OUTPUT.unexpected()
    if unexpected:
        listing = "\n".join(f"  {kind}: {text.strip()}" for kind, text in unexpected)
        VTK_OUTPUT.messages.clear()
        pytest.fail(f"VTK printed {len(unexpected)} unexpected message(s) during {phase}:\n"
                    f"{listing}", pytrace=False)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    VTK_OUTPUT.reset()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item):
    outcome = yield
    if outcome.excinfo is None:
        _check_vtk_output("the test")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_teardown(item):
    yield
    _check_vtk_output("teardown")


@pytest.fixture
def messages():
    return Messages


@pytest.fixture
def vtk_messages():
    """The current test's VTK output log: `vtk_messages.expect(pattern)` allows a message,
    `vtk_messages.messages` lists what was printed."""
    return VTK_OUTPUT


def pytest_sessionstart(session):
    # tools/test-headless.sh runs tests through VTK's run-time choice of window system (VTK 9.4
    # and later): they must really render through the class it names.
    expected = os.environ.get("LIGHTSHAFTS_EXPECTED_RENDER_WINDOW")
    if expected:
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
        from vtkmodules.vtkRenderingCore import vtkRenderWindow
        actual = vtkRenderWindow().GetClassName()
        if actual != expected:
            pytest.exit(f"VTK renders through {actual}, not {expected} "
                        f"(LIGHTSHAFTS_EXPECTED_RENDER_WINDOW)", returncode=1)


def pytest_configure(config):
    # A Python warning fails the test, as VTK's output does: a test that expects one says so
    # (pytest.warns). Deprecations are the exception: a VTK (or Python) API our code calls that
    # is deprecated fails the test, since the next VTK removes it (VTK 9.5 deprecated
    # vtkRenderer::AddActor2D, for one); other packages' own (PyVista's, numpy's) are theirs.
    # (The last matching filter wins.)
    for line in ("error", "default::DeprecationWarning", "default::PendingDeprecationWarning"):
        config.addinivalue_line("filterwarnings", line)
    config.addinivalue_line(
        "filterwarnings",
        r"error::DeprecationWarning:(test_|lightshafts|render_helpers|lightshaft_reference|"
        r"vtk_output)")
    # The sweeps: one code path over many parameter values, a numerical bound per case, or the
    # benchmark scripts. CI runs them on Debian 12; the other releases' lanes leave them out
    # (tools/test-distros.sh with LIGHTSHAFTS_DISTROS_PYTEST_MARK="not sweep"), and run every
    # other test: the API, the methods, the light kinds, the features, PyVista, the examples.
    config.addinivalue_line(
        "markers", "sweep: a parameter sweep or numerical bound that no VTK version changes "
        "(left out of CI's Debian 13 and unstable lanes)")


def pytest_addoption(parser):
    parser.addoption("--fuzz-frames", type=int, default=300,
                     help="frames the seeded fuzz test renders (default 300)")
    parser.addoption("--fuzz-seed", default="20261129",
                     help="seed of the fuzz test's random sequence, or 'random'")
