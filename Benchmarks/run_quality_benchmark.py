#!/usr/bin/env python3
"""vtkReconstructionQuality on meshes of long thin triangles (and on any meshes given), for two
builds alternated: CPU time (least of N runs, each in its own process) and whether every output
(field data bit for bit, point and cell arrays by md5) is identical.

Generated meshes of T triangles over a cloud of T / 2 points on the unit sphere, each measured
against a UV sphere of 9800 triangles and against the cloud:
  fan      T triangles from one point of the sphere to consecutive points (by azimuth) of T + 1;
  slivers  T triangles (i, i + n/2, i + n/2 + 1) of the cloud sorted by azimuth: chords across;
  soup     T random triples of cloud points;
  planar   a flat fan of T triangles (centre to the unit circle) against the same fan 0.25 above.

  Benchmarks/run_quality_benchmark.py --before /work/main/build/lib/python3/dist-packages \
      --after build/lib/python3/dist-packages --triangles 20000 --runs 3 [--pairs mesh.vtp:ref.vtp ...]
"""
import argparse
import hashlib
import os
import subprocess
import sys
import tempfile

MEASURE = r'''
import sys, hashlib
sys.path.insert(0, sys.argv[1])
from pointcloudsurface import vtkReconstructionQuality
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy
def read(path):
    r = vtkXMLPolyDataReader(); r.SetFileName(path); r.Update(); return r.GetOutput()
q = vtkReconstructionQuality(); q.SetInputData(read(sys.argv[2])); q.SetReferenceData(read(sys.argv[3]))
q.Update()
o = q.GetOutput(); fd = o.GetFieldData()
for i in range(fd.GetNumberOfArrays()):
    print(fd.GetArray(i).GetName(), float(fd.GetArray(i).GetTuple1(0)).hex())
for data in (o.GetPointData(), o.GetCellData()):
    for i in range(data.GetNumberOfArrays()):
        print(data.GetArray(i).GetName(), hashlib.md5(vtk_to_numpy(data.GetArray(i)).tobytes()).hexdigest())
'''


def write_meshes(directory, triangles):
    import numpy as np
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    def poly(points, cells):
        data = vtkPolyData()
        pts = vtkPoints()
        pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
        data.SetPoints(pts)
        if cells is not None:
            cells = np.asarray(cells, dtype=np.int64)
            offsets = np.arange(0, 3 * len(cells) + 1, 3, dtype=np.int64)
            polys = vtkCellArray()
            polys.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
                          numpy_to_vtkIdTypeArray(cells.ravel().copy(), deep=1))
            data.SetPolys(polys)
        return data

    def write(data, name):
        path = os.path.join(directory, name + ".vtp")
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(data)
        writer.Write()
        return path

    def on_sphere(count, rng):
        v = rng.normal(size=(count, 3))
        return v / np.linalg.norm(v, axis=1)[:, None]

    rng = np.random.default_rng(1)
    t = triangles
    n = t // 2 + 2
    cloud = on_sphere(n, rng)
    fan_points = on_sphere(t + 1, rng)
    fan_points[0] = (0, 0, 1)
    rim = np.argsort(np.arctan2(fan_points[1:, 1], fan_points[1:, 0])) + 1
    fan = [(0, rim[i], rim[(i + 1) % t]) for i in range(t)]
    order = np.argsort(np.arctan2(cloud[:, 1], cloud[:, 0]))
    slivers = [(order[i % n], order[(i + n // 2) % n], order[(i + n // 2 + 1) % n])
               for i in range(t)]
    soup = rng.integers(0, n, size=(t, 3))
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(100)
    sphere.SetPhiResolution(50)
    sphere.Update()
    angles = 2 * np.pi * np.arange(t) / t
    flat = np.vstack([[0, 0, 0], np.column_stack([np.cos(angles), np.sin(angles), 0 * angles])])
    flat_fan = [(0, 1 + i, 1 + (i + 1) % t) for i in range(t)]
    files = {
        "fan": write(poly(fan_points, fan), "fan"),
        "slivers": write(poly(cloud, slivers), "slivers"),
        "soup": write(poly(cloud, soup), "soup"),
        "cloud": write(poly(cloud, None), "cloud"),
        "sphere": write(sphere.GetOutput(), "sphere"),
        "planar": write(poly(flat, flat_fan), "planar"),
        "planar-above": write(poly(flat + (0, 0, 0.25), flat_fan), "planar_above"),
    }
    pairs = [(files[m], files[r], "%s T=%d vs %s" % (m, t, r))
             for m in ("fan", "slivers", "soup") for r in ("sphere", "cloud")]
    pairs.append((files["planar"], files["planar-above"], "planar fan T=%d vs fan 0.25 above" % t))
    return pairs


def run(python_path, mesh, reference, script):
    times = tempfile.NamedTemporaryFile(suffix=".time", delete=False).name
    out = subprocess.run(["/usr/bin/time", "-f", "%U", "-o", times, sys.executable, script,
                          python_path, mesh, reference], capture_output=True, text=True)
    with open(times) as f:
        cpu = float(f.read().split()[-1])
    os.unlink(times)
    return cpu, out.stdout if out.returncode == 0 else "failed: " + out.stderr[-300:]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--before", required=True, help="python package path of the old build")
    parser.add_argument("--after", required=True, help="python package path of the new build")
    parser.add_argument("--triangles", type=int, default=20000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--pairs", nargs="*", default=[], help="more mesh.vtp:reference.vtp")
    args = parser.parse_args()
    directory = tempfile.mkdtemp(prefix="pcs-quality-")
    script = os.path.join(directory, "measure.py")
    with open(script, "w") as f:
        f.write(MEASURE)
    pairs = write_meshes(directory, args.triangles) if args.triangles > 0 else []
    pairs += [(p.split(":")[0], p.split(":")[1], os.path.basename(p)) for p in args.pairs]
    print("| case | before s | after s | outputs |")
    print("|---|---:|---:|---|")
    for mesh, reference, label in pairs:
        best = {"before": float("inf"), "after": float("inf")}
        outputs = {}
        for _ in range(args.runs):
            for side in ("before", "after"):
                cpu, text = run(getattr(args, side), mesh, reference, script)
                best[side] = min(best[side], cpu)
                outputs[side] = text
        same = "identical" if outputs["before"] == outputs["after"] else "DIFFERENT"
        print("| %s | %.2f | %.2f | %s |" % (label, best["before"], best["after"], same), flush=True)


if __name__ == "__main__":
    main()
