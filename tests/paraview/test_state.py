"""pvbatch test: LightShaftsRenderView through a .pvsm state file, saved by one pvbatch and
loaded by another, as users share states; and a state saved by ParaView 5.11 (Debian 12's)
loaded by this ParaView.

    pvbatch test_state.py save OUTPUT_DIR     # the scene with every property away from its
                                              # default: OUTPUT_DIR/state.pvsm and state.png
    pvbatch test_state.py load STATE PNG OUTPUT_DIR [--tolerance baseline]
                                              # a fresh process loads STATE: every property as
                                              # saved, and the picture as PNG
    pvbatch test_state.py trace OUTPUT_DIR    # the properties in a Python trace

tests/paraview/run_state.sh runs the three, and `load` of tests/baselines/paraview-5.11.pvsm
(written by `save` under ParaView 5.11) against its picture, tests/baselines/paraview-5.11.png.
Every property is compared by its raw values, the picture by the render test's tolerances for
another ParaView's picture (--tolerance baseline), else almost exactly (the same ParaView).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402

# Every property away from its default. (The cookie's file is a path on the machine that saved
# the state: left out of the baseline written for another machine, see `save --baseline`.)
VALUES = {
    "LightShafts": 1,
    "ShaftLights": [2, 1],
    "ShadowSurfaces": 1,
    "AttenuateSurfaceLight": 0,
    "SplitLongFrames": 0,
    "TranslucentShadows": 0,
    "ScatteringCoefficient": [0.06, 0.08, 0.1],
    "AbsorptionCoefficient": [0.01, 0.02, 0.0],
    "PhaseFunction": 1,
    "Anisotropy": 0.6,
    "ShaftExposure": 400.0,
    "AttenuateScene": 0,
    "ShaftQuality": 3,
    "ShaftTargetError": 0.02,
    "NumberOfSlices": 96,
    "ShadowMapSize": 512,
    "AutomaticSliceCount": 1,
    "MaximumNumberOfSlices": 300,
    "ShaftJitter": 0,
    "ShaftBlurRadius": 3,
    "ShaftDownsampleFactor": 2,
    "AccumulationPrecision": 1,
    "CookieFileName": os.path.join(scene.ROOT, "docs", "images", "stained_glass.png"),
    "NoiseAmplitude": 0.4,
    "NoiseScale": 5.0,
    "NoiseVelocity1": [0.1, -0.2],
    "NoiseVelocity2": [0.3, 0.05],
    "LinkShaftTimeToAnimation": 0,
    "ShaftTime": 2.5,
    "ShaftMethod": 1,
    "LatticeResolution": 8,
    "NumberOfSteps": 48,
    "InterleaveSize": 3,
    "RadialSamples": 32,
    "Decay": 0.97,
    "Density": 0.8,
    "Weight": 0.6,
    "RadialJitter": 0,
    "DistributedShadowMap": 0,
    "RadialGuardBand": 3.0,
}
# The picture of a state against the picture saved with it: the same ParaView renders the same
# pixels; another ParaView (its VTK) within the render test's baseline tolerances.
SAME_PARAVIEW = dict(mean_tolerance=0.05, pixel_fraction=0.0005, pixel_level=4)
BASELINE = dict(mean_tolerance=1.5, pixel_fraction=0.005, pixel_level=12)


def same(a, b):
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        return abs(float(a) - float(b)) <= 1e-9 * max(1.0, abs(float(a)))
    return a == b


def raw(view, name):
    prop = view.GetProperty(name).SMProperty  # numbers, not enumeration texts
    got = [prop.GetElement(i) for i in range(prop.GetNumberOfElements())]
    return got[0] if len(got) == 1 else got


def save(out, baseline):
    from paraview import simple
    view, _, _ = scene.make_scene()
    values = {k: v for k, v in VALUES.items() if not (baseline and k == "CookieFileName")}
    for name, value in values.items():
        setattr(view, name, value)
    simple.Render(view)
    state = os.path.join(out, "state.pvsm")
    simple.SaveState(state)
    scene.screenshot(view, os.path.join(out, "state.png"))
    print(f"saved {len(values)} properties: {state}, {out}/state.png")
    return []


def load(state, picture, out, tolerance):
    from paraview import simple
    failures = []
    simple.LoadState(state)
    views = [v for v in simple.GetViews() if v.GetXMLName() == "LightShaftsRenderView"]
    if len(views) != 1:
        return [f"{len(views)} LightShaftsRenderView after loading {state}"]
    view = views[0]
    with open(state) as text:
        held = text.read()
    checked = 0
    for name, value in VALUES.items():
        if name == "CookieFileName" and not raw(view, name):
            continue  # a baseline state saved without it
        if f'name="{name}"' not in held:
            # A property newer than the state (an older plugin saved it): its default.
            prop = view.GetProperty(name).SMProperty
            value = prop.GetDefaultValue(0)
        if not same(value, raw(view, name)):
            failures.append(f"{name}: saved {value}, loaded {raw(view, name)}")
        checked += 1
    shot = scene.screenshot(view, os.path.join(out, "loaded.png"))
    mean, fraction, ok = scene.compare_images(shot, scene.read_png(picture), **tolerance)
    print(f"{state}: {checked} properties as saved; picture against {picture}: mean |diff| "
          f"{mean:.3f} levels, {100 * fraction:.3f}% of pixels off by more than "
          f"{tolerance['pixel_level']}")
    if not ok:
        failures.append(f"the loaded state's picture differs from {picture}")
    return failures


def trace():
    # Python trace: the properties as the GUI traces them (its Apply wraps the changes in a
    # PropertiesModified trace item, as here), and the trace replayed: it makes a view with
    # them. (ParaView 6 traces `view.Set(Name=value, ...)`, earlier ones `view.Name = value`.)
    import re
    from paraview import simple, smtrace
    failures = []
    smtrace.start_trace()
    traced = simple.CreateView("LightShaftsRenderView")
    item = smtrace.PropertiesModified(traced)
    traced.ShaftMethod = "Radial Blur"
    traced.RadialSamples = 24
    traced.ScatteringCoefficient = [0.02, 0.03, 0.04]
    traced.ShaftExposure = 12.0
    item.finalize()
    text = smtrace.stop_trace()
    print("trace:\n" + text)
    expected = {"ShaftMethod": ("'Radial Blur'", 2), "RadialSamples": ("24", 24),
                "ScatteringCoefficient": ("[0.02, 0.03, 0.04]", [0.02, 0.03, 0.04]),
                "ShaftExposure": ("12.0", 12.0)}
    if "CreateView('LightShaftsRenderView')" not in text:
        failures.append("the trace does not create a LightShaftsRenderView")
    for name, (written, _) in expected.items():
        if not re.search(rf"(\.{name} = |\b{name}=){re.escape(written)}", text):
            failures.append(f"the trace lacks {name} = {written}")
    before = {view.GetGlobalIDAsString() for view in simple.GetViews()}
    exec(compile(text, "trace", "exec"), {})
    replayed = [view for view in simple.GetViews()
                if view.GetGlobalIDAsString() not in before
                and view.GetXMLName() == "LightShaftsRenderView"]
    if len(replayed) != 1:
        return failures + [f"the replayed trace made {len(replayed)} LightShaftsRenderView"]
    for name, (_, value) in expected.items():
        if not same(value, raw(replayed[0], name)):
            failures.append(f"replayed trace: {name} is {raw(replayed[0], name)}, not {value}")
    print(f"trace replayed: {len(expected)} properties as traced")
    return failures


def main():
    args = sys.argv[1:]
    scene.load_plugin()
    if args[:1] == ["save"]:
        os.makedirs(args[1], exist_ok=True)
        failures = save(args[1], "--baseline" in args)
    elif args[:1] == ["load"]:
        os.makedirs(args[3], exist_ok=True)
        tolerance = BASELINE if args[4:6] == ["--tolerance", "baseline"] else SAME_PARAVIEW
        failures = load(args[1], args[2], args[3], tolerance)
    elif args[:1] == ["trace"]:
        failures = trace()
    else:
        print(__doc__)
        return 2
    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
