"""Where a reference mesh crosses itself, and how far a genus-0 web must reach (issue 4).

vtkPerimeterPeelSurface leaves a web across the loop that two parts of an object close where they
touch (CGAL's camel: the hind legs at the knees). For a vertex set of a libcgal-demo mesh this
script prints:
- the triangle pairs of the mesh that intersect (edges crossing triangles; pairs sharing a vertex
  are skipped), grouped by position: where the mesh crosses itself, its parts overlap, so the
  solid they bound (the union) is joined there, whatever the mesh's own genus;
- with --path (a polyline, "x,y,z;x,y,z;..."), the smallest distance from the polyline to the
  mesh, in mean spacings. When the polyline, closed far outside the object, links a loop of the
  joined solid (it passes once through the loop), every output that joins the parts and has
  genus 0 crosses it, so its Hausdorff distance to the mesh is at least that smallest distance;
- the peel's Hausdorff distance (vtkReconstructionQuality, mean spacings: the MeanSpacing of the
  output, the unit of run_peel_benchmark.py) with the default 3 samples per triangle and with
  --samples (denser: the largest distance inside large triangles).

Usage (a build with the Python package):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
      Benchmarks/run_reference_contacts.py --data /work/cgaldata/data --mesh camel \\
      --path "0,-0.035,0.6;0,-0.035,-0.2;0.6,-0.035,-0.2"
"""
import argparse
import collections
import os

import numpy as np
from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance

from pointcloudsurface import vtkPerimeterPeelSurface, vtkReconstructionQuality
from run_peel_benchmark import cloud, field
from run_reconstruction_benchmark import mesh_from_arrays, read_off


def candidate_pairs(points, triangles, cell):
    """Pairs (i < j) of triangles whose boxes overlap, found through a grid of the given cell."""
    low = points[triangles].min(axis=1)
    high = points[triangles].max(axis=1)
    bins = collections.defaultdict(list)
    first = np.floor(low / cell).astype(np.int64)
    last = np.floor(high / cell).astype(np.int64)
    for i in range(len(triangles)):
        for x in range(first[i, 0], last[i, 0] + 1):
            for y in range(first[i, 1], last[i, 1] + 1):
                for z in range(first[i, 2], last[i, 2] + 1):
                    bins[(x, y, z)].append(i)
    pairs = set()
    for members in bins.values():
        for a in range(len(members)):
            for b in range(a + 1, len(members)):
                pairs.add((members[a], members[b]))
    pairs = np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2)
    overlap = np.all((low[pairs[:, 0]] <= high[pairs[:, 1]]) &
                     (low[pairs[:, 1]] <= high[pairs[:, 0]]), axis=1)
    pairs = pairs[overlap]
    t = triangles[pairs]
    shared = (t[:, 0, :, None] == t[:, 1, None, :]).any(axis=(1, 2))
    return pairs[~shared]


def segments_cross(a, b, triangle):
    """Whether the open segments a-b cross the triangles (vectorized Moller-Trumbore)."""
    e1 = triangle[:, 1] - triangle[:, 0]
    e2 = triangle[:, 2] - triangle[:, 0]
    d = b - a
    h = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, h)
    ok = np.abs(det) > 1e-300
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = a - triangle[:, 0]
    u = inv * np.einsum("ij,ij->i", s, h)
    q = np.cross(s, e1)
    v = inv * np.einsum("ij,ij->i", d, q)
    t = inv * np.einsum("ij,ij->i", e2, q)
    return ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < 1)


def self_intersections(points, triangles, cell):
    pairs = candidate_pairs(points, triangles, cell)
    first = points[triangles[pairs[:, 0]]]
    second = points[triangles[pairs[:, 1]]]
    hit = np.zeros(len(pairs), dtype=bool)
    for k in range(3):
        hit |= segments_cross(first[:, k], first[:, (k + 1) % 3], second)
        hit |= segments_cross(second[:, k], second[:, (k + 1) % 3], first)
    return pairs[hit]


def clusters(centres, reach):
    """Groups of the centres joined by links shorter than `reach` (single linkage)."""
    root = list(range(len(centres)))

    def find(i):
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i

    for i in range(len(centres)):
        near = np.nonzero(np.linalg.norm(centres[i + 1:] - centres[i], axis=1) < reach)[0]
        for j in near + i + 1:
            root[find(j)] = find(i)
    groups = collections.defaultdict(list)
    for i in range(len(centres)):
        groups[find(i)].append(i)
    return sorted(groups.values(), key=lambda g: -len(g))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default="/tmp/cgal/data",
                        help="the unpacked libcgal-demo data.tar.gz (holds meshes/)")
    parser.add_argument("--mesh", default="camel")
    parser.add_argument("--path", help='polyline "x,y,z;x,y,z;..." for the distance bound')
    parser.add_argument("--samples", type=int, default=100,
                        help="samples per triangle for the denser Hausdorff distance")
    parser.add_argument("--cluster", type=float, default=3.0,
                        help="pairs closer than this (mean spacings) are one place")
    args = parser.parse_args()

    p, t = read_off(os.path.join(args.data, "meshes", args.mesh + ".off"))
    reference = mesh_from_arrays(p, t)
    peel = vtkPerimeterPeelSurface()
    peel.SetInputData(cloud(p))
    peel.Update()
    hausdorff = []
    for samples in (3, args.samples):
        quality = vtkReconstructionQuality()
        quality.SetInputData(0, peel.GetOutput())
        quality.SetInputData(1, reference)
        quality.SetSamplesPerTriangle(samples)
        quality.Update()
        q = quality.GetOutput()
        hausdorff.append(field(q, "HausdorffOverSpacing"))
        spacing = field(q, "MeanSpacing")
    print("%s: %d points, %d triangles; peel genus %d, mean spacing %.6g; Hausdorff / spacing "
          "%.2f (3 samples per triangle), %.2f (%d)"
          % (args.mesh, len(p), len(t), field(q, "Genus"), spacing, hausdorff[0], hausdorff[1],
             args.samples))

    crossing = self_intersections(p, t, 2 * spacing)
    print("intersecting triangle pairs of the mesh: %d" % len(crossing))
    centres = np.array([(p[t[i]].mean(axis=0) + p[t[j]].mean(axis=0)) / 2 for i, j in crossing])
    for members in clusters(centres, args.cluster * spacing):
        c = centres[members]
        print("  %3d pairs around (%.3f, %.3f, %.3f), extent %.1f x %.1f x %.1f spacings"
              % ((len(c),) + tuple(c.mean(axis=0)) + tuple((c.max(axis=0) - c.min(axis=0))
                                                            / spacing)))

    if args.path:
        corners = np.array([[float(v) for v in corner.split(",")]
                            for corner in args.path.split(";")])
        distance = vtkImplicitPolyDataDistance()
        distance.SetInput(reference)
        step = 0.1 * spacing
        smallest, where = np.inf, None
        for a, b in zip(corners[:-1], corners[1:]):
            n = max(1, int(np.ceil(np.linalg.norm(b - a) / step)))
            for s in np.linspace(0.0, 1.0, n + 1):
                x = a + s * (b - a)
                d = abs(distance.EvaluateFunction(x))
                if d < smallest:
                    smallest, where = d, x
        print("path %s: smallest distance to the mesh %.2f spacings, at (%.3f, %.3f, %.3f) "
              "(sampled every 0.1 spacing)" % (args.path, smallest / spacing, *where))


if __name__ == "__main__":
    main()
