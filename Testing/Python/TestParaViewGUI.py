"""The ParaView GUI starts with the plugin autoloaded, applies a filter from a script and saves a
screenshot, which must match the baseline Testing/Data/Baseline/TestParaViewGUI.png.

Usage: python3 TestParaViewGUI.py <paraview executable> <plugins.xml> <baseline.png> <output dir>
(run under an X server: ctest runs the suite under xvfb-run).
"""
import os
import subprocess
import sys

paraview, plugins_xml, baseline, outdir = sys.argv[1:5]
screenshot = os.path.join(outdir, "TestParaViewGUI.png")
for stale in (screenshot, screenshot + ".error"):
    if os.path.exists(stale):
        os.remove(stale)
env = dict(os.environ)
env["PV_PLUGIN_CONFIG_FILE"] = plugins_xml
env.pop("PV_PLUGIN_PATH", None)
env["PCS_GUI_SCREENSHOT"] = screenshot
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ParaViewGUIScript.py")
try:
    subprocess.run([paraview, "--dr", "--script=" + script], env=env, timeout=240,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
except subprocess.TimeoutExpired:
    print("FAILED: the ParaView GUI did not finish within 240 s")
    sys.exit(1)
if os.path.exists(screenshot + ".error"):
    print("FAILED: the GUI script failed:\n" + open(screenshot + ".error").read())
    sys.exit(1)
if not os.path.exists(screenshot):
    print("FAILED: no screenshot")
    sys.exit(1)

from vtkmodules.vtkImagingCore import vtkImageDifference  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

if not os.path.exists(baseline):
    print("FAILED: no baseline %s (the screenshot is %s)" % (baseline, screenshot))
    sys.exit(1)
readers = []
for path in (screenshot, baseline):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    readers.append(reader)
difference = vtkImageDifference()
difference.SetInputConnection(readers[0].GetOutputPort())
difference.SetImageConnection(readers[1].GetOutputPort())
difference.Update()
error = difference.GetThresholdedError()
print("image difference %g (threshold 10)" % error)
if error > 10:
    print("FAILED: the screenshot differs from the baseline")
    sys.exit(1)
print("ParaView GUI test passed")
