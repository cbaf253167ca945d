"""pvpython example: load the plugin, reconstruct a cloud with the PointCloudSurface filters
(those this build has), measure each result with ReconstructionQuality and save a screenshot.

    eval "$(scripts/env.sh)"
    pvpython Examples/pvpython_reconstruct.py [cloud.vtp] [--screenshot out.png]

Without a cloud file, 5,000 random points on a sphere (PointSource) are used.
"""
import argparse
import os

from paraview import servermanager
from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, PointSource, Render,
                             ResetCamera, SaveScreenshot, Show, OpenDataFile)
import paraview.simple as simple

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("cloud", nargs="?")
parser.add_argument("--screenshot", default="pvpython_reconstruct.png")
args = parser.parse_args()

# The plugin autoloads when scripts/env.sh was evaluated; otherwise load it from the build.
if not hasattr(simple, "IncrementalDelaunay3D"):
    here = os.path.dirname(os.path.abspath(__file__))
    LoadPlugin(os.path.join(here, "..", "build", "lib", "paraview-plugins", "PointCloudSurface",
                            "PointCloudSurface.so"), ns=globals())

cloud = OpenDataFile(args.cloud) if args.cloud else PointSource(NumberOfPoints=5000, Radius=1.0)

# Every reconstruction proxy of the plugin that this build has.
methods = [name for name in ("PerimeterPeelSurface", "LocalOptimumGrowth", "CDTAdvancingFront",
                             "GreedySurfaceTriangulation", "IncrementalDelaunay3D")
           if hasattr(simple, name)]
last = None
for name in methods:
    surface = getattr(simple, name)(Input=cloud)
    quality = simple.ReconstructionQuality(Input=surface)
    quality.UpdatePipeline()
    fd = servermanager.Fetch(quality).GetFieldData()
    values = {key: fd.GetArray(key).GetTuple1(0) for key in
              ("NumberOfTriangles", "Coverage", "NumberOfBoundaryEdges", "Genus")}
    print("%-28s %7d triangles, coverage %.3f, %d boundary edges, genus %d"
          % (name, values["NumberOfTriangles"], values["Coverage"],
             values["NumberOfBoundaryEdges"], values["Genus"]))
    last = surface

view = GetActiveViewOrCreate("RenderView")
Show(last, view).SetRepresentationType("Surface With Edges")
ResetCamera(view)
Render(view)
SaveScreenshot(args.screenshot, view, ImageResolution=[800, 600])
print("wrote", args.screenshot)
