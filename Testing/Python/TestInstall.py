"""`cmake --install` installs a working package, command and plugin.

Installs the build into a fresh prefix, then, with nothing of the build tree on PYTHONPATH or in
the plugin variables:
- the interpreter running this test (/usr/bin/python3) imports `pointcloudsurface` from the
  prefix (the extension and the module library loaded are the installed ones, found through the
  extension's RUNPATH) and
  reconstruct() meshes an n x m grid in 2.5D with 2 (n - 1) (m - 1) triangles;
- <prefix>/bin/pointcloud-surface meshes the same grid written as .xyz into a .ply and prints
  the quality line with that triangle count;
- pvpython with PV_PLUGIN_CONFIG_FILE = the installed PointCloudSurface.plugins.xml autoloads the
  installed plugin (no LoadPlugin) and runs LocalOptimumGrowth on a UV sphere: 2V - 4 triangles.

Usage: python3 TestInstall.py <cmake> <build dir> <prefix> <python destination> <bindir> <libdir>
       [<pvpython>]
(python destination, bindir and libdir relative to the prefix, as CMake installs them).
"""
import os
import shutil
import subprocess
import sys

cmake, build, prefix, python_dest, bindir, libdir = sys.argv[1:7]
pvpython = sys.argv[7] if len(sys.argv) > 7 else None
failed = False


def check(condition, message):
    global failed
    if not condition:
        print("FAILED:", message)
        failed = True
    return condition


def clean_env():
    env = dict(os.environ)
    for name in ("PYTHONPATH", "PV_PLUGIN_PATH", "PV_PLUGIN_CONFIG_FILE", "LD_LIBRARY_PATH"):
        env.pop(name, None)
    return env


if os.path.exists(prefix):
    shutil.rmtree(prefix)
run = subprocess.run([cmake, "--install", build, "--prefix", prefix], capture_output=True,
                     text=True)
if not check(run.returncode == 0, "cmake --install exits 0:\n" + run.stdout + run.stderr):
    sys.exit(1)

package = os.path.join(prefix, python_dest, "pointcloudsurface")
command = os.path.join(prefix, bindir, "pointcloud-surface")
plugins_xml = os.path.join(prefix, libdir, "paraview-plugins", "PointCloudSurface.plugins.xml")
for path in [os.path.join(package, name) for name in
             ("__init__.py", "__main__.py", "arrays.py", "cli.py", "fileio.py", "methods.py",
              "render.py")] + [command]:
    check(os.path.isfile(path), "installed: %s" % os.path.relpath(path, prefix))
check(os.access(command, os.X_OK), "the command is executable")
check(any(n.startswith("vtkPointCloudSurfaceFilters") and n.endswith(".so")
          for n in os.listdir(package)), "installed: the wrapped extension")

# Python from the prefix only.
N, M = 7, 5
script = r"""
import os, sys
import numpy as np
import pointcloudsurface
from pointcloudsurface import reconstruct
prefix = os.path.realpath(sys.argv[1])
assert os.path.realpath(pointcloudsurface.__file__).startswith(prefix), pointcloudsurface.__file__
loaded = sorted(set(l.split()[-1] for l in open("/proc/self/maps") if "PointCloudSurface" in l))
outside = [p for p in loaded if not os.path.realpath(p).startswith(prefix)]
assert loaded and not outside, "libraries loaded from outside the prefix: %s" % outside
x, y = np.meshgrid(np.arange(@N@, dtype=float), np.arange(@M@, dtype=float))
points = np.column_stack([x.ravel(), y.ravel(), 0.1 * x.ravel() * y.ravel()])
mesh = reconstruct(points, method="terrain")
print("installed python: %d triangles from %s" % (mesh.GetNumberOfPolys(), loaded))
""".replace("@N@", str(N)).replace("@M@", str(M))
run = subprocess.run([sys.executable, "-c", script, prefix], env=dict(
    clean_env(), PYTHONPATH=os.path.join(prefix, python_dest)), capture_output=True, text=True)
expected = 2 * (N - 1) * (M - 1)
check(run.returncode == 0 and "installed python: %d triangles" % expected in run.stdout,
      "the installed package imports and meshes the grid (%d triangles):\n%s%s"
      % (expected, run.stdout, run.stderr))
print(run.stdout.strip())

# The installed command, from any directory, with nothing on PYTHONPATH.
work = os.path.join(os.path.dirname(prefix), "install-run")
os.makedirs(work, exist_ok=True)
cloud = os.path.join(work, "grid.xyz")
with open(cloud, "w") as stream:
    for j in range(M):
        for i in range(N):
            stream.write("%d %d %g\n" % (i, j, 0.1 * i * j))
mesh_path = os.path.join(work, "grid.ply")
if os.path.exists(mesh_path):
    os.remove(mesh_path)
run = subprocess.run([command, cloud, "-m", "terrain", "-o", mesh_path, "--no-progress"],
                     env=clean_env(), cwd=work, capture_output=True, text=True)
check(run.returncode == 0 and "quality: %d triangles" % expected in run.stdout
      and os.path.isfile(mesh_path),
      "installed pointcloud-surface writes the mesh and the quality line:\n%s%s"
      % (run.stdout, run.stderr))
print("installed command:", run.stdout.strip().splitlines()[-1] if run.stdout.strip() else "")

# The installed plugin, autoloaded by pvpython from the installed plugins file.
if pvpython:
    check(os.path.isfile(plugins_xml), "installed: %s" % os.path.relpath(plugins_xml, prefix))
    script = r"""
import os, sys
import paraview.simple as simple
from paraview import servermanager
assert hasattr(simple, "LocalOptimumGrowth"), "the plugin was not autoloaded"
sphere = simple.Sphere(ThetaResolution=16, PhiResolution=10)
mesh = simple.LocalOptimumGrowth(Input=sphere)
mesh.UpdatePipeline()
points = servermanager.Fetch(sphere).GetNumberOfPoints()
triangles = servermanager.Fetch(mesh).GetNumberOfPolys()
prefix = os.path.realpath(sys.argv[1])
loaded = sorted(set(l.split()[-1] for l in open("/proc/self/maps") if "PointCloudSurface" in l))
outside = [p for p in loaded if not os.path.realpath(p).startswith(prefix)]
assert len(loaded) >= 2 and not outside, "plugin libraries: %s" % loaded
print("installed plugin: %d points, %d triangles" % (points, triangles))
"""
    with open(os.path.join(work, "autoload.py"), "w") as stream:
        stream.write(script)
    run = subprocess.run([pvpython, "--force-offscreen-rendering",
                          os.path.join(work, "autoload.py"), prefix],
                         env=dict(clean_env(), PV_PLUGIN_CONFIG_FILE=plugins_xml),
                         capture_output=True, text=True, timeout=200)
    line = [l for l in run.stdout.splitlines() if l.startswith("installed plugin:")]
    ok = False
    if run.returncode == 0 and line:
        points, triangles = [int(w) for w in line[0].replace(",", " ").split() if w.isdigit()]
        ok = triangles == 2 * points - 4
    check(ok, "pvpython autoloads the installed plugin and meshes the sphere closed "
          "(2V - 4 triangles):\n%s%s" % (run.stdout, run.stderr[-2000:]))
    print(line[0] if line else "")

if failed:
    sys.exit(1)
print("install ok")
