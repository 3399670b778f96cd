"""The documentation: README.md and every page of docs/ (the guide and the measured results).

Static checks, one test per page: every relative link and image resolves to a file or folder
of the repository, every #anchor to a heading of the page it names (GitHub's slugs), every
repository path named in code (inline or a block) exists, every `tools/<script>` named exists
and is executable, and the pages keep their size (README.md under 300 lines, each page of
docs/ under 400).

The README's examples, each marked by an HTML comment on the line before its fence:
  <!-- test: run -->                 a Python block run with /usr/bin/python3 in a fresh folder,
                                      as the examples run (tests/python/test_examples.py): it
                                      must exit 0, print no VTK error or warning, write a PNG;
  <!-- test: run-pyvista -->         the same where `import pyvista` works (else skipped);
  <!-- test: pvpython -->            run by pvpython (or pvbatch) with the LightShafts plugin,
                                      skipped where neither or no plugin is found;
  <!-- test: excerpt <file> -->      every line of the block is a line of <file> (leading and
                                      trailing whitespace aside).
The static checks need no build: `pytest tests/python/test_docs.py -k "not readme"`.
"""

import glob
import os
import re
import shutil
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAGES = ["README.md"] + sorted(
    os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "docs", "**", "*.md"),
                                                recursive=True))
README_MAX_LINES = 300
PAGE_MAX_LINES = 400
PROJECT_DIRS = ("tools", "examples", "tests", "docs", "plugin", "python", "paraview", "shaders",
                "cmake", r"\.ci")
# A project path in code: one of the project's top folders at the start of a word (not inside
# another path such as build/lib/python3.11 or /usr/local/lib/paraview-5.11).
PROJECT_PATH = re.compile(r"(?<![\w./$~-])(?:%s)/[\w./+-]*" % "|".join(PROJECT_DIRS))
TOOL = re.compile(r"(?<![\w./$~-])tools/([\w.+-]+)")
LINK = re.compile(r"!?\[([^\]]*)\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```+|~~~+)\s*([\w+-]*)")
INLINE_CODE = re.compile(r"(`+)((?:(?!\1).|\n(?!\s*\n))+?)\1")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
TEST_MARK = re.compile(r"^<!--\s*test:\s*([\w-]+)\s*(.*?)\s*-->\s*$")
# What VTK prints for an error or a warning (vtkOutputWindow, vtkLogger): the ctest tests fail
# on the same expression (CMakeLists.txt, LIGHTSHAFTS_VTK_MESSAGE_REGEX).
VTK_MESSAGE = re.compile(r"ERROR: In |Warning: In |Generic Warning|ERR\||WARN\|")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
TIMEOUT = 300


def read(page):
    with open(os.path.join(ROOT, page), encoding="utf-8") as f:
        return f.read()


def split_code(text):
    """(prose with the fenced blocks blanked out, [(info string, block text, first line)])."""
    prose, blocks = [], []
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        match = FENCE.match(line)
        if fence is None:
            if match:
                fence = (match.group(1)[0], len(match.group(1)))
                blocks.append([match.group(2), [], number])
                prose.append("")
            else:
                prose.append(line)
        else:
            stripped = line.strip()
            if (stripped and set(stripped) == {fence[0]} and len(stripped) >= fence[1]):
                fence = None
            else:
                blocks[-1][1].append(line)
            prose.append("")
    return "\n".join(prose), [(info, "\n".join(lines), first) for info, lines, first in blocks]


def inline_code(prose):
    return [m.group(2) for m in INLINE_CODE.finditer(prose)]


def indented_code(prose):
    """Indented code blocks: lines of four or more spaces after a blank line (and the lines
    that follow them), outside lists."""
    lines, code, previous_blank, in_block = prose.split("\n"), [], True, False
    for line in lines:
        if line.startswith("    ") and line.strip() and (previous_blank or in_block):
            in_block = previous_blank or in_block
            code.append(line)
        elif line.strip():
            in_block = False
        previous_blank = not line.strip()
    return code


def slug(heading):
    """GitHub's anchor for a heading: its text as rendered, lower case, without punctuation
    but - and _, spaces as -."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page):
    """Every anchor a page's headings give, duplicates numbered as GitHub numbers them."""
    prose, _ = split_code(read(page))
    seen, result = {}, set()
    for line in prose.split("\n"):
        match = HEADING.match(line)
        if not match:
            continue
        base = slug(match.group(2))
        count = seen.get(base, 0)
        result.add(base if count == 0 else f"{base}-{count}")
        seen[base] = count + 1
    return result


