"""numpy helpers of pointcloudsurface: arrays -> VTK -> arrays, reconstruct(), parameter table.

Known by construction:
- points_to_polydata / polydata_to_arrays / triangles_to_polydata return the same values;
- the convex hull of the 6 octahedron vertices plus points strictly inside it has the 8 faces
  of the octahedron (reconstruct(method="delaunay")), and uses exactly those 6 points;
- the 2.5D Delaunay triangulation of an n x m grid has 2 (n - 1) (m - 1) triangles (every
  grid point is a vertex: T = 2 N - 2 - h with h = 2 (n + m) - 4 points on the hull boundary).
Run by /usr/bin/python3 (and pvpython) with PYTHONPATH=<build>/lib/python3/dist-packages.
"""
import sys
import warnings

import numpy as np

import pointcloudsurface
from pointcloudsurface import (points_to_polydata, polydata_to_arrays, reconstruct,
                               triangles_to_polydata)
from pointcloudsurface.methods import (METHODS, MethodNotAvailable, ParameterError,
                                       find_method)


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


rng = np.random.default_rng(8)

# Arrays -> cloud -> arrays.
points = rng.normal(size=(1000, 3))
normals = points / np.linalg.norm(points, axis=1)[:, None]
intensity = rng.random(1000)
cloud = points_to_polydata(points, normals, point_data={"intensity": intensity})
check(cloud.GetNumberOfPoints() == 1000, "1000 points")
check(cloud.GetNumberOfVerts() == 1000, "one vertex cell per point")
check(cloud.GetPoints().GetDataType() == 11, "double coordinates")
back, triangles = polydata_to_arrays(cloud)
check(np.array_equal(back, points), "points unchanged")
check(triangles.shape == (0, 3), "a cloud has no triangles")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

check(np.array_equal(vtk_to_numpy(cloud.GetPointData().GetNormals()), normals),
      "normals unchanged")
check(np.array_equal(vtk_to_numpy(cloud.GetPointData().GetArray("intensity")), intensity),
      "point data unchanged")
points[0, 0] = 99.0
check(cloud.GetPoint(0)[0] != 99.0, "the cloud holds a copy, not the numpy memory")
for bad in (np.zeros((4, 2)), np.zeros(3), [[1, 2, 3, 4]]):
    try:
        points_to_polydata(bad)
        check(False, "shape %s refused" % (np.shape(bad),))
    except ValueError:
        pass
try:
    points_to_polydata(np.zeros((4, 3)), normals=np.zeros((3, 3)))
    check(False, "normals of another length refused")
except ValueError:
    pass
empty = points_to_polydata(np.zeros((0, 3)))
p, t = polydata_to_arrays(empty)
check(p.shape == (0, 3) and t.shape == (0, 3), "empty cloud")

# Triangles -> mesh -> triangles; a quad is skipped with a warning.
grid = np.array([[x, y, 0.0] for y in range(3) for x in range(3)])
tris = np.array([[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4]])
mesh = triangles_to_polydata(grid, tris)
p, t = polydata_to_arrays(mesh)
check(np.array_equal(p, grid) and np.array_equal(t, tris), "triangle mesh round trip")
mesh.GetPolys().InsertNextCell(4, [3, 4, 7, 6])
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    p, t = polydata_to_arrays(mesh)
check(np.array_equal(t, tris), "the quad is not returned")
check(any("without exactly 3 points" in str(w.message) for w in caught), "quad warning")
try:
    triangles_to_polydata(grid, [[0, 1, 9]])
    check(False, "out-of-range triangle index refused")
except ValueError:
    pass

# reconstruct(): convex hull of an octahedron with interior points.
octahedron = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                      dtype=float)
inside = rng.uniform(-1, 1, size=(200, 3))
inside = inside[np.abs(inside).sum(axis=1) < 0.9]
cloud_points = np.vstack([inside, octahedron])
fractions = []
hull = reconstruct(cloud_points, method="delaunay", progress=fractions.append)
p, t = polydata_to_arrays(hull)
check(np.array_equal(p, cloud_points), "every input point passed through, in order")
check(t.shape == (8, 3), "8 hull triangles (got %d)" % t.shape[0])
check(set(t.reshape(-1)) == set(range(len(inside), len(cloud_points))),
      "the hull uses exactly the 6 octahedron vertices")
check(fractions and fractions[-1] == 1.0 and fractions == sorted(fractions),
      "progress from 0 to 1 (got %s)" % fractions[-3:])
# The same from a vtkPolyData input.
hull2 = reconstruct(points_to_polydata(cloud_points), method="delaunay")
check(hull2.GetNumberOfPolys() == 8, "8 triangles from a vtkPolyData")

