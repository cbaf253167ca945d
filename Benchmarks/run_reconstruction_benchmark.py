"""Reconstruction benchmark: every surface filter of PointCloudSurface that this build has, and
the peers a user would pick instead, on the same clouds in one run.

Peers: vtkDelaunay3D with Alpha followed by surface extraction (what ParaView users do today),
CGAL's Advancing Front Surface Reconstruction (pcsBenchCGALAFSR), and, for the
tetrahedralization, CGAL's Delaunay_triangulation_3 against vtkIncrementalDelaunay3D
(pcsBenchDelaunay).

Inputs: generated surfaces whose answers are known (sphere, torus, genus-2 surface, open
cylinder, half-sphere), the vertices of real meshes from Debian's libcgal-demo data (the meshes
are the references), damaged variants after paper 001 section 4 (two regions removed, three
regions thinned tenfold) and noisy variants (Gaussian noise of a quarter of the mean spacing).
Quality numbers come from vtkReconstructionQuality against the reference surface. Scaling: time
and memory from 10^4 to 10^6 points on the sphere and the torus, plotted log-log, with the
exponent of a least-squares fit.

Each method runs in its own process (this script with --worker, or the CGAL executable), so its
time is the reconstruction alone and its memory the growth of the resident set during it (peak
minus the resident set with the input loaded).

Usage (after the README's set-up; Benchmarks/run_reconstruction_benchmark.sh does all of it):
  /usr/bin/python3 Benchmarks/run_reconstruction_benchmark.py --bench-bin build-bench/bin \
      --data build-bench/cgal-data/data --output-dir Benchmarks/results [--quick]
"""
import argparse
import datetime
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

# The surface filters of the project, by command-line name: (class, parameters).
PROJECT_METHODS = [
    ("peel", "vtkPerimeterPeelSurface"),
    ("local-optimum", "vtkLocalOptimumGrowth"),
    ("cdt-front", "vtkCDTAdvancingFront"),
    ("greedy", "vtkGreedySurfaceTriangulation"),
]
PEER_METHODS = ["vtk-delaunay-alpha", "cgal-afsr"]

# vtkDelaunay3D is O(n^1.5) or worse in practice (50 s at 10^5 uniform points): not run above.
VTK_DELAUNAY_LIMIT = 30000
# Alpha of the vtkDelaunay3D peer, in units of the cloud's mean nearest-neighbour spacing, with
# AlphaTris on (a surface sample has no tetrahedra under a small alpha: the surface comes from the
# alpha triangles). Measured on a 5000-point sphere: alpha = 1, 1.5, 2, 3 spacings covered 34, 79,
# 96, 99 % of the points with 100, 1043, 3846, 11613 non-manifold edges; 2 is the usual choice.
VTK_ALPHA_SPACINGS = 2.0
TIMEOUT_SECONDS = 900


# ---------------------------------------------------------------------------------------------
# VTK helpers (imported lazily so that --help works without VTK).
def vtk():
    import vtkmodules.all as v  # noqa: F401

    return v


def numpy_to_polydata(points):
    v = vtk()
    from vtkmodules.util.numpy_support import numpy_to_vtk

    pts = v.vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=True))
    cloud = v.vtkPolyData()
    cloud.SetPoints(pts)
    return cloud


def polydata_points(mesh):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)


def triangulated(mesh):
    v = vtk()
    tri = v.vtkTriangleFilter()
    tri.SetInputData(mesh)
    tri.PassVertsOff()
    tri.PassLinesOff()
    clean = v.vtkCleanPolyData()  # merge the seam points of parametric sources
    clean.SetInputConnection(tri.GetOutputPort())
    clean.SetTolerance(1e-9)
    clean.Update()
    out = v.vtkPolyData()
    out.DeepCopy(clean.GetOutput())
    return out


