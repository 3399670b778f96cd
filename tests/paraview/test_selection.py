"""pvbatch test: selection in LightShaftsRenderView gives the answers of a plain RenderView.

The test scene (sphere over a floor under the spotlight) in both views with the same camera:
rectangle selections of surface cells and surface points, over the whole view and over a box
on the sphere, select the same ids in both (the light-shaft view's mid-refinement, its second of
four estimates); the light-shaft view still has its shafts after selecting (its converged
picture is the same as before, once converged again).
Usage: pvbatch test_selection.py OUTPUT_DIR
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lightshafts_pvscene as scene  # noqa: E402

RECTANGLES = {"view": [0, 0, scene.WIDTH - 1, scene.HEIGHT - 1], "sphere": [170, 110, 230, 170]}


def selected_ids(source):
    """The original ids of the cells and points the current selection extracts from `source`."""
    from paraview import servermanager, simple
    extracted = simple.ExtractSelection(Input=source)
    data = servermanager.Fetch(extracted)
    simple.Delete(extracted)
    blocks = [data.GetBlock(i) for i in range(data.GetNumberOfBlocks())] \
        if data.IsA("vtkMultiBlockDataSet") else [data]
    ids = []
    for block in filter(None, blocks):
        for kind, attributes in (("cell", block.GetCellData()), ("point", block.GetPointData())):
            original = attributes.GetArray(f"vtkOriginal{kind.capitalize()}Ids")
            if original is not None:
                ids += [(kind, int(original.GetValue(i)))
                        for i in range(original.GetNumberOfTuples())]
    return sorted(set(ids))


def clear(sources):
    from paraview import simple
    for source in sources.values():
        simple.ClearSelection(source)


def selections(view, sources):
    from paraview import simple
    results = {}
    for name, rectangle in RECTANGLES.items():
        for kind, select in (("cells", simple.SelectSurfaceCells),
                             ("points", simple.SelectSurfacePoints)):
            clear(sources)
            select(Rectangle=rectangle, View=view)
            results[(name, kind)] = {label: selected_ids(source)
                                     for label, source in sources.items()}
    clear(sources)
    return results


def converge(view, failures):
    """Still renders until the view's shafts have converged."""
    from paraview import simple
    for _ in range(8):
        view.UpdatePropertyInformation()
        if view.GetPropertyValue("RefinementConverged"):
            return
        simple.Render(view)
    failures.append("the light-shaft view did not converge after selecting mid-refinement")


def main():
    import numpy as np
    from paraview import simple
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    failures = []
    scene.load_plugin()

    results = {}
    for name in ("RenderView", "LightShaftsRenderView"):
        view, _, ball_display = scene.make_scene(simple.CreateView(name))
        simple.SetActiveView(view)
        sources = {"sphere": ball_display.Input}
        floor = [s for s in simple.GetSources().values()
                 if s.GetXMLName() == "PlaneSource"][-1]
        sources["floor"] = floor
        simple.Render(view)  # the first render resets the camera: place it again
        view.CameraPosition = [0.0, 3.0, 14.0]
        view.CameraFocalPoint = [0.0, 3.0, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraViewAngle = 40.0
        simple.Render(view)
        if name == "LightShaftsRenderView":
            # Selecting mid-refinement (Progressive Refinement is on by default): the second of
            # four estimates; then the converged picture must survive another selection.
            view.RefinementFrames = 4
            simple.Render(view)
            results[name] = selections(view, sources)
            converge(view, failures)
            before = scene.screenshot(view, os.path.join(out, f"{name}_before.png"))
            selections(view, sources)
            # (Selecting shows and then clears the selection's representation: a change of the
            # scene, so the shafts refine again, to the same picture.)
            converge(view, failures)
        else:
            before = scene.screenshot(view, os.path.join(out, f"{name}_before.png"))
            results[name] = selections(view, sources)
        after = scene.screenshot(view, os.path.join(out, f"{name}_after.png"))
        difference = float(np.abs(after - before).max())
        print(f"{name}: picture after selecting differs by at most {difference} levels")
        if difference > 0.0:
            failures.append(f"{name}: the picture changed after selecting")
        for source in list(sources.values()):
            simple.Delete(source)
        simple.Delete(view)

    plain, shafted = results["RenderView"], results["LightShaftsRenderView"]
    for key in sorted(plain):
        counts = {label: len(ids) for label, ids in plain[key].items()}
        print(f"{key[0]} {key[1]}: RenderView {counts}, LightShaftsRenderView "
              f"{ {label: len(ids) for label, ids in shafted[key].items()} }")
        if not any(counts.values()):
            failures.append(f"{key}: the plain view selected nothing")
        if shafted[key] != plain[key]:
            failures.append(f"{key}: the light-shaft view selected other ids")
    return scene.report(failures)


if __name__ == "__main__":
    scene.finish(main())
