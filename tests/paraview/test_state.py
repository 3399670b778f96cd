"""pvbatch test: the light-shaft properties of LightShaftsRenderView survive a .pvsm round trip.
Usage: pvbatch test_state.py OUTPUT_DIR
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402

# Every property away from its default.
VALUES = {
    "LightShafts": 1,
    "ShaftLights": [2, 1],
    "ShadowSurfaces": 1,
    "ScatteringCoefficient": [0.03, 0.04, 0.05],
    "AbsorptionCoefficient": [0.01, 0.02, 0.0],
    "PhaseFunction": 1,
    "Anisotropy": 0.6,
    "ShaftExposure": 7.5,
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


def same(a, b):
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        return abs(float(a) - float(b)) <= 1e-9 * max(1.0, abs(float(a)))
    return a == b


def main():
    from paraview import simple
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    failures = []
    scene.load_plugin()

    view, _, _ = scene.make_scene()
    for name, value in VALUES.items():
        setattr(view, name, value)
    simple.Render(view)

    state = os.path.join(out, "lightshafts_state.pvsm")
    simple.SaveState(state)
    simple.ResetSession()  # the plugin stays loaded
    simple.LoadState(state)
    views = [v for v in simple.GetViews() if v.GetXMLName() == "LightShaftsRenderView"]
    if len(views) != 1:
        failures.append(f"{len(views)} LightShaftsRenderView after loading the state")
    else:
        loaded = views[0]
        for name, value in VALUES.items():
            raw = loaded.GetProperty(name).SMProperty  # numbers, not enumeration texts
            got = [raw.GetElement(i) for i in range(raw.GetNumberOfElements())]
            got = got[0] if len(got) == 1 else got
            if not same(value, got):
                failures.append(f"{name}: saved {value}, loaded {got}")
        simple.Render(loaded)
    print(f"{len(VALUES)} properties through .pvsm ({state})")

    # Python trace: the properties as the GUI traces them (its Apply wraps the changes in a
    # PropertiesModified trace item, as here).
    from paraview import smtrace
    smtrace.start_trace()
    traced = simple.CreateView("LightShaftsRenderView")
    item = smtrace.PropertiesModified(traced)
    traced.ShaftMethod = "Radial Blur"
    traced.RadialSamples = 24
    traced.ScatteringCoefficient = [0.02, 0.03, 0.04]
    traced.ShaftExposure = 12.0
    item.finalize()
    text = smtrace.stop_trace()
    for line in ("CreateView('LightShaftsRenderView')", ".ShaftMethod = 'Radial Blur'",
                 ".RadialSamples = 24", ".ScatteringCoefficient = [0.02, 0.03, 0.04]",
                 ".ShaftExposure = 12.0"):
        if line not in text:
            failures.append(f"trace lacks {line!r}")
    print("trace:\n" + text)
    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
