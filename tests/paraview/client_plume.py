"""examples/paraview/smoke_plume.py through a pvserver (its plume made on the server, the view's
MediumDensity) or in a builtin session, for the client-server test (run_client_server.sh).

    pvpython client_plume.py HOST PORT OUTPUT.png [--fxaa] [the example's options]   (a client)
    pvbatch client_plume.py builtin OUTPUT.png [--fxaa] [the example's options]      (serial)

Remote rendering is forced (the medium lives where the data does: on the server) and the plugin
is loaded on both sides. Through a pvserver, the picture saved, a bad array name and a NaN
exposure are then set, for the test to find the server's messages in the client's output.
ParaView's FXAA is off unless --fxaa is given (the render view settings' UseFXAA).
"""

import os
import runpy
import sys

# pvpython puts its own prefix's dist-packages before PYTHONPATH: where that holds another VTK's
# vtkmodules (Debian 12's python3-vtk9 beside the unpacked python3-paraview), ParaView's must come
# first.
for entry in reversed(os.environ.get("PYTHONPATH", "").split(os.pathsep)):
    if entry:
        sys.path.insert(0, entry)
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lightshafts_pvscene as scene  # noqa: E402


def main():
    from paraview import simple
    arguments = sys.argv[1:]
    remote = arguments[0] != "builtin"
    if remote:
        simple.Connect(arguments[0], int(arguments[1]))
        simple.LoadPlugin(scene.plugin_path(), remote=True)  # (the example loads it locally)
        arguments = arguments[2:]
    else:
        arguments = arguments[1:]
    settings = simple.GetSettingsProxy("RenderViewSettings")
    settings.RemoteRenderThreshold = 0.0
    fxaa = "--fxaa" in arguments
    if fxaa:
        arguments.remove("--fxaa")
    settings.UseFXAA = int(fxaa)
    sys.argv = [sys.argv[0], "-o", arguments[0], "--size", "400", "300"] + arguments[1:]
    runpy.run_path(os.path.join(HERE, "..", "..", "examples", "paraview", "smoke_plume.py"))
    if remote:
        # Bad input on the server's objects: its messages reach the client's output.
        view = simple.GetActiveView()
        view.MediumDensityArray = "no-such-array"
        simple.Render(view)
        view.ShaftExposure = float("nan")
        simple.Render(view)
        simple.Disconnect()
    return 0


if __name__ == "__main__":
    scene.finish(main())
