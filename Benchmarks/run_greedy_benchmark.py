"""vtkGreedySurfaceTriangulation against CGAL's Advancing Front Surface Reconstruction (issue 7).

Each input is given to pcsBenchGreedySurfaceTriangulation once per method, each run in its own
process, on the same cloud (the executable's damage and noise use fixed seeds): "ours" (the
filter's defaults) and "cgal" (CGAL::advancing_front_surface_reconstruction, defaults); "log"
(vtkLocalOptimumGrowth, defaults) when asked for with --methods. Inputs
are the vertices of meshes of CGAL's demo data, clean, damaged (two regions removed, three
thinned tenfold: the reconstruction benchmark's definition) and noisy (Gaussian noise of 1/4 of
the mean spacing); the reference surface is the undamaged mesh.

Printed per input and method: points, time, points/s, triangles, unused points (and the points
the method added, FairHoleFills), boundary edges /
loops, non-manifold edges / vertices, components, genus, Hausdorff / spacing, completeness (share
of the reference vertices within 2 mean spacings of the mesh), the input bound (share of the
reference vertices within 2 mean spacings of some input point: what the damaged cloud itself
still covers; a mesh exceeds it only by long triangles spanning gaps of the cloud, or by
points it adds); and the criteria of issue 7 on
the damaged and noisy inputs: 0 non-manifold edges, boundary edges <= 10 % of CGAL's,
completeness >= 99 %.

Usage:
  /usr/bin/python3 Benchmarks/run_greedy_benchmark.py --bench-bin build/bin \
      --data <dir with meshes/*.off> [--seeds 7 8 9] [--markdown table.md] \
      meshes/bunny00.off meshes/armadillo.off ...
  (inputs may also be sample:meshes/x.off:N, sphere:N, torus:N; greedy against
  vtkLocalOptimumGrowth on clean clouds: --methods ours log --variants clean)
"""
import argparse
import datetime
import json
import os
import platform
import subprocess


def run(binary, method, spec, before=None):
    env = None
    if method == "before":
        # The same executable built from an earlier commit (its library beside it in ../lib).
        binary, method = before, "ours"
        env = dict(os.environ, LD_LIBRARY_PATH=os.path.join(os.path.dirname(before), "..", "lib"))
    out = subprocess.run([binary, method, spec], check=True, capture_output=True, text=True,
                         env=env)
    line = [l for l in out.stdout.splitlines() if l.startswith("{")][-1]
    return json.loads(line)


def resolve(rel, data):
    """The executable's input spec and a label: mesh paths are looked up under --data, also
    inside sample:<mesh.off>:N; sphere:N and torus:N are passed as they are."""
    if rel.startswith(("sphere:", "torus:")):
        return rel, rel
    if rel.startswith("sample:"):
        mesh, n = rel[len("sample:"):].rsplit(":", 1)
        mesh = mesh if os.path.isabs(mesh) else os.path.join(data, mesh)
        return "sample:%s:%s" % (mesh, n), "%s sample %s" % (os.path.basename(mesh), n)
    return (rel if os.path.isabs(rel) else os.path.join(data, rel)), os.path.basename(rel)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bench-bin", default="build/bin")
    parser.add_argument("--data", default="build/Testing/CGALData/data")
    parser.add_argument("--seeds", type=int, nargs="+", default=[7])
    parser.add_argument("--markdown")
    parser.add_argument("--methods", nargs="+", default=["ours", "cgal"])
    parser.add_argument("--variants", nargs="+", default=["clean", "damaged", "noisy"])
    parser.add_argument("--before-bin", help="pcsBenchGreedySurfaceTriangulation of an earlier "
                        "build (its library in ../lib): method 'before' in --methods runs it")
    parser.add_argument("inputs", nargs="+")
    args = parser.parse_args()
    binary = os.path.join(args.bench_bin, "pcsBenchGreedySurfaceTriangulation")
    header = ("| input | points | method | time s | points/s | triangles | unused | boundary "
              "edges / loops | non-manifold edges / vertices | components | genus | Hausdorff | "
              "completeness (2 s) | input bound (2 s) | criteria |")
    lines = [header, "|" + "---|" * 15]
    print(header)
    failures = 0
    for rel in args.inputs:
        path, name = resolve(rel, args.data)
        for variant in args.variants:
            seeds = [None] if variant == "clean" else args.seeds
            for seed in seeds:
                if variant == "clean":
                    spec, label = path, name
                elif variant == "damaged":
                    spec, label = "damaged=%d:%s" % (seed, path), "%s damaged (seed %d)" % (name, seed)
                else:
                    spec = "noisy:damaged=%d:%s" % (seed, path) if variant == "noisy-damaged" \
                        else "noisy:%s" % path
                    label = "%s %s" % (name, variant) + (" (seed %d)" % seed
                                                         if variant == "noisy-damaged" else "")
                    if variant == "noisy" and seed != seeds[0]:
                        continue
                before = (os.path.join(args.before_bin, "pcsBenchGreedySurfaceTriangulation")
                          if args.before_bin else None)
                results = {m: run(binary, m, spec, before) for m in args.methods}
                for m in args.methods:
                    r = results[m]
                    verdict = ""
                    if (m.startswith("ours") or m == "before") and variant != "clean" \
                            and "cgal" in results:
                        c = results["cgal"]
                        ok = (r["non_manifold_edges"] == 0
                              and r["boundary_edges"] <= 0.1 * c["boundary_edges"]
                              and r["completeness_2s"] >= 0.99)
                        failures += 0 if ok else 1
                        verdict = "ok" if ok else "FAILS"
                    row = ("| %s | %d | %s | %.3f | %.0f | %d | %s | %d / %d | %d / %d | %d | %s | "
                           "%.2f | %.4f | %.4f | %s |" % (
                               label, r["points"], m, r["seconds"], r["points_per_second"],
                               r["triangles"],
                               "%d" % r["unused"] + (" (+%d added)" % r["added"]
                                                     if r.get("added", 0) > 0 else ""),
                               r["boundary_edges"],
                               r["boundary_loops"], r["non_manifold_edges"],
                               r["non_manifold_vertices"], r["components"],
                               r["genus"] if r["genus"] >= 0 else "-",
                               r["hausdorff_over_spacing"], r["completeness_2s"],
                               r["input_bound_2s"], verdict))
                    print(row, flush=True)
                    lines.append(row)
    if args.markdown:
        load = os.getloadavg()
        with open(args.markdown, "w") as f:
            f.write("# vtkGreedySurfaceTriangulation against CGAL's advancing front\n\n")
            f.write("Command: `/usr/bin/python3 Benchmarks/run_greedy_benchmark.py %s`. Date %s; "
                    "%s; load average at the end %.1f.\n\n" % (
                        " ".join(os.sys.argv[1:]), datetime.date.today().isoformat(),
                        platform.processor() or platform.machine(), load[0]))
            f.write("\n".join(lines) + "\n")
    print("criteria failures:", failures)


if __name__ == "__main__":
    main()
