#!/usr/bin/env python3
"""vtkCDTAdvancingFront's estimated normals against the meshes' normals, and what they cost the front.

On the vertex sets of CGAL demo meshes (the clouds of issue 6's time bound), the normals the
filter estimates (its defaults, no input normals; point data `Normals` of its output) are compared
with the mesh's area-weighted vertex normals: the median angle between their lines, how many are
more than 30 and 60 degrees off, and how many point the other way (negative dot product: an
orientation error, whatever the line). The front's work on them is shown by the triangles made by
its hole filling (cell data `HoleFilled`), the boundary edges and the Hausdorff distance over the
mean spacing (vtkReconstructionQuality, the mesh as reference), and the CPU time of Update (least
of --repeat runs).

With --hybrid, the filter is also run on input normals made from both: the mesh's normals, except
at the points whose estimated normal is more than --hybrid degrees off the mesh's (there the
estimated one, turned to the mesh's side), and the reverse (the estimated normals turned to the
mesh's side, with the mesh's normals at those points). Which of the estimated normals make the
front reject candidates and fill holes: if the first is as slow as the estimated normals and the
second as fast as the mesh's, those few points are the cost.

With --flags, two per-point measures that flag a normal as untrusted without another search are
checked against those points (more than 30 degrees off): the surface variation 3 l0 / (l0 + l1 +
l2) of the point and its 9 nearest (the estimation's `variation`, here on the plain 9-nearest
table), and the spread of the oriented estimated normals over that row (1 - the least dot product
with a neighbour's). For each, the share of the > 30 degree points among the 5, 10 and 20 % of
points it ranks highest (recall) and the share of those points that are > 30 degrees off
(precision).

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
    Benchmarks/run_estimated_normals.py --data /usr/share/cgal-demo/data [--meshes elephant ...] \\
    [--hybrid 30] [--repeat 5] [--flags]
"""
import argparse
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import pointcloudsurface as pcs

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_mesh_vertex_sweep import polydata, read_off  # noqa: E402

DEFAULT_MESHES = ["bunny00", "armadillo", "camel", "elephant", "refined_elephant",
                  "fandisk_large", "knot1", "knot2", "diplodocus", "cow"]


def vertex_normals(points, triangles):
    """Area-weighted vertex normals of a mesh (unit; zero where no triangle has area)."""
    normals = np.zeros_like(points)
    areas = np.cross(points[triangles[:, 1]] - points[triangles[:, 0]],
                     points[triangles[:, 2]] - points[triangles[:, 0]])
    for corner in range(3):
        np.add.at(normals, triangles[:, corner], areas)
    length = np.linalg.norm(normals, axis=1)
    return normals / np.where(length > 0.0, length, 1.0)[:, None]


