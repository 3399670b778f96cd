"""What VTK prints during the tests: every error and warning that goes through VTK's output
window. conftest.py fails a test on any message it did not expect; a test (or a helper) that
expects one says so with `VTK_OUTPUT.expect(pattern)`."""

import re

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkOutputWindow

# The pass's documented warnings that tests meet on purpose.
ANALYTIC_IGNORES_SHADOWS = r"Method ANALYTIC ignores shadows"
LIGHT_VOLUME_GIVES_WAY = r"Method LIGHT_VOLUME has no closed form"


class Messages:
    """Collects the ErrorEvent/WarningEvent messages some VTK objects emit (VTK then does not
    print them): a pass and its medium, say, whose setters report on the medium."""

    def __init__(self, *objects):
        self.errors = []
        self.warnings = []

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, message):
            self.errors.append(message)

        @calldata_type(VTK_STRING)
        def on_warning(_obj, _event, message):
            self.warnings.append(message)

        self._callbacks = (on_error, on_warning)
        for obj in objects:
            self.observe(obj)

    def observe(self, obj):
        """Collect `obj`'s messages too."""
        on_error, on_warning = self._callbacks
        obj.AddObserver("ErrorEvent", on_error)
        obj.AddObserver("WarningEvent", on_warning)


class VTKOutputLog:
    """Every error and warning VTK prints through its output window (vtkErrorMacro,
    vtkWarningMacro, vtkGenericWarningMacro, ... of any object without its own observer)."""

    def __init__(self):
        self.messages = []  # (kind, text)
        self.expected = []  # regular expressions
        self.windows = []   # the output windows observed

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, text):
            self.messages.append(("error", text))

        @calldata_type(VTK_STRING)
        def on_warning(_obj, _event, text):
            self.messages.append(("warning", text))

        self._callbacks = (on_error, on_warning)
        self.attach()

    def attach(self):
        """Observe VTK's current output window too. (`import pyvista` replaces it with a
        vtkStringOutputWindow that sends VTK's messages to Python's logging: unobserved, every
        later message would pass unseen.)"""
        window = vtkOutputWindow.GetInstance()
        if any(window is seen for seen in self.windows):
            return
        on_error, on_warning = self._callbacks
        window.AddObserver("ErrorEvent", on_error)
        window.AddObserver("WarningEvent", on_warning)
        self.windows.append(window)

    def reset(self):
        self.attach()
        self.messages.clear()
        self.expected.clear()

    def expect(self, pattern):
        """Messages matching `pattern` (a regular expression) do not fail the current test."""
        self.expected.append(re.compile(pattern))

    def unexpected(self):
        return [(kind, text) for kind, text in self.messages
                if not any(p.search(text) for p in self.expected)]


VTK_OUTPUT = VTKOutputLog()
