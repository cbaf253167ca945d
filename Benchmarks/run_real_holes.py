"""Planes, spheres and cylinders with a real hole: does vtkCDTAdvancingFront keep it open? (issue 6)

Clouds (1 point per unit area, so a grid spacing of 1; the mean nearest-point distance of the
random clouds is about 0.5): a k x k grid plane (plain, jittered by 0.1, rotated by 0.3 rad) and
k^2 uniform random points on the same square, without the points within r = 3, 5, 10, 20 of the
centre; a random sphere of radius 20 without a cap of geodesic radius 10; a random cylinder of
radius 10 and length 60 without a disc of radius 8 (in the unrolled surface). Each with the
default parameters (PCA normals), HoleFilling off and on. Printed: triangles, boundary edges and
loops (the plane and the cylinder have their outer boundaries too: 2 loops and 3 loops when the
hole stays open, 1 loop for the sphere), unused points, triangles whose centroid lies more than
half a unit inside the hole, the closest centroid over r, and the longest edge in mean spacings.

Usage: PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
    Benchmarks/run_real_holes.py [--refuse-rim-fans] [name filter ...]
(--refuse-rim-fans: vtkCDTAdvancingFront::RefuseRimFans on; default parameters otherwise.)
"""
import sys, math, numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
import pointcloudsurface as pcs
rng = np.random.default_rng(7)
def grid(k):
    i, j = np.meshgrid(np.arange(k), np.arange(k)); p = np.c_[i.ravel(), j.ravel(), np.zeros(k * k)].astype(float)
    return p - (k - 1) / 2
def rot(p, a=0.3):
    R = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]]); return p @ R.T
def clouds():
    for r in (3, 5, 10, 20):
        k = max(40, 4 * r)
        p = grid(k); keep = np.hypot(p[:, 0], p[:, 1]) > r
        yield "grid %d, hole r%d" % (k, r), p[keep], (lambda q: np.hypot(q[..., 0], q[..., 1])), r, 1.0
        pj = p[keep] + np.c_[rng.normal(scale=0.1, size=(keep.sum(), 2)), np.zeros(keep.sum())]
        yield "jittered grid %d, hole r%d" % (k, r), pj, (lambda q: np.hypot(q[..., 0], q[..., 1])), r, 1.0
        R = np.array([[1, 0, 0], [0, math.cos(0.3), -math.sin(0.3)], [0, math.sin(0.3), math.cos(0.3)]])
        yield "rotated grid %d, hole r%d" % (k, r), rot(p[keep]), (lambda q: np.hypot(*(q @ R)[..., :2].T) if q.ndim == 2 else np.hypot((q @ R)[..., 0], (q @ R)[..., 1])), r, 1.0
        # random points, density 1 per unit area (spacing ~ 1)
        n = k * k; q = np.c_[rng.uniform(-k / 2, k / 2, (n, 2)), np.zeros(n)]
        keep = np.hypot(q[:, 0], q[:, 1]) > r
        yield "random plane %d, hole r%d" % (n, r), q[keep], (lambda q: np.hypot(q[..., 0], q[..., 1])), r, 1.0
    # sphere of radius 20 (points 1 per unit area): a cap of angular radius matching 10 units removed
    n = int(4 * math.pi * 400); x = rng.normal(size=(n, 3)); x = 20 * x / np.linalg.norm(x, axis=1)[:, None]
    geo = lambda q: 20 * np.arccos(np.clip(q[..., 2] / np.linalg.norm(q, axis=-1), -1, 1))
    yield "random sphere r20, hole r10", x[geo(x) > 10], geo, 10, 1.0
    # cylinder radius 10, length 60, 1 point per unit area, a hole of radius 8 around (10, 0, 0)
    n = int(2 * math.pi * 10 * 60); t = rng.uniform(0, 2 * math.pi, n); z = rng.uniform(-30, 30, n)
    c = np.c_[10 * np.cos(t), 10 * np.sin(t), z]
    d = lambda q: np.hypot(10 * np.arctan2(q[..., 1], q[..., 0]), q[..., 2])
    yield "random cylinder r10, hole r8", c[d(c) > 8], d, 8, 1.0
def run(x, hf):
    pts = vtkPoints(); pts.SetData(numpy_to_vtk(np.ascontiguousarray(x, dtype=float), deep=1))
    pd = vtkPolyData(); pd.SetPoints(pts)
    f = pcs.vtkCDTAdvancingFront(); f.SetInputData(pd); f.SetHoleFilling(hf)
    if REFUSE:
        f.SetRefuseRimFans(True)
    f.Update()
    o = f.GetOutput()
    tri = vtk_to_numpy(o.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return tri, f.GetMeanSpacing()
def loops(tri):
    e = np.sort(np.r_[tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]], axis=1)
    ue, c = np.unique(e, axis=0, return_counts=True); b = ue[c == 1]
    parent = {}
    def find(a):
        while parent.setdefault(a, a) != a: a = parent[a]
        return a
    for a, bb in b: parent[find(a)] = find(bb)
    return len(b), len(set(find(v) for v in b.ravel()))
REFUSE = "--refuse-rim-fans" in sys.argv
only = [a for a in sys.argv[1:] if a != "--refuse-rim-fans"]
for name, x, dist, r, h in clouds():
    if only and not any(o in name for o in only): continue
    for hf in (0, 1):
        tri, s = run(x, hf)
        P = x[tri]; c = P.mean(axis=1); dc = dist(c)
        L = np.linalg.norm(P - np.roll(P, 1, axis=1), axis=2).max(axis=1) / s
        over = (dc < r - 0.5 * s).sum()
        nb, nl = loops(tri)
        print("%-30s HF=%d T=%d boundary edges %d loops %d unused %d | triangles with centroid 0.5 spacing inside the hole %d, closest centroid %.2f r | longest edge %.1f spacings" % (
            name, hf, len(tri), nb, nl, len(x) - len(np.unique(tri)), over, dc.min() / r, L.max()), flush=True)