def read_off(path):
    """Points and triangles of an OFF file (polygons fanned into triangles)."""
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                tokens.extend(line.split())
    if not tokens[0].upper().endswith("OFF"):
        raise ValueError(path + ": not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    points = np.array(tokens[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    triangles = []
    for _ in range(nf):
        k = int(tokens[at])
        ids = [int(t) for t in tokens[at + 1:at + 1 + k]]
        at += 1 + k
        for j in range(1, k - 1):
            triangles.append((ids[0], ids[j], ids[j + 1]))
    return points, np.array(triangles, dtype=np.int64).reshape(-1, 3)


def mesh_from_arrays(points, triangles):
    v = vtk()
    from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray

    mesh = numpy_to_polydata(points)
    n = len(triangles)
    cells = np.empty((n, 4), dtype=np.int64)
    cells[:, 0] = 3
    cells[:, 1:] = triangles
    ca = v.vtkCellArray()
    ca.SetCells(n, numpy_to_vtkIdTypeArray(cells.ravel(), deep=True))
    mesh.SetPolys(ca)
    return mesh


def mean_spacing(points):
    """Mean distance to the nearest other point (vtkStaticPointLocator)."""
    v = vtk()
    cloud = numpy_to_polydata(points)
    locator = v.vtkStaticPointLocator()
    locator.SetDataSet(cloud)
    locator.BuildLocator()
    ids = v.vtkIdList()
    rng = np.random.default_rng(7)
    sample = rng.choice(len(points), size=min(len(points), 20000), replace=False)
    total = 0.0
    for i in sample:
        locator.FindClosestNPoints(2, points[i], ids)
        j = ids.GetId(1) if ids.GetId(0) == i else ids.GetId(0)
        total += float(np.linalg.norm(points[j] - points[i]))
    return total / len(sample)


# ---------------------------------------------------------------------------------------------
# Generated surfaces: (points, reference mesh, description). Deterministic for a given seed.
def sample_sphere(n, rng, hemisphere=False):
    p = rng.normal(size=(n, 3))
    p /= np.linalg.norm(p, axis=1)[:, None]
    if hemisphere:
        p[:, 2] = np.abs(p[:, 2])
    return p


def sample_torus(n, rng, big=1.0, small=0.35):
    # Area element (big + small cos v): rejection sampling on v.
    u = rng.uniform(0, 2 * math.pi, size=4 * n)
    v = rng.uniform(0, 2 * math.pi, size=4 * n)
    keep = rng.uniform(0, 1, size=4 * n) < (big + small * np.cos(v)) / (big + small)
    u, v = u[keep][:n], v[keep][:n]
    r = big + small * np.cos(v)
    return np.column_stack([r * np.cos(u), r * np.sin(u), small * np.sin(v)])


def sample_cylinder(n, rng, radius=0.5, height=2.0):
    # Axis y, as vtkCylinderSource.
    t = rng.uniform(0, 2 * math.pi, size=n)
    y = rng.uniform(-height / 2, height / 2, size=n)
    return np.column_stack([radius * np.cos(t), y, radius * np.sin(t)])


def sample_mesh(mesh, n, rng):
    """Area-uniform random points on a triangle mesh."""
    pts = polydata_points(mesh)
    from vtkmodules.util.numpy_support import vtk_to_numpy

    conn = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a, b, c = pts[conn[:, 0]], pts[conn[:, 1]], pts[conn[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    tri = rng.choice(len(conn), size=n, p=area / area.sum())
    r1, r2 = rng.uniform(size=n), rng.uniform(size=n)
    s = np.sqrt(r1)
    return (1 - s)[:, None] * a[tri] + (s * (1 - r2))[:, None] * b[tri] + (s * r2)[:, None] * c[tri]


def reference_sphere(hemisphere=False):
    v = vtk()
    s = v.vtkSphereSource()
    s.SetRadius(1.0)
    s.SetThetaResolution(720)
    s.SetPhiResolution(360 if not hemisphere else 180)
    if hemisphere:
        s.SetEndPhi(90.0)
    s.Update()
    return triangulated(s.GetOutput())


def reference_torus(big=1.0, small=0.35):
    v = vtk()
    torus = v.vtkParametricTorus()
    torus.SetRingRadius(big)
    torus.SetCrossSectionRadius(small)
    src = v.vtkParametricFunctionSource()
    src.SetParametricFunction(torus)
    src.SetUResolution(720)
    src.SetVResolution(240)
    src.Update()
    return triangulated(src.GetOutput())


def reference_cylinder(radius=0.5, height=2.0):
    v = vtk()
    c = v.vtkCylinderSource()
    c.SetRadius(radius)
    c.SetHeight(height)
    c.SetResolution(1440)
    c.CappingOff()
    c.Update()
    return triangulated(c.GetOutput())


def reference_genus2():
    """A closed genus-2 surface: the level set of a smooth implicit function whose zero set is a
    tube around a figure-eight (lemniscate) curve, contoured finely (marching cubes)."""
    v = vtk()
    # f(x, y, z) = (((x^2 + y^2)^2 - (x^2 - y^2))^2 + z^2 - 0.04: a thickened lemniscate.
    n = 200
    xs = np.linspace(-1.4, 1.4, n)
    ys = np.linspace(-0.8, 0.8, int(n * 1.6 / 2.8))
    zs = np.linspace(-0.4, 0.4, int(n * 0.8 / 2.8))
    X, Y, Z = np.meshgrid(xs, ys, zs, indexing="ij")
    g = (X**2 + Y**2) ** 2 - (X**2 - Y**2)
    f = g**2 * 4.0 + Z**2 - 0.04
    image = v.vtkImageData()
    image.SetDimensions(len(xs), len(ys), len(zs))
    image.SetOrigin(xs[0], ys[0], zs[0])
    image.SetSpacing(xs[1] - xs[0], ys[1] - ys[0], zs[1] - zs[0])
    from vtkmodules.util.numpy_support import numpy_to_vtk

    values = numpy_to_vtk(np.ascontiguousarray(f.transpose(2, 1, 0).ravel()), deep=True)
    values.SetName("f")
    image.GetPointData().SetScalars(values)
    contour = v.vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOff()
    contour.Update()
    return triangulated(contour.GetOutput())


def generated_inputs(n, rng, names=None):
    makers = {
        "sphere": lambda: (sample_sphere(n, rng), reference_sphere()),
        "torus": lambda: (sample_torus(n, rng), reference_torus()),
        "genus-2 surface": lambda: (lambda ref: (sample_mesh(ref, n, rng), ref))(reference_genus2()),
        "open cylinder": lambda: (sample_cylinder(n, rng), reference_cylinder()),
        "half-sphere": lambda: (sample_sphere(n, rng, hemisphere=True), reference_sphere(True)),
    }
    for name, make in makers.items():
        if names is None or name in names:
            points, reference = make()
            yield name, points, reference


# ---------------------------------------------------------------------------------------------
# Damaged and noisy variants.
def damaged(points, rng, spacing):
    """Paper 001 section 4: two regions removed and three regions thinned tenfold. Region radius:
    8 % of the bounding-box diagonal; centres are random points of the cloud."""
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    radius = 0.08 * diagonal
    keep = np.ones(len(points), dtype=bool)
    centres = points[rng.choice(len(points), size=5, replace=False)]
    for k, c in enumerate(centres):
        inside = np.linalg.norm(points - c, axis=1) < radius
        if k < 2:
            keep &= ~inside
        else:
            keep &= ~(inside & (rng.uniform(size=len(points)) >= 0.1))
    return points[keep]


def noisy(points, rng, spacing, fraction=0.25):
    return points + rng.normal(scale=fraction * spacing, size=points.shape)


# ---------------------------------------------------------------------------------------------
# Worker: one method on one cloud, in its own process.
def status_mb(field):
    """VmRSS (current) or VmHWM (peak) of this process in MB. VmHWM belongs to the process's own
    address space, unlike getrusage's ru_maxrss, which keeps the parent's peak across exec."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def resident_mb():
    return status_mb("VmRSS")


def worker(args):
    v = vtk()
    points = np.load(args.cloud)
    cloud = numpy_to_polydata(points)
    params = json.loads(args.params) if args.params else {}
    baseline = resident_mb()
    if args.worker == "vtk-delaunay-alpha":
        delaunay = v.vtkDelaunay3D()
        delaunay.SetInputData(cloud)
        delaunay.SetAlpha(params["Alpha"])
        delaunay.AlphaTetsOn()
        delaunay.AlphaTrisOn()
        delaunay.AlphaLinesOff()
        delaunay.AlphaVertsOff()
        surface = v.vtkDataSetSurfaceFilter()
        surface.SetInputConnection(delaunay.GetOutputPort())
        surface.PassThroughPointIdsOn()
        start = time.perf_counter()
        surface.Update()
        seconds = time.perf_counter() - start
        # Back onto all input points, so coverage compares like with like.
        from vtkmodules.util.numpy_support import vtk_to_numpy

        out = surface.GetOutput()
        original = out.GetPointData().GetArray(surface.GetOriginalPointIdsName())
        tri = v.vtkTriangleFilter()
        tri.SetInputData(out)
        tri.Update()
        polys = tri.GetOutput().GetPolys()
        if polys.GetNumberOfCells() > 0 and original is not None:
            conn = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
            ids = vtk_to_numpy(original)[conn]
        else:
            ids = np.zeros((0, 3), dtype=np.int64)
        mesh = mesh_from_arrays(points, ids)
    elif args.worker == "ours-delaunay":
        import pointcloudsurface as pcs

        delaunay = pcs.vtkIncrementalDelaunay3D()
        delaunay.SetInputData(cloud)
        start = time.perf_counter()
        delaunay.Update()
        seconds = time.perf_counter() - start
        mesh = delaunay.GetOutput()
    else:
        import pointcloudsurface as pcs

        class_name = dict(PROJECT_METHODS)[args.worker]
        algorithm = getattr(pcs, class_name)()
        algorithm.SetInputData(cloud)
        for name, value in params.items():
            getattr(algorithm, "Set" + name)(value)
        start = time.perf_counter()
        algorithm.Update()
        seconds = time.perf_counter() - start
        mesh = algorithm.GetOutput()
    peak = status_mb("VmHWM")
    if args.out:
        writer = v.vtkXMLPolyDataWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(args.out)
        writer.SetDataModeToAppended()
        writer.Write()
    print(json.dumps({"seconds": seconds, "peak_mb": peak, "baseline_mb": baseline,
                      "triangles": mesh.GetNumberOfPolys()}))


# ---------------------------------------------------------------------------------------------
class Runner:
    def __init__(self, args, workdir):
        self.args = args
        self.workdir = workdir
        self.counter = 0
        import pointcloudsurface as pcs

        self.project = [(m, c) for m, c in PROJECT_METHODS if hasattr(pcs, c)]
        self.missing = [c for m, c in PROJECT_METHODS if not hasattr(pcs, c)]

    def methods(self):
        return [m for m, _ in self.project] + PEER_METHODS

    def run(self, method, points, spacing, want_mesh=True):
        """Returns a dict with seconds, memory_mb, triangles and (want_mesh) the mesh, or a dict
        with 'skipped' giving the reason."""
        if method == "vtk-delaunay-alpha" and len(points) > VTK_DELAUNAY_LIMIT:
            return {"skipped": "n > %d" % VTK_DELAUNAY_LIMIT}
        self.counter += 1
        base = os.path.join(self.workdir, "run%d" % self.counter)
        try:
            if method == "cgal-afsr":
                xyz = base + ".xyz"
                np.savetxt(xyz, points, fmt="%.17g")
                off = base + ".off" if want_mesh else None
                cmd = [os.path.join(self.args.bench_bin, "pcsBenchCGALAFSR"), xyz] + ([off] if off else [])
                result = self._call(cmd)
                if want_mesh:
                    p, t = read_off(off)
                    result["mesh"] = mesh_from_arrays(points, t)
            else:
                npy = base + ".npy"
                np.save(npy, points)
                vtp = base + ".vtp" if want_mesh else None
                params = {"Alpha": VTK_ALPHA_SPACINGS * spacing} if method == "vtk-delaunay-alpha" else {}
                cmd = [sys.executable, os.path.abspath(__file__), "--worker", method, "--cloud", npy,
                       "--params", json.dumps(params)] + (["--out", vtp] if vtp else [])
                result = self._call(cmd)
                if want_mesh:
                    reader = vtk().vtkXMLPolyDataReader()
                    reader.SetFileName(vtp)
                    reader.Update()
                    result["mesh"] = reader.GetOutput()
        except subprocess.TimeoutExpired:
            return {"skipped": "timeout %d s" % TIMEOUT_SECONDS}
        except (subprocess.CalledProcessError, ValueError, OSError) as error:
            return {"skipped": "failed (%s)" % str(error).splitlines()[0][:80]}
        finally:
            for ext in (".xyz", ".npy", ".vtp", ".off"):
                if os.path.exists(base + ext):
                    os.remove(base + ext)
        result["memory_mb"] = max(result["peak_mb"] - result["baseline_mb"], 0.0)
        return result

    def _call(self, cmd):
        out = subprocess.run(cmd, check=True, capture_output=True, text=True,
                             timeout=TIMEOUT_SECONDS).stdout
        return json.loads(out.strip().splitlines()[-1])

    def delaunay(self, method, points):
        """Tetrahedralization only: 'ours' (vtkIncrementalDelaunay3D) or 'cgal' (DT3)."""
        self.counter += 1
        xyz = os.path.join(self.workdir, "run%d.xyz" % self.counter)
        np.savetxt(xyz, points, fmt="%.17g")
        try:
            out = subprocess.run([os.path.join(self.args.bench_bin, "pcsBenchDelaunay"), method, xyz],
                                 check=True, capture_output=True, text=True,
                                 timeout=TIMEOUT_SECONDS).stdout
            return json.loads(out.strip().splitlines()[-1])
        finally:
            os.remove(xyz)


def quality(mesh, reference):
    v = vtk()
    import pointcloudsurface as pcs

    q = pcs.vtkReconstructionQuality()
    q.SetInputData(0, mesh)
    q.SetInputData(1, reference)
    q.Update()
    fd = q.GetOutput().GetFieldData()

    def get(name):
        array = fd.GetArray(name)
        return array.GetTuple1(0) if array is not None else float("nan")

    names = ["NumberOfTriangles", "Coverage", "NumberOfNonManifoldEdges",
             "NumberOfNonManifoldVertices", "NumberOfBoundaryEdges", "NumberOfBoundaryLoops",
             "NumberOfConnectedComponents", "EulerCharacteristic", "Genus",
             "OrientationConsistency", "AccuracyMeanOverSpacing", "CompletenessMaxOverSpacing",
             "HausdorffOverSpacing", "MinAngleP1"]
    return {n: get(n) for n in names}


def reference_topology(reference):
    import pointcloudsurface as pcs

    q = pcs.vtkReconstructionQuality()
    q.SetInputData(0, reference)
    q.SetComputeDistances(False)
    q.Update()
    fd = q.GetOutput().GetFieldData()
    get = lambda n: fd.GetArray(n).GetTuple1(0)
    loops = int(get("NumberOfBoundaryLoops"))
    if loops == 0 and get("NumberOfNonManifoldEdges") == 0:
        return "closed, genus %d" % int(get("Genus"))
    return "open, %d boundary loop%s" % (loops, "" if loops == 1 else "s")


# ---------------------------------------------------------------------------------------------
def fmt(x, digits=2):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if isinstance(x, float) and x == int(x) and abs(x) < 1e15 and digits == 0:
        return "%d" % int(x)
    return ("%." + str(digits) + "f") % x


def quality_section(runner, args, rng, lines):
    n_generated = 5000 if args.quick else 20000
    inputs = []
    for name, points, reference in generated_inputs(n_generated, rng):
        inputs.append((name, points, reference))
    real = [("bunny (CGAL bunny00)", "meshes/bunny00.off"),
            ("armadillo (CGAL)", "meshes/armadillo.off"),
            ("camel (CGAL)", "meshes/camel.off"),
            ("knot (CGAL knot1)", "meshes/knot1.off")]
    if args.quick:
        real = real[2:3]
    for label, rel in real:
        path = os.path.join(args.data, rel)
        if not os.path.exists(path):
            print("missing real surface", path, file=sys.stderr)
            continue
        p, t = read_off(path)
        reference = mesh_from_arrays(p, t)
        inputs.append((label, p, reference))
        spacing = mean_spacing(p)
        inputs.append((label + ", damaged", damaged(p, rng, spacing), reference))
        inputs.append((label + ", noisy", noisy(p, rng, spacing), reference))

    lines.append("## Quality on surfaces with known answers\n")
    lines.append("Accuracy, completeness and Hausdorff distances are in units of the cloud's mean "
                 "nearest-neighbour spacing (vtkReconstructionQuality). Coverage: fraction of the "
                 "input points that are triangle vertices. Memory: growth of the resident set "
                 "during the reconstruction. vtkDelaunay3D+Alpha uses Alpha = %.1f x the mean "
                 "spacing and runs up to %d points.\n" % (VTK_ALPHA_SPACINGS, VTK_DELAUNAY_LIMIT))
    lines.append("| input | reference | points | method | time s | memory MB | triangles | coverage | "
                 "non-manifold edges / vertices | boundary edges / loops | components | genus | "
                 "orientation | accuracy mean | completeness max | Hausdorff | min angle P1 |")
    lines.append("|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    summary = {}
    topologies = {}
    for name, points, reference in inputs:
        spacing = mean_spacing(points)
        topology = reference_topology(reference)
        topologies[name] = topology
        for method in runner.methods():
            result = runner.run(method, points, spacing)
            print(name, method, {k: v for k, v in result.items() if k != "mesh"}, flush=True)
            if "skipped" in result:
                lines.append("| %s | %s | %d | %s | %s |  |  |  |  |  |  |  |  |  |  |  |  |"
                             % (name, topology, len(points), method, result["skipped"]))
                continue
            q = quality(result["mesh"], reference)
            summary.setdefault(method, []).append((name, q, result))
            lines.append("| %s | %s | %d | %s | %s | %s | %d | %s | %d / %d | %d / %d | %d | %s | %s | %s | %s | %s | %s |" % (
                name, topology, len(points), method, fmt(result["seconds"], 3),
                fmt(result["memory_mb"], 0), result["triangles"], fmt(q["Coverage"], 4),
                q["NumberOfNonManifoldEdges"], q["NumberOfNonManifoldVertices"],
                q["NumberOfBoundaryEdges"], q["NumberOfBoundaryLoops"],
                q["NumberOfConnectedComponents"],
                "-" if q["Genus"] < 0 else "%d" % q["Genus"],
                fmt(q["OrientationConsistency"], 3), fmt(q["AccuracyMeanOverSpacing"]),
                fmt(q["CompletenessMaxOverSpacing"]), fmt(q["HausdorffOverSpacing"]),
                fmt(q["MinAngleP1"], 1)))
    lines.append("")
    return summary, topologies


def summary_section(summary, lines, topologies):
    """One row per method over every input of the quality table: the figures a user compares."""
    cgal = {name: result for name, _, result in summary.get("cgal-afsr", [])}
    lines.append("## Summary\n")
    lines.append("Over every input of the quality table below (%d inputs). Time ratio: the method's "
                 "time divided by CGAL's advancing front on the same cloud (median, and the worst). "
                 "Closed / right genus: outputs that are closed 2-manifolds, and of those the "
                 "ones with the reference's genus, among the inputs whose reference is closed. "
                 "Distances in mean spacings.\n" % len(topologies))
    lines.append("| method | inputs | time ratio median (max) | coverage median (min) | "
                 "non-manifold edges + vertices (sum) | closed / right genus | orientation min | "
                 "Hausdorff median (max) |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|")
    closed_inputs = [n for n, t in topologies.items() if t.startswith("closed")]
    for method, rows in summary.items():
        ratios = [r["seconds"] / cgal[n]["seconds"] for n, _, r in rows
                  if n in cgal and cgal[n]["seconds"] > 0]
        coverage = [q["Coverage"] for _, q, _ in rows]
        nonmanifold = sum(int(q["NumberOfNonManifoldEdges"] + q["NumberOfNonManifoldVertices"])
                          for _, q, _ in rows)
        closed = [(n, q) for n, q, _ in rows if n in closed_inputs and q["NumberOfBoundaryLoops"] == 0
                  and q["NumberOfNonManifoldEdges"] == 0 and q["NumberOfNonManifoldVertices"] == 0]
        right = [n for n, q in closed if topologies[n] == "closed, genus %d" % int(q["Genus"])]
        tested_closed = [n for n, _, _ in rows if n in closed_inputs]
        hausdorff = [q["HausdorffOverSpacing"] for _, q, _ in rows]
        orientation = [q["OrientationConsistency"] for _, q, _ in rows]
        lines.append("| %s | %d | %s (%s) | %s (%s) | %d | %d / %d of %d | %s | %s (%s) |" % (
            method, len(rows), fmt(float(np.median(ratios)) if ratios else None),
            fmt(max(ratios) if ratios else None), fmt(float(np.median(coverage)), 4),
            fmt(min(coverage), 4), nonmanifold, len(closed), len(right), len(tested_closed),
            fmt(min(orientation), 3), fmt(float(np.median(hausdorff))), fmt(max(hausdorff))))
    lines.append("")


def fit_exponent(ns, values):
    pairs = [(n, t) for n, t in zip(ns, values) if t is not None and t > 0]
    if len(pairs) < 2:
        return None
    x = np.log([p[0] for p in pairs])
    y = np.log([p[1] for p in pairs])
    return float(np.polyfit(x, y, 1)[0])


def scaling_section(runner, args, rng, lines, outdir):
    sizes = [10000, 30000, 100000] if args.quick else [10000, 30000, 100000, 300000, 1000000]
    series = {}  # (surface, method) -> {"n": [], "seconds": [], "memory": []}
    for surface in ("sphere", "torus"):
        for n in sizes:
            points = sample_sphere(n, rng) if surface == "sphere" else sample_torus(n, rng)
            spacing = mean_spacing(points) if n <= VTK_DELAUNAY_LIMIT else None
            for method in runner.methods():
                result = runner.run(method, points, spacing, want_mesh=False)
                print(surface, n, method, result, flush=True)
                s = series.setdefault((surface, method), {"n": [], "seconds": [], "memory": []})
                s["n"].append(n)
                s["seconds"].append(result.get("seconds"))
                s["memory"].append(result.get("memory_mb"))
            for method in ("ours", "cgal"):
                result = runner.delaunay(method, points)
                key = (surface, "tetrahedralization: " + ("vtkIncrementalDelaunay3D" if method == "ours"
                                                          else "CGAL Delaunay_triangulation_3"))
                s = series.setdefault(key, {"n": [], "seconds": [], "memory": []})
                s["n"].append(n)
                s["seconds"].append(result["seconds"])
                s["memory"].append(None)

    lines.append("## Scaling (time and memory from 10^4 to 10^6 points)\n")
    lines.append("Exponent: slope of the least-squares line through log(time) (or log(memory)) "
                 "against log(points). Memory: growth of the resident set during the run (peak "
                 "minus the resident set with the input loaded), also per input point at the "
                 "largest size. Plots: `reconstruction_scaling_time.png`, "
                 "`reconstruction_scaling_memory.png`.\n")
    header = ("| surface | method | " + " | ".join("%g s" % n for n in sizes) +
              " | time exponent | memory exponent | bytes per point at %g |" % sizes[-1])
    lines.append(header)
    lines.append("|---|---|" + "---:|" * (len(sizes) + 3))
    for (surface, method), s in series.items():
        cells = [fmt(t, 3) if t is not None else "-" for t in s["seconds"]]
        last = s["memory"][-1] if s["memory"] else None
        per_point = "%.0f" % (last * 1048576.0 / s["n"][-1]) if last else "-"
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            surface, method, " | ".join(cells), fmt(fit_exponent(s["n"], s["seconds"])),
            fmt(fit_exponent(s["n"], s["memory"])), per_point))
    lines.append("")
    # Ratios to CGAL's advancing front.
    lines.append("Time ratio to CGAL's advancing front (same cloud):\n")
    lines.append("| surface | method | " + " | ".join("%g" % n for n in sizes) + " |")
    lines.append("|---|---|" + "---:|" * len(sizes))
    for (surface, method), s in series.items():
        if method in ("cgal-afsr",) or method.startswith("tetrahedralization"):
            continue
        ref = series.get((surface, "cgal-afsr"))
        cells = []
        for t, r in zip(s["seconds"], ref["seconds"]):
            cells.append(fmt(t / r) if t and r else "-")
        lines.append("| %s | %s | %s |" % (surface, method, " | ".join(cells)))
    lines.append("")

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        lines.append("(matplotlib missing: no plots)\n")
        return
    for quantity, ylabel, filename in (("seconds", "time (s)", "reconstruction_scaling_time.png"),
                                       ("memory", "memory growth (MB)", "reconstruction_scaling_memory.png")):
        fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
        for ax, surface in zip(axes, ("sphere", "torus")):
            for (surf, method), s in series.items():
                if surf != surface:
                    continue
                pairs = [(n, y) for n, y in zip(s["n"], s[quantity]) if y is not None and y > 0]
                if len(pairs) < 2:
                    continue
                exponent = fit_exponent([p[0] for p in pairs], [p[1] for p in pairs])
                ax.loglog([p[0] for p in pairs], [p[1] for p in pairs], "o-",
                          label="%s (n^%.2f)" % (method, exponent))
            ax.set_title(surface)
            ax.set_xlabel("points")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        axes[0].set_ylabel(ylabel)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, filename), dpi=90)
        plt.close(fig)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def source_state():
    """The commit measured, and whether the working tree differed from it."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], check=True,
                                capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"],
                               check=True, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "not a git checkout"
    return "commit %s%s" % (commit, " with local changes" if dirty else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench-bin", default="build-bench/bin")
    parser.add_argument("--data", default="build-bench/cgal-data/data")
    parser.add_argument("--output-dir", default="Benchmarks/results")
    parser.add_argument("--quick", action="store_true", help="small sizes (a smoke run)")
    parser.add_argument("--skip-scaling", action="store_true")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    parser.add_argument("--cloud", help=argparse.SUPPRESS)
    parser.add_argument("--params", help=argparse.SUPPRESS)
    parser.add_argument("--out", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args)
        return
    os.makedirs(args.output_dir, exist_ok=True)
    rng = np.random.default_rng(2026)
    lines = ["# Reconstruction benchmark\n",
             "Command: `Benchmarks/run_reconstruction_benchmark.sh%s`. Date %s; %s, %d cores; %s; "
             "source %s; load average %.1f at the start.\n"
             % (" ".join([""] + [a for a in sys.argv[1:] if a in ("--quick", "--skip-scaling")]),
                datetime.date.today().isoformat(), cpu_model(), os.cpu_count(), platform.platform(),
                source_state(), os.getloadavg()[0])]
    with tempfile.TemporaryDirectory(prefix="pcs-bench-") as workdir:
        runner = Runner(args, workdir)
        lines.append("Methods: %s. Not built yet (skipped): %s.\n" % (
            ", ".join(runner.methods()), ", ".join(runner.missing) or "none"))
        table = []
        summary, topologies = quality_section(runner, args, rng, table)
        summary_section(summary, lines, topologies)
        lines.extend(table)
        if not args.skip_scaling:
            scaling_section(runner, args, rng, lines, args.output_dir)
    name = "reconstruction_quick.md" if args.quick else "reconstruction.md"
    with open(os.path.join(args.output_dir, name), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", os.path.join(args.output_dir, name))


if __name__ == "__main__":
    main()
