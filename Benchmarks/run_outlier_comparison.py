"""Outlier rules compared (the OutlierFactor of vtkPerimeterPeelSurface and vtkLocalOptimumGrowth).

Rules (k = 8 nearest neighbours; a point's reach = mean distance to them):
  SOR25xF  VTK's vtkStatisticalOutlierRemoval (SampleSize 25, StandardDeviationFactor F)
  L FxGy   reach > x times the median reach of its 8 neighbours, or > y times the cloud's median
  D Fx     reach > 4 x the cloud's median reach ("sparse") and > x times the median reach of its
           8 nearest non-sparse points (pcs::FindOutliers until 2026-11-24)
  DP Fx    the rule kept (pcs::FindOutliers): D Fx, except a point whose 8 nearest points are all
           sparse and a flat disc (covariance eigenvalues: smallest < 0.02, middle >=
           0.1 of the sum) with the point within 0.3 x its reach of their plane (DP F8 H0.1:
           0.1, the rule until 2026-11-25), and at least
           half of those 8 passing the same test (a sparse part of a sampled surface)
Modes:
  fp MODE  false positives on the vertex sets of every CGAL demo mesh of >= 32 distinct points
           (MODE vertices or noisy: Gaussian noise of 0.4 mean spacings per coordinate), or on
           10^5-point random samples (MODE sample, samplenoisy) of the meshes in --only
  tp MODE  flagged / planted outliers (flagged clean points in parentheses) for outliers added to
           the meshes in --only (MODE vertices or sample): uniform in a box 1.5 or 3 times the
           bounding box (those within 10 mean spacings of the points not counted), single far
           points, a clump of 5, 20 points at 5 or 10 mean spacings off the surface
Usage: /usr/bin/python3 Benchmarks/run_outlier_comparison.py fp vertices --data /work/cgaldata/data
       /usr/bin/python3 Benchmarks/run_outlier_comparison.py tp vertices --only bunny00,camel,knot1,elephant
"""
import argparse
import glob
import os

import numpy as np
from scipy.spatial import cKDTree


def read_off_any(path):
    """Vertices and triangles of an OFF / COFF file (line based: colour values ignored)."""
    lines = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                lines.append(line.split())
    at = 1
    counts = lines[0][1:4] if len(lines[0]) > 1 else lines[1]
    at = 1 if len(lines[0]) > 1 else 2
    nv, nf = int(counts[0]), int(counts[1])
    p = np.array([[float(v) for v in l[:3]] for l in lines[at:at + nv]])
    tris = []
    for l in lines[at + nv:at + nv + nf]:
        ids = [int(x) for x in l[1:1 + int(l[0])]]
        tris += [(ids[0], ids[j], ids[j + 1]) for j in range(1, len(ids) - 1)]
    return p, np.array(tris, dtype=np.int64).reshape(-1, 3)


def reach_of(p, k=8):
    tree = cKDTree(p)
    d, i = tree.query(p, k + 1)
    return tree, d[:, 1:].mean(axis=1), i[:, 1:]


def upper_median(r, axis):
    return np.sort(r, axis=axis).take(r.shape[axis] // 2, axis=axis)


def local_rule(p, F, G, k=8):
    if len(p) < 4 * k:
        return np.zeros(len(p), bool)
    _, r, i = reach_of(p, k)
    return (r > F * upper_median(r[i], 1)) | (r > G * upper_median(r, 0))


def dense_rule(p, F, S=4.0, k=8):
    if len(p) < 4 * k:
        return np.zeros(len(p), bool)
    _, r, _ = reach_of(p, k)
    sparse = r > S * upper_median(r, 0)
    flag = np.zeros(len(p), bool)
    if sparse.any() and not sparse.all():
        dense = np.where(~sparse)[0]
        w = min(k, len(dense))
        _, near = cKDTree(p[dense]).query(p[sparse], w)
        near = dense[near.reshape(len(near), -1)]
        flag[sparse] = r[sparse] > F * upper_median(r[near], 1)
    return flag


def dense_plane_rule(p, F, S=4.0, k=8, H=0.3):
    """The rule kept since 2026-11-24: dense_rule, except points on the flat sample of their
    own nearest points (a sparse part of the surface), the point within H x its reach of their
    plane (H 0.1 until 2026-11-25, 0.3 since)."""
    if len(p) < 4 * k:
        return np.zeros(len(p), bool)
    _, r, i = reach_of(p, k)
    flag = dense_rule(p, F, S, k)
    idx = np.where(r > S * upper_median(r, 0))[0]
    if len(idx):
        q = p[i[idx]]
        c = q.mean(axis=1)
        d = q - c[:, None, :]
        cov = np.einsum("mki,mkj->mij", d, d) / k
        w, v = np.linalg.eigh(cov)
        flat = (w[:, 0] < 0.02 * w.sum(axis=1)) & (w[:, 1] >= 0.1 * w.sum(axis=1))
        h = np.abs(np.einsum("mi,mi->m", c - p[idx], v[:, :, 0]))
        sparse = r > S * upper_median(r, 0)
        among = sparse[i[idx]].all(axis=1)
        ok = np.zeros(len(p), bool)
        ok[idx[flat & among & (h < H * r[idx])]] = True
        surface = ok & (2 * ok[i].sum(axis=1) >= k)
        flag[surface] = False
    return flag


def sor(p, F, k=25):
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    pts = vtk.vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(p), deep=1))
    cloud = vtk.vtkPolyData()
    cloud.SetPoints(pts)
    ids = numpy_to_vtk(np.arange(len(p), dtype=np.int64), deep=1)
    ids.SetName("ids")
    cloud.GetPointData().AddArray(ids)
    f = vtk.vtkStatisticalOutlierRemoval()
    f.SetInputData(cloud)
    f.SetSampleSize(k)
    f.SetStandardDeviationFactor(F)
    f.Update()
    flag = np.ones(len(p), bool)
    flag[vtk_to_numpy(f.GetOutput().GetPointData().GetArray("ids"))] = False
    return flag


