#!/usr/bin/env python3
"""vtkLocalOptimumGrowth on a tube sampled as rings: the walls of issue 5's camel, reproduced.

The legs of CGAL's camel (a decimated mesh) are tubes of radius 2-3 mean spacings sampled as dense
rings a few spacings apart; the filter spans them with walls (triangles across the inside of the
tube) instead of meshing from ring to ring (Benchmarks/results/local_optimum.md). This script builds
the same sampling on a capsule with known normals: a tube of radius R along z (in units of the
spacing along a ring, 1), rings g apart, closed by two hemispheres sampled at spacing 1. For each
configuration it prints the triangles by kind (within one ring, between adjacent rings, on a cap,
from a cap to a ring, other), walls (triangles whose vertices' normals are more than 90 degrees
apart), triangles farther than 1 spacing from the capsule (over their centroid and edge midpoints)
and the filter's counts. A mesh of the surface has no walls, no far triangles and 2V - 4 triangles.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_ring_tube.py \
    [--radius 2 2.5] [--gap 4 5 6] [--rings 8]
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import pointcloudsurface as pcs


def capsule(radius, gap, rings, twist):
    """Points, normals and ring index (-1 on the caps) of the ring-sampled capsule."""
    per_ring = max(3, int(round(2.0 * np.pi * radius)))
    length = gap * (rings - 1)
    points, normals, ring = [], [], []
    for i in range(rings):
        phi = np.arange(per_ring) * 2.0 * np.pi / per_ring + twist * i
        normals += [np.stack([np.cos(phi), np.sin(phi), np.zeros(per_ring)], 1)]
        points += [np.stack([radius * np.cos(phi), radius * np.sin(phi),
                             np.full(per_ring, i * gap)], 1)]
        ring += [np.full(per_ring, i)]
    # Hemispheres: Fibonacci points at spacing 1, the band next to the rim left to the ring.
    count = int(round(2.0 * np.pi * radius * radius))
    heights = (np.arange(count) + 0.5) / count
    heights = heights[heights > 0.5 / radius]
    phi = np.pi * (1.0 + 5.0 ** 0.5) * np.arange(len(heights))
    across = np.sqrt(1.0 - heights * heights)
    for sign, base in ((-1.0, 0.0), (1.0, length)):
        n = np.stack([across * np.cos(phi), across * np.sin(phi), sign * heights], 1)
        normals += [n]
        points += [radius * n + [0.0, 0.0, base]]
        ring += [np.full(len(n), -1)]
    return np.concatenate(points), np.concatenate(normals), np.concatenate(ring), length


def distance_to_capsule(x, radius, length):
    z = np.clip(x[:, 2], 0.0, length)
    return np.abs(np.sqrt(x[:, 0] ** 2 + x[:, 1] ** 2 + (x[:, 2] - z) ** 2) - radius)


def kind(rings):
    r = sorted(set(rings))
    if -1 in r:
        return "cap" if len(r) == 1 else "cap-ring"
    if len(r) == 1:
        return "in-ring"
    return "ring-to-ring" if len(r) == 2 and r[1] - r[0] == 1 else "other"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--radius", type=float, nargs="+", default=[2.0, 2.5])
    parser.add_argument("--gap", type=float, nargs="+", default=[4.0, 5.0, 6.0])
    parser.add_argument("--rings", type=int, default=8)
    args = parser.parse_args()
    kinds = ["in-ring", "ring-to-ring", "cap", "cap-ring", "other"]
    print("| R | g | twist | points | triangles (2V-4) | " + " | ".join(kinds) +
          " | walls | far > 1 | max distance | boundary edges | unused | seeds |")
    print("|---:|---:|---:|---:|---:|" + "---:|" * len(kinds) + "---:|---:|---:|---:|---:|---:|")
    for radius in args.radius:
        for gap in args.gap:
            per_ring = max(3, int(round(2.0 * np.pi * radius)))
            for twist in (0.0, np.pi / per_ring):  # aligned rings; each turned by half a step
                x, normals, ring, length = capsule(radius, gap, args.rings, twist)
                cloud = vtkPolyData()
                points = vtkPoints()
                points.SetData(numpy_to_vtk(x, deep=1))
                cloud.SetPoints(points)
                growth = pcs.vtkLocalOptimumGrowth()
                growth.SetInputData(cloud)
                growth.Update()
                cells = vtk_to_numpy(growth.GetOutput().GetPolys().GetConnectivityArray())
                t = cells.reshape(-1, 3)
                a, b, c = x[t[:, 0]], x[t[:, 1]], x[t[:, 2]]
                probes = np.concatenate([(a + b + c) / 3, (a + b) / 2, (b + c) / 2, (c + a) / 2])
                distance = distance_to_capsule(probes, radius, length).reshape(4, -1).max(0)
                na, nb, nc = normals[t[:, 0]], normals[t[:, 1]], normals[t[:, 2]]
                smallest = np.minimum(np.minimum((na * nb).sum(1), (nb * nc).sum(1)),
                                      (nc * na).sum(1))
                counts = {k: 0 for k in kinds}
                for triangle in t:
                    counts[kind(ring[triangle])] += 1
                print("| %.2f | %.1f | %.2f | %d | %d (%d) | %s | %d | %d | %.2f | %d | %d | %d |" % (
                    radius, gap, twist, len(x), len(t), 2 * len(x) - 4,
                    " | ".join(str(counts[k]) for k in kinds), np.sum(smallest < 0.0),
                    np.sum(distance > 1.0), distance.max() if len(t) else 0.0,
                    growth.GetNumberOfBoundaryEdges(), growth.GetNumberOfUnusedPoints(),
                    growth.GetNumberOfSeeds()), flush=True)


if __name__ == "__main__":
    main()
