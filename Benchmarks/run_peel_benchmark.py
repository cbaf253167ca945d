"""Peeling time against tetrahedralization time for vtkPerimeterPeelSurface (issue 4).

The filter reports both in its field data: DelaunayTime (the exact tetrahedralization of the
vtkIncrementalDelaunay3D kernel) and PeelTime (everything after it: peeling, group removals,
output). This script runs the filter on random samples of a sphere and of a torus (ring radius
1, tube radius 0.35, uniform by area) of N points, one run per cloud, and prints both times, their
ratio (the issue asks for PeelTime <= 0.5 x DelaunayTime at 10^6 points) and the topology of the
result (vtkReconstructionQuality: genus, coverage, non-manifold vertices). Timings on a shared
machine: report the `uptime` load with them (printed first).

Usage (a build with the Python package, e.g. build-peel):
  PYTHONPATH=build-peel/lib/python3/dist-packages \\
      /usr/bin/python3 Benchmarks/run_peel_benchmark.py [--points 1000000] [--json out.json]
"""
import argparse
import json
import math
import os
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from pointcloudsurface import vtkPerimeterPeelSurface, vtkReconstructionQuality


def sphere(n, rng):
    p = rng.normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1)[:, None]


def torus(n, rng, ring=1.0, tube=0.35):
    out = np.empty((0, 3))
    while len(out) < n:
        a, b, u = rng.random((3, 2 * n)) * np.array([[2 * math.pi], [2 * math.pi], [1.0]])
        keep = u <= (ring + tube * np.cos(b)) / (ring + tube)  # area-uniform by rejection
        r = ring + tube * np.cos(b[keep])
        out = np.vstack([out, np.c_[r * np.cos(a[keep]), r * np.sin(a[keep]),
                                    tube * np.sin(b[keep])]])
    return out[:n]


def cloud(xyz):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz, dtype=float), deep=1))
    data = vtkPolyData()
    data.SetPoints(points)
    return data


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetTuple1(0) if array else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--shapes", default="sphere,torus")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", help="also write the results to this file")
    args = parser.parse_args()
    load = os.getloadavg()
    print("load average %.2f %.2f %.2f, %d cores" % (load + (os.cpu_count(),)))
    results = []
    for shape in args.shapes.split(","):
        xyz = {"sphere": sphere, "torus": torus}[shape](args.points,
                                                        np.random.default_rng(args.seed))
        peel = vtkPerimeterPeelSurface()
        peel.SetInputData(cloud(xyz))
        start = time.perf_counter()
        peel.Update()
        wall = time.perf_counter() - start
        out = peel.GetOutput()
        quality = vtkReconstructionQuality()
        quality.SetInputData(out)
        quality.ComputeDistancesOff()
        quality.Update()
        q = quality.GetOutput()
        row = {
            "shape": shape, "points": args.points, "wall_s": wall,
            "delaunay_s": field(out, "DelaunayTime"), "peel_s": field(out, "PeelTime"),
            "groups": field(out, "NumberOfGroupRemovals"),
            "genus": field(q, "Genus"), "coverage": field(q, "Coverage"),
            "non_manifold_vertices": field(q, "NumberOfNonManifoldVertices"),
        }
        row["ratio"] = row["peel_s"] / row["delaunay_s"]
        results.append(row)
        print("%-6s %8d points: Delaunay %.2f s, peel %.2f s, peel/Delaunay %.2f; genus %d, "
              "coverage %.4f, %d groups, %d non-manifold vertices"
              % (shape, args.points, row["delaunay_s"], row["peel_s"], row["ratio"],
                 row["genus"], row["coverage"], row["groups"], row["non_manifold_vertices"]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"load": load, "results": results}, f, indent=1)


if __name__ == "__main__":
    main()
