"""pvbatch under MPI: a cloud read (or generated) in pieces, one per process, reconstructed by
the PointCloudSurface filters, which gather the cloud on process 0 (the result is the serial
one), then written by the script (process 0).

    eval "$(scripts/env.sh)"
    mpirun -np 4 pvbatch Examples/pvbatch_mpi_reconstruct.py [cloud.vtp] [--output mesh.vtp]

(As root, Open MPI also wants OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; more
processes than cores need --oversubscribe.)
"""
import argparse
import os

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, PointSource
import paraview.simple as simple
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("cloud", nargs="?")
parser.add_argument("--output", default="pvbatch_mesh.vtp")
args = parser.parse_args()

if not hasattr(simple, "IncrementalDelaunay3D"):
    here = os.path.dirname(os.path.abspath(__file__))
    LoadPlugin(os.path.join(here, "..", "build", "lib", "paraview-plugins", "PointCloudSurface",
                            "PointCloudSurface.so"), ns=globals())
processes = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()

# Readers and PointSource produce one piece per process under pvbatch.
cloud = OpenDataFile(args.cloud) if args.cloud else PointSource(NumberOfPoints=20000, Radius=1.0)
method = next(name for name in ("LocalOptimumGrowth", "PerimeterPeelSurface", "CDTAdvancingFront",
                                "GreedySurfaceTriangulation", "IncrementalDelaunay3D")
              if hasattr(simple, name))
surface = getattr(simple, method)(Input=cloud)
quality = simple.ReconstructionQuality(Input=surface)
quality.UpdatePipeline()
measured = servermanager.Fetch(quality)  # the mesh (it lives on process 0) with its measures
fd = measured.GetFieldData()
print("%d process(es), %s: %d triangles, coverage %.3f" % (
    processes, method, fd.GetArray("NumberOfTriangles").GetTuple1(0),
    fd.GetArray("Coverage").GetTuple1(0)))
writer = vtkXMLPolyDataWriter()
writer.SetInputData(measured)
writer.SetFileName(args.output)
writer.Write()
print("wrote", args.output)