def links(page):
    """The relative links and images of a page, code left out: [(target, line)]."""
    prose, _ = split_code(read(page))
    prose = INLINE_CODE.sub(lambda m: " " * len(m.group(0)), prose)
    found = []
    for match in LINK.finditer(prose):
        target = match.group(2)
        if re.match(r"^[a-zA-Z][\w+.-]*:", target):  # http:, https:, mailto:, ...
            continue
        found.append((target, prose.count("\n", 0, match.start()) + 1))
    return found


def code_texts(page):
    prose, blocks = split_code(read(page))
    return inline_code(prose) + [block for _, block, _ in blocks] + indented_code(prose)


def project_paths(code):
    """The project paths named in a piece of code (arguments after a space are other words)."""
    paths = []
    for match in PROJECT_PATH.finditer(code):
        path, after = match.group(0), code[match.end():match.end() + 1]
        if after and after in "<*{$[":  # a placeholder or a pattern: examples/<name>.py
            continue
        path = path.rstrip(".,:;")
        if "X.Y" in path:
            continue
        paths.append(path)
    return paths


@pytest.mark.parametrize("page", PAGES)
def test_links_resolve(page):
    here = os.path.dirname(os.path.join(ROOT, page))
    broken = []
    for target, line in links(page):
        path, _, anchor = target.partition("#")
        resolved = os.path.normpath(os.path.join(here, path)) if path else os.path.join(ROOT, page)
        if not resolved.startswith(ROOT) or not os.path.exists(resolved):
            broken.append(f"line {line}: {target} (no such file or folder)")
            continue
        if anchor:
            if not resolved.endswith(".md") or not os.path.isfile(resolved):
                broken.append(f"line {line}: {target} (an anchor into something not a page)")
            elif anchor not in anchors(os.path.relpath(resolved, ROOT)):
                broken.append(f"line {line}: {target} (no heading with that anchor)")
    assert not broken, f"{page}: broken links:\n  " + "\n  ".join(broken)


@pytest.mark.parametrize("page", PAGES)
def test_code_paths_exist(page):
    missing = sorted({path for code in code_texts(page) for path in project_paths(code)
                      if not os.path.exists(os.path.join(ROOT, path))})
    assert not missing, f"{page} names paths that do not exist: {missing}"


@pytest.mark.parametrize("page", PAGES)
def test_tool_commands_exist(page):
    text = read(page)
    bad = []
    for match in TOOL.finditer(text):
        if text[match.end():match.end() + 1] in ("<", "*"):
            continue
        name = match.group(1).rstrip(".,:;")
        path = os.path.join(ROOT, "tools", name)
        if not os.path.isfile(path) or not os.access(path, os.X_OK):
            bad.append(f"tools/{name}")
    assert not bad, f"{page} names commands that are not executable files: {sorted(set(bad))}"


@pytest.mark.parametrize("page", PAGES)
def test_page_size(page):
    lines = len(read(page).splitlines())
    limit = README_MAX_LINES if page == "README.md" else PAGE_MAX_LINES
    assert lines < limit, f"{page} has {lines} lines: keep it under {limit}"


def test_the_guide_pages_are_there():
    for name in ("getting-started", "quality-and-cost", "methods", "lights-and-cookies", "medium",
                 "translucent-and-volumes", "paraview", "pyvista", "headless",
                 "reference-and-benchmarks", "architecture", "tests", "known-issues",
                 "parameters"):
        assert f"docs/{name}.md" in PAGES, name
        assert f"(docs/{name}.md)" in read("README.md"), f"the README's index lacks {name}"


# The README's examples.

def readme_blocks(kind):
    """The README's code blocks marked `<!-- test: kind ... -->`: [(argument, code, line)]."""
    lines = read("README.md").split("\n")
    found = []
    for i, line in enumerate(lines):
        match = TEST_MARK.match(line)
        if not match or match.group(1) != kind:
            continue
        fence = FENCE.match(lines[i + 1]) if i + 1 < len(lines) else None
        assert fence, f"README.md line {i + 1}: <!-- test: {kind} --> is not followed by a fence"
        body = []
        for other in lines[i + 2:]:
            if other.strip().startswith(fence.group(1)):
                break
            body.append(other)
        found.append((match.group(2), "\n".join(body) + "\n", i + 1))
    return found


def test_readme_marks_each_kind_of_example():
    assert len(readme_blocks("run")) >= 1
    assert len(readme_blocks("run-pyvista")) == 1
    assert len(readme_blocks("pvpython")) == 1
    assert len(readme_blocks("excerpt")) >= 1


