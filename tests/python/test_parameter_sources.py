"""One source for the parameters' defaults and ranges: vtkLightShaftPass and vtkLightShaftMedium.

The classes' headers declare each parameter's default and clamp; the ParaView XML, the headers'
own documentation and the parameter table of docs/parameters.md are checked against what the
classes do (a fresh object's values, and the range read by setting values far outside it), so
that none of them can drift.
"""

import math
import os
import re
import xml.etree.ElementTree as ElementTree

import pytest

from lightshafts import parameter_owner, vtkLightShaftMedium, vtkLightShaftPass

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
INTEGER_PROBE = 2 ** 31 - 1
FLOAT_PROBE = 1e300

# ParaView property name -> the pass's parameter, where they differ.
PARAVIEW_NAMES = {"ShaftExposure": "Exposure", "ShaftMethod": "Method", "ShaftJitter": "Jitter",
                  "ShaftBlurRadius": "BlurRadius", "ShaftDownsampleFactor": "DownsampleFactor",
                  "ShaftTime": "Time", "MediumDensityScale": "DensityScale",
                  "MediumBackgroundDensity": "BackgroundDensity",
                  "MediumShadowResolution": "FieldShadowResolution",
                  "MediumFieldResolution": "FieldResolution"}
# The public headers whose documented groups hold parameters, and the class of each.
HEADERS = {"pass/vtkLightShaftPass.h": vtkLightShaftPass,
           "core/vtkLightShaftMedium.h": vtkLightShaftMedium}


def has_parameter(name):
    """Whether `name` is a parameter (a Set and a Get) of the pass or of its medium."""
    try:
        owner = parameter_owner(vtkLightShaftPass(), name)
    except TypeError:
        return False
    return hasattr(owner, "Get" + name)


def default(name):
    value = getattr(parameter_owner(vtkLightShaftPass(), name), "Get" + name)()
    return tuple(value) if isinstance(value, tuple) else (value,)


def clamp_range(name, integer):
    """(low, high) of the first component, from setting values far outside the range."""
    shafts = vtkLightShaftPass()
    setter, getter = getattr(parameter_owner(shafts, name), "Set" + name), getattr(parameter_owner(shafts, name), "Get" + name)
    n = len(default(name))
    probe = INTEGER_PROBE if integer else FLOAT_PROBE
    setter(*([-probe] * n))
    low = getter()
    setter(*([probe] * n))
    high = getter()
    first = (lambda v: v[0] if isinstance(v, tuple) else v)
    return first(low), first(high)


def close(a, b):
    return math.isclose(float(a), float(b), rel_tol=1e-12, abs_tol=1e-12)


def paraview_properties():
    """(pass parameter, kind, defaults, domain min, domain max, enumeration values) of every
    property of LightShaftsRenderView that is one of the pass's parameters."""
    tree = ElementTree.parse(os.path.join(ROOT, "paraview", "plugin", "LightShafts.xml"))
    view = tree.getroot().find(".//RenderViewProxy[@name='LightShaftsRenderView']")
    shafts = vtkLightShaftPass()
    rows = []
    for prop in view:
        if prop.tag not in ("IntVectorProperty", "DoubleVectorProperty"):
            continue
        name = PARAVIEW_NAMES.get(prop.get("name"), prop.get("name"))
        if not has_parameter(name) or not hasattr(parameter_owner(shafts, name), "Get" + name):
            continue
        defaults = tuple(float(v) for v in prop.get("default_values").split())
        domain = prop.find("IntRangeDomain")
        if domain is None:
            domain = prop.find("DoubleRangeDomain")
        low = high = None
        if domain is not None:
            low = float(domain.get("min").split()[0])
            high = float(domain.get("max").split()[0])
        entries = [int(e.get("value")) for e in prop.findall("EnumerationDomain/Entry")]
        rows.append((name, prop.tag, defaults, low, high, entries))
    return rows


PARAVIEW = paraview_properties()
# The view's defaults that differ from the pass's, on purpose: ParaView's GUI renders a still
# view again until it converges (paraview/plugin/gui), so refinement is on there; a new view is
# given no coefficient, so it chooses them from the scene (as add_light_shafts does).
PARAVIEW_OWN_DEFAULTS = {"ProgressiveRefinement": (1,), "FitMediumToScene": (1,)}


def test_the_paraview_view_exposes_the_pass_parameters():
    assert len(PARAVIEW) >= 29


@pytest.mark.parametrize("name,kind,defaults,low,high,entries", PARAVIEW,
                         ids=[row[0] for row in PARAVIEW])
def test_paraview_defaults_and_ranges_are_the_pass(name, kind, defaults, low, high, entries):
    expected = PARAVIEW_OWN_DEFAULTS.get(name, default(name))
    assert len(defaults) == len(expected)
    assert all(close(a, float(b)) for a, b in zip(defaults, expected)), (defaults, expected)
    integer = kind == "IntVectorProperty"
    if low is not None:
        assert (low, high) == pytest.approx(clamp_range(name, integer))
    if entries and name != "DownsampleFactor":
        assert (min(entries), max(entries)) == clamp_range(name, integer)
    if name == "DownsampleFactor":
        assert entries == [1, 2, 4]


