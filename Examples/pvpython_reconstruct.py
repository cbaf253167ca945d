"""pvpython example: load the plugin, reconstruct a cloud with every PointCloudSurface filter of
this build, measure each result with ReconstructionQuality and save a screenshot.

    eval "$(scripts/env.sh)"
    xvfb-run -a pvpython Examples/pvpython_reconstruct.py [cloud.vtp] [--screenshot out.png]

Without a cloud file, 5,000 random points on the unit sphere (a ProgrammableSource) are used.
Without the plugin autoloaded (scripts/env.sh), --plugin names PointCloudSurface.so (default:
the one of ./build). The screenshot (rendering needs an X display: xvfb-run -a) shows the last
filter's surface with its edges.
"""
import argparse
import os

from paraview import servermanager
from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, OpenDataFile, ProgrammableSource,
                             Render, ResetCamera, SaveScreenshot, Show)
import paraview.simple as simple

HERE = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("cloud", nargs="?", help="a point cloud file ParaView reads (.vtp, .vtk, ...)")
parser.add_argument("--screenshot", default="pvpython_reconstruct.png")
parser.add_argument("--plugin", default=os.path.join(
    HERE, "..", "build", "lib", "paraview-plugins", "PointCloudSurface", "PointCloudSurface.so"))
args = parser.parse_args()

# Autoloaded plugins define their proxies in paraview.simple; LoadPlugin(ns=globals()) here.
if not hasattr(simple, "IncrementalDelaunay3D"):
    LoadPlugin(args.plugin, ns=globals())


def proxy(name):
    """The function that creates the proxy ``name``, or None when the plugin lacks it."""
    return globals().get(name) or getattr(simple, name, None)


if args.cloud:
    cloud = OpenDataFile(args.cloud)
else:
    cloud = ProgrammableSource(OutputDataSetType="vtkPolyData")
    cloud.Script = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.util.numpy_support import numpy_to_vtk
p = np.random.default_rng(1).normal(size=(5000, 3))
p /= np.linalg.norm(p, axis=1)[:, None]
points = vtkPoints()
points.SetData(numpy_to_vtk(p, deep=True))
self.GetOutput().SetPoints(points)
"""

# Every reconstruction proxy of the plugin that this build has.
methods = [name for name in ("IncrementalDelaunay3D", "PerimeterPeelSurface", "LocalOptimumGrowth",
                             "CDTAdvancingFront", "GreedySurfaceTriangulation") if proxy(name)]
last = None
for name in methods:
    surface = proxy(name)(Input=cloud)
    quality = proxy("ReconstructionQuality")(Input=surface)
    quality.UpdatePipeline()
    fd = servermanager.Fetch(quality).GetFieldData()
    values = {key: fd.GetArray(key).GetTuple1(0) for key in
              ("NumberOfTriangles", "Coverage", "NumberOfBoundaryEdges", "Genus")}
    print("%-28s %7d triangles, coverage %.3f, %d boundary edges, genus %s"
          % (name, values["NumberOfTriangles"], values["Coverage"],
             values["NumberOfBoundaryEdges"],
             "%d" % values["Genus"] if values["Genus"] >= 0 else "n/a"))
    last = surface

view = GetActiveViewOrCreate("RenderView")
Show(last, view).SetRepresentationType("Surface With Edges")
ResetCamera(view)
Render(view)
SaveScreenshot(args.screenshot, view, ImageResolution=[800, 600])
print("wrote", args.screenshot)
