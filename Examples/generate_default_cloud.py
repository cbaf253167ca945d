"""The bundled default cloud: a deterministic, scan-like sample of a hilly terrain.

20,000 points of z = f(x, y) over [0, 100] x [0, 60] metres, drawn with a fixed seed, with 5 cm
of Gaussian measurement noise in z, a denser strip (an overlapping scan pass) and a few exact
duplicates, as real merged scans have.
"""
import argparse
import math
import random

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def height(x, y):
    """Smooth hills, a ridge and a valley (metres)."""
    return (6.0 * math.exp(-((x - 30.0) ** 2 + (y - 25.0) ** 2) / 300.0)
            + 4.0 * math.exp(-((x - 70.0) ** 2 + (y - 40.0) ** 2) / 150.0)
            + 1.5 * math.sin(x / 9.0) * math.cos(y / 7.0)
            - 2.0 * math.exp(-((y - 0.4 * x - 5.0) ** 2) / 20.0))


def make_cloud(number_of_points=20000, seed=2026):
    rng = random.Random(seed)
    points = vtkPoints()
    points.SetDataTypeToDouble()
    coordinates = []
    for i in range(number_of_points):
        if i % 5 == 0:  # denser overlapping pass along a strip
            x, y = rng.uniform(40.0, 60.0), rng.uniform(0.0, 60.0)
        else:
            x, y = rng.uniform(0.0, 100.0), rng.uniform(0.0, 60.0)
        coordinates.append((x, y, height(x, y) + rng.gauss(0.0, 0.05)))
    for i in range(0, number_of_points, 200):  # points recorded twice
        coordinates.append(coordinates[i])
    for p in coordinates:
        points.InsertNextPoint(p)
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    vertices = vtkCellArray()
    for i in range(points.GetNumberOfPoints()):
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(i)
    cloud.SetVerts(vertices)
    return cloud


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("output", nargs="?", default="default_cloud.vtp")
    args = parser.parse_args()
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(make_cloud())
    writer.Write()
    print("wrote", args.output)


if __name__ == "__main__":
    main()
