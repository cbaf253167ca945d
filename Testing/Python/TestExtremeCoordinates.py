"""Coordinates far from 1 (2^+-700): the exact predicates must not overflow or underflow.

Scaling a cloud by a power of two is exact, so the triangulation of the scaled cloud must have
exactly the same tetrahedra (3D) and triangles (2.5D) as the original.

A small object far from the origin (spheres of radius 10^-7 centred 10 and 1000 units away, of
10^-3 at 1.7 x 10^5: the spacing is 10^-12 to 10^-10 of the coordinates, still 4-6 significant
digits of a double) must come out of every surface filter closed, manifold, of genus 0 and using
every point. Constructions along short directions (a cross product of short edges added to a
point) must not be rounded away there: vtkCDTAdvancingFront made 1,456 of the 5,996 triangles of
the first sphere before they were scaled up (pcs::projected::EdgePlaneSide).

Two objects of very different scales in one cloud (a unit sphere and, 5 units away, a sphere 10^3
or 10^4 times smaller, 10,000 points each: the small one's spacing is 10^-3 to 10^-4 of the mean)
must come out of every surface filter as two closed, manifold components of genus 0 using every
point (2 x 20,000 - 8 triangles): vtkCDTAdvancingFront's automatic neighbourhood radius, taken from
the mean spacing, held the whole small sphere in every ring of candidates and left holes and 121
unused points there until the radius followed the local spacing of parts 64 times denser than the
mean (DenseSpacingRatio).
"""
import math
import random
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from pointcloudsurface import (vtkCDTAdvancingFront, vtkGreedySurfaceTriangulation,
                               vtkIncrementalDelaunay3D, vtkLocalOptimumGrowth,
                               vtkPerimeterPeelSurface, vtkReconstructionQuality)


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


def quality(mesh):
    check = vtkReconstructionQuality()
    check.SetInputData(mesh)
    check.Update()
    data = check.GetOutput().GetFieldData()
    return {name: data.GetArray(name).GetValue(0) for name in
            ("NumberOfBoundaryEdges", "NumberOfNonManifoldEdges", "NumberOfNonManifoldVertices",
             "Genus", "NumberOfUnusedPoints", "NumberOfConnectedComponents")}


def unit_sphere(count):
    """count points uniform on the unit sphere (normalised Gaussian triples)."""
    points = []
    while len(points) < count:
        g = [rng.gauss(0.0, 1.0) for _ in range(3)]
        length = math.sqrt(sum(c * c for c in g))
        if length > 1e-3:
            points.append([c / length for c in g])
    return points


def closed_spheres(coordinates, components, label):
    """Whether every surface filter makes `components` closed, manifold spheres of
    `coordinates`, using every point (2 V - 4 components triangles)."""
    good_all = True
    for make in (vtkPerimeterPeelSurface, vtkLocalOptimumGrowth, vtkCDTAdvancingFront,
                 vtkGreedySurfaceTriangulation):
        surface = make()
        surface.SetInputData(cloud(coordinates))
        surface.Update()
        mesh = surface.GetOutput()
        q = quality(mesh)
        triangles = mesh.GetNumberOfPolys()
        good = (q["NumberOfBoundaryEdges"] == 0 and q["NumberOfNonManifoldEdges"] == 0 and
                q["NumberOfNonManifoldVertices"] == 0 and q["Genus"] == 0 and
                q["NumberOfConnectedComponents"] == components and
                q["NumberOfUnusedPoints"] == 0 and
                triangles == 2 * len(coordinates) - 4 * components)
        print("%s, %s: %d triangles, %s -> %s"
              % (label, make.__name__, triangles, q, "ok" if good else "FAILED"))
        good_all = good_all and good
    return good_all


# Small spheres far from the origin.
unit = unit_sphere(3000)
for radius, centre in ((1e-7, (10.0, -20.0, 5.0)), (1e-7, (1000.0, 0.0, 0.0)),
                       (1e-3, (1e5, 1e5, -1e5))):
    small = [tuple(centre[k] + radius * p[k] for k in range(3)) for p in unit]
    failed = not closed_spheres(small, 1, "sphere of radius %g at %s" % (radius, centre)) or failed
# Two scales in one cloud.
many = unit_sphere(10000)
for scale in (1e-3, 1e-4):
    both = [tuple(p) for p in many] + [(5.0 + scale * p[0], scale * p[1], scale * p[2])
                                       for p in many]
    failed = not closed_spheres(
        both, 2, "unit sphere and a sphere %g times its size" % scale) or failed
sys.exit(1 if failed else 0)
