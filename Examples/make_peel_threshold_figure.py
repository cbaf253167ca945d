"""README figure: how ThresholdFactor changes vtkPerimeterPeelSurface's result.

The cloud is the goblet of the paper's Fig. 1 (a surface of revolution with a cavity, the
profile of Testing/Cxx/pcsPeelTestShapes.h: foot, stem, cup 0.1 thick), 8,000 random points
uniform by area. The filter runs with ThresholdFactor 1.0, 1.5, 2.0 and 3.0 (other parameters at
their defaults); each result is cut in half by the plane y = 0 so that the cavity shows, and the
four are pictured in a row in docs/peel_threshold_factor.png: the top row with the relative
measure (LocalSpacingNeighbors 6, the default), the bottom row with the paper's absolute measure
(LocalSpacingNeighbors 0). A table (triangles, coverage, genus, whether the cup's axis at
mid-height is outside the solid) is printed for the README.

    PYTHONPATH=build-peel/lib/python3/dist-packages \\
        xvfb-run -a /usr/bin/python3 Examples/make_peel_threshold_figure.py [--output PATH]
"""
import argparse
import bisect
import math
import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkClipPolyData, vtkPolyDataNormals
from vtkmodules.vtkFiltersModeling import vtkSelectEnclosedPoints
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (rendering back end)

from pointcloudsurface import vtkPerimeterPeelSurface, vtkReconstructionQuality

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FACTORS = (1.0, 1.5, 2.0, 3.0)


def profile(s):
    """The goblet's closed profile (r, z), s in [0, 7): one unit per piece."""
    piece = min(6, int(s))
    t = s - piece
    q = 0.5 * math.pi * t
    return [(0.6 * t, 0.0), (0.6, 0.12 * t), (0.6 - 0.5 * t, 0.12 + 0.18 * t),
            (0.1, 0.3 + 0.4 * t), (0.1 + 0.5 * math.sin(q), 0.7 + 0.8 * (1 - math.cos(q))),
            (0.6 - 0.1 * t, 1.5), (0.5 * math.cos(q), 0.9 + 0.6 * (1 - math.sin(q)))][piece]


def goblet(n, seed):
    """n random points of the goblet, uniform by area (pieces weighted by r x length)."""
    pieces = 7 * 4000
    nodes = [profile(7.0 * i / pieces) for i in range(pieces + 1)]
    weight = [0.0]
    for a, b in zip(nodes, nodes[1:]):
        weight.append(weight[-1] + 0.5 * (a[0] + b[0]) * math.hypot(b[0] - a[0], b[1] - a[1]))
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        w = rng.random() * weight[-1]
        i = min(pieces - 1, bisect.bisect_right(weight, w) - 1)
        f = (w - weight[i]) / max(1e-300, weight[i + 1] - weight[i])
        r, z = profile(7.0 * (i + min(1.0, max(0.0, f))) / pieces)
        angle = 2 * math.pi * rng.random()
        out.append((r * math.cos(angle), r * math.sin(angle), z))
    return np.array(out)


def field(data, name):
    return data.GetFieldData().GetArray(name).GetTuple1(0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default=os.path.join(REPOSITORY, "docs",
                                                         "peel_threshold_factor.png"))
    args = parser.parse_args()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(goblet(8000, 1), deep=1))
    cloud = vtkPolyData()
    cloud.SetPoints(points)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    rows = (6, 0)  # LocalSpacingNeighbors: relative (default), absolute (the paper's)
    window.SetSize(300 * len(FACTORS), 330 * len(rows))
    window.SetMultiSamples(0)
    print("| LocalSpacingNeighbors | ThresholdFactor | triangles | coverage | genus | cup hollow |")
    print("|---|---|---|---|---|---|")
    for row, i, factor in [(r, i, f) for r in range(len(rows)) for i, f in enumerate(FACTORS)]:
        neighbors = rows[row]
        peel = vtkPerimeterPeelSurface()
        peel.SetInputData(cloud)
        peel.SetThresholdFactor(factor)
        peel.SetLocalSpacingNeighbors(neighbors)
        peel.Update()
        mesh = peel.GetOutput()
        quality = vtkReconstructionQuality()
        quality.SetInputData(mesh)
        quality.ComputeDistancesOff()
        quality.Update()
        enclosed = vtkSelectEnclosedPoints()
        enclosed.Initialize(mesh)
        hollow = not enclosed.IsInsideSurface(0.0, 0.0, 1.2)
        q = quality.GetOutput()
        print("| %d | %.1f | %d | %.4f | %d | %s |" % (neighbors, factor, mesh.GetNumberOfPolys(),
                                                field(q, "Coverage"), field(q, "Genus"),
                                                "yes" if hollow else "no"))
        plane = vtkPlane()
        plane.SetNormal(0, 1, 0)
        half = vtkClipPolyData()
        half.SetInputData(mesh)
        half.SetClipFunction(plane)
        normals = vtkPolyDataNormals()
        normals.SetInputConnection(half.GetOutputPort())
        normals.SplittingOff()
        normals.ConsistencyOff()
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(normals.GetOutputPort())
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.85, 0.78, 0.62)
        renderer = vtkRenderer()
        bottom = (len(rows) - 1 - row) / len(rows)
        renderer.SetViewport(i / len(FACTORS), bottom, (i + 1) / len(FACTORS),
                             bottom + 1 / len(rows))
        renderer.SetBackground(1, 1, 1)
        renderer.AddActor(actor)
        label = vtkTextActor()
        label.SetInput("ThresholdFactor %.1f, %s" % (factor, "relative" if neighbors else "absolute"))
        label.GetTextProperty().SetColor(0.1, 0.1, 0.1)
        label.GetTextProperty().SetFontSize(16)
        label.SetPosition(10, 305)
        renderer.AddActor2D(label)
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0.75)
        camera.SetPosition(1.2, -3.0, 2.4)
        camera.SetViewUp(0, 0, 1)
        renderer.ResetCamera()
        camera.Zoom(1.1)
        window.AddRenderer(renderer)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print("wrote", args.output)


if __name__ == "__main__":
    main()
