#!/usr/bin/env python3
"""How much of a Hausdorff distance is the sample's: every method on several random samples.

The issues bound the Hausdorff distance of the clean real surfaces in mean spacings (<= 2 for
vtkLocalOptimumGrowth and vtkCDTAdvancingFront, <= 4 for vtkPerimeterPeelSurface). The other
benchmarks sample each mesh once, with one fixed seed. This script draws several uniform random
samples of the same mesh (area weighted, numpy's default_rng(seed)) and gives each to every
filter of the project (defaults) and to CGAL's advancing front (pcsBenchCGALAFSR, when given),
then measures each mesh against the mesh it was sampled from with vtkReconstructionQuality.

Printed per mesh, seed and method: triangles, unused points (negative when a filter adds points:
vtkGreedySurfaceTriangulation's faired fills), boundary edges, the Hausdorff
distance and its two one-sided maxima (accuracy: mesh to reference; completeness: reference to
mesh) over the mean spacing. Per mesh and seed also the sample's own void: the largest distance
from a reference sample (the reference's vertices and triangle centroids) to the nearest input
point, over the same mean spacing. A mesh through the input points cannot follow the reference
inside such a void where the reference curves there (a thin tip no sample reached). A summary
line per method counts the samples within its bound: 2 mean spacings for LOG and CDT (and for
CGAL, their peer), 4 for the peel, and 2 for greedy (its issue asks for LOG's quality).

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_sample_seeds.py \
      --data /usr/share/cgal-demo/data [--cgal <bench-bin>/pcsBenchCGALAFSR] \
      [--meshes camel armadillo] [--seeds 1 2 3 4 5] [--points 100000] [--filters log cdt] \
      [--samples-per-triangle 45]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy

import pointcloudsurface as pcs

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_mesh_vertex_sweep import FILTERS, polydata, read_off  # noqa: E402
from run_outlier_comparison import sample_mesh as sample_triangles  # noqa: E402

# The Hausdorff bound of each method's issue, in mean spacings (CGAL: the LOG/CDT bound).
BOUNDS = {"log": 2.0, "cdt": 2.0, "greedy": 2.0, "peel": 4.0, "cgal": 2.0}


def sample_mesh(points, triangles, count, seed):
    """count points uniformly distributed over the triangles' area, drawn with default_rng(seed)."""
    return sample_triangles(points, triangles, count, np.random.default_rng(seed))


def largest_void(points, triangles, cloud):
    """Largest distance from the reference's vertices and centroids to the nearest cloud point."""
    queries = np.vstack([points, points[triangles].mean(axis=1)])
    return float(cKDTree(cloud).query(queries)[0].max())


def cgal_mesh(binary, cloud):
    with tempfile.TemporaryDirectory() as folder:
        xyz, off = os.path.join(folder, "cloud.xyz"), os.path.join(folder, "mesh.off")
        np.savetxt(xyz, cloud)
        subprocess.run([binary, xyz, off], check=True, capture_output=True)
        return polydata(cloud, read_off(off)[1])


def measure(mesh, reference, samples_per_triangle):
    quality = pcs.vtkReconstructionQuality()
    quality.SetSamplesPerTriangle(samples_per_triangle)
    quality.SetInputData(mesh)
    quality.SetReferenceData(reference)
    quality.Update()
    fields = quality.GetOutput().GetFieldData()
    return {k: fields.GetArray(k).GetValue(0) for k in (
        "NumberOfBoundaryEdges", "HausdorffOverSpacing", "AccuracyMaxOverSpacing",
        "CompletenessMaxOverSpacing", "MeanSpacing")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has meshes/)")
    parser.add_argument("--meshes", nargs="+", default=["camel", "elephant", "armadillo",
                                                        "bunny00"])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5])
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--filters", nargs="+", default=["log", "cdt"], choices=list(FILTERS))
    parser.add_argument("--cgal", help="pcsBenchCGALAFSR executable (CGAL's advancing front)")
    parser.add_argument("--samples-per-triangle", type=int, default=3,
                        help="vtkReconstructionQuality's SamplesPerTriangle (3: its default; 45 "
                        "measures each triangle more densely: H45 in Benchmarks/results)")
    args = parser.parse_args()
    methods = args.filters + (["cgal"] if args.cgal else [])
    within = {m: 0 for m in methods}
    print("| mesh | seed | method | triangles | unused | boundary edges | Hausdorff | "
          "accuracy max | completeness max | largest void |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|")
    for name in args.meshes:
        points, triangles = read_off(os.path.join(args.data, "meshes", name + ".off"))
        reference = polydata(points, triangles)
        for seed in args.seeds:
            cloud = sample_mesh(points, triangles, args.points, seed)
            void = largest_void(points, triangles, cloud)
            for method in methods:
                if method == "cgal":
                    mesh = cgal_mesh(args.cgal, cloud)
                else:
                    algorithm = FILTERS[method]()
                    algorithm.SetInputData(polydata(cloud))
                    algorithm.Update()
                    mesh = algorithm.GetOutput()
                cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())
                unused = len(cloud) - (len(np.unique(cells)) if len(cells) else 0)
                q = measure(mesh, reference, args.samples_per_triangle)
                within[method] += q["HausdorffOverSpacing"] <= BOUNDS[method]
                print("| %s | %d | %s | %d | %d | %d | %.2f | %.2f | %.2f | %.2f |" % (
                    name, seed, method, len(cells) // 3, unused, q["NumberOfBoundaryEdges"],
                    q["HausdorffOverSpacing"], q["AccuracyMaxOverSpacing"],
                    q["CompletenessMaxOverSpacing"], void / q["MeanSpacing"]), flush=True)
    runs = len(args.meshes) * len(args.seeds)
    for method in methods:
        print("%s: Hausdorff <= %g mean spacings on %d of %d samples" % (
            method, BOUNDS[method], within[method], runs))


if __name__ == "__main__":
    main()
