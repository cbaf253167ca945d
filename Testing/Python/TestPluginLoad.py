"""The ParaView plugin loads in pvpython and IncrementalDelaunay3D runs with its 3 outputs.

Usage: pvpython TestPluginLoad.py <path to PointCloudSurface.so>
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, PointSource


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


LoadPlugin(sys.argv[1], ns=globals())
check("IncrementalDelaunay3D" in globals(), "LoadPlugin defines IncrementalDelaunay3D")

source = PointSource(NumberOfPoints=500, Radius=1.0)
delaunay = IncrementalDelaunay3D(Input=source)  # noqa: F821 (defined by LoadPlugin)

# Every property of the XML, with the class defaults (enumerations read back as their labels).
defaults = {"Dimension": "3D", "ProjectionPlane": "XY plane", "Tolerance": 0.0,
            "GenerateTetrahedra": 1, "GenerateVoronoi": 0}
for name, value in defaults.items():
    check(name in delaunay.ListProperties(), "property %s exists" % name)
    check(delaunay.GetPropertyValue(name) == value, "default of %s is %s (got %s)"
          % (name, value, delaunay.GetPropertyValue(name)))
entries = list(delaunay.GetProperty("Dimension").Available)
check(entries == ["2.5D (terrain)", "3D"], "Dimension entries (got %s)" % entries)
check(delaunay.GetNumberOfOutputPorts() == 3, "3 output ports")
check([delaunay.GetOutputPortName(i) for i in range(3)] == ["Surface", "Tetrahedra", "Voronoi"],
      "output port names")

delaunay.GenerateVoronoi = 1
delaunay.UpdatePipeline()
surface = servermanager.Fetch(delaunay, None, None, 0)
tetrahedra = servermanager.Fetch(delaunay, None, None, 1)
voronoi = servermanager.Fetch(delaunay, None, None, 2)
print("surface", surface.GetNumberOfPoints(), surface.GetNumberOfCells(),
      "tetrahedra", tetrahedra.GetNumberOfCells(), "voronoi", voronoi.GetNumberOfPoints())
check(surface.GetNumberOfPoints() == 500, "the 500 points pass through")
check(tetrahedra.IsA("vtkUnstructuredGrid"), "output 1 is a vtkUnstructuredGrid")
check(tetrahedra.GetNumberOfCells() > 0, "tetrahedra are produced")
check(surface.GetNumberOfCells() > 0, "hull triangles are produced")
# Voronoi: one vertex per tetrahedron plus one ray end per hull triangle.
check(voronoi.GetNumberOfPoints() == tetrahedra.GetNumberOfCells() + surface.GetNumberOfCells(),
      "Voronoi vertex count")
print("ok")
