"""Parallel correctness under MPI (issue 8): run with `mpirun -np N pvbatch` (N = 1, 2, 4).

A programmable source gives each process a contiguous piece of one cloud of 2,000 random points
on the unit sphere followed by exact copies of its first 20 points (2,020 in all, the copies in
the last piece), with their normals (point array Normals) and their index in the whole cloud
(OriginalIndex). Every filter proxy of Plugin/PointCloudSurface.xml (IncrementalDelaunay3D,
PerimeterPeelSurface, LocalOptimumGrowth, CDTAdvancingFront, GreedySurfaceTriangulation, and any
proxy added there later) runs on the split cloud with its default properties, followed by a
ReconstructionQuality proxy; the fetched mesh and measures are compared with the serial answer
computed in this script: the plain VTK class of the filter (the Python package), given the
proxy's property values through the same setters, run in-process on the whole cloud with a single-process controller, then measured
by vtkReconstructionQuality. They must agree exactly, whatever N is:

- the number of points passed through and the triangles themselves, as oriented triples of
  OriginalIndex (so the same triangles in the same orientation, not just as many);
- every field data value of the filter and of ReconstructionQuality (triangles, used points,
  coverage, boundary edges and loops, non-manifold edges and vertices, components, Euler
  characteristic, genus, orientation consistency, and the distances to the cloud, which is
  ReconstructionQuality's Reference input, split as well), timings excepted.

A rank that meshed only its own piece would fail: with N > 1 the script checks that the mesh of
the first piece alone differs from the whole-cloud reference (the comparison can tell them
apart). Known by construction besides: the points are in convex position, so the Delaunay hull
has 2V - 4 triangles over the V = 2,000 distinct points, closed, genus 0.

ReconstructionQuality on a mesh split in pieces (as a partitioned file is read): a second
programmable source gives each process a band of rows of a 24 x 12 torus grid mesh, each band
with its own copy of the border row it shares with the next band (the same coordinates). The
gathered mesh must measure as the serial one: 288 points, 576 triangles, closed, one component,
Euler characteristic 0, genus 1, every field value equal.

Client-server: with `--server MPIEXEC PVSERVER N` the script, run by pvpython, starts
`MPIEXEC -np N PVSERVER` on a free local port, connects to it, loads the plugin on both sides
and runs the same checks on the server's N processes (the serial reference in the client).

Usage: mpirun -np N pvbatch TestParallelGather.py <path to PointCloudSurface.so>
       pvpython TestParallelGather.py <path to PointCloudSurface.so> --server MPIEXEC PVSERVER N
(PYTHONPATH must reach the build's pointcloudsurface package.)
"""
import atexit
import os
import socket
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

import numpy as np
from paraview import servermanager
import paraview.simple as simple
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkParallelCore import vtkDummyController, vtkMultiProcessController

POINTS = 2000
DUPLICATES = 20  # exact copies of the first points, at the end (in the last piece)
TOTAL = POINTS + DUPLICATES
SEED = 17
# Proxy properties changed from their defaults (the serial reference gets every proxy value).
PROPERTIES = {"IncrementalDelaunay3D": {"GenerateTetrahedra": 0}}
# Timings differ from run to run: Seconds, PointsPerSecond, DelaunayTime, PeelTime, ...
TIMING_SUFFIXES = ("Seconds", "Second", "Time")


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


def sphere_cloud():
    """The whole cloud: points and normals (the same numbers as the programmable source)."""
    points = np.random.default_rng(SEED).normal(size=(POINTS, 3))
    points /= np.linalg.norm(points, axis=1)[:, None]
    return np.vstack([points, points[:DUPLICATES]])


