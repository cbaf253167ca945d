"""vtkGreedySurfaceTriangulation against vtkLocalOptimumGrowth on clean clouds (issue 7: "on clean
surfaces, at least as good as vtkLocalOptimumGrowth").

Each input is given to pcsBenchGreedySurfaceTriangulation twice, methods "ours" (greedy, its
defaults) and "log" (vtkLocalOptimumGrowth, its defaults), each in its own process on the same
cloud; the meshes come back as OFF over all input points (and the points greedy's fill fairing
added) and both are measured here by vtkReconstructionQuality against the known surface: the
mesh itself for mesh.off (its vertices) and sample:mesh.off:N, a fine sphere or torus for
sphere:N and torus:N (the executable's fixed-seed clouds) and for sphere:N:SEED / torus:N:SEED
(numpy default_rng(SEED), run_reconstruction_benchmark.py's generators, written as .xyz).

Printed per input, greedy then LOG: triangles, unused input points (+ added points), boundary
edges / loops, non-manifold edges / vertices, components, genus (- when not closed), Hausdorff
and accuracy mean over the mesh's mean spacing, and the 1st / 5th / 50th percentiles of the
triangles' smallest angle (degrees). Rows where greedy is worse than LOG on some figure are
flagged in the last column with the figures concerned (unused points, boundary edges,
components when LOG's are not more than the surface's, a genus that is not the surface's known
genus, non-manifold elements, Hausdorff more than 0.25 spacings larger, smallest angle P1 or P5
more than 1 degree lower).

Usage:
  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Benchmarks/run_greedy_vs_log.py \
      --bench-bin build/bin --data /work/cgaldata/data [--markdown table.md] [--default-set]
      [inputs ...]
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_local_optimum_benchmark as lb  # noqa: E402
import run_reconstruction_benchmark as rb  # noqa: E402

MESHES = ["bunny00", "armadillo", "camel", "elephant", "refined_elephant", "fandisk_large",
          "knot1", "knot2", "diplodocus"]
# Known genus of the closed surfaces (None: not known here).
GENUS = {"bunny00": 0, "armadillo": 0, "camel": 0, "elephant": 3, "refined_elephant": 3,
         "fandisk_large": 0, "knot1": 1, "knot2": 2, "diplodocus": 0, "sphere": 0, "torus": 1}


def default_set():
    inputs = ["meshes/%s.off" % m for m in MESHES]
    inputs += ["sample:meshes/%s.off:100000" % m for m in MESHES]
    for n in [2000, 5000, 10000, 20000, 50000, 100000]:
        inputs += ["sphere:%d" % n, "torus:%d" % n]
    for n in [2000, 5000, 20000]:
        for seed in [1, 2]:
            inputs += ["sphere:%d:%d" % (n, seed), "torus:%d:%d" % (n, seed)]
    return inputs


def resolve(spec, data, workdir):
    """The executable's input spec, the reference surface and the surface's name (sphere:N:SEED
    written as .xyz; the other forms as run_local_optimum_benchmark.py resolves them)."""
    parts = spec.split(":")
    name = parts[0] if parts[0] in ("sphere", "torus") else \
        os.path.splitext(os.path.basename(parts[1] if parts[0] == "sample" else spec))[0]
    if parts[0] in ("sphere", "torus") and len(parts) == 3:
        sample = rb.sample_sphere if parts[0] == "sphere" else rb.sample_torus
        path = os.path.join(workdir, "%s_%s_%s.xyz" % tuple(parts))
        np.savetxt(path, sample(int(parts[1]), np.random.default_rng(int(parts[2]))), fmt="%.17g")
        spec = "%s:%s" % (parts[0], parts[1])
        return path, lb.resolve(spec, data)[1], name
    full, reference, _ = lb.resolve(spec, data)
    return full, reference, name


def run(bench, method, spec, workdir):
    off = os.path.join(workdir, method + ".off")
    out = subprocess.run([bench, method, spec, off], check=True, capture_output=True,
                         text=True).stdout
    result = [json.loads(l) for l in out.splitlines() if l.startswith("{")][-1]
    points, triangles = rb.read_off(off)
    os.remove(off)
    result["mesh"] = rb.mesh_from_arrays(points, triangles)
    return result


def measure(mesh, reference):
    """vtkReconstructionQuality's figures (rb.quality) and the percentiles of the triangles'
    smallest angles (nearest rank, as MinAngleP1), computed here from the mesh's arrays."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    r = rb.quality(mesh, reference)
    xyz = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    ids = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    corners = xyz[ids]
    smallest = np.full(len(ids), 180.0)
    for i in range(3):
        u = corners[:, (i + 1) % 3] - corners[:, i]
        w = corners[:, (i + 2) % 3] - corners[:, i]
        lengths = np.linalg.norm(u, axis=1) * np.linalg.norm(w, axis=1)
        cosine = np.where(lengths > 0, (u * w).sum(axis=1) / np.where(lengths > 0, lengths, 1.0), 1.0)
        smallest = np.minimum(smallest, np.degrees(np.arccos(np.clip(cosine, -1.0, 1.0))))
    smallest = np.sort(smallest)
    for p in (1, 5, 50):
        rank = max(0, int(np.ceil(p / 100.0 * len(smallest))) - 1)
        r["P%d" % p] = smallest[rank] if len(smallest) else float("nan")
    return r


