"""Coordinates far from 1 (2^+-700): the exact predicates must not overflow or underflow.

Scaling a cloud by a power of two is exact, so the triangulation of the scaled cloud must have
exactly the same tetrahedra (3D) and triangles (2.5D) as the original.
"""
import math
import random
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from pointcloudsurface import vtkIncrementalDelaunay3D


def cloud(coordinates):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for p in coordinates:
        points.InsertNextPoint(p)
    data = vtkPolyData()
    data.SetPoints(points)
    return data


def cells(coordinates, dimension):
    delaunay = vtkIncrementalDelaunay3D()
    delaunay.SetInputData(cloud(coordinates))
    delaunay.SetDimension(dimension)
    delaunay.Update()
    grid = delaunay.GetOutputDataObject(1)
    result = set()
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        result.add(tuple(sorted(ids.GetId(k) for k in range(ids.GetNumberOfIds()))))
    radius = grid.GetCellData().GetArray("Circumradius")
    return result, [radius.GetValue(c) for c in range(grid.GetNumberOfCells())]


rng = random.Random(4)
base = [(rng.random(), rng.random(), rng.random()) for _ in range(2000)]
failed = False
for dimension in (3, 2):
    reference, radii = cells(base, dimension)
    for exponent in (700, -700, 900, -900):
        scaled = [tuple(math.ldexp(c, exponent) for c in p) for p in base]
        result, scaled_radii = cells(scaled, dimension)
        same = result == reference
        print("dimension %d, scale 2^%d: %d cells, same as unscaled: %s"
              % (dimension, exponent, len(result), same))
        failed = failed or not same
        if dimension == 3 and same:
            # Circumradius is reported in the input's units.
            worst = max(abs(math.ldexp(r, -exponent) / r0 - 1.0)
                        for r, r0 in zip(sorted(scaled_radii), sorted(radii)) if r0 > 0)
            failed = failed or worst > 1e-9


def voronoi_vertices(coordinates):
    delaunay = vtkIncrementalDelaunay3D()
    delaunay.SetInputData(cloud(coordinates))
    delaunay.GenerateVoronoiOn()
    delaunay.Update()
    diagram = delaunay.GetOutputDataObject(2)
    return [diagram.GetPoint(i) for i in range(diagram.GetNumberOfPoints())]


# The Voronoi vertices of the scaled cloud are the scaled vertices (no overflow on the way).
reference = voronoi_vertices(base[:300])
for exponent in (700, -700):
    scaled = voronoi_vertices([tuple(math.ldexp(c, exponent) for c in p) for p in base[:300]])
    same = len(scaled) == len(reference) and all(
        math.ldexp(q[k], -exponent) == p[k] for p, q in zip(reference, scaled) for k in range(3))
    print("Voronoi, scale 2^%d: %d vertices, equal after unscaling: %s"
          % (exponent, len(scaled), same))
    failed = failed or not same
sys.exit(1 if failed else 0)
