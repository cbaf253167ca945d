#!/usr/bin/env python3
"""Thin tubes sampled at random: triangles across the inside (issue 5's walls), counted.

vtkLocalOptimumGrowth closes thin parts of random samples (legs, tails, tips of radius 2-4 mean
spacings) with walls and discs across the inside here and there (Benchmarks/results/
local_optimum.md). This script reproduces them on surfaces whose distance function is known:
capsules of radius 2, 3 and 4, a round cone whose radius goes from 6 to 1, and bent capsules
(arcs of a circle) of radius 3 and 2.5, all in units of the sample's expected nearest-neighbour
distance. Each surface is triangulated finely (flying edges on its signed distance), sampled
uniformly by area (area / 4 points, numpy's default_rng(seed): Poisson density 1/4, expected
nearest-neighbour distance 1) and given to the filter with its defaults. Printed per shape and
seed: points, triangles (a closed genus-0 mesh has 2V - 4), triangles farther than 2 mean spacings
from the surface (analytic distance at 15 barycentric points each, over the sample's measured mean
spacing), the largest such distance, boundary edges and unused points; then totals per shape.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_thin_tubes.py \
      [--shapes capsule3 cone arc2.5] [--seeds 1 2 3] [--filters log cdt]
"""
import argparse
import os
import sys

import numpy as np
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_mesh_vertex_sweep import FILTERS, polydata  # noqa: E402
from run_outlier_comparison import sample_mesh  # noqa: E402


def capsule(radius, length):
    """Signed distance to the capsule of the segment (0, 0, 0)-(0, 0, length)."""
    def distance(x):
        z = np.clip(x[:, 2], 0.0, length)
        return np.sqrt(x[:, 0] ** 2 + x[:, 1] ** 2 + (x[:, 2] - z) ** 2) - radius
    return distance


def round_cone(r1, r2, height):
    """Signed distance to the hull of the spheres (0, 0, 0; r1) and (0, 0, height; r2)."""
    sine = (r1 - r2) / height
    cosine = np.sqrt(1.0 - sine * sine)

    def distance(x):
        q = np.stack([np.hypot(x[:, 0], x[:, 1]), x[:, 2]], 1)
        along = q @ np.array([-sine, cosine])
        side = q @ np.array([cosine, sine]) - r1
        return np.where(along < 0.0, np.linalg.norm(q, axis=1) - r1,
                        np.where(along > cosine * height,
                                 np.linalg.norm(q - [0.0, height], axis=1) - r2, side))
    return distance


def arc(bend, radius, angle):
    """Signed distance to the tube of the arc of radius `bend` from angle 0 to `angle` (z = 0)."""
    ends = np.array([[bend, 0.0, 0.0], [bend * np.cos(angle), bend * np.sin(angle), 0.0]])

    def distance(x):
        theta = np.arctan2(x[:, 1], x[:, 0]) % (2.0 * np.pi)
        to_circle = np.hypot(np.hypot(x[:, 0], x[:, 1]) - bend, x[:, 2])
        to_ends = np.min([np.linalg.norm(x - e, axis=1) for e in ends], axis=0)
        return np.where(theta <= angle, to_circle, to_ends) - radius
    return distance


# name: (signed distance, box low corner, box high corner)
SHAPES = {
    "capsule2": (capsule(2.0, 60.0), (-3, -3, -3), (3, 3, 63)),
    "capsule3": (capsule(3.0, 60.0), (-4, -4, -4), (4, 4, 64)),
    "capsule4": (capsule(4.0, 60.0), (-5, -5, -5), (5, 5, 65)),
    "cone": (round_cone(6.0, 1.0, 60.0), (-7, -7, -7), (7, 7, 62)),
    "arc3": (arc(15.0, 3.0, np.pi), (-19, -4, -4), (19, 19, 4)),
    "arc2.5": (arc(12.0, 2.5, 1.5 * np.pi), (-15, -15, -3.5), (15, 15, 3.5)),
}
# 15 barycentric points per triangle (a grid of step 1/4).
BARYCENTRIC = np.array([(i / 4, j / 4, 1 - i / 4 - j / 4) for i in range(5) for j in range(5 - i)])


def surface(name, step=0.15):
    """A fine triangulation of the shape's zero level (flying edges on a grid of `step`)."""
    distance, low, high = SHAPES[name]
    low, high = np.array(low, float) - 1.0, np.array(high, float) + 1.0
    dims = np.ceil((high - low) / step).astype(int) + 1
    axes = [low[i] + step * np.arange(dims[i]) for i in range(3)]
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, 3)
    values = distance(grid).reshape(dims)
    image = vtkImageData()
    image.SetDimensions(*dims)
    image.SetOrigin(*low)
    image.SetSpacing(step, step, step)
    image.GetPointData().SetScalars(
        numpy_to_vtk(np.ascontiguousarray(values.transpose(2, 1, 0).ravel()), deep=1))
    contour = vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOff()
    contour.Update()
    mesh = contour.GetOutput()
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    return points, vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def sample(points, triangles, seed):
    """area / 4 points uniformly over the triangles' area, drawn with default_rng(seed)."""
    a, b, c = (points[triangles[:, i]] for i in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
    return sample_mesh(points, triangles, int(area / 4.0), np.random.default_rng(seed))


def measure(name, cloud, key):
    algorithm = FILTERS[key]()
    algorithm.SetInputData(polydata(cloud))
    algorithm.Update()
    mesh = algorithm.GetOutput()
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    # The output's own points: greedy appends the points its hole filling adds.
    vertices = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    spacing = cKDTree(cloud).query(cloud, 2)[0][:, 1].mean()
    probes = np.einsum("bk,tkd->tbd", BARYCENTRIC, vertices[triangles]).reshape(-1, 3)
    far = np.abs(SHAPES[name][0](probes)).reshape(len(triangles), -1).max(axis=1) / spacing
    edges = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    used = np.unique(triangles) if len(triangles) else np.array([], int)
    used = used[used < len(cloud)]  # unused input points only
    return (len(triangles), int((far > 2.0).sum()), float(far.max()) if len(far) else 0.0,
            int((counts == 1).sum()), len(cloud) - len(used))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=list(SHAPES))
    parser.add_argument("--seeds", type=int, nargs="+", default=list(range(1, 11)))
    parser.add_argument("--filters", nargs="+", default=["log"], choices=list(FILTERS))
    args = parser.parse_args()
    print("| shape | seed | filter | points | triangles (2V-4) | triangles > 2 spacings off | "
          "farthest | boundary edges | unused |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    totals = {}
    for name in args.shapes:
        points, triangles = surface(name)
        for seed in args.seeds:
            cloud = sample(points, triangles, seed)
            for key in args.filters:
                count, far, farthest, boundary, unused = measure(name, cloud, key)
                total = totals.setdefault((name, key), [0, 0, 0, 0])
                for i, value in enumerate((far, farthest > 2.0, boundary, unused)):
                    total[i] += value
                print("| %s | %d | %s | %d | %d (%d) | %d | %.2f | %d | %d |" % (
                    name, seed, key, len(cloud), count, 2 * len(cloud) - 4, far, farthest,
                    boundary, unused), flush=True)
    for (name, key), (far, over, boundary, unused) in totals.items():
        print("%s %s: %d triangles > 2 spacings off, %d of %d samples over 2, %d boundary edges, "
              "%d unused points" % (name, key, far, over, len(args.seeds), boundary, unused))


if __name__ == "__main__":
    main()
