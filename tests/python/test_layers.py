"""The layers (docs/architecture.md): no loop in the include graph between the plugin's classes
(tools/include-loops.py), and the pass's header included only where the pass is used."""

import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# The files that may include vtkLightShaftPass.h: the pass's own, the reference's public filter
# (its input is a pass), and ParaView's view (it holds one).
PASS_USERS = {
    "plugin/vtkLightShaftPass.cxx",
    "plugin/vtkLightShaftPassInternals.h",
    "plugin/vtkLightShaftPassReadouts.cxx",
    "plugin/vtkLightShaftPassSampling.cxx",
    "plugin/vtkLightShaftReference.cxx",
    "paraview/plugin/module/vtkPVLightShaftsView.cxx",
}


def test_no_loop_between_classes():
    result = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "include-loops.py"),
                             os.path.join(ROOT, "plugin")], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.strip() == "no loop between classes"


def test_the_pass_header_is_included_only_where_the_pass_is_used():
    including = set()
    for folder in ("plugin", "paraview"):
        for directory, _, names in os.walk(os.path.join(ROOT, folder)):
            for name in names:
                if not name.endswith((".h", ".cxx")):
                    continue
                path = os.path.join(directory, name)
                with open(path, encoding="utf-8") as source:
                    if re.search(r'^\s*#\s*include\s+"vtkLightShaftPass\.h"', source.read(),
                                 re.M):
                        including.add(os.path.relpath(path, ROOT).replace(os.sep, "/"))
    assert including <= PASS_USERS, sorted(including - PASS_USERS)
