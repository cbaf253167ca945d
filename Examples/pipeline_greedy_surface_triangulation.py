"""vtkGreedySurfaceTriangulation in a VTK Python pipeline.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_greedy_surface_triangulation.py [--output-dir DIR]

vtkPointSource draws 3,000 random points on a sphere (its shell distribution); the greedy
triangulation (Emelyanov and Skala) connects them without normals: nearest-neighbour candidate
edges by length (the crossing test switched on here), then the holes and islands of its later
steps. vtkReconstructionQuality measures the result: a sphere sample gives a closed surface of
genus 0 over every point, so 2V - 4 triangles (checked; the script exits non-zero otherwise).
The mesh is written as greedy_sphere.vtp.
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersSources import vtkPointSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from pointcloudsurface import vtkGreedySurfaceTriangulation, vtkReconstructionQuality

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--output-dir", default=".")
args = parser.parse_args()

cloud = vtkPointSource()
cloud.SetNumberOfPoints(3000)
cloud.SetRadius(1.0)
cloud.SetDistributionToShell()

greedy = vtkGreedySurfaceTriangulation()
greedy.SetInputConnection(cloud.GetOutputPort())
greedy.SetNumberOfNeighbors(20)
greedy.SetCrossingTestToOn()

quality = vtkReconstructionQuality()
quality.SetInputConnection(greedy.GetOutputPort())
quality.Update()
fd = quality.GetOutput().GetFieldData()
values = {name: fd.GetArray(name).GetTuple1(0) for name in (
    "NumberOfTriangles", "NumberOfUsedPoints", "NumberOfBoundaryEdges",
    "NumberOfNonManifoldEdges", "Genus")}
print("greedy on %d sphere points: %d triangles, %d points used, %d boundary edges, "
      "%d non-manifold edges, genus %d" % (
          cloud.GetOutput().GetNumberOfPoints(), values["NumberOfTriangles"],
          values["NumberOfUsedPoints"], values["NumberOfBoundaryEdges"],
          values["NumberOfNonManifoldEdges"], values["Genus"]))

writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(greedy.GetOutputPort())
writer.SetFileName(os.path.join(args.output_dir, "greedy_sphere.vtp"))
writer.Write()

points = cloud.GetOutput().GetNumberOfPoints()
if not (values["NumberOfTriangles"] == 2 * points - 4 and values["Genus"] == 0
        and values["NumberOfUsedPoints"] == points):
    sys.exit("FAILED: expected a closed genus-0 surface over every point")