def worse(g, l, genus):
    """The figures on which greedy (g) is worse than LOG (l)."""
    bad = []
    if g["unused"] > l["unused"]:
        bad.append("unused")
    if g["NumberOfBoundaryEdges"] > l["NumberOfBoundaryEdges"]:
        bad.append("boundary")
    if g["NumberOfConnectedComponents"] > l["NumberOfConnectedComponents"]:
        bad.append("components")
    if genus is not None and g["Genus"] != genus and (l["Genus"] == genus or l["Genus"] < 0):
        if g["Genus"] >= 0 or l["Genus"] == genus:
            bad.append("genus")
    if (g["NumberOfNonManifoldEdges"] + g["NumberOfNonManifoldVertices"]
            > l["NumberOfNonManifoldEdges"] + l["NumberOfNonManifoldVertices"]):
        bad.append("non-manifold")
    if g["HausdorffOverSpacing"] > l["HausdorffOverSpacing"] + 0.25:
        bad.append("Hausdorff")
    if g["P1"] < l["P1"] - 1.0 or g["P5"] < l["P5"] - 1.0:
        bad.append("angles")
    return bad


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--default-set", action="store_true",
                        help="the 9 CGAL vertex sets, their 10^5 samples, spheres and tori")
    parser.add_argument("--methods", nargs="+", default=["ours", "log"])
    for option, default in (("--bench-bin", "build/bin"),
                            ("--data", "build/Testing/CGALData/data"), ("--markdown", None)):
        parser.add_argument(option, default=default)
    parser.add_argument("inputs", nargs="*")
    args = parser.parse_args()
    bench = os.path.join(args.bench_bin, "pcsBenchGreedySurfaceTriangulation")
    inputs = (default_set() if args.default_set else []) + args.inputs
    command = " ".join(["Benchmarks/run_greedy_vs_log.py"] + sys.argv[1:])
    stamp = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC")
    columns = ["input", "points", "method", "triangles", "unused (+added)",
               "boundary edges / loops", "non-manifold e / v", "components", "genus",
               "Hausdorff / s", "accuracy mean / s", "min angle P1 / P5 / P50", "greedy worse on"]
    lines = ["`%s` (%s, load %s)\n" % (command, stamp, open("/proc/loadavg").read().split()[0]),
             "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    print("\n".join(lines), flush=True)
    flagged = 0
    with tempfile.TemporaryDirectory(prefix="pcs-greedy-log-") as workdir:
        for spec in inputs:
            full, reference, surface = resolve(spec, args.data, workdir)
            rows = {}
            for method in args.methods:
                r = run(bench, method, full, workdir)
                q = measure(r["mesh"], reference)
                q.update(points=r["points"], unused=r["unused"], added=r["added"])
                rows[method] = q
            bad = []
            if "ours" in rows and "log" in rows:
                bad = worse(rows["ours"], rows["log"], GENUS.get(surface))
                flagged += 1 if bad else 0
            for method, q in rows.items():
                line = ("| %s | %d | %s | %d | %d%s | %d / %d | %d / %d | %d | %s | %.2f | %.3f | "
                        "%.1f / %.1f / %.1f | %s |") % (
                    spec, q["points"], "greedy" if method == "ours" else method,
                    q["NumberOfTriangles"], q["unused"],
                    " (+%d)" % q["added"] if q["added"] else "",
                    q["NumberOfBoundaryEdges"], q["NumberOfBoundaryLoops"],
                    q["NumberOfNonManifoldEdges"], q["NumberOfNonManifoldVertices"],
                    q["NumberOfConnectedComponents"],
                    "-" if q["Genus"] < 0 else "%d" % q["Genus"], q["HausdorffOverSpacing"],
                    q["AccuracyMeanOverSpacing"], q["P1"], q["P5"], q["P50"],
                    ", ".join(bad) if method == "ours" else "")
                lines.append(line)
                print(line, flush=True)
    lines.append("\nInputs where greedy is worse on some figure: %d of %d" % (flagged, len(inputs)))
    print(lines[-1])
    if args.markdown:
        with open(args.markdown, "a") as f:
            f.write("\n".join(lines) + "\n\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
