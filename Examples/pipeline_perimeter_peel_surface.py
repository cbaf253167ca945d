"""vtkPerimeterPeelSurface in a VTK Python pipeline.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_perimeter_peel_surface.py [--output-dir DIR]

vtkPointSource draws 3,000 random points on the unit sphere; vtkPerimeterPeelSurface
(Rodriguez et al., DGCI 2000, section 3) tetrahedralizes them (exact Delaunay) and peels the
tetrahedra that show the outside a facet larger than the threshold (the mean exterior facet
perimeter times ThresholdFactor), then keeps the result a manifold (ManifoldOutput). The field
data of the filter tell how the peeling went (iterations, final threshold, tetrahedra, removed
tetrahedra, ...); vtkReconstructionQuality measures the surface, which must be closed and manifold
(checked; the script exits non-zero otherwise). The mesh is written as peel_sphere.vtp.
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersSources import vtkPointSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from pointcloudsurface import vtkPerimeterPeelSurface, vtkReconstructionQuality

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--output-dir", default=".")
args = parser.parse_args()

cloud = vtkPointSource()
cloud.SetNumberOfPoints(3000)
cloud.SetRadius(1.0)
cloud.SetDistributionToShell()

peel = vtkPerimeterPeelSurface()
peel.SetInputConnection(cloud.GetOutputPort())
peel.SetFacetMeasureToPerimeter()
peel.SetThresholdFactor(1.0)
peel.ManifoldOutputOn()

quality = vtkReconstructionQuality()
quality.SetInputConnection(peel.GetOutputPort())
quality.Update()
mesh = quality.GetOutput()
fd = mesh.GetFieldData()


def value(name):
    array = fd.GetArray(name)
    return array.GetTuple1(0) if array is not None else float("nan")


# The filter's own counts (iterations, final threshold, tetrahedra, ...), as it names them.
counts = peel.GetOutput().GetFieldData()
print("peeling: " + ", ".join("%s %.6g" % (counts.GetArray(i).GetName(),
                                           counts.GetArray(i).GetTuple1(0))
                              for i in range(counts.GetNumberOfArrays())))
print("surface: %d triangles, %d of %d points used, %d boundary edges, %d non-manifold edges, "
      "%d components, genus %d" % (
          value("NumberOfTriangles"), value("NumberOfUsedPoints"), mesh.GetNumberOfPoints(),
          value("NumberOfBoundaryEdges"), value("NumberOfNonManifoldEdges"),
          value("NumberOfConnectedComponents"), value("Genus")))

writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(peel.GetOutputPort())
writer.SetFileName(os.path.join(args.output_dir, "peel_sphere.vtp"))
writer.Write()

if not (value("NumberOfTriangles") > 0 and value("NumberOfBoundaryEdges") == 0
        and value("NumberOfNonManifoldEdges") == 0 and value("NumberOfNonManifoldVertices") == 0):
    sys.exit("FAILED: expected a closed manifold surface")
