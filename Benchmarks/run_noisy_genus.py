#!/usr/bin/env python3
"""Noisy clouds of known genus: false handles and holes of vtkCDTAdvancingFront (issue 6).

Clouds (random, uniform by area, seed fixed; no input normals, so CDT and LOG estimate them):
  sphere        unit sphere, genus 0
  torus         R 1, r 0.35, genus 1
  dtorus        two such tori with centres 1.9 apart, the points inside the other solid torus
                dropped: the boundary of their union, genus 2
  rings         unit sphere on latitude rings, points 8x denser along a ring than across
                (ring gap g, spacing g / 8 along, the first ring g / 2 from the pole), every
                point jittered by Gaussian noise of 0.3 times the clean sample's mean spacing
                (about g / 8) on each coordinate, whatever --sigmas says; genus 0
Noise: Gaussian, sigma times the mean spacing of the clean sample (mean distance to the nearest
other point) on each coordinate.
Printed per cloud and method: genus (2C - chi - L) / 2 of the output (holds for open meshes),
boundary edges, connected components, unused points, non-manifold edges, and the Hausdorff
distance to the true surface in mean spacings: mesh -> surface over the triangles' vertices,
centroids and edge midpoints (analytic distance), surface -> mesh over 4,000 random points of the
true surface (closest point on the mesh); the larger of the two.
Methods: cdt (vtkCDTAdvancingFront), log (vtkLocalOptimumGrowth), cgal (CGAL's advancing front,
the benchmark binary pcsBenchCGALAFSR of the build).

Usage:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_noisy_genus.py \
    [--build build] [--shapes sphere torus dtorus rings] [--sizes 10000 100000] \
    [--sigmas 0 0.15 0.3] [--methods cdt log cgal] [--seed 1]
"""
import argparse
import json
import os
import subprocess
import tempfile
import time

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkStaticCellLocator

import pointcloudsurface as pcs

R_TORUS, r_TORUS, GAP = 1.0, 0.35, 1.9


def sphere_points(rng, n):
    x = rng.normal(size=(n, 3))
    return x / np.linalg.norm(x, axis=1)[:, None]


def torus_points(rng, n, centre=0.0):
    # Uniform by area: the angle around the tube weighted by R + r cos(v).
    out = []
    while sum(len(o) for o in out) < n:
        u = rng.uniform(0, 2 * np.pi, 2 * n)
        v = rng.uniform(0, 2 * np.pi, 2 * n)
        keep = rng.uniform(0, 1, 2 * n) < (R_TORUS + r_TORUS * np.cos(v)) / (R_TORUS + r_TORUS)
        u, v = u[keep], v[keep]
        w = R_TORUS + r_TORUS * np.cos(v)
        out.append(np.c_[w * np.cos(u) + centre, w * np.sin(u), r_TORUS * np.sin(v)])
    return np.concatenate(out)[:n]


def torus_signed(x, centre=0.0):
    q = np.sqrt((x[:, 0] - centre) ** 2 + x[:, 1] ** 2) - R_TORUS
    return np.sqrt(q * q + x[:, 2] ** 2) - r_TORUS


