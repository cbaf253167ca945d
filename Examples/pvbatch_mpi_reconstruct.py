"""pvbatch under MPI: a cloud read (or generated) in pieces, one per process, reconstructed by a
PointCloudSurface filter, which gathers the cloud on process 0 (the result is the serial one),
measured by ReconstructionQuality and written by the script (process 0).

    eval "$(scripts/env.sh)"
    mpirun -np 4 pvbatch Examples/pvbatch_mpi_reconstruct.py [cloud.pvtp] [--method NAME]
                         [--output mesh.vtp]

(As root, Open MPI also wants OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; more
processes than cores need --oversubscribe.) Without a cloud file, 20,000 random points on the
unit sphere are generated in pieces: process i makes the i-th slice of the cloud. --method is a
proxy name (default LocalOptimumGrowth); --plugin names PointCloudSurface.so when it is not
autoloaded (default: the one of ./build).
"""
import argparse
import os

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, ProgrammableSource
import paraview.simple as simple
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController

HERE = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("cloud", nargs="?", help="a point cloud file ParaView reads in pieces")
parser.add_argument("--method", default="LocalOptimumGrowth",
                    help="IncrementalDelaunay3D, PerimeterPeelSurface, LocalOptimumGrowth, "
                         "CDTAdvancingFront or GreedySurfaceTriangulation")
parser.add_argument("--output", default="pvbatch_mesh.vtp")
parser.add_argument("--plugin", default=os.path.join(
    HERE, "..", "build", "lib", "paraview-plugins", "PointCloudSurface", "PointCloudSurface.so"))
args = parser.parse_args()

# Autoloaded plugins define their proxies in paraview.simple; LoadPlugin(ns=globals()) here.
if not hasattr(simple, "IncrementalDelaunay3D"):
    LoadPlugin(args.plugin, ns=globals())


def proxy(name):
    function = globals().get(name) or getattr(simple, name, None)
    if function is None:
        parser.error("the plugin has no proxy %s" % name)
    return function


processes = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
if args.cloud:
    cloud = OpenDataFile(args.cloud)  # parallel readers give one piece per process
else:
    cloud = ProgrammableSource(OutputDataSetType="vtkPolyData")
    cloud.Script = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
p = np.random.default_rng(1).normal(size=(20000, 3))
p /= np.linalg.norm(p, axis=1)[:, None]
chunk = p[piece * len(p) // pieces:(piece + 1) * len(p) // pieces]
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(chunk), deep=True))
self.GetOutput().SetPoints(points)
"""
surface = proxy(args.method)(Input=cloud)
quality = proxy("ReconstructionQuality")(Input=surface)
quality.UpdatePipeline()
measured = servermanager.Fetch(quality)  # the mesh (it lives on process 0) with its measures
fd = measured.GetFieldData()


def value(name):
    return fd.GetArray(name).GetTuple1(0)


print("%d process(es), %s: %d points, %d triangles, coverage %.3f, %d boundary edges, "
      "genus %s" % (processes, args.method, measured.GetNumberOfPoints(),
                    value("NumberOfTriangles"), value("Coverage"), value("NumberOfBoundaryEdges"),
                    "%d" % value("Genus") if value("Genus") >= 0 else "n/a"))
writer = vtkXMLPolyDataWriter()
writer.SetInputData(measured)
writer.SetFileName(args.output)
writer.Write()
print("wrote", args.output)
