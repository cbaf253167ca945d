#!/usr/bin/env python3
"""Where a filter's mesh of a random sample is farther than a bound from the sampled surface.

run_sample_seeds.py gives one Hausdorff distance per sample; this script says where it comes
from. A random sample is drawn as there (numpy default_rng(seed), area weighted; with --vertices,
the mesh's own vertices are taken instead), meshed by one filter of the project (defaults), and
measured against the mesh it was sampled from, densely:
every triangle at the 28 points of a barycentric grid of step 1/6 (its vertices among them) and
its centroid, every reference triangle likewise. Distances are screened with a k-d tree on a
denser sample of the other side and the candidates over 1.5 mean spacings (or --bound, if
smaller) measured exactly
(vtkStaticCellLocator). The unit is the mean nearest-neighbour distance of the used points
(vtkReconstructionQuality's MeanSpacing).

Printed per sample:
- every triangle farther than --bound mean spacings from the reference (accuracy side): its
  distance, centroid, edge lengths and depth (largest distance from its dense samples to the
  nearest input point), and the values of --cell-array for it when the output has that array
  (e.g. a temporary trace of the step that made each triangle);
- the places where the reference is farther than --bound from the mesh (completeness side, one
  line per place 5 spacings apart): the distance, the nearest input point (the sample's void
  there), the distance to the convex hull of the 10 and 30 nearest input points (a triangle
  over those points cannot come nearer), and the nearest boundary edge of the mesh.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_far_triangles.py \
      --data /usr/share/cgal-demo/data [--filter log] [--meshes camel armadillo] \
      [--seeds 1 2 3 4 5] [--points 100000] [--bound 2] [--cell-array NAME] [--vertices]
"""
import argparse
import os
import sys

import numpy as np
from scipy.spatial import ConvexHull, cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference
from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_mesh_vertex_sweep import FILTERS, polydata, read_off  # noqa: E402
from run_sample_seeds import sample_mesh  # noqa: E402


def barycentric_grid(steps):
    """Barycentric weights of a grid with `steps` intervals per edge, and the centroid."""
    weights = [(i / steps, j / steps, (steps - i - j) / steps)
               for i in range(steps + 1) for j in range(steps + 1 - i)]
    return np.array(weights + [(1 / 3, 1 / 3, 1 / 3)])


def dense_samples(points, triangles, weights):
    """(triangles, samples, 3): the weighted points of every triangle."""
    return np.einsum("sk,tkd->tsd", weights, points[triangles])


def cell_locator(points, triangles):
    locator = vtkStaticCellLocator()
    locator.SetDataSet(polydata(points, triangles))
    locator.BuildLocator()
    return locator


def exact_distances(locator, queries):
    closest, cell, sub, d2 = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
    out = np.empty(len(queries))
    for i, q in enumerate(queries):
        locator.FindClosestPoint(q, closest, cell, sub, d2)
        out[i] = np.sqrt(d2.get())
    return out


def hull_distance(x, points):
    """Distance from x to the convex hull of points (0 inside)."""
    hull = ConvexHull(points)
    if np.all(hull.equations[:, :3] @ x + hull.equations[:, 3] <= 0.0):
        return 0.0
    return float(exact_distances(cell_locator(points, hull.simplices.astype(np.int64)), [x])[0])


def far_side(from_samples, to_dense, to_locator, spacing, bound):
    """Exact distances (over spacing) of the samples a k-d tree screening puts over 1.5 spacings;
    returns the indices (into the flattened samples) over bound and their distances."""
    flat = from_samples.reshape(-1, 3)
    screened = cKDTree(to_dense).query(flat, distance_upper_bound=10 * spacing)[0]
    candidates = np.where(screened > min(1.5, bound) * spacing)[0]
    exact = exact_distances(to_locator, flat[candidates]) / spacing
    return candidates[exact > bound], exact[exact > bound]


