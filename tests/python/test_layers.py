"""The layers (docs/architecture.md): no loop in the include graph between the plugin's classes
(tools/include-loops.py); each folder of plugin/ includes only its own headers and those of the
folders below it (core, reference, gl, methods, pass: plugin/LightShaftsSources.cmake); the
LightShafts::Core folders include no OpenGL header; and the pass's header is included only where
the pass is used."""

import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# The files that may include vtkLightShaftPass.h: the pass's own, the reference's public filter
# (its input is a pass), and ParaView's view (it holds one) with its distributed exchanges.
PASS_USERS = {
    "plugin/pass/vtkLightShaftPass.cxx",
    "plugin/pass/vtkLightShaftPassInternals.h",
    "plugin/pass/vtkLightShaftPassReadouts.cxx",
    "plugin/pass/vtkLightShaftPassSampling.cxx",
    "plugin/pass/vtkLightShaftReference.cxx",
    "paraview/plugin/module/vtkPVLightShaftsView.cxx",
    "paraview/plugin/module/vtkPVLightShaftsExchange.cxx",
    "paraview/plugin/module/vtkPVLightShaftsTranslucentGather.cxx",
    "paraview/plugin/module/vtkPVLightShaftsViewInternals.h",
    "paraview/plugin/module/vtkPVLightShaftsVolumeGather.cxx",
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


# The folders of plugin/, lowest first, as plugin/LightShaftsSources.cmake lists them; the first
# two make LightShafts::Core.
LAYERS = ("core", "reference", "gl", "methods", "pass")
CORE_LAYERS = ("core", "reference")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# Headers of VTK's OpenGL module (and GL loaders) that LightShafts::Core must never include.
GL_HEADER = re.compile(r"^(vtkOpenGL|vtk_glew|vtk_glad|vtkShader|vtkTextureObject|vtkRenderState"
                       r"|vtkRenderPass|vtkCameraPass|vtkImageProcessingPass|vtkRenderTimer"
                       r"|vtkFrameBufferObject|vtkLightShaftOpenGL|GL/)")


def plugin_files():
    """{file name: (layer, path)} of every header and source under plugin/."""
    files = {}
    for layer in LAYERS:
        folder = os.path.join(ROOT, "plugin", layer)
        for name in sorted(os.listdir(folder)):
            if name.endswith((".h", ".cxx")):
                files[name] = (layer, os.path.join(folder, name))
    return files


def test_the_folders_are_the_layers_the_build_lists():
    with open(os.path.join(ROOT, "plugin", "LightShaftsSources.cmake")) as f:
        listed = re.search(r"set\(lightshafts_layers ([^)]*)\)", f.read()).group(1).split()
    assert tuple(listed) == LAYERS
    stray = [name for name in os.listdir(os.path.join(ROOT, "plugin"))
             if name.endswith((".h", ".cxx"))]
    assert not stray, f"files outside the layers' folders: {stray}"


def test_each_folder_includes_only_its_own_and_lower_folders():
    files = plugin_files()
    upward = []
    for name, (layer, path) in files.items():
        with open(path, encoding="utf-8") as source:
            for included in INCLUDE.findall(source.read()):
                if included in files and \
                        LAYERS.index(files[included][0]) > LAYERS.index(layer):
                    upward.append(f"{layer}/{name} includes {files[included][0]}/{included}")
    assert not upward, "\n".join(upward)


def test_the_core_module_includes_no_opengl_header():
    files = plugin_files()
    found = []
    for name, (layer, path) in files.items():
        if layer in CORE_LAYERS:
            with open(path, encoding="utf-8") as source:
                found += [f"{layer}/{name}: {included}"
                          for included in INCLUDE.findall(source.read())
                          if GL_HEADER.match(included) or included.endswith(("FS.h", "VS.h"))]
    assert not found, "\n".join(found)


def function_lengths(path):
    """(lines, first line) of each function defined at namespace level in a clang-formatted file:
    a body opened and closed by a brace in column 0, from the line its declaration starts."""
    with open(path, encoding="utf-8") as source:
        lines = source.read().split("\n")
    found = []
    i = 0
    while i < len(lines):
        if lines[i] == "{":
            start = i - 1
            while start > 0 and not re.match(r"\S", lines[start]):
                start -= 1
            if re.match(r"(namespace|class|struct|enum|union|extern)\b", lines[start]):
                i += 1
                continue
            end = i + 1
            while end < len(lines) and lines[end] != "}" and not lines[end].startswith("};"):
                end += 1
            found.append((end - start + 1, lines[start].strip()))
            i = end
        i += 1
    return found


def test_files_and_functions_stay_short():
    """No file of plugin/ over 1,000 lines, the pass's header under 500, no function over 150."""
    long_files, long_functions = [], []
    for name, (layer, path) in plugin_files().items():
        with open(path, encoding="utf-8") as source:
            count = sum(1 for _ in source)
        if count >= (500 if name == "vtkLightShaftPass.h" else 1000):
            long_files.append(f"{layer}/{name}: {count} lines")
        long_functions += [f"{layer}/{name}: {n} lines from {first}"
                           for n, first in function_lengths(path) if n > 150]
    assert not long_files, long_files
    assert not long_functions, long_functions
