"""PointCloudSurface: surface reconstruction filters for VTK.

Import the filters from here, e.g. ``from pointcloudsurface import vtkIncrementalDelaunay3D``.

numpy helpers (imported on first use, so the filters alone do not need numpy):
``points_to_polydata(array, normals=None)``, ``polydata_to_arrays(mesh)`` -> (points,
triangles), ``reconstruct(points, method="delaunay", **params)``, ``read_cloud(path)``,
``write_mesh(mesh, path)`` (see the submodules arrays, fileio, methods; the command line is
``python3 -m pointcloudsurface.cli``).
"""
# The VTK modules the filters derive from must be loaded first.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .vtkPointCloudSurfaceFilters import *  # noqa: F401,F403

# Helpers from the pure-Python submodules, loaded on first access (PEP 562).
_HELPERS = {
    "points_to_polydata": "arrays", "polydata_to_arrays": "arrays",
    "triangles_to_polydata": "arrays", "reconstruct": "methods",
    "read_cloud": "fileio", "write_cloud": "fileio", "read_mesh": "fileio", "write_mesh": "fileio",
}


def __getattr__(name):
    if name in _HELPERS:
        import importlib

        return getattr(importlib.import_module("." + _HELPERS[name], __name__), name)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))
