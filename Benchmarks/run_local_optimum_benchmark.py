"""vtkLocalOptimumGrowth against CGAL's Advancing Front Surface Reconstruction (issue 5).

Each input is given to pcsBenchLocalOptimumGrowth twice in one invocation of this script, once
per method ("ours", then "cgal"), each in its own process; both get the same cloud (the
executable's generators use fixed seeds). The meshes come back as OFF over all input points and
are measured with vtkReconstructionQuality against the known surface: a fine sphere or torus for
sphere:N and torus:N, the mesh itself for sample:mesh.off:N and for a mesh's vertices (mesh.off).

Printed per input and method: time, triangles, coverage, non-manifold edges / vertices, boundary
edges (and their share of all edges), components, genus, Hausdorff over the mean spacing, and the
time ratio ours / CGAL, with the criteria of issue 5 checked (0 non-manifold edges and vertices,
coverage >= 99 %, boundary edges <= 0.5 % of the edges on closed surfaces, Hausdorff <= 2 mean
spacings, time <= 0.5 x CGAL from 10^5 points up).

With --scaling PNG the inputs are only timed (no meshes, no quality): for each input family
given as sphere or torus, sizes 10^4 to 10^6, both methods, with the exponent of the
least-squares line through log(time) against log(points), plotted log-log into PNG.

Usage:
  /usr/bin/python3 Benchmarks/run_local_optimum_benchmark.py --bench-bin build-log/bin \
      --data <dir with meshes/*.off> sphere:100000 torus:100000 meshes/bunny00.off \
      sample:meshes/bunny00.off:100000 [--markdown table.md] [--ours-only]
  /usr/bin/python3 Benchmarks/run_local_optimum_benchmark.py --scaling scaling.png sphere torus
Paths of the form meshes/x.off are looked up under --data (the libcgal-demo data, unpacked as
Benchmarks/run_reconstruction_benchmark.py does).
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
import run_reconstruction_benchmark as rb  # noqa: E402


def read_off_fast(path):
    with open(path) as f:
        tokens = f.read().split()
    nv, nf = int(tokens[1]), int(tokens[2])
    points = np.array(tokens[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
    faces = np.array(tokens[4 + 3 * nv:4 + 3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    return points, faces[:, 1:]


def resolve(spec, data):
    """The spec with a meshes/... path made absolute, and the reference surface."""
    if spec.startswith("sphere:"):
        return spec, rb.reference_sphere(), True
    if spec.startswith("torus:"):
        return spec, rb.reference_torus(), True
    if spec.startswith("sample:"):
        path, n = spec[7:].rsplit(":", 1)
        path = path if os.path.isabs(path) else os.path.join(data, path)
        spec = "sample:%s:%s" % (path, n)
    else:
        path = spec if os.path.isabs(spec) else os.path.join(data, spec)
        spec = path
    p, t = rb.read_off(path)
    reference = rb.mesh_from_arrays(p, t)
    topology = rb.reference_topology(reference)
    return spec, reference, topology.startswith("closed")


def run(bench, method, spec, workdir):
    off = os.path.join(workdir, method + ".off")
    out = subprocess.run([bench, method, spec, off], check=True, capture_output=True,
                         text=True).stdout
    result = json.loads(out.strip().splitlines()[-1])
    points, triangles = read_off_fast(off)
    os.remove(off)
    result["mesh"] = rb.mesh_from_arrays(points, triangles)
    return result


def scaling(args, bench):
    sizes = [10000, 30000, 100000, 300000, 1000000]
    load = open("/proc/loadavg").read().split()[:3]
    lines = ["Date %s, load average before the run %s; command: `%s`\n"
             % (datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"), " ".join(load),
                " ".join(["Benchmarks/run_local_optimum_benchmark.py"] + sys.argv[1:])),
             "| input | method | " + " | ".join("%g" % n for n in sizes) + " | exponent |",
             "|---|---|" + "---:|" * (len(sizes) + 1)]
    series = {}
    for family in args.inputs:
        for method in ["ours", "cgal"]:
            times = []
            for n in sizes:
                out = subprocess.run([bench, method, "%s:%d" % (family, n)], check=True,
                                     capture_output=True, text=True).stdout
                times.append(json.loads(out.strip().splitlines()[-1])["seconds"])
                print(family, method, n, times[-1], flush=True)
            exponent = float(np.polyfit(np.log(sizes), np.log(times), 1)[0])
            series[(family, method)] = (times, exponent)
            lines.append("| %s | %s | %s | %.2f |" % (
                family, method, " | ".join("%.3f" % t for t in times), exponent))
        ratios = [a / b for a, b in zip(series[(family, "ours")][0], series[(family, "cgal")][0])]
        lines.append("| %s | ours / CGAL | %s |  |" % (family, " | ".join("%.2f" % r for r in ratios)))
    print("\n".join(lines))
    if args.markdown:
        with open(args.markdown, "a") as f:
            f.write("\n".join(lines) + "\n\n")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for (family, method), (times, exponent) in series.items():
        label = "%s, %s (n^%.2f)" % (family, "vtkLocalOptimumGrowth" if method == "ours"
                                     else "CGAL advancing front", exponent)
        ax.loglog(sizes, times, "o-" if method == "ours" else "s--", label=label)
    ax.set_xlabel("points")
    ax.set_ylabel("time (s)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.scaling, dpi=90)
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+")
    parser.add_argument("--bench-bin", default="build-log/bin")
    parser.add_argument("--data", default="build-log/cgal-data/data")
    parser.add_argument("--markdown", help="append the table to this file")
    parser.add_argument("--ours-only", action="store_true", help="skip CGAL (profiling runs)")
    parser.add_argument("--scaling", metavar="PNG", help="time sphere/torus from 10^4 to 10^6")
    args = parser.parse_args()
    bench = os.path.join(args.bench_bin, "pcsBenchLocalOptimumGrowth")
    if args.scaling:
        return scaling(args, bench)
    load = open("/proc/loadavg").read().split()[:3]
    header = ("| input | points | method | time s | ratio | triangles | coverage | "
              "non-manifold e / v | boundary edges (% of edges) | components | genus | "
              "Hausdorff / spacing | criteria |")
    lines = ["Date %s, load average before the run %s; command: `%s`\n"
             % (datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"), " ".join(load),
                " ".join(["Benchmarks/run_local_optimum_benchmark.py"] + sys.argv[1:])),
             header, "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    print("\n".join(lines), flush=True)
    all_ok = True
    with tempfile.TemporaryDirectory(prefix="pcs-log-bench-") as workdir:
        for spec in args.inputs:
            full, reference, closed = resolve(spec, args.data)
            results = {}
            for method in ["ours"] if args.ours_only else ["ours", "cgal"]:
                results[method] = run(bench, method, full, workdir)
            for method, r in results.items():
                q = rb.quality(r["mesh"], reference)
                edges = (3 * q["NumberOfTriangles"] + q["NumberOfBoundaryEdges"]) / 2.0
                boundary_share = q["NumberOfBoundaryEdges"] / edges if edges else float("nan")
                ratio = (r["seconds"] / results["cgal"]["seconds"]) if "cgal" in results else None
                checks = []
                if method == "ours":
                    checks.append(("manifold", q["NumberOfNonManifoldEdges"] == 0
                                   and q["NumberOfNonManifoldVertices"] == 0))
                    checks.append(("coverage", q["Coverage"] >= 0.99))
                    if closed:
                        checks.append(("boundary", boundary_share <= 0.005))
                    checks.append(("Hausdorff", q["HausdorffOverSpacing"] <= 2.0))
                    if ratio is not None and r["points"] >= 100000:
                        checks.append(("time", ratio <= 0.5))
                    all_ok = all_ok and all(ok for _, ok in checks)
                verdict = ", ".join(("" if ok else "FAIL ") + name for name, ok in checks)
                line = "| %s | %d | %s | %.3f | %s | %d | %.4f | %d / %d | %d (%.3f %%) | %d | %s | %.2f | %s |" % (
                    spec, r["points"], method, r["seconds"],
                    "%.2f" % ratio if ratio is not None else "-", q["NumberOfTriangles"],
                    q["Coverage"], q["NumberOfNonManifoldEdges"],
                    q["NumberOfNonManifoldVertices"], q["NumberOfBoundaryEdges"],
                    100.0 * boundary_share, q["NumberOfConnectedComponents"],
                    "-" if q["Genus"] < 0 else "%d" % q["Genus"], q["HausdorffOverSpacing"],
                    verdict)
                lines.append(line)
                print(line, flush=True)
    if args.markdown:
        with open(args.markdown, "a") as f:
            f.write("\n".join(lines) + "\n\n")
    return 0 if all_ok else 1


if __name__ == "__main__":
    sys.exit(main())
