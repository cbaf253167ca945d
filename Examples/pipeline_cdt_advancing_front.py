"""vtkCDTAdvancingFront in a VTK Python pipeline, with normals computed in the pipeline.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_cdt_advancing_front.py [--output-dir DIR]

vtkPointSource draws 3,000 random points on the unit sphere; vtkArrayCalculator gives each its
normal (the position itself, outwards) as the active point normals; vtkCDTAdvancingFront (Huang
and Wischgoll) meshes the cloud with those normals (UseInputNormals, the array chosen with
SetInputArrayToProcess), then a second run estimates its own (PCA) normals instead. Both are
measured by vtkReconstructionQuality: a sphere sample gives a closed surface of genus 0 over
every point, 2V - 4 triangles (checked; the script exits non-zero otherwise). The meshes are
written as cdt_front_sphere.vtp and cdt_front_sphere_pca.vtp.
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersCore import vtkArrayCalculator
from vtkmodules.vtkFiltersSources import vtkPointSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from pointcloudsurface import vtkCDTAdvancingFront, vtkReconstructionQuality

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--output-dir", default=".")
args = parser.parse_args()

cloud = vtkPointSource()
cloud.SetNumberOfPoints(3000)
cloud.SetRadius(1.0)
cloud.SetDistributionToShell()

normals = vtkArrayCalculator()
normals.SetInputConnection(cloud.GetOutputPort())
normals.SetAttributeTypeToPointData()
normals.AddCoordinateVectorVariable("p")
normals.SetFunction("p")
normals.SetResultArrayName("Normals")
normals.ResultNormalsOn()  # the result becomes the active point normals

front = vtkCDTAdvancingFront()
front.SetInputConnection(normals.GetOutputPort())
front.SetUseInputNormals(True)
front.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "Normals")

failed = False
for name, use_input_normals in (("cdt_front_sphere", True), ("cdt_front_sphere_pca", False)):
    front.SetUseInputNormals(use_input_normals)
    quality = vtkReconstructionQuality()
    quality.SetInputConnection(front.GetOutputPort())
    quality.Update()
    fd = quality.GetOutput().GetFieldData()
    values = {key: fd.GetArray(key).GetTuple1(0) for key in (
        "NumberOfTriangles", "NumberOfUsedPoints", "NumberOfBoundaryEdges",
        "NumberOfNonManifoldEdges", "Genus")}
    points = front.GetOutput().GetNumberOfPoints()
    print("CDT advancing front, %s normals: %d triangles, %d of %d points used, %d boundary "
          "edges, %d non-manifold edges, genus %d" % (
              "input" if use_input_normals else "estimated", values["NumberOfTriangles"],
              values["NumberOfUsedPoints"], points, values["NumberOfBoundaryEdges"],
              values["NumberOfNonManifoldEdges"], values["Genus"]))
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(front.GetOutputPort())
    writer.SetFileName(os.path.join(args.output_dir, name + ".vtp"))
    writer.Write()
    failed |= not (values["NumberOfTriangles"] == 2 * points - 4 and values["Genus"] == 0
                   and values["NumberOfUsedPoints"] == points)
if failed:
    sys.exit("FAILED: expected closed genus-0 surfaces over every point")
