"""numpy in, mesh out, numpy back: the pointcloudsurface helpers on a generated height field.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/numpy_round_trip.py \
        [--method terrain] [--output mesh.npz]

1. 5,000 points of z = sin(x) cos(y) over [0, 6] x [0, 4] (an (N, 3) numpy array);
2. points_to_polydata(): the array as a vtkPolyData cloud (normals optional);
3. reconstruct(): the surface by a method of the command line's table ("terrain": the 2.5D
   Delaunay triangulation; any method this build has, with its parameters as keywords);
4. polydata_to_arrays(): the mesh back as (points, triangles) arrays, written to an .npz file
   and checked: the points come back unchanged and every triangle is counter-clockwise seen from
   above (the 2.5D triangulation is oriented upwards).
"""
import argparse
import sys

import numpy as np

from pointcloudsurface import points_to_polydata, polydata_to_arrays, reconstruct


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--method", default="terrain")
    parser.add_argument("--output", default=None, help="write points and triangles (.npz)")
    args = parser.parse_args()

    rng = np.random.default_rng(1)
    xy = rng.uniform((0.0, 0.0), (6.0, 4.0), size=(5000, 2))
    points = np.column_stack([xy, np.sin(xy[:, 0]) * np.cos(xy[:, 1])])

    cloud = points_to_polydata(points)
    progress = []
    mesh = reconstruct(cloud, method=args.method, progress=progress.append)
    out_points, triangles = polydata_to_arrays(mesh)

    print("cloud: %d points; mesh: %d triangles over %d used points (progress events: %d)"
          % (len(points), len(triangles), len(np.unique(triangles)), len(progress)))
    if not np.array_equal(out_points, points):
        print("the points changed")
        return 1
    if args.method == "terrain":
        a, b, c = (out_points[triangles[:, i], :2] for i in range(3))
        cross = ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1])
                 - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
        print("triangles counter-clockwise from above: %d of %d" % ((cross > 0).sum(),
                                                                    len(triangles)))
    if args.output:
        np.savez(args.output, points=out_points, triangles=triangles)
        print("wrote", args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
