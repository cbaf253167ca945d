"""numpy <-> VTK helpers: an (N, 3) array to a point cloud, a triangle mesh back to arrays.

    >>> import numpy as np
    >>> from pointcloudsurface import points_to_polydata, polydata_to_arrays, reconstruct
    >>> cloud = points_to_polydata(np.random.rand(1000, 3))
    >>> mesh = reconstruct(cloud, method="delaunay")        # or reconstruct(array, ...)
    >>> points, triangles = polydata_to_arrays(mesh)        # (N, 3) float64, (T, 3) int64

The arrays are copied (deep): the VTK objects do not keep a reference to numpy memory and the
returned arrays do not alias VTK memory.
"""
import warnings

import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_ID_TYPE, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

__all__ = ["points_to_polydata", "polydata_to_arrays", "triangles_to_polydata", "as_point_array"]


def as_point_array(values, name="points"):
    """``values`` as a C-contiguous float64 (N, 3) array; ValueError for any other shape."""
    array = np.asarray(values, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError("%s must have shape (N, 3), got %s" % (name, array.shape))
    return np.ascontiguousarray(array)


def _id_array(values):
    return numpy_to_vtk(np.ascontiguousarray(values, dtype=np.int64), deep=1,
                        array_type=VTK_ID_TYPE)


def _cells(offsets, connectivity):
    cells = vtkCellArray()
    cells.SetData(_id_array(offsets), _id_array(connectivity))
    return cells


def points_to_polydata(points, normals=None, point_data=None, vertices=True):
    """A vtkPolyData cloud from an (N, 3) array.

    points: (N, 3) array-like (copied as float64; NaN/Inf rows are kept, the filters skip and
        count them). normals: optional (N, 3) array, stored as the point data array "Normals"
        and set as the active normals. point_data: optional dict name -> array of N values or
        (N, k) tuples, added as point data. vertices: add one vertex cell per point (default
        True) so that the cloud renders and writes as points; the filters ignore cells.
    """
    xyz = as_point_array(points)
    n = xyz.shape[0]
    cloud = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(xyz, deep=1))
    cloud.SetPoints(vtk_points)
    if vertices:
        cloud.SetVerts(_cells(np.arange(n + 1), np.arange(n)))
    if normals is not None:
        nxyz = as_point_array(normals, "normals")
        if nxyz.shape[0] != n:
            raise ValueError("normals has %d rows, points %d" % (nxyz.shape[0], n))
        array = numpy_to_vtk(nxyz, deep=1)
        array.SetName("Normals")
        cloud.GetPointData().SetNormals(array)
    for name, values in (point_data or {}).items():
        values = np.ascontiguousarray(values)
        if values.shape[0] != n or values.ndim > 2:
            raise ValueError("point data %r must have %d rows (1 or 2 dimensions)" % (name, n))
        array = numpy_to_vtk(values, deep=1)
        array.SetName(str(name))
        cloud.GetPointData().AddArray(array)
    return cloud


def polydata_to_arrays(mesh):
    """(points, triangles) of a vtkPolyData (or any vtkPointSet with polygons).

    points: (N, 3) float64, every point of the mesh (a reconstruction passes ALL input points
    through, used or not, so point i of the mesh is point i of the cloud). triangles: (T, 3)
    int64 indices into points, the polygons with exactly 3 points in cell order. Polygons with
    another point count are skipped with a RuntimeWarning (triangulate them first with
    vtkTriangleFilter if needed); vertex and line cells are ignored.
    """
    n = mesh.GetNumberOfPoints()
    if n == 0 or mesh.GetPoints() is None:
        points = np.zeros((0, 3), dtype=np.float64)
    else:
        points = np.array(vtk_to_numpy(mesh.GetPoints().GetData()), dtype=np.float64)
        points = points.reshape(n, 3)
    polys = mesh.GetPolys() if hasattr(mesh, "GetPolys") else None
    if polys is None or polys.GetNumberOfCells() == 0:
        return points, np.zeros((0, 3), dtype=np.int64)
    offsets = vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    connectivity = vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    sizes = np.diff(offsets)
    is_triangle = sizes == 3
    if not is_triangle.all():
        warnings.warn("polydata_to_arrays: %d polygon(s) without exactly 3 points skipped"
                      % int((~is_triangle).sum()), RuntimeWarning, stacklevel=2)
    starts = offsets[:-1][is_triangle]
    triangles = connectivity[starts[:, None] + np.arange(3)[None, :]]
    return points, np.ascontiguousarray(triangles, dtype=np.int64)


def triangles_to_polydata(points, triangles):
    """A vtkPolyData triangle mesh from (N, 3) points and (T, 3) indices (no vertex cells)."""
    xyz = as_point_array(points)
    tri = np.asarray(triangles, dtype=np.int64)
    if tri.ndim != 2 or tri.shape[1] != 3:
        raise ValueError("triangles must have shape (T, 3), got %s" % (tri.shape,))
    if tri.size and (tri.min() < 0 or tri.max() >= xyz.shape[0]):
        raise ValueError("triangle indices out of range [0, %d)" % xyz.shape[0])
    mesh = points_to_polydata(xyz, vertices=False)
    mesh.SetPolys(_cells(np.arange(0, 3 * tri.shape[0] + 1, 3), tri.reshape(-1)))
    return mesh
