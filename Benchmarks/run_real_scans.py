#!/usr/bin/env python3
"""Every filter and CGAL's advancing front on CGAL's real point sets (data/points_3).

The other benchmarks sample meshes, so their clouds are uniform or follow the mesh's vertices.
CGAL's demo data also ships point sets as users have them: scans and sampled models with density
that varies by a factor of 70 (radar), heavy noise (sphere_20k: radial noise of about 1.6 mean
spacings), planar clouds (point_set_2, circles), a volume of random points (oneK), CAD-like
buildings with sharp edges (building, b9_training). There is no reference surface, so this
script reports what can be judged without one, side by side with CGAL's advancing front
(pcsBenchCGALAFSR, default parameters) on the same points:

- CPU seconds of the reconstruction alone (the filter's Update; CGAL's own processor time), and
  the ratio to CGAL's;
- triangles, input points left unused, points added (greedy's faired fills), boundary edges,
  connected components, non-manifold edges + vertices (vtkReconstructionQuality);
- long edges: triangle edges longer than 6 times the larger of their two end points' distance to
  their 6th nearest input point: edges that jump over the local sampling (webs, bridges, caps).

Each run is a separate process with a time limit, so a hang shows as TIMEOUT and a crash as its
return code. Only the point coordinates are given to the filters (normals in the files are
ignored: vtkCDTAdvancingFront estimates its own), with default parameters.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_real_scans.py \
      --data /usr/share/cgal-demo/data [--cgal <bench-bin>/pcsBenchCGALAFSR] \
      [--clouds kitten radar] [--filters log cdt greedy peel] [--timeout 300]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree

# The point sets of data/points_3 that hold a surface or a hostile case; file name per label.
CLOUDS = {
    "kitten": "kitten.xyz", "hippo1": "hippo1.ply", "hippo2": "hippo2.ply", "oni": "oni.ply",
    "ball": "ball.ply", "building": "building.ply", "radar": "radar.xyz",
    "poste_france": "poste_france.xyz", "b9_training": "b9_training.ply",
    "sphere_20k": "sphere_20k.xyz", "blobby": "blobby.xyz", "point_set_3": "point_set_3.xyz",
    "fin90": "fin90_with_PCA_normals.xyz", "circles": "circles.ply", "half": "half.xyz",
    "before_upsample": "before_upsample.xyz", "point_set_2": "point_set_2.xyz",
    "spheres": "spheres.ply", "oneK": "oneK.xyz"}
FILTER_NAMES = ["peel", "log", "cdt", "greedy"]
LONG_EDGE_FACTOR = 6.0
LOCAL_NEIGHBOR = 6


def load_points(path):
    """The x y z of a PLY (vtkPLYReader) or of a whitespace text file (first three columns)."""
    if path.endswith(".ply"):
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkIOPLY import vtkPLYReader
        reader = vtkPLYReader()
        reader.SetFileName(path)
        reader.Update()
        return vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)
    return np.loadtxt(path, ndmin=2)[:, :3].astype(float)


def long_edges(points, triangles):
    """Edges longer than LONG_EDGE_FACTOR x the larger local spacing of their two end points."""
    if len(triangles) == 0:
        return 0
    k = min(LOCAL_NEIGHBOR + 1, len(points))
    local = cKDTree(points).query(points, k=k)[0][:, -1]
    edges = np.sort(np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]],
                               triangles[:, [2, 0]]]), axis=1)
    edges = np.unique(edges, axis=0)
    length = np.linalg.norm(points[edges[:, 0]] - points[edges[:, 1]], axis=1)
    return int(np.count_nonzero(length > LONG_EDGE_FACTOR *
                                np.maximum(local[edges[:, 0]], local[edges[:, 1]])))


def summarize(points, mesh_points, triangles):
    """The counts of one output; mesh_points may extend points (added points come last)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from run_mesh_vertex_sweep import polydata
    import pointcloudsurface as pcs
    quality = pcs.vtkReconstructionQuality()
    quality.SetInputData(polydata(mesh_points, triangles))
    quality.Update()
    fields = quality.GetOutput().GetFieldData()
    value = lambda name: int(fields.GetArray(name).GetValue(0))  # noqa: E731
    vertices = np.unique(triangles) if len(triangles) else np.zeros(0, np.int64)
    used = int(np.count_nonzero(vertices < len(points)))
    return {"triangles": len(triangles), "unused": len(points) - used,
            "added": int(np.count_nonzero(vertices >= len(points))),
            "boundary": value("NumberOfBoundaryEdges"),
            "components": value("NumberOfConnectedComponents"),
            "nonmanifold": value("NumberOfNonManifoldEdges") +
            value("NumberOfNonManifoldVertices"),
            "long": long_edges(mesh_points, triangles)}


