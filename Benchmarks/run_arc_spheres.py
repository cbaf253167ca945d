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

Printed per cloud: boundary edges, unused points, non-manifold edges; then the number of clouds
not closed and the total of boundary edges.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_arc_spheres.py \
      [--normals pca exact] [--counts 400 800] [--seeds 1 2 ... 20]
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from pointcloudsurface import vtkCDTAdvancingFront, vtkReconstructionQuality


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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--normals", nargs="+", choices=("pca", "exact"), default=["pca", "exact"])
    parser.add_argument("--counts", nargs="+", type=int, default=[400, 800])
    parser.add_argument("--seeds", nargs="+", type=int, default=list(range(1, 21)))
    args = parser.parse_args()
    for mode in args.normals:
        print("| normals | random points | seed | boundary edges | unused | non-manifold edges |")
        print("|---|---:|---:|---:|---:|---:|")
        open_clouds = total = 0
        for count in args.counts:
            for seed in args.seeds:
                points = sphere_with_arcs(count, 8, 60, seed)
                front = vtkCDTAdvancingFront()
                front.SetInputData(cloud(points, mode == "exact"))
                front.Update()
                quality = vtkReconstructionQuality()
                quality.SetInputData(front.GetOutput())
                quality.Update()
                fields = quality.GetOutput().GetFieldData()
                boundary = int(fields.GetArray("NumberOfBoundaryEdges").GetTuple1(0))
                nonmanifold = int(fields.GetArray("NumberOfNonManifoldEdges").GetTuple1(0))
                unused = front.GetNumberOfUnusedPoints()
                print("| %s | %d | %d | %d | %d | %d |" % (mode, count, seed, boundary, unused,
                                                          nonmanifold))
                open_clouds += 1 if boundary else 0
                total += boundary
        print("\n%s normals: %d of %d clouds not closed, %d boundary edges in all\n"
              % (mode, open_clouds, len(args.counts) * len(args.seeds), total))


if __name__ == "__main__":
    main()