def nearest_table(points, k):
    """The k nearest other points of each point, nearest first (brute force, in blocks)."""
    table = np.empty((len(points), k), dtype=np.int64)
    for start in range(0, len(points), 256):
        block = points[start:start + 256]
        d2 = ((block[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
        d2[np.arange(len(block)), np.arange(start, start + len(block))] = np.inf
        rows = np.argpartition(d2, k, axis=1)[:, :k]
        order = np.argsort(np.take_along_axis(d2, rows, axis=1), axis=1)
        table[start:start + len(block)] = np.take_along_axis(rows, order, axis=1)
    return table


def flag_rows(name, points, normals, far):
    """Recall and precision of the untrusted-normal flags (see --flags) on the points `far`."""
    table = nearest_table(points, 9)
    rows = np.concatenate([np.arange(len(points))[:, None], table], axis=1)
    centred = points[rows] - points[rows].mean(axis=1, keepdims=True)
    values = np.linalg.eigvalsh(np.einsum("nki,nkj->nij", centred, centred))
    variation = 3.0 * values[:, 0] / np.maximum(values.sum(axis=1), 1e-300)
    spread = 1.0 - np.einsum("ij,ikj->ik", normals, normals[table]).min(axis=1)
    lines = []
    for label, measure in (("surface variation", variation), ("normal spread", spread)):
        ranked = np.argsort(-measure, kind="stable")
        cells = []
        for share in (0.05, 0.10, 0.20):
            top = ranked[:int(share * len(points))]
            cells.append("%.2f / %.2f" % (far[top].sum() / max(1, far.sum()), far[top].mean()))
        lines.append("| %s | %d | %s | %s |" % (name, far.sum(), label, " | ".join(cells)))
    return lines


def run_front(points, normals, repeat):
    """The filter on the points (with `normals` as input normals when given): output, CPU s."""
    best, output = float("inf"), None
    for _ in range(repeat):
        data = polydata(points)
        if normals is not None:
            array = numpy_to_vtk(np.ascontiguousarray(normals), deep=1)
            array.SetName("Normals")
            data.GetPointData().SetNormals(array)
        front = pcs.vtkCDTAdvancingFront()
        front.SetInputData(data)
        start = time.process_time()
        front.Update()
        best = min(best, time.process_time() - start)
        output = front.GetOutput()
    return output, best


def front_row(name, label, output, seconds, reference):
    quality = pcs.vtkReconstructionQuality()
    quality.SetInputData(output)
    quality.SetReferenceData(reference)
    quality.Update()
    fields = quality.GetOutput().GetFieldData()
    filled = vtk_to_numpy(output.GetCellData().GetArray("HoleFilled")).sum()
    return "| %s | %s | %d | %d | %d | %.2f | %.4f |" % (
        name, label, output.GetNumberOfCells(), filled,
        fields.GetArray("NumberOfBoundaryEdges").GetValue(0),
        fields.GetArray("HausdorffOverSpacing").GetValue(0), seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has meshes/)")
    parser.add_argument("--meshes", nargs="+", default=DEFAULT_MESHES)
    parser.add_argument("--hybrid", type=float, default=0.0,
                        help="also run on mixed normals, split at this angle (degrees)")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--flags", action="store_true",
                        help="also check the untrusted-normal flags against the > 30 deg points")
    args = parser.parse_args()
    angles, fronts, flags = [], [], []
    for name in args.meshes:
        try:
            points, triangles = read_off(os.path.join(args.data, "meshes", name + ".off"))
        except (OSError, ValueError) as error:
            print("skipped %s: %s" % (name, error), file=sys.stderr)
            continue
        reference = polydata(points, triangles)
        exact = vertex_normals(points, triangles)
        output, seconds = run_front(points, None, args.repeat)
        estimated = vtk_to_numpy(output.GetPointData().GetArray("Normals")).copy()
        dot = np.einsum("ij,ij->i", exact, estimated)
        angle = np.degrees(np.arccos(np.clip(np.abs(dot), 0.0, 1.0)))
        angles.append("| %s | %d | %.2f | %d | %d | %d |" % (
            name, len(points), np.median(angle), (angle > 30).sum(), (angle > 60).sum(),
            (dot < 0).sum()))
        fronts.append(front_row(name, "estimated", output, seconds, reference))
        if args.flags and (angle > 30).any():
            flags.extend(flag_rows(name, points, estimated, angle > 30))
        if args.hybrid > 0.0:
            far = (angle > args.hybrid)[:, None]
            turned = estimated * np.where(dot < 0, -1.0, 1.0)[:, None]
            runs = [("mesh's", exact),
                    ("mesh's, estimated beyond %g deg" % args.hybrid, np.where(far, turned, exact)),
                    ("estimated, mesh's beyond %g deg" % args.hybrid, np.where(far, exact, turned))]
            for label, normals in runs:
                output, seconds = run_front(points, normals, args.repeat)
                fronts.append(front_row(name, label, output, seconds, reference))
    print("| vertex set | points | median angle | > 30 deg | > 60 deg | reversed |")
    print("|---|---:|---:|---:|---:|---:|")
    print("\n".join(angles))
    print()
    print("| vertex set | normals | triangles | hole-filling triangles | boundary edges "
          "| Hausdorff / spacing | CPU s |")
    print("|---|---|---:|---:|---:|---:|---:|")
    print("\n".join(fronts))
    if flags:
        print()
        print("| vertex set | > 30 deg | flag | top 5 %: recall / precision | top 10 % "
              "| top 20 % |")
        print("|---|---:|---|---|---|---|")
        print("\n".join(flags))


if __name__ == "__main__":
    main()