def run_filter(path, name):
    """Child process: one filter on one cloud; prints one JSON line."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from run_mesh_vertex_sweep import reconstruct
    from vtkmodules.util.numpy_support import vtk_to_numpy
    points = load_points(path)
    mesh, cpu = reconstruct(name, points)
    mesh_points = vtk_to_numpy(mesh.GetPoints().GetData()) if mesh.GetPoints() else points
    cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    result = summarize(points, np.asarray(mesh_points, float), cells.astype(np.int64))
    result.update(points=len(points), cpu=cpu)
    print(json.dumps(result))


def run_cgal(binary, path, timeout):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from run_mesh_vertex_sweep import read_off
    points = load_points(path)
    with tempfile.TemporaryDirectory() as folder:
        xyz, off = os.path.join(folder, "cloud.xyz"), os.path.join(folder, "mesh.off")
        np.savetxt(xyz, points)
        out = subprocess.run([binary, xyz, off], check=True, capture_output=True, text=True,
                             timeout=timeout)
        report = json.loads(out.stdout.strip().splitlines()[-1])
        triangles = read_off(off)[1]
    result = summarize(points, points, triangles.reshape(-1, 3))
    result.update(points=len(points), cpu=report["cpu_seconds"])
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has points_3/)")
    parser.add_argument("--clouds", nargs="+", default=list(CLOUDS), choices=list(CLOUDS))
    parser.add_argument("--filters", nargs="+", default=FILTER_NAMES, choices=FILTER_NAMES)
    parser.add_argument("--cgal", help="pcsBenchCGALAFSR executable (CGAL's advancing front)")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per run")
    parser.add_argument("--one", nargs=2, metavar=("FILE", "FILTER"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:
        run_filter(*args.one)
        return
    print("| cloud | points | method | CPU s | / CGAL | triangles | unused | added | "
          "boundary edges | components | non-manifold | long edges |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label in args.clouds:
        path = os.path.join(args.data, "points_3", CLOUDS[label])
        rows = []
        cgal = None
        if args.cgal:
            try:
                cgal = run_cgal(args.cgal, path, args.timeout)
            except (subprocess.SubprocessError, ValueError, IndexError, OSError) as error:
                print("| %s | | cgal | failed: %s |" % (label, str(error)[:80]))
        for name in args.filters:
            try:
                command = [sys.executable, os.path.abspath(__file__), "--data", args.data,
                           "--one", path, name]
                out = subprocess.run(command, capture_output=True, text=True,
                                     timeout=args.timeout)
                lines = out.stdout.strip().splitlines()
                if out.returncode != 0 or not lines:
                    rows.append((name, "exit code %d" % out.returncode))
                    continue
                try:
                    rows.append((name, json.loads(lines[-1])))
                except ValueError:
                    rows.append((name, "bad output: %s" % lines[-1][:60]))
            except subprocess.TimeoutExpired:
                rows.append((name, "TIMEOUT (%g s)" % args.timeout))
        if cgal:
            rows.append(("cgal", cgal))
        for name, r in rows:
            if isinstance(r, str):
                print("| %s | | %s | %s | | | | | | | | |" % (label, name, r))
                continue
            ratio = "%.2f" % (r["cpu"] / cgal["cpu"]) if cgal and cgal["cpu"] > 0 else ""
            print("| %s | %d | %s | %.3f | %s | %d | %d | %d | %d | %d | %d | %d |" % (
                label, r["points"], name, r["cpu"], ratio, r["triangles"], r["unused"],
                r["added"], r["boundary"], r["components"], r["nonmanifold"], r["long"]),
                flush=True)


if __name__ == "__main__":
    main()
