"""Main job: reconstruct the bundled default cloud and write the mesh and a picture of it.

The cloud is a terrain scan (see generate_default_cloud.py); it is reconstructed with
vtkIncrementalDelaunay3D in 2.5D mode (exact Delaunay triangulation of the x-y projection,
lifted back to the points). Writes <output-dir>/default_cloud.vtp, default_mesh.vtp and
default_mesh.png, and prints the counts.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from generate_default_cloud import make_cloud  # noqa: E402

from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkPolyDataNormals  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter)
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
import vtkmodules.vtkInteractionStyle  # noqa: E402,F401

from pointcloudsurface import vtkIncrementalDelaunay3D  # noqa: E402


def write(data, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()


def render(mesh, path, size=(1200, 800)):
    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.SplittingOff()
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(normals.GetOutputPort())
    bounds = mesh.GetBounds()
    elevation.SetLowPoint(0, 0, bounds[4])
    elevation.SetHighPoint(0, 0, bounds[5])
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(elevation.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetScale(1.0, 1.0, 2.0)  # vertical exaggeration
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Elevation(-55)
    camera.Azimuth(-20)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    png = vtkPNGWriter()
    png.SetFileName(path)
    png.SetInputConnection(grab.GetOutputPort())
    png.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--output-dir", default="build")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)

    cloud = make_cloud()
    write(cloud, os.path.join(args.output_dir, "default_cloud.vtp"))

    delaunay = vtkIncrementalDelaunay3D()
    delaunay.SetInputData(cloud)
    delaunay.SetDimension(2)
    delaunay.GenerateTetrahedraOff()
    start = time.perf_counter()
    delaunay.Update()
    seconds = time.perf_counter() - start
    mesh = delaunay.GetOutput()

    mesh_path = os.path.join(args.output_dir, "default_mesh.vtp")
    png_path = os.path.join(args.output_dir, "default_mesh.png")
    write(mesh, mesh_path)
    render(mesh, png_path)
    print("input points:      %d" % delaunay.GetNumberOfInputPoints())
    print("duplicates merged: %d" % delaunay.GetNumberOfDuplicatePoints())
    print("skipped (NaN/Inf): %d" % delaunay.GetNumberOfSkippedPoints())
    print("triangles:         %d (%.3f s)" % (mesh.GetNumberOfCells(), seconds))
    print("wrote %s and %s" % (mesh_path, png_path))


if __name__ == "__main__":
    main()
