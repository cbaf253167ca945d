#!/usr/bin/env python3
"""Thin closed tubes sampled by rings of few points: closed around the tube, or capped (issues 5, 6).

Clouds (known genus; no input normals):
  knotRxM        (2,3) trefoil knot tube: R = 300 rings of M points, radius 0.15, around the
                 centre curve (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t); genus 1
  gtorusNxM_rR   torus of radii 1 and R on a (u, v) grid, N rings of M points, N about M / R (the
                 spacing along the core circle that around the tube); genus 1
  gtorusNxM_tw   the same with R = 0.3, N = 3 M, v turned by u / 2 (rings turned around the tube
                 from one to the next); genus 1
  rtorus_rR_N_sS N points uniform by area on the torus of radii 1 and R (numpy default_rng(S));
                 genus 1
  straightM, bentM  open tubes of radius 0.2 sampled by rings of M points, straight (length 3) or
                 along a bent arc (three quarters of a circle of radius 1.5, with a wave in z);
                 genus 0, two rims
Printed per cloud and filter (default parameters): boundary edges b, boundary loops L, genus g
(vtkReconstructionQuality, closed manifold meshes only; "-" otherwise), unused points u,
components c, non-manifold edges nm.

Usage:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_tube_loops.py \
      [--filters log cdt] [--only knot]
"""
import argparse
import math

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkObject, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

import pointcloudsurface as pcs

FILTERS = {"log": pcs.vtkLocalOptimumGrowth, "cdt": pcs.vtkCDTAdvancingFront,
           "greedy": pcs.vtkGreedySurfaceTriangulation, "peel": pcs.vtkPerimeterPeelSurface}


def rings(centre, tangent, m, radius):
    """m points of a circle of the given radius around each centre, in the plane normal to the
    tangent (frame: a = t x w / |t x w|, b = t x a, w a fixed direction)."""
    tangent = tangent / np.linalg.norm(tangent, axis=1)[:, None]
    a = np.cross(tangent, [0.3, 0.5, 0.81])
    a /= np.linalg.norm(a, axis=1)[:, None]
    b = np.cross(tangent, a)
    v = np.arange(m) * 2 * math.pi / m
    return (centre[:, None, :] + radius * (np.cos(v)[None, :, None] * a[:, None, :]
                                           + np.sin(v)[None, :, None] * b[:, None, :])).reshape(-1, 3)


def knot_tube(count, m, radius=0.15):
    t = np.arange(count) * 2 * math.pi / count
    centre = np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)]
    tangent = np.c_[np.cos(t) + 4 * np.cos(2 * t), -np.sin(t) + 4 * np.sin(2 * t), -3 * np.cos(3 * t)]
    return rings(centre, tangent, m, radius)


def grid_torus(n, m, r, turn=0.0):
    u, v = np.meshgrid(np.arange(n) * 2 * math.pi / n, np.arange(m) * 2 * math.pi / m, indexing="ij")
    v = v + turn * u
    u, v = u.ravel(), v.ravel()
    return np.c_[(1 + r * np.cos(v)) * np.cos(u), (1 + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def random_torus(n, r, rng):
    out = []
    while sum(len(o) for o in out) < n:
        u, v, w = rng.uniform(0, 2 * math.pi, n), rng.uniform(0, 2 * math.pi, n), rng.uniform(0, 1, n)
        keep = w < (1 + r * np.cos(v)) / (1 + r)
        u, v = u[keep], v[keep]
        out.append(np.c_[(1 + r * np.cos(v)) * np.cos(u), (1 + r * np.cos(v)) * np.sin(u), r * np.sin(v)])
    return np.concatenate(out)[:n]


def clouds():
    for m in (8, 10, 12, 16):
        yield "knot300x%d" % m, knot_tube(300, m)
    for m in (8, 10, 12, 14, 16):
        for r in (0.1, 0.2, 0.35):
            n = int(round(m / r))
            yield "gtorus%dx%d_r%.2f" % (n, m, r), grid_torus(n, m, r)
        yield "gtorus%dx%d_tw" % (3 * m, m), grid_torus(3 * m, m, 0.3, 0.5)
    for r, sizes in ((0.15, (500, 800, 1200, 1800)), (0.1, (300, 500, 800, 1200))):
        for n in sizes:
            for seed in range(3):
                yield "rtorus_r%.2f_%d_s%d" % (r, n, seed), random_torus(n, r, np.random.default_rng(seed))
    for m in (8, 12, 16):
        step = 2 * math.pi * 0.2 / m
        z = np.arange(0, 3, step)
        yield "straight%d" % m, rings(np.c_[0 * z, 0 * z, z], np.c_[0 * z, 0 * z, 1 + 0 * z], m, 0.2)
        t = np.arange(0, 1.5 * math.pi, step / 1.5)
        centre = np.c_[1.5 * np.cos(t), 1.5 * np.sin(t), 0.3 * np.sin(2 * t)]
        tangent = np.c_[-1.5 * np.sin(t), 1.5 * np.cos(t), 0.6 * np.cos(2 * t)]
        yield "bent%d" % m, rings(centre, tangent, m, 0.2)


def run(name, x):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(x, dtype=float), deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    f = FILTERS[name]()
    f.SetInputData(cloud)
    f.Update()
    quality = pcs.vtkReconstructionQuality()
    quality.SetInputData(f.GetOutput())
    quality.Update()
    field = quality.GetOutput().GetFieldData()

    def value(key):
        array = field.GetArray(key)
        return array.GetTuple1(0) if array is not None else float("nan")

    genus = value("Genus")
    return "b%d L%d g%s u%d c%d nm%d" % (
        value("NumberOfBoundaryEdges"), value("NumberOfBoundaryLoops"),
        "%d" % genus if genus == genus and genus >= 0 else "-", f.GetNumberOfUnusedPoints(),
        value("NumberOfConnectedComponents"), value("NumberOfNonManifoldEdges"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--filters", nargs="+", default=["log", "cdt"], choices=list(FILTERS))
    parser.add_argument("--only", default="", help="clouds whose name contains this")
    args = parser.parse_args()
    vtkObject.GlobalWarningDisplayOff()
    for cloud, x in clouds():
        if args.only in cloud:
            print("%-22s %6d" % (cloud, len(x)),
                  " | ".join("%s %s" % (f, run(f, x)) for f in args.filters), flush=True)


if __name__ == "__main__":
    main()
