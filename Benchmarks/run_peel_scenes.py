"""Scenes of several objects for vtkPerimeterPeelSurface (issue 4, rule 9 of the class docs).

Random samples (uniform by area) of:
- two unit spheres, centres `gap` apart, n points each (gaps 5, 3, 2.2, 2.05; n 5,000 and 20,000);
- three spheres of radii 1, 0.5 and 0.3 and three densities; a unit sphere and a sphere of radius
  0.05 of as many points (20 times denser); nine unit spheres on a 3 x 3 grid, centres 3 apart;
- dumbbells: two unit spheres, centres 3 apart, joined by a cylinder of radius k mean spacings
  (one object: its neck is sampled; k 1, 1.5, 2, 3, 4), seeds 1 and 2.
Printed per cloud: triangles, connected components and genus of the result
(vtkReconstructionQuality), unused points, group removals, strut points; for the spheres, the
triangles whose centroid is over one mean spacing h = r sqrt(4 pi / n) of its nearest sphere
(distance in that sphere's h) and the largest such distance.

Usage (a build with the Python package):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_peel_scenes.py
"""
import math

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from pointcloudsurface import vtkPerimeterPeelSurface
from run_peel_benchmark import cloud, field, quality


def sphere(rng, n, radius=1.0, centre=(0.0, 0.0, 0.0)):
    p = rng.normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1)[:, None] * radius + np.asarray(centre)


def dumbbell(rng, n, neck, length=3.0):
    """Unit spheres at x = 0 and x = length joined by a cylinder of radius `neck` along x."""
    sphere_area, neck_area = 4 * math.pi, 2 * math.pi * neck * length
    parts = []
    while sum(len(p) for p in parts) < n:
        pick = rng.choice(3, size=n, p=np.array([sphere_area, sphere_area, neck_area]) /
                          (2 * sphere_area + neck_area))
        s = sphere(rng, n)
        t, a = rng.random(n) * length, rng.random(n) * 2 * math.pi
        p = np.where((pick == 2)[:, None], np.c_[t, neck * np.cos(a), neck * np.sin(a)],
                     s + np.where((pick == 1)[:, None], [length, 0.0, 0.0], 0.0))
        in_a = np.linalg.norm(p, axis=1) < 1 - 1e-12
        in_b = np.linalg.norm(p - [length, 0.0, 0.0], axis=1) < 1 - 1e-12
        in_c = (p[:, 0] > 0) & (p[:, 0] < length) & (np.hypot(p[:, 1], p[:, 2]) < neck * (1 - 1e-12))
        keep = np.where(pick == 0, ~in_b & ~in_c, np.where(pick == 1, ~in_a & ~in_c, ~in_a & ~in_b))
        parts.append(p[keep])
    return np.vstack(parts)[:n]


def run(label, xyz, balls=None):
    """balls: (centre, radius, points) of each sphere of the scene, or None."""
    peel = vtkPerimeterPeelSurface()
    peel.SetInputData(cloud(xyz))
    peel.Update()
    out = peel.GetOutput()
    q = quality(out)
    far, farthest = "-", "-"
    if balls:
        t = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        c = xyz[t].mean(axis=1)
        d = np.min([np.abs(np.linalg.norm(c - np.asarray(ctr), axis=1) - r) /
                    (r * math.sqrt(4 * math.pi / n)) for ctr, r, n in balls], axis=0)
        far, farthest = str(int((d > 1).sum())), "%.2f" % d.max()
    print("| %s | %d | %d | %d | %d | %d | %d | %d | %s | %s |" % (
        label, len(xyz), out.GetNumberOfPolys(), field(q, "NumberOfConnectedComponents"),
        field(q, "Genus"), field(out, "NumberOfUnusedPoints"), field(out, "NumberOfGroupRemovals"),
        field(out, "NumberOfStrutPoints"), far, farthest), flush=True)


def main():
    print("| scene | points | triangles | components | genus | unused | groups | strut points |"
          " triangles over 1 h | farthest / h |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    rng = np.random.default_rng(9)
    for gap in (5, 3, 2.2, 2.05):
        for n in (5000, 20000):
            balls = [((0, 0, 0), 1.0, n), ((gap, 0, 0), 1.0, n)]
            run("two spheres, gap %g, %d each" % (gap, n),
                np.vstack([sphere(rng, n, r, c) for c, r, n in balls]), balls)
    scenes = {
        "three spheres, radii 1, 0.5, 0.3": [((0, 0, 0), 1.0, 8000), ((2.5, 0, 0), 0.5, 3000),
                                             ((0, 2.0, 0.5), 0.3, 2000)],
        "sphere and a 20x denser one": [((0, 0, 0), 1.0, 10000), ((3, 0, 0), 0.05, 10000)],
        "nine spheres": [((3 * i, 3 * j, 0), 1.0, 3000) for i in range(3) for j in range(3)],
    }
    for label, balls in scenes.items():
        run(label, np.vstack([sphere(rng, n, r, c) for c, r, n in balls]), balls)
    n = 20000
    h = math.sqrt(8 * math.pi / n)
    for seed in (1, 2):
        for k in (1.0, 1.5, 2.0, 3.0, 4.0):
            run("dumbbell, neck radius %g h, seed %d" % (k, seed),
                dumbbell(np.random.default_rng(seed), n, k * h))


if __name__ == "__main__":
    main()
