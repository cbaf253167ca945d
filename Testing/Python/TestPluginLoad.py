"""The ParaView plugin loads in pvpython, IncrementalDelaunay3D runs with its 3 outputs, and every
proxy of the plugin's XML runs with its default properties on one cloud with sane output.

The proxies are read from Plugin/PointCloudSurface.xml, so a proxy added there is run here too.
The cloud: 1,000 random points on the unit sphere with their normals (point array Normals), a
point data array to pass through, and 10 exact duplicates. Each reconstruction proxy must give a
vtkPolyData with every input point (1,010), the point data passed, triangles only (> 0), point
ids in range and no triangle with a repeated id; its Used array (when it has one) must be the
triangles' vertex set, with used points > 0 and never both copies of a duplicate used. The
ReconstructionQuality proxy then measures each mesh: its triangle and used-point counts must be
the ones counted here. Progress: every filter reports intermediate progress and is observed by
ParaView's progress handler (what feeds the GUI's progress bar).

The XML against the classes (the Python package's wrapped classes): every proxy has long and
short help and the menu category "Point Cloud Surface", every property has documentation; each
one-number property's default is the class's default, exactly (a double written with enough
digits to read back as the same double, e.g. 0.3333333333333333 for 1/3), in the XML and in the
proxy ParaView makes from it, so ParaView sends the class's own defaults; its range domain is
the class's clamp range (no max = VTK_DOUBLE_MAX), a clamped parameter has a range, boolean or
enumeration domain, an enumeration lists exactly the clamp range, and its entries' texts are the
class's names of those values (the SetXToY methods); its documentation states a default and (when
clamped) a range, "Default ...; range [...]", and they are the class's (read by
TestReadmeParameters.check_statements); and
every parameter of the class (its own Set/Get pairs, as the command line finds them) has a
property.

Usage: pvpython TestPluginLoad.py <path to PointCloudSurface.so>
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

from paraview import servermanager
from paraview.simple import LoadPlugin, PointSource


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)
    return True


LoadPlugin(sys.argv[1], ns=globals())
check("IncrementalDelaunay3D" in globals(), "LoadPlugin defines IncrementalDelaunay3D")

source = PointSource(NumberOfPoints=500, Radius=1.0)
delaunay = IncrementalDelaunay3D(Input=source)  # noqa: F821 (defined by LoadPlugin)

# Every property of the XML, with the class defaults (enumerations read back as their labels).
defaults = {"Dimension": "3D", "ProjectionPlane": "XY plane", "Tolerance": 0.0,
            "GenerateTetrahedra": 1, "GenerateVoronoi": 0}
for name, value in defaults.items():
    check(name in delaunay.ListProperties(), "property %s exists" % name)
    check(delaunay.GetPropertyValue(name) == value, "default of %s is %s (got %s)"
          % (name, value, delaunay.GetPropertyValue(name)))
entries = list(delaunay.GetProperty("Dimension").Available)
check(entries == ["2.5D (terrain)", "3D"], "Dimension entries (got %s)" % entries)
check(delaunay.GetNumberOfOutputPorts() == 3, "3 output ports")
check([delaunay.GetOutputPortName(i) for i in range(3)] == ["Surface", "Tetrahedra", "Voronoi"],
      "output port names")

delaunay.GenerateVoronoi = 1
delaunay.UpdatePipeline()
surface = servermanager.Fetch(delaunay, None, None, 0)
tetrahedra = servermanager.Fetch(delaunay, None, None, 1)
voronoi = servermanager.Fetch(delaunay, None, None, 2)
print("surface", surface.GetNumberOfPoints(), surface.GetNumberOfCells(),
      "tetrahedra", tetrahedra.GetNumberOfCells(), "voronoi", voronoi.GetNumberOfPoints())
check(surface.GetNumberOfPoints() == 500, "the 500 points pass through")
check(tetrahedra.IsA("vtkUnstructuredGrid"), "output 1 is a vtkUnstructuredGrid")
check(tetrahedra.GetNumberOfCells() > 0, "tetrahedra are produced")
check(surface.GetNumberOfCells() > 0, "hull triangles are produced")
# Voronoi: one vertex per tetrahedron plus one ray end per hull triangle.
check(voronoi.GetNumberOfPoints() == tetrahedra.GetNumberOfCells() + surface.GetNumberOfCells(),
      "Voronoi vertex count")

# ------------------------------------------------------------------------------------------
# Every proxy of the plugin on one cloud.
import numpy as np  # noqa: E402
from paraview.simple import ProgrammableSource  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

xml_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                        "PointCloudSurface.xml")
proxies = [element.get("name") for element in ElementTree.parse(xml_path).iter("SourceProxy")]
classes = {element.get("name"): element.get("class")
           for element in ElementTree.parse(xml_path).iter("SourceProxy")}
print("proxies in the XML:", ", ".join(proxies))
check("IncrementalDelaunay3D" in proxies and "ReconstructionQuality" in proxies
      and len(proxies) >= 5, "the XML lists the filters")

POINTS, DUPLICATES = 1000, 10
cloud = ProgrammableSource(OutputDataSetType="vtkPolyData")
cloud.Script = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.util.numpy_support import numpy_to_vtk
p = np.random.default_rng(5).normal(size=(%d, 3))
p /= np.linalg.norm(p, axis=1)[:, None]
p = np.vstack([p, p[:%d]])
points = vtkPoints()
points.SetData(numpy_to_vtk(p, deep=True))
out = self.GetOutput()
out.SetPoints(points)
normals = numpy_to_vtk(p, deep=True)
normals.SetName("Normals")
out.GetPointData().SetNormals(normals)
label = numpy_to_vtk(np.arange(len(p), dtype=np.int32), deep=True)
label.SetName("Label")
out.GetPointData().AddArray(label)
""" % (POINTS, DUPLICATES)
cloud.UpdatePipeline()
total = POINTS + DUPLICATES

