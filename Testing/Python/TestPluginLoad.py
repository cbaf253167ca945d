"""The ParaView plugin loads in pvpython and exposes IncrementalDelaunay3D with its 3 outputs."""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, PointSource

LoadPlugin(sys.argv[1], ns=globals())

source = PointSource(NumberOfPoints=500, Radius=1.0)
delaunay = IncrementalDelaunay3D(Input=source)  # noqa: F821 (defined by LoadPlugin)
for name in ("Dimension", "ProjectionPlane", "Tolerance", "GenerateTetrahedra",
             "GenerateVoronoi"):
    if name not in delaunay.ListProperties():
        print("FAILED: missing property", name)
        sys.exit(1)
delaunay.GenerateVoronoi = 1
delaunay.UpdatePipeline()
surface = servermanager.Fetch(delaunay, None, None, 0)
tets = servermanager.Fetch(delaunay, None, None, 1)
voronoi = servermanager.Fetch(delaunay, None, None, 2)
print("surface", surface.GetNumberOfPoints(), surface.GetNumberOfCells(),
      "tetrahedra", tets.GetNumberOfCells(), "voronoi", voronoi.GetNumberOfPoints())
if surface.GetNumberOfPoints() != 500 or tets.GetClassName() != "vtkUnstructuredGrid":
    sys.exit(1)
# Voronoi: one vertex per tetrahedron plus one ray end per hull triangle.
if voronoi.GetNumberOfPoints() != tets.GetNumberOfCells() + surface.GetNumberOfCells():
    sys.exit(1)
print("ok")
