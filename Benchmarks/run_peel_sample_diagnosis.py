#!/usr/bin/env python3
"""Where vtkPerimeterPeelSurface's far triangles and unused points are on a random mesh sample.

Draws the uniform random sample of run_sample_seeds.py (same seed, same points), peels it with
the defaults and measures the output against the mesh with vtkReconstructionQuality. Then, in
mean spacings (vtkReconstructionQuality's MeanSpacing):

- far triangles: output triangles whose centroid is over --far spacings from the mesh, grouped
  into clusters (centroids within 10 spacings of each other, chained). Per cluster: its size,
  its farthest centroid, its centre, and the smallest dot product of the mesh normals at the
  triangles' vertices (each vertex's normal is that of the nearest mesh triangle): about -1 when
  the triangles join two parts of the surface that face each other (a web or a strut across a
  gap), about 1 when they cut across one side (a lid over a cave or a slit);
- unused points (point data Used = 0), grouped the same way (5 spacings): per cluster of 3 or
  more, its size, its deepest point under the output surface (distance to it), its centre, and
  how many of its points have a mesh normal on either side of the first point's (two walls facing
  each other, e.g. a slit narrower than the spacing, give both signs);
- completeness: the 5 mesh samples (vertices and triangle centroids) farthest from the output,
  and how many are over --far spacings.

Usage:
  PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
      Benchmarks/run_peel_sample_diagnosis.py --data /usr/share/cgal-demo/data \
      --mesh camel --seed 1 [--points 100000] [--far 4]
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference as vtk_reference
from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator

import pointcloudsurface as pcs

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_mesh_vertex_sweep import polydata, read_off  # noqa: E402
from run_sample_seeds import sample_mesh  # noqa: E402


class Closest:
    """Distance to a surface and the id of its nearest triangle."""

    def __init__(self, surface):
        self.locator = vtkStaticCellLocator()
        self.locator.SetDataSet(surface)
        self.locator.BuildLocator()
        self.point = [0.0, 0.0, 0.0]
        self.cell, self.sub, self.squared = (vtk_reference(0), vtk_reference(0),
                                             vtk_reference(0.0))

    def __call__(self, query):
        self.locator.FindClosestPoint(query, self.point, self.cell, self.sub, self.squared)
        return np.sqrt(float(self.squared)), int(self.cell)


def clusters(points, radius):
    """Labels of the groups of points chained by distances under radius."""
    labels = -np.ones(len(points), int)
    count = 0
    for seed in range(len(points)):
        if labels[seed] >= 0:
            continue
        labels[seed] = count
        stack = [seed]
        while stack:
            near = np.linalg.norm(points - points[stack.pop()], axis=1) < radius
            new = np.nonzero(near & (labels < 0))[0]
            labels[new] = count
            stack.extend(new)
        count += 1
    return labels, count


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", required=True, help="the CGAL demo data folder (has meshes/)")
    parser.add_argument("--mesh", default="camel")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--points", type=int, default=100000)
    parser.add_argument("--far", type=float, default=4.0, help="in mean spacings")
    args = parser.parse_args()

    points, triangles = read_off(os.path.join(args.data, "meshes", args.mesh + ".off"))
    reference = polydata(points, triangles)
    a, b, c = (points[triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    cloud = sample_mesh(points, triangles, args.points, args.seed)

    peel = pcs.vtkPerimeterPeelSurface()
    peel.SetInputData(polydata(cloud))
    peel.Update()
    output = peel.GetOutput()
    quality = pcs.vtkReconstructionQuality()
    quality.SetInputData(output)
    quality.SetReferenceData(reference)
    quality.Update()
    fields = quality.GetOutput().GetFieldData()
    value = {fields.GetArrayName(i): fields.GetArray(i).GetValue(0)
             for i in range(fields.GetNumberOfArrays())}
    spacing = value["MeanSpacing"]
    print("%s seed %d: mean spacing %.4g, genus %d, coverage %.4f, unused %d, groups %d, "
          "Hausdorff %.2f (accuracy %.2f, completeness %.2f) spacings" % (
              args.mesh, args.seed, spacing, value["Genus"], value["Coverage"],
              value["NumberOfUnusedPoints"], value["NumberOfGroupRemovals"],
              value["HausdorffOverSpacing"], value["AccuracyMaxOverSpacing"],
              value["CompletenessMaxOverSpacing"]))

    to_reference = Closest(reference)
    out_points = vtk_to_numpy(output.GetPoints().GetData()).astype(float)
    out_triangles = vtk_to_numpy(output.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    vertex_normal = {}

    def true_normal(point_id):
        if point_id not in vertex_normal:
            vertex_normal[point_id] = normals[to_reference(out_points[point_id])[1]]
        return vertex_normal[point_id]

    centroids = out_points[out_triangles].mean(axis=1)
    distance = np.array([to_reference(g)[0] for g in centroids]) / spacing
    far = np.nonzero(distance > args.far)[0]
    print("far triangles (centroid over %.1f spacings): %d" % (args.far, len(far)))
    labels, count = clusters(centroids[far], 10 * spacing)
    for k in range(count):
        members = far[labels == k]
        facing = min(float(true_normal(t[i]) @ true_normal(t[j]))
                     for t in out_triangles[members] for i, j in ((0, 1), (1, 2), (2, 0)))
        print("  %4d triangles, farthest %.2f, at %s, smallest normal dot %.2f" % (
            len(members), distance[members].max(), np.round(centroids[members].mean(0), 3),
            facing))

    used = vtk_to_numpy(output.GetPointData().GetArray("Used"))
    unused = np.nonzero(used == 0)[0]
    to_output = Closest(output)
    depth = np.array([to_output(out_points[i])[0] for i in unused]) / spacing
    print("unused points: %d; depth under the output (spacings) histogram [0, 0.5, 1, 2, 4, 8, "
          "inf): %s" % (len(unused), np.histogram(depth, [0, 0.5, 1, 2, 4, 8, np.inf])[0]))
    labels, count = clusters(out_points[unused], 5 * spacing)
    for k in range(count):
        members = np.nonzero(labels == k)[0]
        if len(members) < 3:
            continue
        first = true_normal(unused[members[0]])
        side = np.array([true_normal(unused[m]) @ first for m in members])
        print("  %4d points, deepest %.2f, at %s, normals along / against the first's %d / %d" % (
            len(members), depth[members].max(), np.round(out_points[unused[members]].mean(0), 3),
            (side > 0).sum(), (side <= 0).sum()))

    samples = np.vstack([points, points[triangles].mean(axis=1)])
    completeness = np.array([to_output(s)[0] for s in samples]) / spacing
    print("mesh samples over %.1f spacings from the output: %d; farthest:" % (
        args.far, (completeness > args.far).sum()))
    for k in np.argsort(-completeness)[:5]:
        print("  %.2f at %s" % (completeness[k], np.round(samples[k], 3)))


if __name__ == "__main__":
    main()