# ParaView's progress bar is fed by the session's progress handler: ParaView registers every
# algorithm it creates with it (an observer of the algorithm's ProgressEvent), and the handler
# relays the events (text: the class name; value: percent) at most once per ProgressInterval
# (0.01 s at least; which events pass depends on timing, so they are counted, not required).
# Deterministic checks: the server-side object has ParaView's observer before ours is added,
# and the filter itself reports intermediate progress (0 < p < 1, besides the pipeline's 0 and
# 1), observed on the server-side object (built-in session).
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402

# Imported before any server-side object reaches Python: an object of a class Python does not
# know yet would register the class name with its base's wrapper (vtkPolyDataAlgorithm), and the
# package's classes could not be used after it.
import pointcloudsurface  # noqa: E402,F401

progress_handler = servermanager.ActiveConnection.Session.GetProgressHandler()
progress_handler.SetProgressInterval(0.01)
relayed = []
progress_handler.AddObserver(vtkCommand.ProgressEvent,
                             lambda handler, event: relayed.append(handler.GetLastProgressText()))
own_progress = []


def watch_progress(name, proxy):
    del own_progress[:]
    algorithm = proxy.GetClientSideObject()
    check(algorithm.IsA(classes[name]), "%s: the server-side object is a %s"
          % (name, classes[name]))
    check(algorithm.HasObserver(vtkCommand.ProgressEvent),
          "%s: ParaView's progress handler observes the filter's progress" % name)
    algorithm.AddObserver(vtkCommand.ProgressEvent,
                          lambda caller, event: own_progress.append(caller.GetProgress()))


def check_progress(name):
    middle = [p for p in own_progress if 0.0 < p < 1.0]
    check(len(middle) > 0, "%s: intermediate progress reported (got %s)" % (name, own_progress))
    return len(middle)


ran = []
for name in proxies:
    if name == "ReconstructionQuality":
        continue
    check(name in globals(), "LoadPlugin defines %s" % name)
    proxy = globals()[name](Input=cloud)
    watch_progress(name, proxy)
    proxy.UpdatePipeline()
    steps = check_progress(name)
    mesh = servermanager.Fetch(proxy, None, None, 0)
    check(mesh is not None and mesh.IsA("vtkPolyData"), "%s: output 0 is a vtkPolyData" % name)
    check(mesh.GetNumberOfPoints() == total, "%s: all %d points pass through (got %d)"
          % (name, total, mesh.GetNumberOfPoints()))
    label = mesh.GetPointData().GetArray("Label")
    check(label is not None and np.array_equal(vtk_to_numpy(label), np.arange(total)),
          "%s: point data passed through in input order" % name)
    polys = mesh.GetPolys()
    triangles = polys.GetNumberOfCells()
    check(triangles > 0, "%s: triangles produced" % name)
    check(mesh.GetNumberOfCells() == triangles, "%s: triangles only (%d cells, %d polygons)"
          % (name, mesh.GetNumberOfCells(), triangles))
    check(np.all(np.diff(vtk_to_numpy(polys.GetOffsetsArray())) == 3),
          "%s: every polygon has 3 points" % name)
    ids = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3)
    check(ids.min() >= 0 and ids.max() < total, "%s: no dangling point id" % name)
    check(np.all((ids[:, 0] != ids[:, 1]) & (ids[:, 1] != ids[:, 2]) & (ids[:, 0] != ids[:, 2])),
          "%s: no triangle with a repeated point" % name)
    used = np.zeros(total, dtype=bool)
    used[ids.reshape(-1)] = True
    check(used.sum() > 0, "%s: used points" % name)
    check(not (used[:DUPLICATES] & used[POINTS:]).any(),
          "%s: never both copies of a duplicated point in the mesh (%s, %s)"
          % (name, used[:DUPLICATES].astype(int), used[POINTS:].astype(int)))
    used_array = mesh.GetPointData().GetArray("Used")
    if used_array is not None:
        check(np.array_equal(vtk_to_numpy(used_array) != 0, used),
              "%s: point data Used is the triangles' vertex set" % name)
    quality = ReconstructionQuality(Input=proxy)  # noqa: F821 (defined by LoadPlugin)
    watch_progress("ReconstructionQuality", quality)
    quality.UpdatePipeline()
    quality_steps = check_progress("ReconstructionQuality")
    fd = servermanager.Fetch(quality).GetFieldData()
    check(fd.GetArray("NumberOfTriangles").GetTuple1(0) == triangles,
          "%s: ReconstructionQuality counts the triangles" % name)
    check(fd.GetArray("NumberOfUsedPoints").GetTuple1(0) == used.sum(),
          "%s: ReconstructionQuality counts the used points" % name)
    print("%s: %d points, %d triangles, %d used, %d boundary edges, %d non-manifold edges; "
          "progress steps %d (quality %d)" % (
              name, total, triangles, used.sum(),
              fd.GetArray("NumberOfBoundaryEdges").GetTuple1(0),
              fd.GetArray("NumberOfNonManifoldEdges").GetTuple1(0), steps, quality_steps))
    ran.append(name)
