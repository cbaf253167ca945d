"""Runs pcsBenchDelaunay for every method and input, takes medians, writes a Markdown table."""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess

# vtkDelaunay3D needs about 100 s at 10^5 points and is not run above that.
VTK_LIMIT = 100000


def run(exe, method, spec):
    env = dict(os.environ)
    if method == "ours-threads":  # the same filter with VTK's STDThread SMP backend
        env["VTK_SMP_BACKEND_IN_USE"] = "STDThread"
        method = "ours"
    else:
        env["VTK_SMP_BACKEND_IN_USE"] = "Sequential"
    out = subprocess.run([exe, method, spec], check=True, capture_output=True, text=True,
                         env=env).stdout
    return json.loads(out.strip().splitlines()[-1])


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--exe", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--output", required=True)
    args = parser.parse_args()

    inputs = [
        ("uniform 10^4", "uniform:10000", 10000),
        ("uniform 10^5", "uniform:100000", 100000),
        ("uniform 10^6", "uniform:1000000", 1000000),
        ("kitten scan (CGAL data)", os.path.join(args.data, "points_3/kitten.xyz"), None),
        ("armadillo vertices (CGAL data)", os.path.join(args.data, "meshes/armadillo.off"), None),
        ("noisy torus surface 10^6", "surface:1000000", 1000000),
    ]
    rows = []
    for label, spec, size in inputs:
        results = {}
        for method in ("ours", "ours-threads", "kernel", "cgal", "vtk"):
            if method == "vtk" and size is not None and size > VTK_LIMIT:
                results[method] = None
                continue
            repeats = 1 if method == "vtk" else args.repeats
            runs = [run(args.exe, method, spec) for _ in range(repeats)]
            results[method] = {
                "seconds": statistics.median(r["seconds"] for r in runs),
                "peak_mb": statistics.median(r["peak_mb"] for r in runs),
                "tetrahedra": runs[0]["tetrahedra"],
                "points": runs[0]["points"],
            }
            print(label, method, results[method], flush=True)
        rows.append((label, results))

    lines = [
        "# Delaunay benchmark",
        "",
        "Command: `Benchmarks/run_delaunay_benchmark.sh %d` (median of %d runs; vtkDelaunay3D "
        "once). Date %s; %s, %d cores; %s." % (
            args.repeats, args.repeats, datetime.date.today().isoformat(), cpu_model(),
            os.cpu_count(), platform.platform()),
        "",
        "Time is the wall time of the construction only (input already in memory): "
        "vtkIncrementalDelaunay3D::Update() with tetrahedra output (VTK arrays, Circumradius "
        "and hull included), CGAL::Delaunay_triangulation_3<Epick> from the point range, "
        "vtkDelaunay3D::Update(). Peak memory is the process's peak resident set (one method "
        "per process), input included.",
        "",
        "\"ours\" runs with VTK's default SMP backend on Debian (Sequential); \"ours 2T\" with "
        "VTK_SMP_BACKEND_IN_USE=STDThread, which runs the spatial sort and the output stage on "
        "both cores (the insertion itself is sequential). CGAL is sequential.",
        "",
        "\"kernel\" is the triangulation kernel alone (pcs::Delaunay3D, no VTK input/output "
        "arrays), the part that does what CGAL's number measures.",
        "",
        "| input | points | ours s | ours 2T s | kernel s | CGAL s | vtkDelaunay3D s | "
        "ours/CGAL time | ours 2T/CGAL time | kernel/CGAL time | ours MB | CGAL MB | "
        "ours/CGAL memory | tetrahedra ours / CGAL / VTK |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for label, r in rows:
        ours, cgal, vtk = r.get("ours"), r.get("cgal"), r.get("vtk")
        threads = r.get("ours-threads")
        kernel = r.get("kernel")
        vtk_time = "%.2f" % vtk["seconds"] if vtk else "skipped (50 s at 10^5)"
        vtk_tets = str(vtk["tetrahedra"]) if vtk else "-"
        lines.append("| %s | %d | %.3f | %.3f | %.3f | %.3f | %s | %.2f | %.2f | %.2f | %.0f | "
                     "%.0f | %.2f | %d / %d / %s |" % (
            label, ours["points"], ours["seconds"], threads["seconds"], kernel["seconds"],
            cgal["seconds"], vtk_time, ours["seconds"] / cgal["seconds"],
            threads["seconds"] / cgal["seconds"], kernel["seconds"] / cgal["seconds"],
            ours["peak_mb"], cgal["peak_mb"],
            ours["peak_mb"] / cgal["peak_mb"], ours["tetrahedra"], cgal["tetrahedra"], vtk_tets))
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
