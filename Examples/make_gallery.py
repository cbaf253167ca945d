"""README gallery: every reconstruction method of this build on the same real surface.

The cloud is the vertex set of CGAL's bunny mesh (Debian's libcgal-demo data: bunny00.off, 37,706
points, closed); each method that this build has reconstructs it with its default parameters,
the result is pictured (`render_png`, the command line's renderer) and measured with
vtkReconstructionQuality (the mesh itself as the reference). Writes docs/gallery/<method>.png and
docs/gallery/README.md (a table: picture, triangles, coverage, boundary edges, non-manifold
edges, genus, Hausdorff / spacing, seconds).

    eval "$(scripts/env.sh)"
    xvfb-run -a /usr/bin/python3 Examples/make_gallery.py [--off path/to/bunny00.off]
"""
import argparse
import os
import subprocess
import sys
import tarfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(HERE)


def bunny_path(requested):
    if requested:
        return requested
    target = os.path.join(REPOSITORY, "build", "cgal-data", "data", "meshes", "bunny00.off")
    if not os.path.exists(target):
        archive = "/usr/share/doc/libcgal-dev/data.tar.gz"
        if not os.path.exists(archive):
            sys.exit("libcgal-demo is not installed (scripts/setup.sh installs it)")
        with tarfile.open(archive) as tar:
            tar.extract("data/meshes/bunny00.off", os.path.join(REPOSITORY, "build", "cgal-data"))
    return target


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--off", help="the reference mesh (default: CGAL's bunny00.off)")
    parser.add_argument("--output-dir", default=os.path.join(REPOSITORY, "docs", "gallery"))
    args = parser.parse_args()

    from pointcloudsurface import fileio, methods, render
    from pointcloudsurface import vtkReconstructionQuality

    reference = fileio.read_cloud(bunny_path(args.off))  # the vertices of the mesh
    mesh_reference = fileio.read_mesh(bunny_path(args.off))
    os.makedirs(args.output_dir, exist_ok=True)
    rows = []
    for method in methods.available_methods():
        if method.name in ("delaunay", "terrain"):
            continue  # hulls and terrains are not surface reconstructions of a closed object
        algorithm = methods.make_filter(method)
        algorithm.SetInputData(reference)
        start = time.perf_counter()
        algorithm.Update()
        seconds = time.perf_counter() - start
        mesh = algorithm.GetOutput()
        picture = os.path.join(args.output_dir, method.name + ".png")
        render.render_png(mesh, picture, size=(640, 480), colour_by=None)
        quality = vtkReconstructionQuality()
        quality.SetInputData(0, mesh)
        quality.SetInputData(1, mesh_reference)
        quality.Update()
        fd = quality.GetOutput().GetFieldData()
        get = lambda name: fd.GetArray(name).GetTuple1(0)  # noqa: E731
        rows.append("| %s | ![%s](%s.png) | %d | %.4f | %d | %d | %s | %.2f | %.2f |" % (
            method.name, method.name, method.name, get("NumberOfTriangles"), get("Coverage"),
            get("NumberOfBoundaryEdges"), get("NumberOfNonManifoldEdges"),
            "-" if get("Genus") < 0 else "%d" % get("Genus"), get("HausdorffOverSpacing"),
            seconds))
        print(rows[-1], flush=True)
    with open(os.path.join(args.output_dir, "README.md"), "w") as f:
        f.write("# Gallery: CGAL's bunny (bunny00.off vertices, %d points)\n\n"
                "Made by `Examples/make_gallery.py` (default parameters of every method).\n\n"
                % reference.GetNumberOfPoints())
        f.write("| method | picture | triangles | coverage | boundary edges | non-manifold edges "
                "| genus | Hausdorff / spacing | seconds |\n")
        f.write("|---|---|---:|---:|---:|---:|---:|---:|---:|\n")
        f.write("\n".join(rows) + "\n")
    print("wrote", os.path.join(args.output_dir, "README.md"))


if __name__ == "__main__":
    main()
