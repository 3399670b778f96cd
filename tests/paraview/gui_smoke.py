"""Run inside the ParaView GUI (paraview --script=...): load the LightShafts plugin, create a
"Render View (Light Shafts)", show a source, switch the method and render; write what happened
to $LIGHTSHAFTS_SMOKE_OUT for run_gui_smoke.sh to check."""

import os

from paraview import simple

simple.LoadPlugin(os.environ["LIGHTSHAFTS_PARAVIEW_PLUGIN"], remote=False, ns=globals())
view = simple.CreateView("LightShaftsRenderView")
simple.Show(simple.Sphere())
view.ShaftMethod = "Ray March"
simple.Render(view)
with open(os.environ["LIGHTSHAFTS_SMOKE_OUT"], "w") as f:
    method = view.GetProperty("ShaftMethod").SMProperty.GetElement(0)
    f.write(f"{view.GetXMLName()} {method}\n")
