#!/usr/bin/env python3
"""Spheres sampled with dense arcs: the holes vtkCDTAdvancingFront leaves along dense rows.

A mesh's vertex set or a profile scan often has rows of points much denser along the row than
across it (the rings of a surface of revolution, scan lines). Each cloud here is the unit sphere
sampled with COUNT random points plus 8 random great-circle arcs of 60 points (0.5 to 2 radians
long, 3 to 15 times denser along the arc than the random points), numpy's RandomState(seed), as
Testing/Python/TestCDTAdvancingFront.py builds its arc clouds. The true answer is known: a closed,
manifold, genus-0 mesh that uses every point (2V - 4 triangles).

With exact normals the arcs are a degenerate case of the paper's rule II.D.1: an arc point's
normal lies in its arc's plane, so the point between two arc points projects onto the chord
joining them, and a triangle on that chord is not blocked by it.

Printed per cloud: boundary edges, unused points, non-manifold edges, and two counts of
triangles that stand across the sphere: those whose three points lie on one arc (nearly collinear:
a sliver in the arc's plane, which holds the sphere's centre, so it is never a face of the
sphere's Delaunay triangulation) and those whose normal is more than 60 degrees from the
sphere's; then totals. The other filters (--filters) read no normals: they run once, with
"pca" in the table.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_arc_spheres.py \
      [--filters cdt log greedy peel] [--normals pca exact] [--counts 400 800] [--seeds 1 2 ... 20]
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import pointcloudsurface as pcs

FILTERS = {"cdt": pcs.vtkCDTAdvancingFront, "log": pcs.vtkLocalOptimumGrowth,
           "greedy": pcs.vtkGreedySurfaceTriangulation, "peel": pcs.vtkPerimeterPeelSurface}
ARCS, PER_ARC = 8, 60


def sphere_with_arcs(count, arcs, per_arc, seed):
    """COUNT random unit-sphere points and ARCS great-circle arcs of PER_ARC points."""
    random = np.random.RandomState(seed)
    points = random.normal(size=(count, 3))
    points /= np.linalg.norm(points, axis=1)[:, None]
    rows = [points]
    for _ in range(arcs):
        a = random.normal(size=3)
        a /= np.linalg.norm(a)
        b = random.normal(size=3)
        b -= (b @ a) * a
        b /= np.linalg.norm(b)
        t = random.uniform(0, 2 * np.pi) + np.linspace(0, random.uniform(0.5, 2.0), per_arc)
        rows.append(np.outer(np.cos(t), a) + np.outer(np.sin(t), b))
    return np.vstack(rows)


def cloud(points, with_normals):
    poly = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    poly.SetPoints(vtk_points)
    if with_normals:
        normals = numpy_to_vtk(np.ascontiguousarray(points), deep=1)  # the unit sphere's
        normals.SetName("Normals")
        poly.GetPointData().SetNormals(normals)
    return poly


def standing_triangles(mesh, count):
    """(triangles of three points of one arc, triangles over 60 degrees to the sphere)."""
    points = vtk_to_numpy(mesh.GetPoints().GetData())
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    arc = np.where((triangles >= count) & (triangles < count + ARCS * PER_ARC),
                   (triangles - count) // PER_ARC, -1 - triangles)  # distinct if not on an arc
    one_arc = int(np.count_nonzero((arc[:, 0] == arc[:, 1]) & (arc[:, 1] == arc[:, 2])))
    a, b, c = (points[triangles[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a)
    centroid = (a + b + c) / 3.0
    cosine = np.abs(np.einsum("ij,ij->i", normal, centroid)) / (
        np.linalg.norm(normal, axis=1) * np.linalg.norm(centroid, axis=1))
    return one_arc, int(np.count_nonzero(cosine < 0.5))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--filters", nargs="+", choices=sorted(FILTERS), default=["cdt"])
    parser.add_argument("--normals", nargs="+", choices=("pca", "exact"), default=["pca", "exact"])
    parser.add_argument("--counts", nargs="+", type=int, default=[400, 800])
    parser.add_argument("--seeds", nargs="+", type=int, default=list(range(1, 21)))
    args = parser.parse_args()
    totals = []
    for name in args.filters:
        for mode in args.normals if name == "cdt" else ["pca"]:
            print("| filter | normals | random points | seed | boundary edges | unused | "
                  "non-manifold edges | one-arc triangles | over 60 degrees |")
            print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
            open_clouds = boundary_total = one_arc_total = standing_total = unused_total = 0
            for count in args.counts:
                for seed in args.seeds:
                    points = sphere_with_arcs(count, ARCS, PER_ARC, seed)
                    surface = FILTERS[name]()
                    surface.SetInputData(cloud(points, mode == "exact"))
                    surface.Update()
                    quality = pcs.vtkReconstructionQuality()
                    quality.SetInputData(surface.GetOutput())
                    quality.Update()
                    fields = quality.GetOutput().GetFieldData()
                    boundary = int(fields.GetArray("NumberOfBoundaryEdges").GetTuple1(0))
                    nonmanifold = int(fields.GetArray("NumberOfNonManifoldEdges").GetTuple1(0))
                    unused_array = surface.GetOutput().GetFieldData().GetArray(
                        "NumberOfUnusedPoints")
                    unused = int(unused_array.GetTuple1(0))
                    one_arc, standing = standing_triangles(surface.GetOutput(), count)
                    print("| %s | %s | %d | %d | %d | %d | %d | %d | %d |" % (
                        name, mode, count, seed, boundary, unused, nonmanifold, one_arc, standing))
                    open_clouds += 1 if boundary else 0
                    boundary_total += boundary
                    one_arc_total += one_arc
                    standing_total += standing
                    unused_total += unused
            totals.append((name, mode, open_clouds, len(args.counts) * len(args.seeds),
                           boundary_total, unused_total, one_arc_total, standing_total))
            print()
    print("| filter | normals | clouds not closed | boundary edges | unused | one-arc triangles | "
          "over 60 degrees |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name, mode, open_clouds, clouds, boundary, unused, one_arc, standing in totals:
        print("| %s | %s | %d of %d | %d | %d | %d | %d |" % (
            name, mode, open_clouds, clouds, boundary, unused, one_arc, standing))


if __name__ == "__main__":
    main()
