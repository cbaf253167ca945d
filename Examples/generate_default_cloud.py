"""The bundled default cloud: a deterministic, scan-like sample of a hilly terrain.

20,000 points of z = f(x, y) over [0, 100] x [0, 60] metres (two hills, a wavy ridge pattern and
a valley), drawn with a fixed seed, with 5 cm of Gaussian measurement noise in z, a denser strip
(an overlapping scan pass) and 100 exact duplicates (points recorded twice), as merged scans have:
20,100 points in all, written as a vtkPolyData with one vertex cell per point.

    /usr/bin/python3 Examples/generate_default_cloud.py [output.vtp]

(default output: build/default_cloud.vtp). Other scripts import make_cloud() and write_polydata().
"""
import argparse
import math
import os
import random

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_OUTPUT = os.path.join(REPOSITORY, "build", "default_cloud.vtp")

NUMBER_OF_POINTS = 20000
SEED = 2026
NOISE = 0.05  # metres, standard deviation in z
DUPLICATE_EVERY = 200  # every 200th point is recorded a second time


def height(x, y):
    """Terrain elevation in metres at (x, y)."""
    hill = 6.0 * math.exp(-((x - 30.0) ** 2 + (y - 25.0) ** 2) / 300.0)
    knoll = 4.0 * math.exp(-((x - 70.0) ** 2 + (y - 40.0) ** 2) / 150.0)
    waves = 1.5 * math.sin(x / 9.0) * math.cos(y / 7.0)
    valley = -2.0 * math.exp(-((y - 0.4 * x - 5.0) ** 2) / 20.0)
    return hill + knoll + waves + valley


def make_cloud(number_of_points=NUMBER_OF_POINTS, seed=SEED):
    """The cloud as a vtkPolyData (double coordinates, one vertex per point)."""
    rng = random.Random(seed)
    coordinates = []
    for i in range(number_of_points):
        if i % 5 == 0:  # a fifth of the points: the overlapping pass over 40 <= x <= 60
            x, y = rng.uniform(40.0, 60.0), rng.uniform(0.0, 60.0)
        else:
            x, y = rng.uniform(0.0, 100.0), rng.uniform(0.0, 60.0)
        coordinates.append((x, y, height(x, y) + rng.gauss(0.0, NOISE)))
    coordinates.extend(coordinates[i] for i in range(0, number_of_points, DUPLICATE_EVERY))

    points = vtkPoints()
    points.SetDataTypeToDouble()
    points.SetNumberOfPoints(len(coordinates))
    for i, p in enumerate(coordinates):
        points.SetPoint(i, p)
    vertices = vtkCellArray()
    for i in range(len(coordinates)):
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(i)
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    cloud.SetVerts(vertices)
    return cloud


def write_polydata(cloud, path):
    """Writes a vtkPolyData as a .vtp file, creating its folder."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(cloud)
    if not writer.Write():
        raise RuntimeError("cannot write " + path)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", nargs="?", default=DEFAULT_OUTPUT)
    args = parser.parse_args()
    cloud = make_cloud()
    write_polydata(cloud, args.output)
    print("wrote %s (%d points)" % (args.output, cloud.GetNumberOfPoints()))


if __name__ == "__main__":
    main()
