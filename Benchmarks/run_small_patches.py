"""Small open patches (issues 5 and 6): do they come back open, with one boundary loop?

Clouds: a bowl z = 0.2 (x^2 + y^2) and a saddle z = 0.3 (x^2 - y^2) over the unit disc, the flat
unit disc, and a flat strip 5 x 0.5; 20 to 2,000 points, random (seeds 0-2) or on a square grid
(two offsets). Filters with default parameters: vtkLocalOptimumGrowth (log),
vtkCDTAdvancingFront with PCA normals (cdt) and with the exact normals (cdtn),
vtkGreedySurfaceTriangulation (greedy). Printed per output that is not one component with one
boundary loop: boundary edges, loops, components, the closed components (triangles, enclosed
volume over area^1.5: 0 for a second layer back to back with the patch), unused points; then a
count per filter.

Usage: PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
    Benchmarks/run_small_patches.py [--summary]
"""
import sys, collections
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
import pointcloudsurface as pcs

def height(shape, x, y):
    if shape == "bowl": return 0.2 * (x * x + y * y)
    if shape == "saddle": return 0.3 * (x * x - y * y)
    return 0.0 * x

def normals(shape, x, y):
    if shape == "bowl": g = (0.4 * x, 0.4 * y)
    elif shape == "saddle": g = (0.6 * x, -0.6 * y)
    else: g = (0 * x, 0 * y)
    n = np.stack([-g[0], -g[1], np.ones_like(x)], 1)
    return n / np.linalg.norm(n, axis=1)[:, None]

def inside(shape, x, y):
    if shape == "strip": return (np.abs(x) <= 2.5) & (np.abs(y) <= 0.25)
    return x * x + y * y <= 1.0

def cloud(shape, n, sampling, seed):
    rng = np.random.default_rng(seed)
    area = 2.5 if shape == "strip" else np.pi
    if sampling == "random":
        pts = []
        while sum(len(p) for p in pts) < n:
            x = rng.uniform(-2.5 if shape == "strip" else -1, 2.5 if shape == "strip" else 1, 4 * n)
            y = rng.uniform(-1, 1, 4 * n)
            k = inside(shape, x, y); pts.append(np.stack([x[k], y[k]], 1))
        xy = np.concatenate(pts)[:n]
    else:
        h = np.sqrt(area / n)
        g = np.arange(-3, 3, h) + (seed * 0.1 * h)
        X, Y = np.meshgrid(g, g)
        x, y = X.ravel(), Y.ravel(); k = inside(shape, x, y)
        xy = np.stack([x[k], y[k]], 1)
    z = height(shape, xy[:, 0], xy[:, 1])
    return np.column_stack([xy, z]), normals(shape, xy[:, 0], xy[:, 1])

def polydata(p, nrm=None):
    pd = vtkPolyData(); pts = vtkPoints(); pts.SetData(numpy_to_vtk(np.ascontiguousarray(p), deep=1)); pd.SetPoints(pts)
    if nrm is not None:
        a = numpy_to_vtk(np.ascontiguousarray(nrm), deep=1); a.SetName("Normals"); pd.GetPointData().SetNormals(a)
    return pd

def triangles(out):
    polys = out.GetPolys()
    if polys.GetNumberOfCells() == 0: return np.zeros((0, 3), int)
    conn = vtk_to_numpy(polys.GetConnectivityArray()); return conn.reshape(-1, 3).astype(np.int64)

def measure(p, tri):
    """loops, components, closed components, |volume| of closed ones / area^1.5, unused"""
    edges = collections.Counter(); directed = {}
    for t in tri:
        for k in range(3):
            a, b = int(t[k]), int(t[(k + 1) % 3]); edges[(min(a, b), max(a, b))] += 1; directed[(a, b)] = 1
    bnd = [e for e, c in edges.items() if c == 1]
    # loops: boundary half-edges, walk
    nxt = collections.defaultdict(list)
    for (a, b) in directed:
        if edges[(min(a, b), max(a, b))] == 1: nxt[b].append(a)  # boundary walks reverse of triangle edge
    parent = {}
    def find(x):
        while parent.setdefault(x, x) != x: parent[x] = parent[parent[x]]; x = parent[x]
        return x
    for (a, b) in bnd: parent[find(a)] = find(b)
    loops = len({find(a) for (a, b) in bnd})
    # components by triangles sharing vertices
    parent2 = {}
    def f2(x):
        while parent2.setdefault(x, x) != x: parent2[x] = parent2[parent2[x]]; x = parent2[x]
        return x
    for t in tri: parent2[f2(t[0])] = f2(t[1]); parent2[f2(t[1])] = f2(t[2])
    comp = collections.defaultdict(list)
    for i, t in enumerate(tri): comp[f2(t[0])].append(i)
    bverts = {v for e in bnd for v in e}
    closed = []; 
    for r, ts in comp.items():
        T = tri[ts]
        if any(v in bverts for v in T.ravel()): continue
        a, b, c = p[T[:, 0]], p[T[:, 1]], p[T[:, 2]]
        vol = abs(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6
        area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
        closed.append((len(ts), vol / max(area, 1e-300) ** 1.5))
    unused = len(p) - len(np.unique(tri)) if len(tri) else len(p)
    return dict(be=len(bnd), loops=loops, comps=len(comp), closed=closed, unused=unused)

def run(method, p, nrm):
    if method == "log": f = pcs.vtkLocalOptimumGrowth(); f.SetInputData(polydata(p))
    elif method == "greedy": f = pcs.vtkGreedySurfaceTriangulation(); f.SetInputData(polydata(p))
    elif method == "cdt": f = pcs.vtkCDTAdvancingFront(); f.SetInputData(polydata(p))
    elif method == "cdtn": f = pcs.vtkCDTAdvancingFront(); f.SetInputData(polydata(p, nrm)); f.UseInputNormalsOn()
    f.Update(); return triangles(f.GetOutput())

if __name__ == "__main__":
    methods = ["log", "cdt", "cdtn", "greedy"]
    bad = collections.Counter(); total = collections.Counter(); rows = []
    for shape in ["bowl", "saddle", "disc", "strip"]:
        for sampling in ["random", "grid"]:
            for n in [20, 30, 60, 100, 200, 500, 2000]:
                for seed in ([0, 1, 2] if sampling == "random" else [0, 1]):
                    p, nrm = cloud(shape, n, sampling, seed)
                    for m in methods:
                        q = measure(p, run(m, p, nrm))
                        total[m] += 1
                        ok = q["loops"] == 1 and not q["closed"] and q["comps"] == 1
                        if not ok:
                            bad[m] += 1
                            rows.append("%s %s %s n=%d seed=%d: be %d loops %d comps %d closed %s unused %d" % (m, shape, sampling, len(p), seed, q["be"], q["loops"], q["comps"], q["closed"], q["unused"]))
                        if q["closed"]: bad[m + " closed"] += 1
    if "--summary" not in sys.argv:
        print("\n".join(rows))
    for m in methods:
        print("%s: not (one component, one loop, none closed) %d of %d; with a closed component %d" % (m, bad[m], total[m], bad[m + " closed"]))
