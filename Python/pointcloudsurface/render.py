"""Offscreen PNG pictures of a reconstructed mesh (and optionally the cloud's unused points).

This VTK (ParaView 5.11's VTK 9.2 on Debian) renders through X only: without an X server the
render window aborts the process. ``can_render()`` tells whether a display is there; the
command line re-runs itself under ``xvfb-run -a`` when it is not.
"""
import os

__all__ = ["can_render", "render_png"]


def can_render():
    return bool(os.environ.get("DISPLAY"))


def render_png(mesh, path, size=(1024, 768), colour_by="z", show_unused=None, view_up=None,
               direction=None):
    """Writes a shaded picture of ``mesh``'s polygons to ``path`` (PNG), white background.

    colour_by: "z" colours by elevation (blue low to red high) or None for a single colour.
    show_unused: a vtkPolyData of points drawn as small dark dots (e.g. unused cloud points).
    The camera looks at the mesh's bounds from the (-1, -2, 1.5) direction, z up (x-y nearly
    flat meshes: from above at the same azimuth); ``view_up`` and ``direction`` (3-vectors, from
    the focal point towards the camera) replace those defaults. Returns the path. Raises
    RuntimeError when no display is available.
    """
    if not can_render():
        raise RuntimeError("rendering needs an X display (run under xvfb-run -a)")
    import vtkmodules.vtkInteractionStyle  # noqa: F401
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window factory)
    from vtkmodules.vtkCommonCore import vtkLookupTable
    from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkPolyDataNormals
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import (
        vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter)

    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    bounds = mesh.GetBounds() if mesh.GetNumberOfPoints() else (0, 1, 0, 1, 0, 1)

    if mesh.GetNumberOfPolys() > 0:
        normals = vtkPolyDataNormals()
        normals.SetInputData(mesh)
        normals.SplittingOff()
        normals.ConsistencyOff()  # keep the filter's orientation; two-sided lighting below
        normals.ComputePointNormalsOn()
        mapper = vtkPolyDataMapper()
        if colour_by == "z":
            elevation = vtkElevationFilter()
            elevation.SetInputConnection(normals.GetOutputPort())
            elevation.SetLowPoint(0.0, 0.0, bounds[4])
            elevation.SetHighPoint(0.0, 0.0, bounds[5] if bounds[5] > bounds[4] else bounds[4] + 1)
            colours = vtkLookupTable()
            colours.SetHueRange(0.667, 0.0)
            colours.Build()
            mapper.SetInputConnection(elevation.GetOutputPort())
            mapper.SetLookupTable(colours)
            mapper.SetScalarRange(0.0, 1.0)
        else:
            mapper.SetInputConnection(normals.GetOutputPort())
            mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        if colour_by != "z":
            actor.GetProperty().SetColor(0.85, 0.85, 0.8)
        renderer.AddActor(actor)
    if show_unused is not None and show_unused.GetNumberOfPoints() > 0:
        dots = vtkPolyDataMapper()
        dots.SetInputData(show_unused)
        dots.ScalarVisibilityOff()
        dots_actor = vtkActor()
        dots_actor.SetMapper(dots)
        dots_actor.GetProperty().SetColor(0.1, 0.1, 0.1)
        dots_actor.GetProperty().SetPointSize(3)
        dots_actor.GetProperty().SetRepresentationToPoints()
        renderer.AddActor(dots_actor)

    renderer.TwoSidedLightingOn()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(int(size[0]), int(size[1]))
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    extent = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    camera.SetFocalPoint(*centre)
    flat = extent[2] < 0.2 * max(extent[0], extent[1])
    if direction is None:
        direction = (-0.4, -1.0, 0.8) if flat else (-1.0, -2.0, 1.5)
    camera.SetPosition(*(c + d for c, d in zip(centre, direction)))
    camera.SetViewUp(*(view_up or (0.0, 0.0, 1.0)))
    renderer.ResetCamera()
    camera.Zoom(1.2)
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(os.fspath(path))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()
    return path
