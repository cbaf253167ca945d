"""Webs of vtkPerimeterPeelSurface between two nearby parts of a surface (issue 4).

Two parallel tubes (radius 0.2, axes along x, 2 long) a given gap apart, sampled uniformly at
random by area, joined into one surface whose shape is known:
- "stadium": the tubes are joined at both ends by half-tori (a tube around a stadium curve):
  genus 1, and the slot between the tubes is a hole through the object;
- "hairpin": joined at one end only, the other ends closed by hemispheres: genus 0, the slot is
  open at one end.
The peel reaches the slot from both faces of the object at once; where the two fronts meet it
leaves a web: a layer of tetrahedra across the slot whose vertices are all on the surface already,
so that no single tetrahedron may go (the sculpting rules) and only group removals can clear it.
Printed per cloud: the gap in mean nearest-neighbour spacings of the cloud, the genus of the result
(vtkReconstructionQuality) against the shape's, coverage, group removals, and the largest distance
from the result to the true surface (vertices, edge midpoints and centroids of its triangles) in
mean spacings, with the number of triangles whose centroid is over 2 spacings from it (a web
across the slot lies about gap / 2 from both tubes).

Usage (a build with the Python package):
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
      Benchmarks/run_peel_web_benchmark.py [--points 20000] [--gaps 6,8,12,16,20] [--seeds 1,2]
"""
import argparse
import math
import os

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from pointcloudsurface import vtkPerimeterPeelSurface
from run_peel_benchmark import cloud, field, quality

LENGTH, RADIUS = 2.0, 0.2
# The area of the stadium's tube for a gap of 0 (the unit of the gaps: see --gaps).
AREA = 2 * math.pi * RADIUS * (2 * LENGTH + 2 * math.pi * RADIUS)


def centreline(s, bend):
    """Points, outward in-plane normals and curvatures at arc lengths s of the stadium curve: the
    upper bar (y = bend, x from -L/2 to L/2), the right half-circle, the lower bar, the left
    half-circle (radius `bend`)."""
    half = LENGTH / 2
    arc = math.pi * bend
    c = np.zeros((len(s), 3))
    normal = np.zeros((len(s), 3))
    curvature = np.zeros(len(s))
    upper = s < LENGTH
    c[upper] = np.c_[-half + s[upper], np.full(upper.sum(), bend), np.zeros(upper.sum())]
    normal[upper] = (0, 1, 0)
    right = (s >= LENGTH) & (s < LENGTH + arc)
    psi = math.pi / 2 - (s[right] - LENGTH) / bend
    c[right] = np.c_[half + bend * np.cos(psi), bend * np.sin(psi), np.zeros(right.sum())]
    normal[right] = np.c_[np.cos(psi), np.sin(psi), np.zeros(right.sum())]
    curvature[right] = 1 / bend
    lower = (s >= LENGTH + arc) & (s < 2 * LENGTH + arc)
    c[lower] = np.c_[half - (s[lower] - LENGTH - arc), np.full(lower.sum(), -bend),
                     np.zeros(lower.sum())]
    normal[lower] = (0, -1, 0)
    left = s >= 2 * LENGTH + arc
    psi = -math.pi / 2 - (s[left] - 2 * LENGTH - arc) / bend
    c[left] = np.c_[-half + bend * np.cos(psi), bend * np.sin(psi), np.zeros(left.sum())]
    normal[left] = np.c_[np.cos(psi), np.sin(psi), np.zeros(left.sum())]
    curvature[left] = 1 / bend
    return c, normal, curvature


def tube_points(m, rng, bend, skip_left):
    """About m points uniform by area on the tube around the stadium curve (without its left
    half-circle when skip_left), by rejection: the area element is 1 + r cos(t) x curvature."""
    total = 2 * LENGTH + 2 * math.pi * bend
    s = rng.random(4 * m) * total
    t = rng.random(4 * m) * 2 * math.pi
    c, normal, curvature = centreline(s, bend)
    keep = rng.random(4 * m) * (1 + RADIUS / bend) <= 1 + RADIUS * np.cos(t) * curvature
    if skip_left:
        keep &= s < 2 * LENGTH + math.pi * bend
    p = c + RADIUS * (np.cos(t)[:, None] * normal + np.sin(t)[:, None] * np.array([0, 0, 1.0]))
    return p[keep]