# 2.5D: n x m grid, parameters by C++ name, snake case and preset method.
n, m = 9, 7
xy = np.array([[i, 0.5 * j] for j in range(m) for i in range(n)], dtype=float)
terrain = np.column_stack([xy, np.sin(xy[:, 0]) * np.cos(xy[:, 1])])
expected = 2 * (n - 1) * (m - 1)
for method, params, cloud_points in (
        ("delaunay", {"Dimension": 2}, terrain), ("delaunay", {"dimension": "2"}, terrain),
        ("terrain", {}, terrain), ("terrain", {"projection_plane": "xy-plane"}, terrain)):
    result = reconstruct(cloud_points, method=method, **params)
    p, t = polydata_to_arrays(result)
    check(t.shape[0] == expected, "%s %s: %d triangles (got %d)" % (method, params, expected,
                                                                   t.shape[0]))
    check(len(set(t.reshape(-1))) == n * m, "every grid point is a vertex")
# Best-fit plane of a tilted planar grid (the rounded projection need not keep the boundary
# points exactly collinear, so only: every point is a vertex of a disk, V - E + F = 1).
tilted = np.column_stack([xy, 0.3 * xy[:, 0] - 0.2 * xy[:, 1]])
p, t = polydata_to_arrays(reconstruct(tilted, method="terrain", ProjectionPlane="BestFitPlane"))
edges = {tuple(sorted(e)) for tri in t for e in ((tri[0], tri[1]), (tri[1], tri[2]),
                                                  (tri[2], tri[0]))}
check(len(set(t.reshape(-1))) == n * m, "best-fit plane: every grid point is a vertex")
check(n * m - len(edges) + len(t) == 1, "best-fit plane: a disk (Euler characteristic 1)")

# Parameter table discovered from the class.
delaunay = find_method("delaunay")
parameters = {p.name: p for p in delaunay.parameters()}
for name in ("Dimension", "ProjectionPlane", "Tolerance", "GenerateTetrahedra",
             "GenerateVoronoi"):
    check(name in parameters, "parameter %s discovered" % name)
check((parameters["Dimension"].minimum, parameters["Dimension"].maximum) == (2, 3),
      "Dimension range [2, 3]")
check(parameters["Dimension"].default == 3, "Dimension default 3")
check(parameters["ProjectionPlane"].choices == {"XYPlane": 0, "BestFitPlane": 1},
      "ProjectionPlane choices (got %s)" % parameters["ProjectionPlane"].choices)
check(parameters["GenerateVoronoi"].kind == "bool", "GenerateVoronoi is a boolean")
check("Default 0" in parameters["Tolerance"].doc, "help text from the class documentation")
check("NumberOfInputPoints" not in parameters, "read-only counts are not parameters")

# Docstrings from the class documentation: every class's docstring is its @class/@brief block
# and more, every parameter has help text giving its default (a parameter documented in a group
# with another takes the group's comment).
from pointcloudsurface.methods import discover_parameters  # noqa: E402

classes = [n for n in dir(pointcloudsurface) if n.startswith("vtk")
           and isinstance(getattr(pointcloudsurface, n), type)
           and hasattr(getattr(pointcloudsurface, n), "SetInputConnection")]
check(len(classes) >= 2, "filter classes in the package (got %s)" % classes)
for name in classes:
    cls = getattr(pointcloudsurface, name)
    doc = cls.__doc__ or ""
    check(doc.startswith(name + " - ") and len(doc) > 1000,
          "%s: the docstring is the class documentation (got %r)" % (name, doc[:80]))
    for parameter in discover_parameters(cls):
        check("default" in parameter.doc.lower(), "%s.%s: help text with its default (got %r)"
              % (name, parameter.name, parameter.doc[:80]))

for bad, text in (({"Dimension": 4}, "out of range"), ({"Tolerance": -1.0}, "out of range"),
                  ({"Dimension": "two"}, "not an integer"),
                  ({"GenerateVoronoi": "maybe"}, "not a boolean"),
                  ({"NoSuchParameter": 1}, "unknown parameter")):
    try:
        reconstruct(terrain, method="delaunay", **bad)
        check(False, "%s refused" % bad)
    except ParameterError as error:
        check(text in str(error), "%s: message '%s' has '%s'" % (bad, error, text))
try:
    reconstruct(terrain, method="no-such-method")
    check(False, "unknown method refused")
except MethodNotAvailable as error:
    check("unknown method" in str(error), "unknown method message")
for method in METHODS:
    check(method.available == hasattr(pointcloudsurface, method.class_name),
          "%s available iff the module has %s" % (method.name, method.class_name))
    if not method.available:
        try:
            reconstruct(terrain, method=method.name)
            check(False, "%s is not built: refused" % method.name)
        except MethodNotAvailable as error:
            check("not available in this build" in str(error), "message for %s" % method.name)
print("methods available:", ", ".join(m.name for m in METHODS if m.available))
print("ok")
