"""vtkLocalOptimumGrowth in a VTK Python pipeline, the cloud made with numpy.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
        Examples/pipeline_local_optimum_growth.py [--output-dir DIR]

4,000 points drawn uniformly (by area) on a torus with radii 2 and 0.7 become a vtkPolyData
(pointcloudsurface.points_to_polydata); vtkLocalOptimumGrowth (Wang et al. 2013) grows a mesh
from a seed triangle over its K nearest neighbours, one locally optimal triangle per front edge,
without normals. vtkReconstructionQuality measures it: a torus sample gives a closed surface of
genus 1 over every point, so 2V triangles (checked; the script exits non-zero otherwise). The
mesh is written as local_optimum_torus.vtp, the arrays back with polydata_to_arrays.
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from pointcloudsurface import (points_to_polydata, polydata_to_arrays, vtkLocalOptimumGrowth,
                               vtkReconstructionQuality)

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--output-dir", default=".")
args = parser.parse_args()

# Uniform by area: the angle v around the tube is kept with probability (R + r cos v) / (R + r).
R, r, N = 2.0, 0.7, 4000
rng = np.random.default_rng(4)
u, v = [], []
while len(u) < N:
    cu, cv = rng.uniform(0, 2 * np.pi, (2, N))
    keep = rng.uniform(0, 1, N) < (R + r * np.cos(cv)) / (R + r)
    u.extend(cu[keep])
    v.extend(cv[keep])
u, v = np.array(u[:N]), np.array(v[:N])
points = np.column_stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u),
                          r * np.sin(v)])

growth = vtkLocalOptimumGrowth()
growth.SetInputData(points_to_polydata(points))
growth.SetNumberOfNeighbors(15)

quality = vtkReconstructionQuality()
quality.SetInputConnection(growth.GetOutputPort())
quality.Update()
fd = quality.GetOutput().GetFieldData()
values = {name: fd.GetArray(name).GetTuple1(0) for name in (
    "NumberOfTriangles", "NumberOfUsedPoints", "NumberOfBoundaryEdges",
    "NumberOfNonManifoldEdges", "Genus")}
print("local optimum growth on %d torus points: %d triangles, %d points used, %d boundary edges, "
      "%d non-manifold edges, genus %d" % (
          N, values["NumberOfTriangles"], values["NumberOfUsedPoints"],
          values["NumberOfBoundaryEdges"], values["NumberOfNonManifoldEdges"], values["Genus"]))

writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(growth.GetOutputPort())
writer.SetFileName(os.path.join(args.output_dir, "local_optimum_torus.vtp"))
writer.Write()

points_back, triangles = polydata_to_arrays(growth.GetOutput())  # (N, 3) and (T, 3) arrays
if not (np.array_equal(points_back, points) and len(triangles) == 2 * N
        and values["Genus"] == 1 and values["NumberOfUsedPoints"] == N):
    sys.exit("FAILED: expected a closed genus-1 surface over every point, points unchanged")
