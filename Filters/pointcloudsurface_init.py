"""PointCloudSurface: surface reconstruction filters for VTK.

Import the filters from here, e.g. ``from pointcloudsurface import vtkIncrementalDelaunay3D``.
"""
# The VTK modules the filters derive from must be loaded first.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .vtkPointCloudSurfaceFilters import *  # noqa: F401,F403