check(len(ran) == len(proxies) - 1, "every reconstruction proxy ran")
print("progress events relayed by ParaView's progress handler: %s"
      % ", ".join("%s %d" % (c, relayed.count(c)) for c in sorted(set(relayed))))

# ------------------------------------------------------------------------------------------
# The XML against the classes.
from pointcloudsurface.methods import discover_parameters  # noqa: E402

# The "Default ...; range [...]" the property documentation states, read as in the README test.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import TestReadmeParameters as readme_test  # noqa: E402
stated = 0




for element in ElementTree.parse(xml_path).iter("SourceProxy"):
    name, class_name = element.get("name"), element.get("class")
    cls = getattr(pointcloudsurface, class_name, None)
    if not check(cls is not None, "%s: class %s in the package" % (name, class_name)):
        continue
    instance = cls()
    class_parameters = {p.name: p for p in discover_parameters(cls)}
    live_proxy = servermanager.ProxyManager().NewProxy("filters", name)
    check(live_proxy is not None, "%s: ParaView makes the proxy" % name)
    doc = element.find("Documentation")
    check(doc is not None and doc.get("long_help") and doc.get("short_help"),
          "%s: long_help and short_help" % name)
    menu = element.find("Hints/ShowInMenu")
    check(menu is not None and menu.get("category") == "Point Cloud Surface",
          "%s: in the Point Cloud Surface menu" % name)
    exposed = set()
    for prop in element:
        if not prop.tag.endswith("Property"):
            continue
        label = "%s.%s" % (name, prop.get("name"))
        text = prop.find("Documentation")
        check(text is not None and (text.text or "").strip(), "%s: documented" % label)
        command = prop.get("command") or ""
        if (prop.tag not in ("IntVectorProperty", "DoubleVectorProperty")
                or prop.get("number_of_elements") != "1" or not command.startswith("Set")):
            continue
        parameter = command[3:]
        exposed.add(parameter)
        default = float(prop.get("default_values"))
        actual = getattr(instance, "Get" + parameter)()
        check(float(actual) == default, "%s: XML default %r = class default %r"
              % (label, default, actual))
        if parameter in class_parameters:
            stated += readme_test.check_statements(
                label + " XML documentation", text.text, class_parameters[parameter], actual,
                required=True)
            entries = [(entry.get("text"), int(entry.get("value")))
                       for entry in prop.iter("Entry")]
            if class_parameters[parameter].choices:
                stated += readme_test.check_choices(label + " XML entries", entries,
                                                    class_parameters[parameter])
        live = live_proxy.GetProperty(prop.get("name")).GetElement(0)
        check(float(live) == float(actual), "%s: the proxy's default %r = class default %r"
              % (label, live, actual))
        clamped = hasattr(instance, "Get%sMinValue" % parameter)
        low = getattr(instance, "Get%sMinValue" % parameter)() if clamped else None
        high = getattr(instance, "Get%sMaxValue" % parameter)() if clamped else None
        domain = prop.find("IntRangeDomain")
        domain = domain if domain is not None else prop.find("DoubleRangeDomain")
        enumeration = prop.find("EnumerationDomain")
        if domain is not None:
            if check(clamped, "%s: a range in the XML and a clamp in the class" % label):
                xml_low = float(domain.get("min")) if domain.get("min") is not None else None
                xml_high = float(domain.get("max")) if domain.get("max") is not None else None
                check(xml_low == low, "%s: XML min %r = clamp min %r" % (label, xml_low, low))
                check(xml_high == high if xml_high is not None else high >= 1e299,
                      "%s: XML max %r = clamp max %r" % (label, xml_high, high))
        elif clamped:
            check(prop.find("BooleanDomain") is not None or enumeration is not None,
                  "%s: the class clamps it, the XML has no range domain" % label)
        if enumeration is not None and clamped:
            values = sorted(int(entry.get("value")) for entry in enumeration.iter("Entry"))
            check(values == list(range(int(low), int(high) + 1)),
                  "%s: enumeration %s = clamp range [%s, %s]" % (label, values, low, high))
    for parameter in discover_parameters(cls):
        check(parameter.name in exposed, "%s: class parameter %s has a property"
              % (name, parameter.name))
    print("%s: %d properties match %s" % (name, len(exposed), class_name))
check(not readme_test.failures, "the XML documentation states the class's defaults and ranges")
print("XML documentation: %d stated defaults and ranges = the class's" % stated)
print("ok")
