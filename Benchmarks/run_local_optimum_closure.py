"""Closure of vtkLocalOptimumGrowth on random (Poisson) samples of closed surfaces (issue 5).

For every size N and seed s: N points uniform by area on the unit sphere (normalized Gaussian
vectors, numpy's default_rng(s)) or on the torus of radii 1 and 0.35 (angles uniform, rejection
on the tube angle), meshed with the default parameters. A run fails when the mesh is not closed
(boundary edges), leaves a point unused, or has the wrong number of triangles (2N - 4 for the
sphere, 2N for the torus: a closed manifold mesh over every point with another count has another
genus). Printed: each failing run, and per shape the number of failing runs.

Usage (the build's Python package on PYTHONPATH; LD_LIBRARY_PATH may point at another build of
the library to compare):
  PYTHONPATH=build-log/lib/python3/dist-packages /usr/bin/python3 \\
      Benchmarks/run_local_optimum_closure.py --sizes 2000,5000,10000,20000 --seeds 1-50
"""
import argparse
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkObject, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from pointcloudsurface import vtkLocalOptimumGrowth


def sample(shape, n, seed):
    rng = np.random.default_rng(seed)
    if shape == "sphere":
        p = rng.normal(size=(n, 3))
        return p / np.linalg.norm(p, axis=1)[:, None]
    points = []
    count = 0
    while count < n:
        a, b, r = rng.uniform(0.0, 2.0 * np.pi, 2 * n), rng.uniform(0.0, 2.0 * np.pi, 2 * n), \
            rng.uniform(0.0, 1.35, 2 * n)
        keep = r <= 1.0 + 0.35 * np.cos(b)
        a, b = a[keep], b[keep]
        rho = 1.0 + 0.35 * np.cos(b)
        points.append(np.stack([rho * np.cos(a), rho * np.sin(a), 0.35 * np.sin(b)], axis=1))
        count += len(a)
    return np.concatenate(points)[:n]


def run(points):
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(vtk_points)
    growth = vtkLocalOptimumGrowth()
    growth.SetInputData(cloud)
    growth.Update()
    return growth


def seeds(text):
    first, _, last = text.partition("-")
    return range(int(first), int(last or first) + 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="2000,5000,10000,20000")
    parser.add_argument("--seeds", default="1-50", help="first-last")
    parser.add_argument("--shapes", default="sphere,torus")
    args = parser.parse_args()
    vtkObject.GlobalWarningDisplayOff()
    for shape in args.shapes.split(","):
        failed = total = 0
        for n in (int(x) for x in args.sizes.split(",")):
            for s in seeds(args.seeds):
                growth = run(sample(shape, n, s))
                expected = 2 * n - 4 if shape == "sphere" else 2 * n
                total += 1
                if (growth.GetNumberOfBoundaryEdges() or growth.GetNumberOfUnusedPoints() or
                        growth.GetNumberOfTriangles() != expected):
                    failed += 1
                    print("%s %d seed %d: %d triangles (closed: %d), %d boundary edges, %d unused"
                          % (shape, n, s, growth.GetNumberOfTriangles(), expected,
                             growth.GetNumberOfBoundaryEdges(), growth.GetNumberOfUnusedPoints()),
                          flush=True)
        print("%s: %d of %d runs not closed over every point with the right genus"
              % (shape, failed, total), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
