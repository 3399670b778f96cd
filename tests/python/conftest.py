"""pytest setup: the tests import the built `lightshafts` package (PYTHONPATH set by
tools/test.sh) and render offscreen (run under xvfb-run)."""

import os
import sys

sys.path.insert(0, os.path.dirname(__file__))

import pytest  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.vtkCommonCore import VTK_STRING  # noqa: E402


class Messages:
    """Collects the ErrorEvent/WarningEvent messages a VTK object emits."""

    def __init__(self, obj):
        self.errors = []
        self.warnings = []

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, message):
            self.errors.append(message)

        @calldata_type(VTK_STRING)
        def on_warning(_obj, _event, message):
            self.warnings.append(message)

        self._callbacks = (on_error, on_warning)
        obj.AddObserver("ErrorEvent", on_error)
        obj.AddObserver("WarningEvent", on_warning)


@pytest.fixture
def messages():
    return Messages
