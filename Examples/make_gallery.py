"""README gallery: every filter of this build on the same real surface.

The cloud is the vertex set of CGAL's bunny mesh (Debian's libcgal-demo data: bunny00.off, 37,706
points; the mesh is closed, genus 0). Each method of the command line that this build has
(`delaunay`: the convex hull, for comparison; `peel`, `local-optimum`, `cdt-front`, `greedy`)
reconstructs it with its default parameters; the result is pictured with the command line's
renderer (`render_png`) and measured with
vtkReconstructionQuality against the original mesh. Writes docs/gallery/<method>.png (and
reference.png, the original mesh) and docs/gallery/README.md: a table with the picture,
triangles, coverage, boundary edges, non-manifold edges, genus, Hausdorff distance / mean spacing
and seconds (one run, wall time of the filter's Update on this machine), and the commit the
pictures were made from.

    eval "$(scripts/env.sh)"
    xvfb-run -a /usr/bin/python3 Examples/make_gallery.py [--off path/to/bunny00.off]
"""
import argparse
import os
import subprocess
import sys
import tarfile
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(HERE)
# The bunny stands on y = min: look at its left side from slightly above, y up.
VIEW_UP = (0.0, 1.0, 0.0)
DIRECTION = (0.35, 0.35, 1.0)
SIZE = (400, 300)


def bunny_path(requested, scratch):
    """``requested``, or bunny00.off extracted from libcgal-demo's data archive into
    ``scratch``."""
    if requested:
        if not os.path.isfile(requested):
            sys.exit("%s: no such file" % requested)
        return requested
    archive = "/usr/share/doc/libcgal-dev/data.tar.gz"
    if not os.path.exists(archive):
        sys.exit("libcgal-demo is not installed (scripts/setup.sh installs it), or pass --off")
    member = "data/meshes/bunny00.off"
    with tarfile.open(archive) as tar:
        tar.extract(member, scratch)
    return os.path.join(scratch, member)


def source_state():
    """The commit, and whether the filters' sources differ from it (shared working tree)."""
    try:
        commit = subprocess.run(["git", "-C", REPOSITORY, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPOSITORY, "status", "--porcelain", "Filters"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "an unknown commit"
    return "commit %s%s" % (commit, " with uncommitted changes in Filters/" if dirty else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--off", help="the reference mesh (default: CGAL's bunny00.off)")
    parser.add_argument("--output-dir", default=os.path.join(REPOSITORY, "docs", "gallery"))
    args = parser.parse_args()

    from pointcloudsurface import fileio, methods, render
    from pointcloudsurface import vtkReconstructionQuality

    with tempfile.TemporaryDirectory() as scratch:
        path = bunny_path(args.off, scratch)
        cloud = fileio.read_cloud(path)  # the vertices of the mesh
        reference = fileio.read_mesh(path)
    os.makedirs(args.output_dir, exist_ok=True)
    view = dict(size=SIZE, colour_by=None, view_up=VIEW_UP, direction=DIRECTION)
    render.render_png(reference, os.path.join(args.output_dir, "reference.png"), **view)
    rows = ["| reference | <img src=\"reference.png\" width=\"200\"> | %d | - | - | - | 0 | - | - |"
            % reference.GetNumberOfPolys()]
    for method in methods.available_methods():
        if method.name == "terrain":
            continue  # the delaunay method in 2.5D: not for a closed object
        algorithm = methods.make_filter(method)
        algorithm.SetInputData(cloud)
        start = time.perf_counter()
        algorithm.Update()
        seconds = time.perf_counter() - start
        mesh = algorithm.GetOutputDataObject(method.port)
        picture = method.name + ".png"
        render.render_png(mesh, os.path.join(args.output_dir, picture), **view)
        quality = vtkReconstructionQuality()
        quality.SetInputData(mesh)
        quality.SetReferenceData(reference)
        quality.Update()
        fd = quality.GetOutput().GetFieldData()

        def get(name):
            return fd.GetArray(name).GetTuple1(0)

        label = "%s (%s)" % (method.name, method.class_name)
        if method.name == "delaunay":
            label += ", convex hull"
        rows.append("| %s | <img src=\"%s\" width=\"200\"> | %d | %.1f %% | %d | %d | %s | %.2f "
                    "| %.2f |" % (label, picture, get("NumberOfTriangles"),
                                  100.0 * get("Coverage"), get("NumberOfBoundaryEdges"),
                                  get("NumberOfNonManifoldEdges"),
                                  "-" if get("Genus") < 0 else "%d" % get("Genus"),
                                  get("HausdorffOverSpacing"), seconds))
        print(rows[-1], flush=True)
    with open(os.path.join(args.output_dir, "README.md"), "w") as f:
        f.write("# Gallery: CGAL's bunny (bunny00.off vertices, %d points)\n\n"
                "Made by `Examples/make_gallery.py` from %s: every method with its default "
                "parameters, no normals given (the filters that need normals estimate them). "
                "Coverage: the fraction of the points that are triangle vertices. Hausdorff "
                "distance to the original mesh over the mean spacing of the "
                "points; seconds: one run on a shared 2-core machine.\n\n"
                % (cloud.GetNumberOfPoints(), source_state()))
        f.write("| method | picture | triangles | coverage | boundary edges | non-manifold edges "
                "| genus | Hausdorff / spacing | seconds |\n")
        f.write("|---|---|---:|---:|---:|---:|---:|---:|---:|\n")
        f.write("\n".join(rows) + "\n")
    print("wrote", os.path.join(args.output_dir, "README.md"))


if __name__ == "__main__":
    main()
