"""The ParaView plugin's ReconstructionQuality proxy: properties, defaults, optional Reference.

Usage: pvpython TestPluginReconstructionQuality.py <path to PointCloudSurface.so>
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, Sphere


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)


LoadPlugin(sys.argv[1], ns=globals())
check("ReconstructionQuality" in globals(), "LoadPlugin defines ReconstructionQuality")

sphere = Sphere(ThetaResolution=16, PhiResolution=10)
quality = ReconstructionQuality(Input=sphere)  # noqa: F821 (defined by LoadPlugin)
defaults = {"SamplesPerTriangle": 3, "ComputeDistances": 1}
for name, value in defaults.items():
    check(name in quality.ListProperties(), "property %s exists" % name)
    check(quality.GetPropertyValue(name) == value, "default of %s is %s (got %s)"
          % (name, value, quality.GetPropertyValue(name)))
check("Reference" in quality.ListProperties(), "Reference input property exists")

# Without a reference (the optional input left empty).
quality.UpdatePipeline()
out = servermanager.Fetch(quality)
fd = out.GetFieldData()
check(fd.GetArray("Genus").GetTuple1(0) == 0, "sphere genus 0")
check(fd.GetArray("EulerCharacteristic").GetTuple1(0) == 2, "sphere Euler characteristic 2")
check(fd.GetArray("Hausdorff") is None, "no distances without a reference")

# With a reference: a finer sphere of the same radius (0.5); the distances are small.
reference = Sphere(ThetaResolution=32, PhiResolution=20)
quality.Reference = reference
quality.UpdatePipeline()
out = servermanager.Fetch(quality)
fd = out.GetFieldData()
hausdorff = fd.GetArray("Hausdorff").GetTuple1(0)
print("Hausdorff", hausdorff, "MeanSpacing", fd.GetArray("MeanSpacing").GetTuple1(0))
check(0 < hausdorff < 0.05, "Hausdorff between two tessellations of one sphere")
check(out.GetPointData().GetArray("DistanceToReference") is not None, "DistanceToReference")
print("ok")
