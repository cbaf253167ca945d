"""`from pointcloudsurface import vtkReconstructionQuality` works in a vtkmodules pipeline.

A UV sphere is closed, manifold and consistently oriented: genus 0, Euler characteristic 2,
no boundary; against its own points as a reference cloud every distance is 0.
Run by /usr/bin/python3 with PYTHONPATH=<build>/lib/python3/dist-packages.
"""
import sys

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

from pointcloudsurface import vtkReconstructionQuality


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


sphere = vtkSphereSource()
sphere.SetThetaResolution(16)
sphere.SetPhiResolution(10)
quality = vtkReconstructionQuality()
check(quality.GetSamplesPerTriangle() == 3, "default SamplesPerTriangle is 3")
check(quality.GetComputeDistances(), "ComputeDistances is on by default")
quality.SetInputConnection(sphere.GetOutputPort())
quality.Update()

out = quality.GetOutput()
fd = out.GetFieldData()


def field(name):
    array = fd.GetArray(name)
    check(array is not None, "field data %s present" % name)
    return array.GetTuple1(0)


# vtkSphereSource: 2 poles + theta * (phi - 2) ring points, 2 theta (phi - 2) triangles.
check(field("NumberOfTriangles") == 2 * 16 * 8, "triangle count")
check(field("NumberOfUsedPoints") == 2 + 16 * 8, "used points")
check(field("EulerCharacteristic") == 2, "Euler characteristic 2")
check(field("Genus") == 0, "genus 0")
check(field("NumberOfBoundaryEdges") == 0, "closed")
check(field("OrientationConsistency") == 1.0, "consistently oriented")
check(fd.GetArray("Hausdorff") is None, "no distances without a reference")

cloud = vtkPolyData()
cloud.SetPoints(sphere.GetOutput().GetPoints())
quality.SetReferenceData(cloud)
quality.SetSamplesPerTriangle(0)
quality.Update()
fd = quality.GetOutput().GetFieldData()
check(field("Hausdorff") < 1e-12, "distance to its own points is 0 (got %g)" % field("Hausdorff"))
check(field("MeanSpacing") > 0, "mean spacing of the cloud")
print("triangles", int(field("NumberOfTriangles")), "genus", int(field("Genus")),
      "spacing", field("MeanSpacing"))
print("ok")
