# Runs inside the ParaView GUI (paraview --script=...), started by TestParaViewGUI.py. The plugin
# is NOT loaded here: it must have been autoloaded from PV_PLUGIN_CONFIG_FILE. Applies
# IncrementalDelaunay3D to the vertices of a UV sphere (its hull is that sphere), saves a
# screenshot of the render view to PCS_GUI_SCREENSHOT and quits; errors go to
# PCS_GUI_SCREENSHOT + ".error".
import os
import traceback

target = os.environ["PCS_GUI_SCREENSHOT"]
try:
    from paraview.simple import (GetActiveViewOrCreate, Render, ResetCamera, SaveScreenshot,
                                 Show, Sphere)
    import paraview.simple as simple

    if not hasattr(simple, "IncrementalDelaunay3D"):
        raise RuntimeError("IncrementalDelaunay3D is not defined: the plugin was not autoloaded")
    sphere = Sphere(ThetaResolution=24, PhiResolution=12, Radius=1.0)
    delaunay = simple.IncrementalDelaunay3D(Input=sphere)
    delaunay.GenerateTetrahedra = 0
    view = GetActiveViewOrCreate("RenderView")
    display = Show(delaunay, view)
    display.SetRepresentationType("Surface With Edges")
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [2.5, 3.0, 4.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(target, view, ImageResolution=[400, 400])
except Exception:
    with open(target + ".error", "w") as f:
        f.write(traceback.format_exc())
os._exit(0)  # quit the GUI at once (a clean exit is not reachable from its Python shell)
