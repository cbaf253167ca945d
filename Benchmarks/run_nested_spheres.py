#!/usr/bin/env python3
"""Two concentric random spheres (radii 1 and 1 - gap, n points each, uniform by area) through
vtkLocalOptimumGrowth: are they two closed surfaces (no triangle with vertices on both, no boundary
edge, 2 (2n - 4) triangles)? Issue 5, task logsharp (Benchmarks/results/local_optimum.md).

  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_nested_spheres.py \
      --gap 0.1 --seeds 1-20
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import pointcloudsurface as pcs
from pointcloudsurface.arrays import points_to_polydata


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gap", type=float, default=0.1)
    parser.add_argument("--points", type=int, default=10000, help="per sphere")
    parser.add_argument("--seeds", default="1-20", help="first-last")
    args = parser.parse_args()
    first, last = (int(v) for v in args.seeds.split("-"))
    n = args.points
    spacing = np.sqrt(4.0 * np.pi / n)
    good = 0
    for seed in range(first, last + 1):
        rng = np.random.default_rng(seed)

        def sphere(count):
            x = rng.normal(size=(count, 3))
            return x / np.linalg.norm(x, axis=1)[:, None]

        x = np.r_[sphere(n), (1.0 - args.gap) * sphere(n)]
        growth = pcs.vtkLocalOptimumGrowth()
        growth.SetInputData(points_to_polydata(x, vertices=False))
        growth.Update()
        polys = growth.GetOutput().GetPolys()
        tri = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
        outer = (tri < n).sum(axis=1)
        joining = int(((outer == 1) | (outer == 2)).sum())
        edges = np.sort(np.r_[tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]], axis=1)
        _, counts = np.unique(edges, axis=0, return_counts=True)
        boundary = int((counts == 1).sum())
        separate = joining == 0 and boundary == 0 and len(tri) == 2 * (2 * n - 4)
        good += separate
        print("seed %d: %d triangles join the spheres, %d boundary edges, %d triangles, %d unused%s"
              % (seed, joining, boundary, len(tri), growth.GetNumberOfUnusedPoints(),
                 " (two closed spheres)" if separate else ""), flush=True)
    print("gap %.3f (%.2f mean spacings of the outer sphere): %d of %d clouds give two closed spheres"
          % (args.gap, args.gap / spacing, good, last - first + 1))


if __name__ == "__main__":
    main()