def sample(shape, n, gap, rng):
    bend = RADIUS + gap / 2
    tube_area = 2 * math.pi * RADIUS * (2 * LENGTH + (2 if shape == "stadium" else 1)
                                        * math.pi * bend)
    caps = 0.0 if shape == "stadium" else 4 * math.pi * RADIUS ** 2
    tubes = int(round(n * tube_area / (tube_area + caps)))
    p = np.empty((0, 3))
    while len(p) < tubes:
        p = np.vstack([p, tube_points(n, rng, bend, shape == "hairpin")])
    p = p[:tubes]
    if shape == "hairpin":
        v = rng.normal(size=(n - tubes, 3))
        v /= np.linalg.norm(v, axis=1)[:, None]
        v[:, 0] = -np.abs(v[:, 0])
        side = np.where(rng.random(n - tubes) < 0.5, bend, -bend)
        p = np.vstack([p, np.c_[-LENGTH / 2 + RADIUS * v[:, 0], side + RADIUS * v[:, 1],
                                RADIUS * v[:, 2]]])
    return p


def sample_stadium(n, gap_spacings, rng):
    """n random points of the stadium whose tubes are gap_spacings mean spacings apart (0.5
    sqrt(area / n) each, the mean nearest-neighbour distance of a uniform random sample)."""
    return sample("stadium", n, gap_spacings * 0.5 * math.sqrt(AREA / n), rng)


def distance(shape, x, gap):
    """Distance from the points x to the true surface."""
    bend = RADIUS + gap / 2
    half = LENGTH / 2
    rho = np.hypot(x[:, 0] - np.clip(x[:, 0], -half, half), x[:, 1])
    to_curve = np.hypot(rho - bend, x[:, 2])
    if shape == "hairpin":
        ends = np.minimum(np.linalg.norm(x - (-half, bend, 0), axis=1),
                          np.linalg.norm(x - (-half, -bend, 0), axis=1))
        to_curve = np.where(x[:, 0] < -half, ends, to_curve)
    return np.abs(to_curve - RADIUS)


def main():
    from scipy.spatial import cKDTree

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=20000)
    parser.add_argument("--shapes", default="hairpin,stadium")
    parser.add_argument("--gaps", default="6,8,12,16,20",
                        help="gaps between the tubes in mean spacings (0.5 sqrt(area / points), the "
                        "mean nearest-neighbour distance of a uniform random sample)")
    parser.add_argument("--seeds", default="1")
    args = parser.parse_args()
    load = os.getloadavg()
    print("load average %.2f %.2f %.2f, %d cores" % (load + (os.cpu_count(),)))
    print("| shape | points | seed | gap / spacing | genus (shape) | coverage | groups "
          "| largest distance / spacing | triangles over 2 spacings |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for shape in args.shapes.split(","):
        for g in args.gaps.split(","):
            gap = float(g) * 0.5 * math.sqrt(AREA / args.points)
            for seed in args.seeds.split(","):
                xyz = sample(shape, args.points, gap, np.random.default_rng(int(seed)))
                spacing = cKDTree(xyz).query(xyz, 2)[0][:, 1].mean()
                peel = vtkPerimeterPeelSurface()
                peel.SetInputData(cloud(xyz))
                peel.Update()
                out = peel.GetOutput()
                q = quality(out)
                triangles = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
                corners = xyz[triangles]
                samples = np.vstack([corners.reshape(-1, 3), corners.mean(axis=1),
                                     0.5 * (corners + np.roll(corners, 1, axis=1)).reshape(-1, 3)])
                far = distance(shape, corners.mean(axis=1), gap) > 2 * spacing
                print("| %s | %d | %s | %.1f | %d (%d) | %.4f | %d | %.2f | %d |"
                      % (shape, args.points, seed, gap / spacing, field(q, "Genus"),
                         1 if shape == "stadium" else 0, field(q, "Coverage"),
                         field(out, "NumberOfGroupRemovals"),
                         distance(shape, samples, gap).max() / spacing, far.sum()), flush=True)


if __name__ == "__main__":
    main()