SOURCE_SCRIPT = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
p = np.random.default_rng(%d).normal(size=(%d, 3))
p /= np.linalg.norm(p, axis=1)[:, None]
p = np.vstack([p, p[:%d]])
begin, end = piece * len(p) // pieces, (piece + 1) * len(p) // pieces
chunk = np.ascontiguousarray(p[begin:end])
points = vtkPoints()
points.SetData(numpy_to_vtk(chunk, deep=True))
out = self.GetOutput()
out.SetPoints(points)
normals = numpy_to_vtk(chunk, deep=True)
normals.SetName("Normals")
out.GetPointData().SetNormals(normals)
ids = numpy_to_vtk(np.arange(begin, end, dtype=np.float64), deep=True)
ids.SetName("OriginalIndex")
out.GetPointData().AddArray(ids)
count = vtkDoubleArray()
count.SetName("NumberOfPieces")
count.InsertNextValue(pieces)
out.GetFieldData().AddArray(count)
""" % (SEED, POINTS, DUPLICATES)


def make_polydata(points, begin=0):
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points), deep=True))
    cloud.SetPoints(vtk_points)
    normals = numpy_to_vtk(np.ascontiguousarray(points), deep=True)
    normals.SetName("Normals")
    cloud.GetPointData().SetNormals(normals)
    ids = numpy_to_vtk(np.arange(begin, begin + len(points), dtype=np.float64), deep=True)
    ids.SetName("OriginalIndex")
    cloud.GetPointData().AddArray(ids)
    return cloud


def serial(function):
    """Runs ``function`` with a single-process global controller: the filters then compute on
    what they are given, without gathering (the other processes are not involved)."""
    parallel = vtkMultiProcessController.GetGlobalController()
    single = vtkDummyController()
    vtkMultiProcessController.SetGlobalController(single)
    try:
        return function()
    finally:
        vtkMultiProcessController.SetGlobalController(parallel)


def serial_mesh(class_name, properties, cloud):
    """The plain VTK filter, its setters called with ``properties`` ({setter: value}), and
    vtkReconstructionQuality on ``cloud``, serially."""
    import pointcloudsurface

    def run():
        algorithm = getattr(pointcloudsurface, class_name)()
        for setter, value in properties.items():
            getattr(algorithm, setter)(value)
        algorithm.SetInputData(cloud)
        quality = pointcloudsurface.vtkReconstructionQuality()
        quality.SetInputConnection(algorithm.GetOutputPort(0))
        quality.SetReferenceData(cloud)  # distances between the mesh and the cloud
        quality.Update()
        result = vtkPolyData()
        result.ShallowCopy(quality.GetOutput())
        return result

    return serial(run)


def oriented_triangles(mesh):
    """The triangles as a sorted list of (a, b, c) OriginalIndex triples, each rotated so that
    its smallest index comes first (orientation kept)."""
    polys = mesh.GetPolys()
    if polys.GetNumberOfCells() == 0:
        return []
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    check(np.all(np.diff(offsets) == 3), "%s: triangles only" % mesh)
    ids = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
    original = vtk_to_numpy(mesh.GetPointData().GetArray("OriginalIndex")).astype(np.int64)
    triples = original[ids]
    first = np.argmin(triples, axis=1)
    rows = np.arange(len(triples))
    rotated = np.stack([triples[rows, first], triples[rows, (first + 1) % 3],
                        triples[rows, (first + 2) % 3]], axis=1)
    return sorted(map(tuple, rotated.tolist()))


def field_values(mesh):
    fd = mesh.GetFieldData()
    values = {}
    for i in range(fd.GetNumberOfArrays()):
        array = fd.GetAbstractArray(i)
        name = array.GetName()
        if (name.endswith(TIMING_SUFFIXES) or name == "NumberOfPieces"
                or not hasattr(array, "GetTuple1")):
            continue
        values[name] = array.GetTuple1(0) if array.GetNumberOfTuples() else None
    return values


def same_value(a, b):
    return a == b or (a != a and b != b)  # NaN measures (no distances) agree too


def start_server(mpiexec, pvserver, count):
    """``mpiexec -np count pvserver`` on a free local port, once it accepts connections."""
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        port = probe.getsockname()[1]
    # pvpython started as an MPI singleton: its Open MPI / PMIx variables would make mpiexec
    # believe it runs inside a job. The consent to run as root is kept.
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))
           or key.startswith("OMPI_ALLOW_RUN_AS_ROOT")}
    server = subprocess.Popen(
        [mpiexec, "--oversubscribe", "-np", str(count), pvserver, "--server-port=%d" % port,
         "--force-offscreen-rendering"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        stdin=subprocess.DEVNULL, text=True, env=env)

    def stop():
        if server.poll() is None:
            server.terminate()
            try:
                server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                server.kill()

    atexit.register(stop)
    deadline = time.time() + 120
    said = []
    for line in server.stdout:
        if "Accepting connection" in line:
            return server, port
        said.append(line.rstrip())
        check(time.time() < deadline, "pvserver did not start: %s" % "; ".join(said[-5:]))
    check(False, "pvserver exited (code %s): %s" % (server.wait(), "; ".join(said[-5:])))


if "--server" in sys.argv:
    mpiexec, pvserver, count = sys.argv[sys.argv.index("--server") + 1:][:3]
    server, port = start_server(mpiexec, pvserver, int(count))
    simple.Connect("localhost", port)
    simple.LoadPlugin(sys.argv[1], remote=False, ns=globals())  # the client's proxies
    simple.LoadPlugin(sys.argv[1], remote=True, ns=globals())
    processes = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    check(processes == int(count), "the server runs %s processes (%d)" % (count, processes))
else:
    simple.LoadPlugin(sys.argv[1], ns=globals())
    processes = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()

cloud_source = simple.ProgrammableSource(OutputDataSetType="vtkPolyData")
cloud_source.Script = SOURCE_SCRIPT

# The source really is split: one piece per process.
cloud = servermanager.Fetch(cloud_source)
check(cloud.GetNumberOfPoints() == TOTAL, "the pieces add up to the cloud")
check(cloud.GetFieldData().GetArray("NumberOfPieces").GetValue(0) == processes,
      "one piece per process")

whole = sphere_cloud()
whole_cloud = make_polydata(whole)
first_piece = make_polydata(whole[:TOTAL // processes])
# Every filter proxy of the plugin's XML with its class (a new proxy is tested here too).
xml_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                        "PointCloudSurface.xml")
FILTERS = [(element.get("name"), element.get("class"), element)
           for element in ElementTree.parse(xml_path).iter("SourceProxy")
           if element.get("name") != "ReconstructionQuality"]


def proxy_settings(proxy, element):
    """{setter: value} of the proxy's one-number properties, as ParaView sends them to the
    class (so the serial reference runs with the proxy's values, whatever its defaults)."""
    settings = {}
    for prop in element:
        if prop.tag in ("IntVectorProperty", "DoubleVectorProperty") \
                and prop.get("number_of_elements") == "1" and prop.get("command"):
            settings[prop.get("command")] = proxy.SMProxy.GetProperty(
                prop.get("name")).GetElement(0)
    return settings

tested = []
for proxy_name, class_name, element in FILTERS:
    check(proxy_name in globals(), "LoadPlugin defines %s" % proxy_name)
    tested.append(proxy_name)
    proxy = globals()[proxy_name](Input=cloud_source)
    for name, value in PROPERTIES.get(proxy_name, {}).items():
        setattr(proxy, name, value)
    properties = proxy_settings(proxy, element)
    check(len(properties) > 0, "%s: its properties found in the XML" % proxy_name)
    print("processes %d: %s: %s" % (processes, proxy_name, ", ".join(
        "%s(%g)" % item for item in sorted(properties.items()))))
    # The reference is the split cloud itself: ReconstructionQuality gathers both inputs.
    quality = globals()["ReconstructionQuality"](Input=proxy, Reference=cloud_source)
    quality.UpdatePipeline()
    measured = servermanager.Fetch(quality)  # the mesh, with the filter's and the measures
    reference = serial_mesh(class_name, properties, whole_cloud)

    triangles = oriented_triangles(measured)
    expected = oriented_triangles(reference)
    values, expected_values = field_values(measured), field_values(reference)
    print("processes %d: %s: %d points, %d triangles (serial %d), genus %g, %d boundary edges"
          % (processes, proxy_name, measured.GetNumberOfPoints(), len(triangles), len(expected),
             values.get("Genus", float("nan")), values.get("NumberOfBoundaryEdges", -1)))
    check(len(expected) > 0, "%s: the serial reference has triangles" % proxy_name)
    check(measured.GetNumberOfPoints() == reference.GetNumberOfPoints() == TOTAL,
          "%s: all %d points on the output (got %d)" % (proxy_name, TOTAL,
                                                        measured.GetNumberOfPoints()))
    check(len(triangles) == len(expected), "%s: %d triangles as serial (got %d)"
          % (proxy_name, len(expected), len(triangles)))
    check(triangles == expected, "%s: the same oriented triangles as serial" % proxy_name)
    check(set(values) == set(expected_values), "%s: the same field data arrays (%s)"
          % (proxy_name, sorted(set(values) ^ set(expected_values))))
    differing = [name for name in sorted(values)
                 if not same_value(values[name], expected_values[name])]
    check(not differing, "%s: field data as serial; differ: %s" % (proxy_name, ", ".join(
        "%s %r (serial %r)" % (n, values[n], expected_values[n]) for n in differing)))
    for name in ("NumberOfTriangles", "NumberOfUsedPoints", "Coverage", "NumberOfBoundaryEdges",
                 "NumberOfNonManifoldEdges", "NumberOfNonManifoldVertices", "Genus",
                 "EulerCharacteristic"):
        check(name in values, "%s: quality field %s" % (proxy_name, name))
    check(values["NumberOfTriangles"] == len(triangles), "%s: measured triangles" % proxy_name)

    if processes > 1:
        # The comparison tells a piece's mesh from the whole cloud's.
        alone = oriented_triangles(serial_mesh(class_name, properties, first_piece))
        check(alone != expected, "%s: the first piece alone meshes differently" % proxy_name)

    if proxy_name == "IncrementalDelaunay3D":
        # Convex position: the hull has 2V - 4 triangles, every point used, closed, genus 0.
        check(len(triangles) == 2 * POINTS - 4, "hull: 2V - 4 triangles")
        check(values["NumberOfUsedPoints"] == POINTS and values["NumberOfBoundaryEdges"] == 0
              and values["NumberOfNonManifoldEdges"] == 0 and values["Genus"] == 0
              and values["EulerCharacteristic"] == 2,
              "hull: closed genus 0 over every distinct point")
        original = vtk_to_numpy(measured.GetPointData().GetArray("OriginalIndex"))
        check(np.array_equal(original, np.arange(TOTAL)),
              "points gathered in process order (the serial order)")

check(len(tested) >= 5, "every filter proxy tested (%s)" % ", ".join(tested))

# ------------------------------------------------------------------------------------------
# ReconstructionQuality on a mesh split in pieces that repeat their border vertices.
TORUS_SCRIPT = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
NU, NV = 24, 12
begin, end = piece * NU // pieces, (piece + 1) * NU // pieces
# Rows begin..end, row end a copy of the next band's first row (rows wrap: NU is row 0); one
# piece wraps by index instead, with no copy.
rows = list(range(begin, end + (1 if pieces > 1 else 0)))
u = 2 * np.pi * (np.array(rows) % NU) / NU
v = 2 * np.pi * np.arange(NV) / NV
uu, vv = np.meshgrid(u, v, indexing="ij")
xyz = np.stack([(2 + np.cos(vv)) * np.cos(uu), (2 + np.cos(vv)) * np.sin(uu), np.sin(vv)],
               axis=-1).reshape(-1, 3)
local = {row: i for i, row in enumerate(rows)}
def pid(row, j):
    row = row if row in local else row % NU
    return local[row] * NV + j % NV
triangles = []
for row in range(begin, end):
    for j in range(NV):
        a, b, c, d = pid(row, j), pid(row + 1, j), pid(row + 1, j + 1), pid(row, j + 1)
        triangles += [(a, b, c), (a, c, d)]
triangles = np.array(triangles, dtype=np.int64)
cells = vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 3 * len(triangles) + 1, 3), deep=True),
              numpy_to_vtkIdTypeArray(triangles.ravel(), deep=True))
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=True))
out = self.GetOutput()
out.SetPoints(points)
out.SetPolys(cells)
"""
torus_source = simple.ProgrammableSource(OutputDataSetType="vtkPolyData")
torus_source.Script = TORUS_SCRIPT
torus_quality = globals()["ReconstructionQuality"](Input=torus_source)
torus_quality.UpdatePipeline()
torus = servermanager.Fetch(torus_quality)


def serial_torus():
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    import pointcloudsurface

    class Info:  # what the script reads from its output information: piece 0 of 1
        def Get(self, key):
            return 1 if key is vtkStreamingDemandDrivenPipeline.UPDATE_NUMBER_OF_PIECES() else 0

    class Self:
        def __init__(self):
            self.output = vtkPolyData()

        def GetOutputInformation(self, port):
            return Info()

        def GetOutput(self):
            return self.output

    holder = Self()
    exec(TORUS_SCRIPT, {"self": holder})

    def run():
        quality = pointcloudsurface.vtkReconstructionQuality()
        quality.SetInputData(holder.output)
        quality.Update()
        result = vtkPolyData()
        result.ShallowCopy(quality.GetOutput())
        return result

    return serial(run)


torus_reference = serial_torus()
values, expected_values = field_values(torus), field_values(torus_reference)
print("processes %d: split torus mesh: %d points, %d triangles, %d boundary edges, genus %g "
      "(serial %d points, genus %g)" % (processes, torus.GetNumberOfPoints(),
                                        values["NumberOfTriangles"],
                                        values["NumberOfBoundaryEdges"], values["Genus"],
                                        torus_reference.GetNumberOfPoints(),
                                        expected_values["Genus"]))
check(torus_reference.GetNumberOfPoints() == 288 and expected_values["NumberOfTriangles"] == 576
      and expected_values["NumberOfBoundaryEdges"] == 0 and expected_values["Genus"] == 1
      and expected_values["EulerCharacteristic"] == 0, "serial torus: closed, genus 1")
check(torus.GetNumberOfPoints() == 288, "split torus: the border copies merged (%d points)"
      % torus.GetNumberOfPoints())
differing = [name for name in sorted(expected_values)
             if not same_value(values.get(name), expected_values[name])]
check(not differing, "split torus: quality as serial; differ: %s" % ", ".join(
    "%s %r (serial %r)" % (n, values.get(n), expected_values[n]) for n in differing))
tested.append("ReconstructionQuality on a split mesh")
print("processes %d: quality as serial (%s)" % (processes, ", ".join(tested)))
