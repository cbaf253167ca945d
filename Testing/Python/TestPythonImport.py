"""`from pointcloudsurface import vtkIncrementalDelaunay3D` works in a vtkmodules pipeline.

Run by /usr/bin/python3 and by pvpython with PYTHONPATH=<build>/lib/python3/dist-packages.
"""
import sys

from vtkmodules.vtkFiltersSources import vtkPointSource

from pointcloudsurface import vtkIncrementalDelaunay3D


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


source = vtkPointSource()
source.SetNumberOfPoints(100)
source.SetRadius(1.0)

delaunay = vtkIncrementalDelaunay3D()
check(delaunay.GetDimension() == 3, "default Dimension is 3")
check(not delaunay.GetGenerateVoronoi(), "GenerateVoronoi is off by default")
delaunay.SetInputConnection(source.GetOutputPort())
delaunay.Update()

surface = delaunay.GetOutput()
tetrahedra = delaunay.GetOutputDataObject(1)
check(surface.GetNumberOfPoints() == 100, "surface has the 100 input points (got %d)"
      % surface.GetNumberOfPoints())
check(tetrahedra.IsA("vtkUnstructuredGrid"), "output 1 is a vtkUnstructuredGrid")
check(tetrahedra.GetNumberOfPoints() == 100, "tetrahedra output has the 100 input points")
check(tetrahedra.GetNumberOfCells() > 0, "tetrahedra are produced")
check(surface.GetNumberOfCells() > 0, "hull triangles are produced")
print("python", sys.version.split()[0], "points", surface.GetNumberOfPoints(),
      "hull triangles", surface.GetNumberOfCells(), "tetrahedra", tetrahedra.GetNumberOfCells())
print("ok")
