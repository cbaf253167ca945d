"""The wrapped filter in a vtkmodules pipeline: counts known by construction."""
import math
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPointSource

from pointcloudsurface import vtkIncrementalDelaunay3D


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


# A random ball through the pipeline: every point passes, tetrahedra are produced.
source = vtkPointSource()
source.SetNumberOfPoints(2000)
source.SetRadius(1.0)
delaunay = vtkIncrementalDelaunay3D()
delaunay.SetInputConnection(source.GetOutputPort())
delaunay.Update()
check(delaunay.GetOutput().GetNumberOfPoints() == 2000, "points pass through")
tets = delaunay.GetOutputDataObject(1)
check(tets.GetNumberOfCells() == delaunay.GetNumberOfCells() > 0, "tetrahedra")
check(tets.GetCellData().GetArray("Circumradius") is not None, "Circumradius")

# The 8 corners of a cube and its centre: the hull is the cube (12 triangles), its volume 1.
points = vtkPoints()
for corner in range(8):
    points.InsertNextPoint(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1)
points.InsertNextPoint(0.5, 0.5, 0.5)
cube = vtkPolyData()
cube.SetPoints(points)
delaunay = vtkIncrementalDelaunay3D()
delaunay.SetInputData(cube)
delaunay.Update()
check(delaunay.GetOutput().GetNumberOfCells() == 12, "cube hull has 12 triangles")
grid = delaunay.GetOutputDataObject(1)
volume = 0.0
for c in range(grid.GetNumberOfCells()):
    ids = grid.GetCell(c).GetPointIds()
    p = [grid.GetPoint(ids.GetId(k)) for k in range(4)]
    u = [p[1][i] - p[0][i] for i in range(3)]
    v = [p[2][i] - p[0][i] for i in range(3)]
    w = [p[3][i] - p[0][i] for i in range(3)]
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    check(det > 0, "VTK-positive tetrahedron")
    volume += det / 6.0
check(math.isclose(volume, 1.0, rel_tol=1e-12), "cube volume %g" % volume)

# 2.5D mode on a 10 x 10 grid: 2n - 2 - h = 200 - 2 - 36 = 162 triangles.
points = vtkPoints()
for i in range(10):
    for j in range(10):
        points.InsertNextPoint(i, j, 0.1 * i * j)
terrain = vtkPolyData()
terrain.SetPoints(points)
delaunay = vtkIncrementalDelaunay3D()
delaunay.SetInputData(terrain)
delaunay.SetDimension(2)
delaunay.Update()
check(delaunay.GetOutput().GetNumberOfCells() == 162, "grid terrain triangles")
print("ok")