def header_groups():
    """The documented groups (///@{ ... ///@}) of the public headers: (class, comment, code)."""
    groups = []
    for header, cls in HEADERS.items():
        with open(os.path.join(ROOT, "plugin", header)) as f:
            text = f.read()
        groups += [(cls, comment, code) for comment, code in
                   re.findall(r"///@\{\s*/\*\*(.*?)\*/(.*?)///@\}", text, re.S)]
    return groups


def group_setters(code):
    """The parameters a group sets, in order (overloads and SetXToY shortcuts once)."""
    names = []
    for a, b in re.findall(r"vtkSet(?:Clamp)?Macro\((\w+),|void Set(\w+)\(", code):
        name = a or b
        if name not in names and not any(name.startswith(n + "To") for n in names):
            names.append(name)
    return names


def documented_defaults(comment):
    """The values after "Default is" / "Defaults are", in order (None for words such as nullptr
    that are no number; a vector's first component)."""
    match = re.search(r"Defaults? (?:is|are) (.*?)\.(?:\s|$)", comment.replace("\n", " ").replace(
        "*", " ") + " ")
    if not match:
        return []
    text = re.sub(r"\((?![-0-9])[^)]*\)", "", match.group(1))  # (remarks), not (vectors)
    items = re.split(r",\s*(?![^()]*\))|\s+and\s+", re.sub(r"\s+", " ", text).strip())
    values = []
    for item in items:
        word = item.strip().lstrip("(").split(",")[0].split()[0] if item.strip() else ""
        values.append(word.rstrip(")"))
    return values


def header_defaults():
    """{parameter: the number the headers' documentation gives as its default}."""
    found = {}
    for cls, comment, code in header_groups():
        names = group_setters(code)
        words = documented_defaults(comment)
        if len(names) > 1 and words:
            assert len(words) == len(names), (names, words)
        for name, word in zip(names, words):
            if word in ("on", "off"):
                found[name] = float(word == "on")
            elif re.fullmatch(r"[A-Z_0-9]+", word) and hasattr(cls, word):
                found[name] = float(getattr(cls, word))
            elif re.fullmatch(r"-?[0-9.e+-]+", word):
                found[name] = float(word)
    return found


HEADER = header_defaults()


def test_the_header_documents_the_defaults():
    assert len(HEADER) >= 40


@pytest.mark.parametrize("name", sorted(HEADER))
def test_header_documented_default_is_the_pass(name):
    assert close(HEADER[name], default(name)[0])


def header_clamps():
    clamps = []
    for header, cls in HEADERS.items():
        with open(os.path.join(ROOT, "plugin", header)) as f:
            text = f.read()
        clamps += [(cls,) + c for c in
                   re.findall(r"vtkSetClampMacro\((\w+), (\w+), (\w+), (\w+)\);", text)]
    return clamps


@pytest.mark.parametrize("cls,name,kind,low,high", header_clamps(), ids=lambda v: str(v))
def test_header_clamps_are_the_documented_ranges(cls, name, kind, low, high):
    value = (lambda v: getattr(cls, v) if v.isidentifier() else float(v))
    assert clamp_range(name, kind == "int") == (value(low), value(high))
    # The group's comment states that range.
    for _, comment, code in header_groups():
        if f"vtkSetClampMacro({name}," in code and re.search(r"in \[", comment):
            stated = re.findall(r"\[(-?[0-9.e+-]+), (-?[0-9.e+-]+)\]", comment)
            assert (float(value(low)), float(value(high))) in \
                [(float(a), float(b)) for a, b in stated], name


def readme_rows():
    """(setters, range text, default text) of the parameter tables (docs/parameters.md: one
    for the pass, one for the medium)."""
    with open(os.path.join(ROOT, "docs", "parameters.md")) as f:
        text = f.read()
    rows = []
    for table in text.split("| parameter | unit / range | default | meaning |")[1:]:
        table = table[:table.index("\n\n")] if "\n\n" in table else table
        for line in table.splitlines()[2:]:
            cells = [c.strip() for c in line.strip("|").split("|")]
            setters = re.findall(r"`Set(\w+)\(", cells[0])
            rows.append((setters, cells[1], cells[2]))
    return rows


def test_readme_ranges_and_defaults_are_the_pass():
    checked = 0
    for setters, range_text, default_text in readme_rows():
        range_text = range_text.replace("\u2212", "-")
        interval = re.search(r"\[(-?[0-9.e+-]+), (-?[0-9.e+-]+)\]", range_text)
        defaults = [d.strip() for d in default_text.split("(")[0].split(",")]
        for i, name in enumerate(setters):
            if not has_parameter(name):
                continue
            integer = isinstance(default(name)[0], (int, bool)) and not isinstance(
                default(name)[0], float)
            if interval:
                low, high = clamp_range(name, integer)
                assert (float(interval.group(1)), float(interval.group(2))) == \
                    (float(low), float(high)), name
                checked += 1
            text = defaults[min(i, len(defaults) - 1)].replace("\u2212", "-")
            if re.fullmatch(r"-?[0-9.e+-]+", text):
                assert close(float(text), default(name)[0]), (name, text)
                checked += 1
            elif text in ("on", "off"):
                assert bool(default(name)[0]) == (text == "on"), name
                checked += 1
    assert checked >= 30