RULES = {
    "SOR25x3": lambda p: sor(p, 3.0), "SOR25x5": lambda p: sor(p, 5.0),
    "SOR25x10": lambda p: sor(p, 10.0), "L F5 G20": lambda p: local_rule(p, 5.0, 20.0),
    "D F6": lambda p: dense_rule(p, 6.0), "D F8": lambda p: dense_rule(p, 8.0),
    "D F10": lambda p: dense_rule(p, 10.0), "DP F8": lambda p: dense_plane_rule(p, 8.0),
    "DP F8 H0.1": lambda p: dense_plane_rule(p, 8.0, H=0.1),
}


def sample_mesh(p, t, n, rng):
    a, b, c = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    f = rng.choice(len(t), n, p=area / area.sum())
    u, v = rng.random(n), rng.random(n)
    s = u + v > 1
    u[s], v[s] = 1 - u[s], 1 - v[s]
    return a[f] + u[:, None] * (b[f] - a[f]) + v[:, None] * (c[f] - a[f])


def spacing(p):
    return cKDTree(p).query(p, 2)[0][:, 1].mean()


def cloud_of(path, mode, rng):
    p0, t = read_off_any(path)
    p = np.unique(p0, axis=0)
    if len(p) < 32:
        return None
    if mode.startswith("sample"):
        if len(t) == 0:
            return None
        p = sample_mesh(p0, t, 100000, rng)
    if mode.endswith("noisy"):
        p = p + rng.normal(scale=0.4 * spacing(p), size=p.shape)
    return p


def false_positives(args, rng):
    total = {r: [0, 0, 0] for r in RULES}
    worst = {r: [] for r in RULES}
    for path in sorted(glob.glob(os.path.join(args.data, "meshes", "*.off"))):
        name = os.path.basename(path)[:-4]
        if args.only and name not in args.only.split(","):
            continue
        p = cloud_of(path, args.mode, rng)
        if p is None:
            continue
        for rule, fn in RULES.items():
            c = int(fn(p).sum())
            total[rule][0] += c
            total[rule][1] += c > 0
            total[rule][2] += len(p)
            if c:
                worst[rule].append((c, name))
    print("| rule | points flagged | of | sets with any | worst |\n|---|---:|---:|---:|---|")
    for rule in RULES:
        print("| %s | %d | %d | %d | %s |" % (rule, total[rule][0], total[rule][2], total[rule][1],
              ", ".join("%s %d" % (n, c) for c, n in sorted(worst[rule], reverse=True)[:4])))


def planted(p, rng):
    n, lo, hi = len(p), p.min(0), p.max(0)
    c, e, s = (lo + hi) / 2, hi - lo, spacing(p)
    out = {}
    for frac in (0.001, 0.01, 0.03, 0.10):
        for scale in (1.5, 3.0):
            m = max(1, int(round(frac * n)))
            out["box %g%% x%g" % (100 * frac, scale)] = c + (rng.random((m, 3)) - 0.5) * e * scale
    diag = np.linalg.norm(e)
    dirs = rng.normal(size=(3, 3))
    out["3 single far"] = c + dirs / np.linalg.norm(dirs, axis=1)[:, None] * diag
    d = rng.normal(size=3)
    out["clump of 5"] = c + d / np.linalg.norm(d) * diag + rng.normal(scale=0.5 * s, size=(5, 3))
    for off in (5, 10):
        dd = rng.normal(size=(20, 3))
        out["20 at %d sp" % off] = (p[rng.choice(n, 20, replace=False)] +
                                   dd / np.linalg.norm(dd, axis=1)[:, None] * off * s)
    return out, s


def true_positives(args, rng):
    res = {}
    labels = None
    for name in args.only.split(","):
        p = cloud_of(os.path.join(args.data, "meshes", name + ".off"), args.mode, rng)
        scenarios, s = planted(p, rng)
        labels = list(scenarios)
        tree = cKDTree(p)
        for label, o in scenarios.items():
            dist = tree.query(o)[0]
            counted = dist > (4 if "sp" in label else 10) * s
            q = np.vstack([p, o])
            for rule, fn in RULES.items():
                m = fn(q)
                a = res.setdefault((rule, label), [0, 0, 0])
                a[0] += int(m[len(p):][counted].sum())
                a[1] += int(counted.sum())
                a[2] += int(m[:len(p)].sum())
    print("| rule | " + " | ".join(labels) + " |\n|---|" + "---|" * len(labels))
    for rule in RULES:
        print("| %s | " % rule + " | ".join("%d/%d (%d)" % tuple(res[(rule, l)]) for l in labels) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("what", choices=["fp", "tp"])
    parser.add_argument("mode", choices=["vertices", "noisy", "sample", "samplenoisy"])
    parser.add_argument("--data", default="/work/cgaldata/data")
    parser.add_argument("--only", default="", help="comma-separated mesh names")
    parser.add_argument("--rules", default="", help="comma-separated rule names (default: all)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if args.rules:
        for r in list(RULES):
            if r not in args.rules.split(","):
                del RULES[r]
    rng = np.random.default_rng(args.seed)
    (false_positives if args.what == "fp" else true_positives)(args, rng)


if __name__ == "__main__":
    main()
