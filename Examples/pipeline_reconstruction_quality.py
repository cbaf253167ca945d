"""vtkReconstructionQuality in a VTK Python pipeline: measure a reconstructed mesh.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_reconstruction_quality.py

A terrain cloud (points of z = 0.3 sin(3x) cos(2y) on a jittered grid) is triangulated by
vtkIncrementalDelaunay3D in 2.5D; vtkReconstructionQuality then reports the topology of the mesh
(field data: triangles, coverage, boundary edges and loops, non-manifold edges and vertices,
components, Euler characteristic, genus) and, with the true surface as the reference on input
port 1 (a fine triangulated grid of the same function), the sampled distances (accuracy,
completeness, Hausdorff, relative to the mean point spacing). Per-point and per-cell arrays
(Used, NonManifoldVertex, DistanceToReference, BoundaryEdge, MinAngle...) are on the output.
The largest distance (AccuracyMax) comes from the long thin triangles that the 2.5D Delaunay
triangulation puts along the convex hull (see MinAngleP1): a chord between far-apart boundary
points cuts across the curved surface.
"""
import math
import random

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource

from pointcloudsurface import vtkIncrementalDelaunay3D, vtkReconstructionQuality


def height(x, y):
    return 0.3 * math.sin(3.0 * x) * math.cos(2.0 * y)


rng = random.Random(3)
points = vtkPoints()
for i in range(40):
    for j in range(30):
        x, y = (i + rng.uniform(-0.3, 0.3)) / 20.0, (j + rng.uniform(-0.3, 0.3)) / 20.0
        points.InsertNextPoint(x, y, height(x, y))
cloud = vtkPolyData()
cloud.SetPoints(points)

delaunay = vtkIncrementalDelaunay3D()
delaunay.SetInputData(cloud)
delaunay.SetDimension(2)
delaunay.GenerateTetrahedraOff()

# The true surface: a fine grid over the same square, lifted onto the function.
plane = vtkPlaneSource()
plane.SetOrigin(-0.015, -0.015, 0.0)
plane.SetPoint1(1.965, -0.015, 0.0)
plane.SetPoint2(-0.015, 1.465, 0.0)
plane.SetResolution(200, 150)
triangles = vtkTriangleFilter()  # the reference surface must be triangles (quads are ignored)
triangles.SetInputConnection(plane.GetOutputPort())
triangles.Update()
truth = vtkPolyData()
truth.DeepCopy(triangles.GetOutput())
for k in range(truth.GetNumberOfPoints()):
    x, y, _ = truth.GetPoint(k)
    truth.GetPoints().SetPoint(k, x, y, height(x, y))

quality = vtkReconstructionQuality()
quality.SetInputConnection(delaunay.GetOutputPort())
quality.SetReferenceData(truth)  # optional: without it, only the topology is measured
quality.SetSamplesPerTriangle(3)
quality.Update()

fields = quality.GetOutput().GetFieldData()
for k in range(fields.GetNumberOfArrays()):
    array = fields.GetArray(k)
    print("%-30s %g" % (array.GetName(), array.GetTuple1(0)))