def report(name, seed, args, points, triangles):
    cloud = points if seed is None else sample_mesh(points, triangles, args.points, seed)
    algorithm = FILTERS[args.filter]()
    algorithm.SetInputData(polydata(cloud))
    algorithm.Update()
    output = algorithm.GetOutput()
    mesh = vtk_to_numpy(output.GetPolys().GetConnectivityArray()).reshape(-1, 3).astype(np.int64)
    used = np.unique(mesh)
    spacing = cKDTree(cloud[used]).query(cloud[used], k=2)[0][:, 1].mean()
    grid, fine = barycentric_grid(6), barycentric_grid(10)
    ours = dense_samples(cloud, mesh, grid)
    far, dist = far_side(ours, dense_samples(points, triangles, fine).reshape(-1, 3),
                         cell_locator(points, triangles), spacing, args.bound)
    per_triangle = {}
    for index, d in zip(far // ours.shape[1], dist):
        per_triangle[index] = max(d, per_triangle.get(index, 0.0))
    reference_samples = np.vstack([points, dense_samples(points, triangles, grid).reshape(-1, 3)])
    far_ref, dist_ref = far_side(reference_samples, dense_samples(cloud, mesh, fine).reshape(-1, 3),
                                 cell_locator(cloud, mesh), spacing, args.bound)
    inputs = cKDTree(cloud)
    array = output.GetCellData().GetArray(args.cell_array) if args.cell_array else None
    print("%s %s (%s): mean spacing %.5g, %d triangles; accuracy max %.2f, %d triangles over "
          "%g; completeness max %.2f" % (
              name, "vertices" if seed is None else "seed %d" % seed, args.filter, spacing,
              len(mesh), max(per_triangle.values(), default=0.0),
              len(per_triangle), args.bound, dist_ref.max() if len(dist_ref) else 0.0))
    for t, d in sorted(per_triangle.items(), key=lambda item: -item[1]):
        corners = cloud[mesh[t]]
        edges = [np.linalg.norm(corners[i] - corners[(i + 1) % 3]) / spacing for i in range(3)]
        depth = inputs.query(ours[t])[0].max() / spacing
        centre = corners.mean(axis=0)
        extra = " %s %g" % (args.cell_array, array.GetValue(int(t))) if array else ""
        print("  triangle %d: %.2f at (%.4g, %.4g, %.4g), edges %.1f %.1f %.1f, depth %.2f%s" % (
            t, d, *centre, *edges, depth, extra))
    counts = {}
    for a, b in np.sort(np.vstack([mesh[:, [0, 1]], mesh[:, [1, 2]], mesh[:, [2, 0]]]), axis=1):
        counts[(a, b)] = counts.get((a, b), 0) + 1
    boundary = np.array([e for e, k in counts.items() if k == 1]).reshape(-1, 2)
    boundary_tree = cKDTree(cloud[boundary].mean(axis=1)) if len(boundary) else None
    places = []
    for i in np.argsort(-dist_ref):
        x = reference_samples[far_ref[i]]
        if any(np.linalg.norm(x - p) < 5 * spacing for p in places):
            continue
        places.append(x)
        hulls = [hull_distance(x, cloud[inputs.query(x, k=k)[1]]) / spacing for k in (10, 30)]
        edge = boundary_tree.query(x)[0] / spacing if boundary_tree else float("inf")
        print("  reference at (%.4g, %.4g, %.4g): %.2f; nearest input point %.2f, hull of 10 / 30 "
              "nearest %.2f / %.2f, nearest boundary edge %.1f" % (
                  *x, dist_ref[i], inputs.query(x)[0] / spacing, *hulls, edge))
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has meshes/)")
    parser.add_argument("--filter", default="log", choices=list(FILTERS))
    parser.add_argument("--meshes", nargs="+", default=["camel", "elephant", "armadillo",
                                                        "bunny00"])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5])
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--bound", type=float, default=2.0, help="in mean spacings")
    parser.add_argument("--cell-array", help="a cell data array of the output to print per far "
                        "triangle")
    parser.add_argument("--vertices", action="store_true", help="mesh the mesh's own vertices "
                        "instead of random samples (--seeds and --points ignored)")
    args = parser.parse_args()
    for name in args.meshes:
        points, triangles = read_off(os.path.join(args.data, "meshes", name + ".off"))
        triangles = np.asarray(triangles, dtype=np.int64)
        for seed in [None] if args.vertices else args.seeds:
            report(name, seed, args, points, triangles)


if __name__ == "__main__":
    main()
