"""Tori on regular (u, v) grids of every shape through vtkGreedySurfaceTriangulation (issue 7).

A grid torus is the most common way to make a torus, and a hard case for a greedy triangulation:
the sampling is anisotropic (spacing 2 pi (R + r cos v) / nu along u, 2 pi r / nv along v) and
full of exact ties (each cell an isosceles trapezoid with diagonals of equal length). Each grid
(R = 1) is meshed with the filter's defaults; a result is correct when it is closed, manifold,
one component, genus 1 and uses every point. Printed per failing grid: boundary edges, genus
(closed results), unused points, components; then the counts of open results and of closed
results of the wrong genus. Square grids of several filters: run_grid_tori.py.

Usage:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_greedy_grid_scan.py \
      [--rotate]
  nu = 24, 36, 48, 64, 96, nv = 12, 16, 24, 36, 48, r = 0.25, 0.4, 0.55, 0.7, the v grid shifted
  by 0 or half a step (200 grids); --rotate: each cloud turned and moved at random (numpy
  default_rng(3)) so that no grid line is axis-aligned.
"""
import argparse
import math

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import pointcloudsurface as pcs


def grid_torus(nu, nv, r, phase):
    u, v = np.meshgrid(np.arange(nu) * 2 * math.pi / nu,
                       (np.arange(nv) + phase) * 2 * math.pi / nv)
    u, v = u.ravel(), v.ravel()
    return np.c_[(1 + r * np.cos(v)) * np.cos(u), (1 + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def topology(mesh, n):
    """Boundary edges, non-manifold edges, components, genus (closed) and unused points, measured
    by vtkReconstructionQuality."""
    quality = pcs.vtkReconstructionQuality()
    quality.SetInputData(mesh)
    quality.Update()
    fd = quality.GetOutput().GetFieldData()

    def get(name):
        return fd.GetArray(name).GetTuple1(0)
    boundary = int(get("NumberOfBoundaryEdges"))
    g = get("Genus")
    genus = int(g) if boundary == 0 and g == g else None
    return (boundary, int(get("NumberOfNonManifoldEdges")), int(get("NumberOfConnectedComponents")),
            genus, n - int(get("NumberOfUsedPoints")))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rotate", action="store_true")
    args = parser.parse_args()
    grids = [(nu, nv, r, phase) for nu in [24, 36, 48, 64, 96] for nv in [12, 16, 24, 36, 48]
             for r in [0.25, 0.4, 0.55, 0.7] for phase in [0.0, 0.5]]
    rng = np.random.default_rng(3)
    wrong_genus = open_results = other = 0
    for nu, nv, r, phase in grids:
        x = grid_torus(nu, nv, r, phase)
        if args.rotate:
            q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
            x = x @ q + rng.normal(size=3) * 10
        points = vtkPoints()
        points.SetData(numpy_to_vtk(np.ascontiguousarray(x), deep=1))
        cloud = vtkPolyData()
        cloud.SetPoints(points)
        greedy = pcs.vtkGreedySurfaceTriangulation()
        greedy.SetInputData(cloud)
        greedy.Update()
        out = greedy.GetOutput()
        boundary, nonmanifold, components, genus, unused = topology(out, out.GetNumberOfPoints())
        if boundary == 0 and nonmanifold == 0 and components == 1 and genus == 1 and unused == 0:
            continue
        if boundary == 0 and genus is not None and genus != 1:
            wrong_genus += 1
        elif boundary > 0:
            open_results += 1
        else:
            other += 1
        print("%3d x %3d r %.2f shift %.1f: boundary edges %d, genus %s, unused %d, components %d"
              % (nu, nv, r, phase, boundary, genus, unused, components), flush=True)
    print("%d grids: %d open, %d closed with the wrong genus, %d other failures"
          % (len(grids), open_results, wrong_genus, other))


if __name__ == "__main__":
    main()
