#!/usr/bin/env python3
"""Every surface filter, with its defaults, on the vertices of CGAL demo meshes.

A check on data no test and no other benchmark reads: the clouds are the vertex sets of meshes in
Debian's libcgal-demo data (irregular sampling, thin features, open borders, CAD parts), the
reference surface is the mesh itself. For each mesh and filter it prints the triangles, the
points left unused (negative when a filter adds points), boundary edges, non-manifold edges, the
Hausdorff distance and both one-sided maxima over the reference's mean spacing, the triangles
standing across the reference (normal more than 60 degrees from the reference's, in % of the
triangles) and the unweighted and area-weighted mean of that angle (vtkReconstructionQuality) and
the filter's CPU time. No normals are given (CDT estimates them).

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
    Benchmarks/run_mesh_vertex_sweep.py --data /usr/share/cgal-demo/data [--meshes bull cow ...]
"""
import argparse
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import pointcloudsurface as pcs

DEFAULT_MESHES = ["bear", "bull", "cow", "ChineseDragon-10kv", "triceratops", "homer", "pig",
                  "elk", "hand", "femur", "lion", "man", "mannequin-devil", "mushroom", "head",
                  "rotor", "turbine", "spool"]
FILTERS = {"log": pcs.vtkLocalOptimumGrowth, "cdt": pcs.vtkCDTAdvancingFront,
           "greedy": pcs.vtkGreedySurfaceTriangulation, "peel": pcs.vtkPerimeterPeelSurface}


def read_off(path):
    """Points and triangles (polygons fanned) of an OFF file; comments allowed, no colours."""
    tokens = " ".join(line.split("#")[0] for line in open(path)).split()
    if tokens[0] != "OFF":
        raise ValueError("%s: only plain OFF is read" % path)
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    points = np.array(tokens[at:at + 3 * nv], float).reshape(nv, 3)
    at += 3 * nv
    triangles = []
    for _ in range(nf):
        k = int(tokens[at])
        v = [int(x) for x in tokens[at + 1:at + 1 + k]]
        at += 1 + k
        triangles += [[v[0], v[j], v[j + 1]] for j in range(1, k - 1)]
    return points, np.array(triangles, np.int64)


def polydata(points, triangles=None):
    data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=1))
    data.SetPoints(vtk_points)
    if triangles is not None:
        cells = vtkCellArray()
        offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
        cells.SetData(numpy_to_vtk(offsets, deep=1),
                      numpy_to_vtk(np.ascontiguousarray(triangles).ravel(), deep=1))
        data.SetPolys(cells)
    return data


def reconstruct(key, points):
    """The mesh of filter `key` (defaults) over the points, and the CPU seconds of its Update."""
    algorithm = FILTERS[key]()
    algorithm.SetInputData(polydata(points))
    start = time.process_time()
    algorithm.Update()
    return algorithm.GetOutput(), time.process_time() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has meshes/)")
    parser.add_argument("--meshes", nargs="+", default=DEFAULT_MESHES)
    parser.add_argument("--filters", nargs="+", default=list(FILTERS), choices=list(FILTERS))
    args = parser.parse_args()
    print("| mesh | filter | points | triangles | unused | boundary edges | non-manifold edges "
          "| Hausdorff | accuracy max | completeness max | standing % | mean angle "
          "| area-weighted angle | CPU s |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name in args.meshes:
        path = os.path.join(args.data, "meshes", name + ".off")
        try:
            points, triangles = read_off(path)
        except (OSError, ValueError) as error:
            print("skipped %s: %s" % (name, error), file=sys.stderr)
            continue
        reference = polydata(points, triangles)
        for key in args.filters:
            mesh, seconds = reconstruct(key, points)
            cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())
            used = len(np.unique(cells)) if len(cells) else 0
            quality = pcs.vtkReconstructionQuality()
            quality.SetInputData(mesh)
            quality.SetReferenceData(reference)
            quality.Update()
            fields = quality.GetOutput().GetFieldData()
            value = lambda k: fields.GetArray(k).GetValue(0)
            standing = 100.0 * value("NumberOfStandingTriangles") / max(1, len(cells) // 3)
            print("| %s | %s | %d | %d | %d | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f "
                  "| %.2f |" % (
                      name, key, len(points), len(cells) // 3, len(points) - used,
                      value("NumberOfBoundaryEdges"), value("NumberOfNonManifoldEdges"),
                      value("HausdorffOverSpacing"), value("AccuracyMaxOverSpacing"),
                      value("CompletenessMaxOverSpacing"), standing,
                      value("MeanReferenceNormalAngle"),
                      value("AreaWeightedMeanReferenceNormalAngle"), seconds), flush=True)


if __name__ == "__main__":
    main()
