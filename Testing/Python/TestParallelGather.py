"""Parallel correctness under MPI (issue 8): run with `mpirun -np N pvbatch` (N = 1, 2, 4).

A programmable source gives each process a contiguous piece of one cloud of 2,000 random points
on the unit sphere (in convex position: its Delaunay hull has exactly 2V - 4 triangles over all
the points, a closed genus-0 surface). The filters gather their input on process 0, so the
fetched results must be the serial ones whatever N is: IncrementalDelaunay3D's hull has 2V - 4
triangles over the V points, and ReconstructionQuality measures it as closed, genus 0, Euler 2,
every point used.

Usage: mpirun -np N pvbatch TestParallelGather.py <path to PointCloudSurface.so>
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, ProgrammableSource
from vtkmodules.vtkParallelCore import vtkMultiProcessController

POINTS = 2000


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


LoadPlugin(sys.argv[1], ns=globals())
processes = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()

cloud_source = ProgrammableSource(OutputDataSetType="vtkPolyData")
cloud_source.Script = """
import numpy as np
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
rng = np.random.default_rng(17)
p = rng.normal(size=(%d, 3))
p /= np.linalg.norm(p, axis=1)[:, None]
begin, end = piece * len(p) // pieces, (piece + 1) * len(p) // pieces
chunk = np.ascontiguousarray(p[begin:end])
points = vtkPoints()
points.SetData(numpy_to_vtk(chunk, deep=True))
ids = numpy_to_vtk(np.arange(begin, end, dtype=np.float64), deep=True)
ids.SetName("OriginalIndex")
out = self.GetOutput()
out.SetPoints(points)
out.GetPointData().AddArray(ids)
count = vtkDoubleArray()
count.SetName("NumberOfPieces")
count.InsertNextValue(pieces)
out.GetFieldData().AddArray(count)
""" % POINTS

# The source really is split: one piece per process.
cloud = servermanager.Fetch(cloud_source)
check(cloud.GetNumberOfPoints() == POINTS, "the pieces add up to the cloud")
check(cloud.GetFieldData().GetArray("NumberOfPieces").GetValue(0) == processes,
      "one piece per process")

delaunay = IncrementalDelaunay3D(Input=cloud_source)  # noqa: F821 (defined by LoadPlugin)
delaunay.GenerateTetrahedra = 0
delaunay.UpdatePipeline()
hull = servermanager.Fetch(delaunay)
print("processes %d: hull %d points, %d triangles" % (processes, hull.GetNumberOfPoints(),
                                                      hull.GetNumberOfPolys()))
check(hull.GetNumberOfPoints() == POINTS, "all %d points on the output (got %d)"
      % (POINTS, hull.GetNumberOfPoints()))
check(hull.GetNumberOfPolys() == 2 * POINTS - 4, "2V - 4 hull triangles (got %d)"
      % hull.GetNumberOfPolys())
original = hull.GetPointData().GetArray("OriginalIndex")
check(original is not None, "OriginalIndex passed through")
in_order = [i for i in range(POINTS) if original.GetValue(i) != i] == []
check(in_order, "points gathered in process order (the serial order)")

quality = ReconstructionQuality(Input=delaunay)  # noqa: F821
quality.UpdatePipeline()
measured = servermanager.Fetch(quality)
fd = measured.GetFieldData()


def field(name):
    array = fd.GetArray(name)
    check(array is not None, "field %s" % name)
    return array.GetTuple1(0)


check(field("NumberOfTriangles") == 2 * POINTS - 4, "quality: triangles")
check(field("Coverage") == 1.0, "quality: coverage 1")
check(field("NumberOfBoundaryEdges") == 0, "quality: closed")
check(field("NumberOfNonManifoldEdges") == 0, "quality: manifold")
check(field("EulerCharacteristic") == 2 and field("Genus") == 0, "quality: genus 0")
print("processes %d: quality as serial" % processes)