def dtorus_points(rng, n):
    out = []
    while sum(len(o) for o in out) < n:
        a = torus_points(rng, n, -GAP / 2)
        b = torus_points(rng, n, GAP / 2)
        a = a[torus_signed(a, GAP / 2) > 0]
        b = b[torus_signed(b, -GAP / 2) > 0]
        both = np.concatenate([a, b])
        out.append(both[rng.permutation(len(both))[: n // 2 + 1]])
    return np.concatenate(out)[:n]


def rings_points(rng, n):
    # Ring gap g with about n points in all: 4 pi / (g * g / 8) = n.
    g = np.sqrt(8 * 4 * np.pi / n)
    points = []
    for theta in np.arange(g / 2, np.pi, g):
        count = max(3, int(round(2 * np.pi * np.sin(theta) / (g / 8))))
        phi = rng.uniform(0, 2 * np.pi) + 2 * np.pi * np.arange(count) / count
        points.append(np.c_[np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi),
                            np.full(count, np.cos(theta))])
    return np.concatenate(points)


def distance(shape, x):
    if shape in ("sphere", "rings"):
        return np.abs(np.linalg.norm(x, axis=1) - 1.0)
    if shape == "torus":
        return np.abs(torus_signed(x))
    return np.abs(np.minimum(torus_signed(x, -GAP / 2), torus_signed(x, GAP / 2)))


GENERATORS = {"sphere": sphere_points, "torus": torus_points, "dtorus": dtorus_points,
              "rings": rings_points}
TRUE_GENUS = {"sphere": 0, "torus": 1, "dtorus": 2, "rings": 0}


def cloud(shape, n, sigma, seed):
    rng = np.random.default_rng(seed)
    clean = GENERATORS[shape](rng, n)
    d, _ = cKDTree(clean).query(clean, k=2)
    spacing = d[:, 1].mean()
    noisy = clean + rng.normal(scale=sigma * spacing, size=clean.shape)
    surface = GENERATORS[shape](np.random.default_rng(seed + 1000), 4000)
    return noisy, spacing, surface


def polydata(points, triangles=None):
    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
    pd.SetPoints(pts)
    if triangles is not None and len(triangles):
        cells = vtkCellArray()
        offsets = np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64)
        cells.SetData(numpy_to_vtk(offsets, deep=1),
                      numpy_to_vtk(np.ascontiguousarray(triangles.ravel(), dtype=np.int64), deep=1))
        pd.SetPolys(cells)
    return pd


def run_vtk(method, points):
    f = pcs.vtkCDTAdvancingFront() if method == "cdt" else pcs.vtkLocalOptimumGrowth()
    f.SetInputData(polydata(points))
    t = time.process_time()
    f.Update()
    t = time.process_time() - t
    out = f.GetOutput()
    if out.GetNumberOfPolys() == 0:
        return np.zeros((0, 3), int), t
    tri = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    # Output points are the input points (no Steiner points in CDT / LOG).
    assert out.GetNumberOfPoints() == len(points)
    return tri.astype(np.int64), t


def run_cgal(binary, points):
    with tempfile.TemporaryDirectory() as tmp:
        xyz, off = os.path.join(tmp, "c.xyz"), os.path.join(tmp, "m.off")
        np.savetxt(xyz, points, fmt="%.17g")
        result = subprocess.run([binary, xyz, off], check=True, capture_output=True, text=True)
        t = json.loads(result.stdout.strip().splitlines()[-1]).get("cpu_seconds", float("nan"))
        with open(off) as f:
            assert f.readline().strip() == "OFF"
            nv, nf = map(int, f.readline().split()[:2])
            lines = f.read().split("\n")
        rows = [l.split() for l in lines if l.strip()]
        faces = np.array([list(map(int, r[1:4])) for r in rows[nv:nv + nf]],
                         dtype=np.int64).reshape(-1, 3)
        return faces, t


def measure(shape, points, tri, spacing, surface):
    n = len(points)
    used = np.zeros(n, bool)
    used[tri.ravel()] = True
    e = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    edges, counts = np.unique(e, axis=0, return_counts=True)
    boundary = edges[counts == 1]
    nonmanifold = int((counts > 2).sum())
    V, E, F = int(used.sum()), len(edges), len(tri)
    if F:
        g = coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
        ncomp, label = connected_components(g, directed=False)
        C = len(np.unique(label[used]))
    else:
        C = 0
    # Boundary loops: components of the boundary-edge graph (exact for manifold boundaries).
    if len(boundary):
        b = coo_matrix((np.ones(len(boundary)), (boundary[:, 0], boundary[:, 1])), shape=(n, n))
        _, bl = connected_components(b, directed=False)
        L = len(np.unique(bl[np.unique(boundary.ravel())]))
    else:
        L = 0
    chi = V - E + F
    genus = (2 * C - chi - L) / 2
    # Hausdorff, mesh -> surface (analytic) and surface -> mesh (closest point on the mesh).
    p = points[tri]
    samples = np.concatenate([points[used], p.mean(axis=1), 0.5 * (p[:, 0] + p[:, 1]),
                              0.5 * (p[:, 1] + p[:, 2]), 0.5 * (p[:, 2] + p[:, 0])])
    to_surface = distance(shape, samples).max() if F else np.inf
    to_mesh = np.inf
    if F:
        loc = vtkStaticCellLocator()
        loc.SetDataSet(polydata(points, tri))
        loc.BuildLocator()
        c = [0.0, 0.0, 0.0]
        cell = reference(0)
        sub = reference(0)
        dist2 = reference(0.0)
        to_mesh = 0.0
        for x in surface:
            loc.FindClosestPoint(x, c, cell, sub, dist2)
            to_mesh = max(to_mesh, float(dist2))
        to_mesh = np.sqrt(to_mesh)
    return dict(genus=genus, bnd=len(boundary), comp=C, unused=n - V, nme=nonmanifold,
                h_ms=to_surface / spacing, h_sm=to_mesh / spacing,
                h=max(to_surface, to_mesh) / spacing, tris=F)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--shapes", nargs="+", default=["sphere", "torus", "dtorus", "rings"])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10000, 100000])
    parser.add_argument("--sigmas", type=float, nargs="+", default=[0.0, 0.15, 0.3])
    parser.add_argument("--methods", nargs="+", default=["cdt", "log", "cgal"])
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    binary = os.path.join(args.build, "bin", "pcsBenchCGALAFSR")
    print("| cloud | n | sigma | method | genus (true) | boundary edges | components | unused |"
          " non-manifold edges | Hausdorff mesh->surface / surface->mesh (spacings) | CPU s |")
    print("|---|---:|---:|---|---:|---:|---:|---:|---:|---|---:|")
    for shape in args.shapes:
        for n in args.sizes:
            sigmas = [0.3] if shape == "rings" else args.sigmas
            for sigma in sigmas:
                points, spacing, surface = cloud(shape, n, sigma, args.seed)
                for method in args.methods:
                    if method == "cgal":
                        tri, t = run_cgal(binary, points)
                    else:
                        tri, t = run_vtk(method, points)
                    m = measure(shape, points, tri, spacing, surface)
                    print(f"| {shape} | {len(points)} | {sigma} | {method} | "
                          f"{m['genus']:g} ({TRUE_GENUS[shape]}) | {m['bnd']} | {m['comp']} | "
                          f"{m['unused']} | {m['nme']} | {m['h_ms']:.2f} / {m['h_sm']:.2f} | "
                          f"{t:.2f} |", flush=True)


if __name__ == "__main__":
    main()