def judge(result, directory, what):
    output = result.stdout + result.stderr
    assert result.returncode == 0, f"{what} exited with {result.returncode}:\n{output[-4000:]}"
    messages = [line for line in output.splitlines() if VTK_MESSAGE.search(line)]
    assert not messages, f"{what} printed VTK errors or warnings:\n" + "\n".join(messages[:20])
    pictures = glob.glob(os.path.join(str(directory), "*.png"))
    assert pictures, f"{what} wrote no PNG into its folder"
    assert all(os.path.getsize(p) > 0 for p in pictures), pictures


def run_python(code, directory, what):
    script = os.path.join(str(directory), "readme_example.py")
    with open(script, "w") as f:
        f.write(code)
    # As the examples run (test_examples.py): a deprecated VTK call in the script or in the
    # lightshafts package is an error. The environment is the test's (tools/test.sh sets
    # PYTHONPATH to the build's package, absolute).
    command = [PYTHON, "-W", "error::DeprecationWarning:__main__", "-W",
               "error::DeprecationWarning:lightshafts", script]
    result = subprocess.run(command, cwd=str(directory), capture_output=True, text=True,
                            timeout=TIMEOUT)
    judge(result, directory, what)


@pytest.mark.parametrize("index", range(len(readme_blocks("run"))))
def test_readme_run_python(tmp_path, index):
    _, code, line = readme_blocks("run")[index]
    run_python(code, tmp_path, f"README.md's Python example (line {line})")


@pytest.mark.parametrize("index", range(len(readme_blocks("run-pyvista"))))
def test_readme_run_pyvista(tmp_path, index):
    if subprocess.run([PYTHON, "-c", "import pyvista"], capture_output=True,
                      timeout=TIMEOUT).returncode != 0:
        pytest.skip("PyVista does not import here")
    _, code, line = readme_blocks("run-pyvista")[index]
    run_python(code, tmp_path, f"README.md's PyVista example (line {line})")


def paraview_plugin():
    """The LightShafts.so the ParaView tests use (tests/paraview/lightshafts_pvscene.py), or
    the installed one; None when there is none."""
    path = os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN")
    if path:
        return path if os.path.exists(path) else None
    listings = [os.environ.get("LIGHTSHAFTS_PARAVIEW_PLUGIN_LIST", "")]
    listings += [os.path.join(ROOT, build, "LightShaftsPluginPath.txt")
                 for build in ("build/paraview-plugin", "build-pv")]
    for listing in listings:
        if listing and os.path.exists(listing):
            with open(listing) as f:
                path = f.read().strip()
            if os.path.exists(path):
                return path
    installed = glob.glob("/usr/local/lib/paraview-*/plugins/LightShafts/LightShafts.so")
    return sorted(installed)[-1] if installed else None


@pytest.mark.parametrize("index", range(len(readme_blocks("pvpython"))))
def test_readme_run_pvpython(tmp_path, index):
    program = shutil.which("pvpython") or shutil.which("pvbatch")
    if not program:
        pytest.skip("neither pvpython nor pvbatch is installed")
    plugin = paraview_plugin()
    if not plugin:
        pytest.skip("the LightShafts ParaView plugin was not built or installed")
    _, code, line = readme_blocks("pvpython")[index]
    script = tmp_path / "readme_paraview.py"
    script.write_text(code)
    # ParaView's Python package as tools/pvbatch and the ctest tests give it (python3-paraview,
    # unpacked by the quick start up to ParaView 5.13), and the plugin the tests use.
    root = os.environ.get("LIGHTSHAFTS_PYTHON3_PARAVIEW_ROOT",
                          "/usr/local/lib/lightshafts/python3-paraview")
    env = dict(os.environ, LIGHTSHAFTS_PARAVIEW_PLUGIN=plugin,
               PYTHONPATH=os.path.join(root, "usr", "lib", "python3", "dist-packages"))
    result = subprocess.run([program, str(script)], cwd=str(tmp_path), env=env,
                            capture_output=True, text=True, timeout=TIMEOUT)
    judge(result, tmp_path, f"README.md's ParaView example (line {line}, "
                            f"{os.path.basename(program)})")


@pytest.mark.parametrize("index", range(len(readme_blocks("excerpt"))))
def test_readme_excerpt_is_in_its_file(index):
    source, code, line = readme_blocks("excerpt")[index]
    path = os.path.join(ROOT, source)
    assert os.path.isfile(path), f"README.md line {line}: {source} does not exist"
    with open(path, encoding="utf-8") as f:
        lines = {other.strip() for other in f.read().splitlines()}
    missing = [other.strip() for other in code.splitlines()
               if other.strip() and other.strip() not in lines]
    assert not missing, (f"README.md line {line}: these lines are not in {source}:\n  "
                         + "\n  ".join(missing))
