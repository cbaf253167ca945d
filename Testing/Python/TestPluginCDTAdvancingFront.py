"""The ParaView plugin's CDTAdvancingFront proxy: properties, defaults, the normals array, a run.

Usage: pvpython TestPluginCDTAdvancingFront.py <path to PointCloudSurface.so>
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Sphere


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


LoadPlugin(sys.argv[1], ns=globals())
check("CDTAdvancingFront" in globals(), "LoadPlugin defines CDTAdvancingFront")

# A UV sphere (with point normals): 20 x 12 resolution, 20 * 10 + 2 points.
sphere = Sphere(ThetaResolution=20, PhiResolution=12)
sphere.UpdatePipeline()  # the array list needs the input arrays
front = CDTAdvancingFront(Input=sphere)  # noqa: F821 (defined by LoadPlugin)
defaults = {"UseInputNormals": 1, "NormalSampleSize": 10, "NeighborhoodRadius": 0.0,
            "NeighborhoodRadiusFactor": 5.0, "MinimumNormalDot": 0.5, "MaximumRayDistance": 0.0,
            "MinimumTriangleArea": 0.0, "MaximumNumberOfCandidates": 20, "HoleFilling": 1,
            "HoleFillingRadiusFactor": 0.5, "HoleFillingMinimumNormalDot": 0.2}
for name, value in defaults.items():
    check(name in front.ListProperties(), "property %s exists" % name)
    check(front.GetPropertyValue(name) == value, "default of %s is %s (got %s)"
          % (name, value, front.GetPropertyValue(name)))
check("Normals" in front.ListProperties(), "Normals array property exists")
check(front.Normals[1] == "Normals", "the sphere's Normals array is selected (%s)" % front.Normals)
front.UpdatePipeline()
out = servermanager.Fetch(front)
fd = out.GetFieldData()
n = out.GetNumberOfPoints()
check(n == 202, "all points passed (%d)" % n)
triangles = fd.GetArray("NumberOfTriangles").GetTuple1(0)
print("sphere:", n, "points,", triangles, "triangles")
check(triangles == 2 * n - 4, "closed sphere: 2V - 4 triangles")
check(fd.GetArray("NumberOfHoleTriangles").GetTuple1(0) == 0, "no hole triangle")
# Estimated normals (the input's ignored).
front.UseInputNormals = 0
front.UpdatePipeline()
out = servermanager.Fetch(front)
check(out.GetFieldData().GetArray("NumberOfTriangles").GetTuple1(0) == 2 * n - 4,
      "closed sphere with estimated normals")
check(out.GetPointData().GetArray("EstimatedNormals") is not None,
      "estimated normals passed as EstimatedNormals beside the input's Normals")
print("ok")
