"""Main job: reconstruct the bundled default cloud, write the mesh and a picture of it.

The cloud is the terrain scan of generate_default_cloud.py. It is reconstructed with
vtkIncrementalDelaunay3D in 2.5D (terrain) mode: the exact Delaunay triangulation of the x-y
projection of the points, lifted back to the points. Writes, in --output-dir (default build/):
default_cloud.vtp (the input), default_mesh.vtp (the mesh) and default_mesh.png (1024 x 768,
offscreen, coloured by elevation), and prints the counts.

Each reconstruction is one entry of RECONSTRUCTIONS (name of the output files, function that
returns the mesh and its counts); the surface filters still to come add their own entries.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        Examples/reconstruct_default.py [--output-dir build]
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from generate_default_cloud import REPOSITORY, make_cloud, write_polydata  # noqa: E402

import vtkmodules.vtkInteractionStyle  # noqa: E402,F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
from vtkmodules.vtkCommonCore import vtkLookupTable  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkPolyDataNormals  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter)

from pointcloudsurface import vtkIncrementalDelaunay3D  # noqa: E402

IMAGE_SIZE = (1024, 768)


def reconstruct_terrain(cloud):
    """2.5D Delaunay triangulation (projection onto the x-y plane) of a terrain cloud."""
    delaunay = vtkIncrementalDelaunay3D()
    delaunay.SetInputData(cloud)
    delaunay.SetDimension(2)
    delaunay.SetProjectionPlaneToXYPlane()
    delaunay.GenerateTetrahedraOff()  # output 0 already holds the triangles
    delaunay.Update()
    mesh = delaunay.GetOutput()
    counts = {
        "input points": delaunay.GetNumberOfInputPoints(),
        "duplicates merged": delaunay.GetNumberOfDuplicatePoints(),
        "skipped (NaN/Inf)": delaunay.GetNumberOfSkippedPoints(),
        "triangles": mesh.GetNumberOfCells(),
    }
    return mesh, counts


# (name of the output files, reconstruction function)
RECONSTRUCTIONS = [
    ("default_mesh", reconstruct_terrain),
]


def render(mesh, path, size=IMAGE_SIZE):
    """Offscreen picture of a mesh, coloured by elevation (z), with 2x vertical exaggeration."""
    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.SplittingOff()
    normals.ConsistencyOn()
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(normals.GetOutputPort())
    bounds = mesh.GetBounds()
    elevation.SetLowPoint(0.0, 0.0, bounds[4])
    elevation.SetHighPoint(0.0, 0.0, bounds[5])
    colours = vtkLookupTable()
    colours.SetHueRange(0.667, 0.0)  # blue (low) to red (high)
    colours.Build()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(elevation.GetOutputPort())
    mapper.SetLookupTable(colours)
    mapper.SetScalarRange(0.0, 1.0)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetScale(1.0, 1.0, 2.0)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    # Looking at the terrain from the south-west, 35 degrees above the horizon, z up.
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetPosition(-0.4, -1.0, 0.8)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    camera.Zoom(1.25)
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--output-dir", default=os.path.join(REPOSITORY, "build"))
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)

    cloud = make_cloud()
    cloud_path = os.path.join(args.output_dir, "default_cloud.vtp")
    write_polydata(cloud, cloud_path)
    print("cloud: %s (%d points)" % (cloud_path, cloud.GetNumberOfPoints()))

    for name, reconstruct in RECONSTRUCTIONS:
        start = time.perf_counter()
        mesh, counts = reconstruct(cloud)
        seconds = time.perf_counter() - start
        mesh_path = os.path.join(args.output_dir, name + ".vtp")
        png_path = os.path.join(args.output_dir, name + ".png")
        write_polydata(mesh, mesh_path)
        render(mesh, png_path)
        print("%s: %s (%.3f s)" % (name, reconstruct.__doc__.split("\n")[0].rstrip("."), seconds))
        for label, value in counts.items():
            print("  %-18s %d" % (label + ":", value))
        print("  wrote %s and %s" % (mesh_path, png_path))
        if counts["triangles"] == 0:
            print("FAILED: no triangles")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
