"""vtkIncrementalDelaunay3D in a VTK Python pipeline: its three outputs, 3D and 2.5D.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_incremental_delaunay3d.py [--output-dir .]

3D: 2,000 random points in a ball (vtkPointSource) -> the exact Delaunay tetrahedralization:
port 0 the convex hull (triangles, outward), port 1 the tetrahedra (cell data Circumradius),
port 2 the Voronoi diagram (GenerateVoronoi on). 2.5D: the same filter with Dimension 2 on a
terrain-like cloud (the point source flattened by a transform) gives the lifted triangulation.
Writes hull.vtp, tetrahedra.vtu, voronoi.vtp and terrain.vtp (open them in ParaView).
"""
import argparse
import os

from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkFiltersSources import vtkPointSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUnstructuredGridWriter

from pointcloudsurface import vtkIncrementalDelaunay3D

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--output-dir", default=".")
args = parser.parse_args()
os.makedirs(args.output_dir, exist_ok=True)


def write(data, name):
    writer = vtkXMLUnstructuredGridWriter() if name.endswith(".vtu") else vtkXMLPolyDataWriter()
    writer.SetFileName(os.path.join(args.output_dir, name))
    writer.SetInputData(data)
    writer.Write()


cloud = vtkPointSource()
cloud.SetNumberOfPoints(2000)
cloud.SetRadius(1.0)

delaunay = vtkIncrementalDelaunay3D()
delaunay.SetInputConnection(cloud.GetOutputPort())
delaunay.GenerateVoronoiOn()  # port 2; off by default (about 3x the tetrahedra's size)
delaunay.Update()
print("3D: %d input points, %d tetrahedra, %d hull triangles, %d Voronoi edges"
      % (delaunay.GetNumberOfInputPoints(), delaunay.GetNumberOfCells(),
         delaunay.GetSurfaceOutput().GetNumberOfPolys(),
         delaunay.GetVoronoiOutput().GetNumberOfLines()))
write(delaunay.GetSurfaceOutput(), "hull.vtp")
write(delaunay.GetTetrahedraOutput(), "tetrahedra.vtu")
write(delaunay.GetVoronoiOutput(), "voronoi.vtp")

# 2.5D: squash the ball into a low mound (z scaled by 0.1) and triangulate over the x-y plane.
squash = vtkTransform()
squash.Scale(1.0, 1.0, 0.1)
flat = vtkTransformFilter()
flat.SetTransform(squash)
flat.SetInputConnection(cloud.GetOutputPort())
terrain = vtkIncrementalDelaunay3D()
terrain.SetInputConnection(flat.GetOutputPort())
terrain.SetDimension(2)
terrain.SetProjectionPlaneToXYPlane()
terrain.GenerateTetrahedraOff()  # port 0 already holds the triangles
terrain.Update()
print("2.5D: %d triangles over %d points" % (terrain.GetOutput().GetNumberOfPolys(),
                                             terrain.GetOutput().GetNumberOfPoints()))
write(terrain.GetOutput(), "terrain.vtp")
