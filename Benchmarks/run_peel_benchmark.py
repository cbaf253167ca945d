"""Peeling time against tetrahedralization time for vtkPerimeterPeelSurface (issue 4).

The filter reports both in its field data: DelaunayTime (the exact tetrahedralization of the
vtkIncrementalDelaunay3D kernel) and PeelTime (everything after it: peeling, group removals,
output). This script runs the filter on random samples of a sphere and of a torus (ring radius
1, tube radius 0.35, uniform by area) of N points, one run per cloud, and prints both times, their
ratio (the issue asks for PeelTime <= 0.5 x DelaunayTime at 10^6 points) and the topology of the
result (vtkReconstructionQuality: genus, coverage, non-manifold vertices). Timings on a shared
machine: report the `uptime` load with them (printed first). The filter also reports the
processor time of both parts (DelaunayCPUTime, PeelCPUTime; the filter is sequential), which a
loaded machine inflates less than the wall times: printed as "CPU".

With --meshes, it runs instead on the vertex sets of real meshes of Debian's libcgal-demo data
(--data: the unpacked data.tar.gz, see run_reconstruction_benchmark.py) and measures the result
against the mesh itself (vtkReconstructionQuality: coverage, non-manifold edges and vertices,
boundary edges, genus of the result and of the mesh, Hausdorff distance in mean spacings).

Usage (a build with the Python package, e.g. build-peel):
  PYTHONPATH=build-peel/lib/python3/dist-packages \\
      /usr/bin/python3 Benchmarks/run_peel_benchmark.py [--points 1000000] [--json out.json]
  PYTHONPATH=build-peel/lib/python3/dist-packages \\
      /usr/bin/python3 Benchmarks/run_peel_benchmark.py --data /tmp/cgal/data \\
      --meshes bunny00,armadillo,camel,elephant,refined_elephant,fandisk_large,knot1
"""
import argparse
import json
import math
import os
import sys
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


def quality(mesh, reference=None):
    q = vtkReconstructionQuality()
    q.SetInputData(0, mesh)
    if reference is None:
        q.ComputeDistancesOff()
    else:
        q.SetInputData(1, reference)
    q.Update()
    return q.GetOutput()


def mesh_rows(args):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from run_reconstruction_benchmark import mesh_from_arrays, read_off

    rows = []
    for name in args.meshes.split(","):
        p, t = read_off(os.path.join(args.data, "meshes", name + ".off"))
        reference = mesh_from_arrays(p, t)
        peel = vtkPerimeterPeelSurface()
        peel.SetInputData(cloud(p))
        peel.Update()
        out = peel.GetOutput()
        q = quality(out, reference)
        r = quality(reference)
        row = {
            "mesh": name, "points": len(p), "delaunay_s": field(out, "DelaunayTime"),
            "peel_s": field(out, "PeelTime"), "groups": field(out, "NumberOfGroupRemovals"),
            "coverage": field(q, "Coverage"),
            "non_manifold_edges": field(q, "NumberOfNonManifoldEdges"),
            "non_manifold_vertices": field(q, "NumberOfNonManifoldVertices"),
            "boundary_edges": field(q, "NumberOfBoundaryEdges"),
            "genus": field(q, "Genus"), "reference_genus": field(r, "Genus"),
            "hausdorff_spacings": field(q, "HausdorffOverSpacing"),
        }
        row["ok"] = (row["non_manifold_edges"] == 0 and row["non_manifold_vertices"] == 0 and
                     row["coverage"] >= 0.97 and row["hausdorff_spacings"] <= 4.0)
        rows.append(row)
        print("| %s | %d | %.4f | %d / %d | %d | %d (%d) | %.2f | %.2f / %.2f | %s |"
              % (name, len(p), row["coverage"], row["non_manifold_edges"],
                 row["non_manifold_vertices"], row["boundary_edges"], row["genus"],
                 row["reference_genus"], row["hausdorff_spacings"], row["peel_s"],
                 row["delaunay_s"], "yes" if row["ok"] else "no"), flush=True)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--shapes", default="sphere,torus")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", help="also write the results to this file")
    parser.add_argument("--meshes", help="comma-separated libcgal-demo meshes (meshes/NAME.off)")
    parser.add_argument("--data", default="/tmp/cgal/data",
                        help="the unpacked libcgal-demo data.tar.gz (holds meshes/)")
    args = parser.parse_args()
    load = os.getloadavg()
    print("load average %.2f %.2f %.2f, %d cores" % (load + (os.cpu_count(),)))
    if args.meshes:
        print("| mesh vertices | points | coverage | non-manifold edges / vertices | boundary edges "
              "| genus (mesh) | Hausdorff / spacing | peel / Delaunay s | criteria met |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---|")
        rows = mesh_rows(args)
        if args.json:
            with open(args.json, "w") as f:
                json.dump({"load": load, "results": rows}, f, indent=1)
        return
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
            "delaunay_cpu_s": field(out, "DelaunayCPUTime"),
            "peel_cpu_s": field(out, "PeelCPUTime"),
            "groups": field(out, "NumberOfGroupRemovals"),
            "genus": field(q, "Genus"), "coverage": field(q, "Coverage"),
            "non_manifold_vertices": field(q, "NumberOfNonManifoldVertices"),
        }
        row["ratio"] = row["peel_s"] / row["delaunay_s"]
        row["cpu_ratio"] = row["peel_cpu_s"] / row["delaunay_cpu_s"]
        results.append(row)
        print("%-6s %8d points: Delaunay %.2f s, peel %.2f s, peel/Delaunay %.2f (CPU %.2f s / "
              "%.2f s = %.2f); genus %d, coverage %.4f, %d groups, %d non-manifold vertices"
              % (shape, args.points, row["delaunay_s"], row["peel_s"], row["ratio"],
                 row["peel_cpu_s"], row["delaunay_cpu_s"], row["cpu_ratio"],
                 row["genus"], row["coverage"], row["groups"], row["non_manifold_vertices"]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"load": load, "results": results}, f, indent=1)


if __name__ == "__main__":
    main()
