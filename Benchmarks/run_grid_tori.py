"""Tori sampled on a regular (u, v) parameter grid (issue 5).

For every n and tube radius r: the n x n points ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),
u and v in steps of 2 pi / n, R = 1, meshed with the default parameters of each filter asked. A
run passes when the mesh is closed, manifold, one component of genus 1 and uses every point (then
it has 2 n^2 triangles). Printed per run: boundary edges b, genus g (when closed), unused points u,
components c, non-manifold edges nm, and the number of triangles not within one grid cell (skip:
a triangle spanning two rows or columns); then the failing runs per filter.

Usage (the build's Python package on PYTHONPATH):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_grid_tori.py \\
      --sizes 24,32,40,48,56,72 --radii 0.2,0.35,0.45,0.5,0.52,0.54,0.65 --filters log
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkObject, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import pointcloudsurface as pcs

FILTERS = {"log": pcs.vtkLocalOptimumGrowth, "cdt": pcs.vtkCDTAdvancingFront,
           "greedy": pcs.vtkGreedySurfaceTriangulation, "peel": pcs.vtkPerimeterPeelSurface}


def grid_torus(n, r, ring=1.0):
    v, u = np.meshgrid(np.arange(n) * 2 * np.pi / n, np.arange(n) * 2 * np.pi / n, indexing="ij")
    u, v = u.ravel(), v.ravel()  # point j * n + i: column i (u), row j (v)
    rho = ring + r * np.cos(v)
    return np.stack([rho * np.cos(u), rho * np.sin(u), r * np.sin(v)], axis=1)


def measure(tri, n):
    points = n * n
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    parent = np.arange(points)

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in unique:
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
    used = np.unique(tri)
    components = len({find(v) for v in used})
    boundary = int((count == 1).sum())
    euler = len(used) - len(unique) + len(tri)
    genus = (2 * components - euler) // 2 if boundary == 0 else None

    def within_cell(index):
        s = np.sort(index, axis=1)
        wraps = (s[:, 0] == 0) & (s[:, 2] == n - 1) & ((s[:, 1] == 0) | (s[:, 1] == n - 1))
        return (s[:, 2] - s[:, 0] <= 1) | wraps

    skip = int((~(within_cell(tri % n) & within_cell(tri // n))).sum())
    return dict(b=boundary, g=genus, u=points - len(used), c=components,
                nm=int((count > 2).sum()), skip=skip)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", default="24,32,40,48,56,72")
    parser.add_argument("--radii", default="0.2,0.35,0.45,0.5,0.52,0.54,0.65")
    parser.add_argument("--filters", default="log")
    args = parser.parse_args()
    vtkObject.GlobalWarningDisplayOff()
    filters = args.filters.split(",")
    failing = {name: 0 for name in filters}
    runs = 0
    for n in (int(s) for s in args.sizes.split(",")):
        for r in (float(s) for s in args.radii.split(",")):
            x = grid_torus(n, r)
            points = vtkPoints()
            points.SetData(numpy_to_vtk(np.ascontiguousarray(x), deep=1))
            cloud = vtkPolyData()
            cloud.SetPoints(points)
            row = []
            runs += 1
            for name in filters:
                f = FILTERS[name]()
                f.SetInputData(cloud)
                f.Update()
                polys = f.GetOutput().GetPolys()
                tri = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3) \
                    if polys.GetNumberOfCells() else np.zeros((0, 3), np.int64)
                m = measure(tri, n)
                ok = m["b"] == 0 and m["g"] == 1 and m["u"] == 0 and m["c"] == 1 and m["nm"] == 0
                failing[name] += 0 if ok else 1
                row.append("%s%s b%d g%s u%d c%d nm%d skip%d" % ("" if ok else "*", name, m["b"],
                           m["g"], m["u"], m["c"], m["nm"], m["skip"]))
            print("%2dx%-2d r %.2f  %s" % (n, n, r, " | ".join(row)), flush=True)
    print("failing runs of %d: %s" % (runs, ", ".join("%s %d" % kv for kv in failing.items())))


if __name__ == "__main__":
    main()
