"""The pointcloud-surface command line and the package's readers and writers.

    TestCommandLine.py <build>/bin/pointcloud-surface

The cloud is a 12 x 9 grid in x-y (shuffled) with heights and unit normals rounded to float32,
so every format, float or double, text or binary, stores it exactly. Known by construction:
its 2.5D Delaunay triangulation (-m terrain) has 2 (n - 1) (m - 1) = 176 triangles, uses all
108 points, has 2 (n - 1) + 2 (m - 1) = 38 boundary edges in 1 loop, no non-manifold edge or
vertex and Euler characteristic 1.

Checks:
- every input format (xyz, txt, pts, pwn, csv with and without a header, ply ASCII / binary
  little and big endian / float and double, pcd ascii / binary / binary_compressed, off, vtp,
  vtk, vtu) reads back the same points (and normals where the format has them), and the
  command line on each gives the same mesh over the same points;
- every output format (vtp vtk ply stl obj, binary and ASCII) holds the same triangles;
- corrupt, truncated, empty, missing and wrong-type input files give exit code 3, a message
  naming the file and no Python traceback; bad parameters exit 2 (4 for a method that is not
  built) with a clear message; an unwritable output exits 5;
- the summary line, the progress bar (--progress) and the PNG (--png, rendered offscreen under
  xvfb-run when there is no display; size and non-background pixels checked);
- every method of the table that this build has runs on a sphere cloud; every parameter of each
  is listed by `-m METHOD --help`, and a non-default value given as option text reaches the
  filter (read back from its getter); inf stands for VTK_DOUBLE_MAX; a value beyond a range
  exits 2; the greedy method runs with options as a user types them;
- Ctrl-C (SIGINT) while the filter runs aborts it: exit code 130, nothing written.
"""
import contextlib
import io
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile

import numpy as np

from vtkmodules.util.numpy_support import vtk_to_numpy

from pointcloudsurface import points_to_polydata, polydata_to_arrays
from pointcloudsurface.cli import main as cli_main
from pointcloudsurface.fileio import (ReadError, read_cloud, read_mesh, write_cloud)
from pointcloudsurface.methods import METHODS, make_filter

COMMAND = sys.argv[1] if len(sys.argv) > 1 else shutil.which("pointcloud-surface")
failures = []


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        failures.append(message)
    return condition


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("ok")
    sys.exit(0)


# --------------------------------------------------------------------------------------------
# The cloud.
NX, NY = 12, 9
rng = np.random.default_rng(2026)
gx, gy = np.meshgrid(np.arange(NX, dtype=np.float64), 0.75 * np.arange(NY))
x, y = gx.ravel(), gy.ravel()
z = (np.sin(0.5 * x) * np.cos(0.7 * y)).astype(np.float32).astype(np.float64)
dzdx = 0.5 * np.cos(0.5 * x) * np.cos(0.7 * y)
dzdy = -0.7 * np.sin(0.5 * x) * np.sin(0.7 * y)
normals = np.column_stack([-dzdx, -dzdy, np.ones_like(x)])
normals = (normals / np.linalg.norm(normals, axis=1)[:, None]).astype(np.float32).astype(float)
order = rng.permutation(x.size)
POINTS = np.column_stack([x, y, z])[order]
NORMALS = normals[order]
N = POINTS.shape[0]
TRIANGLES = 2 * (NX - 1) * (NY - 1)
BOUNDARY = 2 * (NX - 1) + 2 * (NY - 1)

work = tempfile.mkdtemp(prefix="pcs-cli-")


def path(name):
    return os.path.join(work, name)


def same(a, b, exact):
    """Equal arrays; for a format that stores 11 significant digits, equal to 1e-10."""
    if a.shape != b.shape:
        return False
    return np.array_equal(a, b) if exact else np.allclose(a, b, rtol=0, atol=1e-10 * 20)


# VTK's legacy ASCII writer prints 11 significant digits: the one lossy format here.
LOSSY = ("writer-ascii.vtk", "out-ascii.vtk")


# --------------------------------------------------------------------------------------------
# Files in every input format: the package's writers, and files written here byte by byte for
# the variants the writers do not produce.
def ply_file(name, fmt, coordinate_type, with_normals=True, extra=True, faces=None):
    endian = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    fields = [("x", coordinate_type), ("y", coordinate_type), ("z", coordinate_type)]
    if with_normals:
        fields += [("nx", "float"), ("ny", "float"), ("nz", "float")]
    if extra:
        fields += [("red", "uchar"), ("label", "int")]
    header = ["ply", "format %s 1.0" % fmt, "comment made by TestCommandLine",
              "element vertex %d" % N]
    header += ["property %s %s" % (t, n) for n, t in fields]
    if faces is not None:
        header += ["element face %d" % len(faces), "property list uchar int vertex_indices"]
    header.append("end_header")
    columns = [POINTS[:, 0], POINTS[:, 1], POINTS[:, 2]]
    if with_normals:
        columns += [NORMALS[:, 0], NORMALS[:, 1], NORMALS[:, 2]]
    if extra:
        columns += [np.arange(N) % 256, np.arange(N) - 50]
    with open(path(name), "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        if endian is None:
            for row in zip(*columns):
                f.write((" ".join("%.17g" % v for v in row) + "\n").encode())
            for face in faces or []:
                f.write(("%d %s\n" % (len(face), " ".join(map(str, face)))).encode())
        else:
            codes = {"float": "f4", "double": "f8", "uchar": "u1", "int": "i4"}
            record = np.dtype([(n, endian + codes[t]) for n, t in fields])
            table = np.zeros(N, dtype=record)
            for (n, _), column in zip(fields, columns):
                table[n] = column
            f.write(table.tobytes())
            for face in faces or []:
                f.write(struct.pack(endian + "B%di" % len(face), len(face), *face))
    return path(name)


def lzf_compress(data):
    """A small LZF compressor (literal runs and back references), for PCD binary_compressed."""
    out, literal, i, table = bytearray(), bytearray(), 0, {}

    def flush():
        for start in range(0, len(literal), 32):
            chunk = literal[start:start + 32]
            out.append(len(chunk) - 1)
            out.extend(chunk)
        literal.clear()

    while i < len(data):
        key = data[i:i + 3]
        ref = table.get(key) if len(key) == 3 else None
        table[key] = i
        if ref is not None and 0 < i - ref <= 8192:
            length = 3
            while (i + length < len(data) and length < 264
                   and data[ref + length] == data[i + length]):
                length += 1
            flush()
            offset = i - ref - 1
            if length - 2 < 7:
                out.append(((length - 2) << 5) | (offset >> 8))
            else:
                out.append((7 << 5) | (offset >> 8))
                out.append(length - 2 - 7)
            out.append(offset & 0xFF)
            i += length
        else:
            literal.append(data[i])
            i += 1
    flush()
    return bytes(out)


def pcd_compressed(name):
    fields = ["x", "y", "z", "normal_x", "normal_y", "normal_z", "intensity"]
    columns = [POINTS[:, 0], POINTS[:, 1], POINTS[:, 2], NORMALS[:, 0], NORMALS[:, 1],
               NORMALS[:, 2], np.full(N, 7.0)]
    raw = b"".join(np.asarray(c, dtype="<f4").tobytes() for c in columns)
    packed = lzf_compress(raw)
    header = ["VERSION 0.7", "FIELDS " + " ".join(fields), "SIZE" + " 4" * 7,
              "TYPE" + " F" * 7, "COUNT" + " 1" * 7, "WIDTH %d" % N, "HEIGHT 1",
              "VIEWPOINT 0 0 0 1 0 0 0", "POINTS %d" % N, "DATA binary_compressed"]
    with open(path(name), "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        f.write(struct.pack("<II", len(packed), len(raw)) + packed)
    return path(name), len(packed) < len(raw)


def pcd_padded_binary(name):
    """PCL's usual layout: x y z and a padding field, then rgb packed as a float, 4-byte
    integer label."""
    record = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("_", "<f4"), ("rgb", "<f4"),
                       ("label", "<u4")])
    table = np.zeros(N, dtype=record)
    table["x"], table["y"], table["z"] = POINTS[:, 0], POINTS[:, 1], POINTS[:, 2]
    table["label"] = np.arange(N)
    header = ["# .PCD v.7", "VERSION .7", "FIELDS x y z _ rgb label", "SIZE 4 4 4 4 4 4",
              "TYPE F F F F F U", "COUNT 1 1 1 1 1 1", "WIDTH %d" % N, "HEIGHT 1",
              "POINTS %d" % N, "DATA binary"]
    with open(path(name), "wb") as f:
        f.write(("\n".join(header) + "\n").encode() + table.tobytes())
    return path(name)


def text_file(name, text):
    with open(path(name), "w") as f:
        f.write(text)
    return path(name)


rows = ["%r %r %r %r %r %r" % tuple(p) for p in np.column_stack([POINTS, NORMALS])]
csv_shuffled = "label;nz;Z;y;x;ny;nx\n" + "".join(
    "%d;%r;%r;%r;%r;%r;%r\n" % (i, n[2], p[2], p[1], p[0], n[1], n[0])
    for i, (p, n) in enumerate(zip(POINTS, NORMALS)))
off = "OFF\n# vertices only\n%d 0 0\n" % N + "".join("%r %r %r\n" % tuple(p) for p in POINTS)

inputs = []  # (file, has normals)
for ext in (".xyz", ".txt", ".pts", ".pwn", ".csv"):
    write_cloud(POINTS, path("cloud" + ext), normals=NORMALS)
    inputs.append((path("cloud" + ext), True))
write_cloud(POINTS, path("plain.xyz"))
inputs.append((path("plain.xyz"), False))
inputs.append((text_file("commas.txt", "# x, y, z, nx, ny, nz\n// a comment\n\n" +
                         "".join(r.replace(" ", ", ") + "\n" for r in rows)), True))
inputs.append((text_file("header.csv", csv_shuffled), True))
inputs.append((text_file("noheader.csv", "".join(r.replace(" ", ",") + "\n" for r in rows)),
               True))
inputs.append((text_file("cloud.off", off), False))
for binary in (True, False):
    kind = "binary" if binary else "ascii"
    for ext in (".ply", ".pcd", ".vtp", ".vtk"):
        write_cloud(POINTS, path("writer-%s%s" % (kind, ext)), normals=NORMALS, binary=binary)
        inputs.append((path("writer-%s%s" % (kind, ext)), True))
inputs.append((ply_file("double-le.ply", "binary_little_endian", "double"), True))
inputs.append((ply_file("double-be.ply", "binary_big_endian", "double"), True))
inputs.append((ply_file("float-be.ply", "binary_big_endian", "float", extra=False), True))
inputs.append((ply_file("ascii-extra.ply", "ascii", "double"), True))
inputs.append((ply_file("faces-le.ply", "binary_little_endian", "float", with_normals=False,
                        faces=[[0, 1, 2], [2, 3, 4, 5]]), False))
compressed, smaller = pcd_compressed("compressed.pcd")
check(smaller, "the test's LZF compressor compresses (back references exercised)")
inputs.append((compressed, True))
inputs.append((pcd_padded_binary("padded.pcd"), False))
# .vtu: an unstructured grid of the points.
from vtkmodules.vtkFiltersCore import vtkAppendFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter  # noqa: E402

append = vtkAppendFilter()
append.AddInputData(points_to_polydata(POINTS, NORMALS))
append.Update()
vtu = vtkXMLUnstructuredGridWriter()
vtu.SetFileName(path("cloud.vtu"))
vtu.SetInputData(append.GetOutput())
vtu.Write()
inputs.append((path("cloud.vtu"), True))

# Reading: same points (exactly) and normals.
for name, has_normals in inputs:
    label = os.path.basename(name)
    try:
        cloud = read_cloud(name)
    except ReadError as error:
        check(False, "%s: read: %s" % (label, error))
        continue
    points, _ = polydata_to_arrays(cloud)
    exact = label not in LOSSY
    check(same(points, POINTS, exact), "%s: same points" % label)
    array = cloud.GetPointData().GetNormals()
    if has_normals:
        check(array is not None and same(vtk_to_numpy(array), NORMALS, exact),
              "%s: same normals" % label)
    else:
        check(array is None, "%s: no normals" % label)
extra = read_cloud(path("ascii-extra.ply")).GetPointData()
check(extra.GetArray("red") is not None and extra.GetArray("label") is not None
      and vtk_to_numpy(extra.GetArray("label"))[0] == -50, "PLY: other properties as point data")
header_data = read_cloud(path("header.csv")).GetPointData()
check(header_data.GetArray("label") is not None
      and np.array_equal(vtk_to_numpy(header_data.GetArray("label")), np.arange(N)),
      "CSV: other columns as point data, by header name")
padded = read_cloud(path("padded.pcd")).GetPointData()
check(padded.GetArray("label") is not None and padded.GetArray("rgb") is not None
      and padded.GetArray("_") is None, "PCD: other fields passed, padding skipped")
faces = read_mesh(path("faces-le.ply"))
check(faces.GetNumberOfPolys() == 2 and faces.GetNumberOfPoints() == N, "PLY faces read")


# --------------------------------------------------------------------------------------------
# The command line in this process (fast) for the format round trips.
def run_in_process(args):
    with contextlib.redirect_stdout(io.StringIO()):
        try:
            return cli_main(list(args) + ["-q", "--no-progress"])
        except SystemExit as exit_:
            return exit_.code


def triangle_set(mesh):
    """The triangles as sorted corner coordinates, whatever the point numbering: (T, 9)."""
    points, triangles = polydata_to_arrays(mesh)
    return np.array(sorted(tuple(sorted(map(tuple, corners)))
                           for corners in points[triangles].tolist())).reshape(-1, 9)



reference_triangles = None
for name, has_normals in inputs:
    label = os.path.basename(name)
    output = path("mesh-from-%s.vtp" % label.replace(".", "-"))
    code = run_in_process([name, "-m", "terrain", "-o", output])
    if not check(code == 0, "%s: exit code 0 (got %s)" % (label, code)):
        continue
    mesh = read_mesh(output)
    points, triangles = polydata_to_arrays(mesh)
    exact = label not in LOSSY
    check(same(points, POINTS, exact), "%s: the mesh holds every input point, in order"
          % label)
    check(triangles.shape[0] == TRIANGLES, "%s: %d triangles (got %d)"
          % (label, TRIANGLES, triangles.shape[0]))
    check(len(np.unique(triangles)) == N, "%s: every point is a vertex" % label)
    if reference_triangles is None:
        reference_triangles = triangle_set(mesh)
    else:
        check(same(triangle_set(mesh), reference_triangles, exact),
              "%s: the same triangles" % label)

for ext in (".vtp", ".vtk", ".ply", ".stl", ".obj"):
    for ascii_ in (False, True):
        output = path("out%s%s" % ("-ascii" if ascii_ else "", ext))
        code = run_in_process([path("cloud.xyz"), "-m", "terrain", "-o", output]
                              + (["--ascii"] if ascii_ else []))
        label = os.path.basename(output)
        if not check(code == 0 and os.path.isfile(output), "%s written" % label):
            continue
        mesh = read_mesh(output)
        check(mesh.GetNumberOfPolys() == TRIANGLES, "%s: %d triangles (got %d)"
              % (label, TRIANGLES, mesh.GetNumberOfPolys()))
        check(same(triangle_set(mesh), reference_triangles, label not in LOSSY),
              "%s: the same triangles" % label)
# A write into a folder that does not exist.
check(run_in_process([path("cloud.xyz"), "-m", "terrain", "-o", path("no/such/dir/out.ply")])
      == 5, "unwritable output: exit code 5")


# --------------------------------------------------------------------------------------------
# The installed command as a user runs it: exit codes and messages.
def run(args, timeout=300):
    result = subprocess.run([COMMAND] + list(args), capture_output=True, text=True,
                            timeout=timeout, stdin=subprocess.DEVNULL)
    return result.returncode, result.stdout, result.stderr


check(COMMAND is not None and os.access(COMMAND, os.X_OK), "the command %s exists" % COMMAND)

code, out, err = run([path("double-le.ply"), "-m", "terrain", "-o", path("cmd.ply"), "--progress"])
check(code == 0, "command: exit 0 (got %d: %s)" % (code, err))
summary = [line for line in out.splitlines() if line.startswith("quality:")]
check(len(summary) == 1, "one quality line on stdout (got %r)" % out)
if summary:
    line = summary[0]
    for part in ("%d triangles" % TRIANGLES, "coverage 100.0%% (%d of %d points used)" % (N, N),
                 "%d boundary edges (1 loop)" % BOUNDARY, "non-manifold: 0 edges, 0 vertices",
                 "1 component", "Euler characteristic 1", "genus n/a (open)"):
        check(part in line, "summary has '%s': %s" % (part, line))
check("100%" in err and "[####" in err, "progress bar drawn to 100%% (stderr: %r)" % err[-300:])
check("read %d points with normals" % N in err, "input described on stderr")

corrupt = {
    "truncated-binary.ply": open(path("double-le.ply"), "rb").read()[:-100],
    "truncated-ascii.ply": open(path("ascii-extra.ply"), "rb").read()[:-400],
    "bad-header.ply": b"ply\nformat ascii 1.0\nelement vertex three\nend_header\n",
    "not-ply.ply": b"solid x\nfacet normal 0 0 1\n",
    "no-xyz.ply": b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float a\nend_header\n1\n",
    "truncated-binary.pcd": open(path("writer-binary.pcd"), "rb").read()[:-10],
    "bad-fields.pcd": b"VERSION 0.7\nFIELDS a b c\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                      b"WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
    "no-data.pcd": b"VERSION 0.7\nFIELDS x y z\n",
    "bad-compressed.pcd": open(path("compressed.pcd"), "rb").read()[:-20],
    "text.xyz": b"1 2 3\n4 5 six\n",
    "ragged.xyz": b"1 2 3\n4 5 6 7\n",
    "two-columns.xyz": b"1 2\n3 4\n",
    "empty.xyz": b"",
    "comments-only.txt": b"# nothing\n",
    "binary.xyz": bytes(range(256)) * 4,
    "header-only.csv": b"x,y,z\n",
    "no-x.csv": b"a,b,c\n1,2,3\n",
    "random.vtp": bytes(rng.integers(0, 256, 2000, dtype=np.uint8)),
    "truncated.vtp": open(path("writer-ascii.vtp"), "rb").read()[:700],
    "truncated.vtk": open(path("writer-binary.vtk"), "rb").read()[:300],
    "not-vtk.vtk": b"hello\n",
    "bad.off": b"OFF\n3 0 0\n1 2 3\n",
}
for name, data in corrupt.items():
    with open(path(name), "wb") as f:
        f.write(data)
cases = [(path(n), n) for n in corrupt] + [
    (path("missing.xyz"), "missing.xyz"), (work, os.path.basename(work)),
    (path("cloud.unknown"), "cloud.unknown")]
with open(path("cloud.unknown"), "w") as f:
    f.write("1 2 3\n")
for file_name, label in cases:
    code, out, err = run([file_name, "-m", "terrain", "-o", path("never.vtp")])
    check(code == 3, "%s: exit code 3 (got %d; stderr %r)" % (label, code, err[-300:]))
    check(label in err and "error:" in err, "%s: message names the file: %r" % (label, err))
    check("Traceback" not in err, "%s: no Python traceback" % label)
    check(not os.path.exists(path("never.vtp")), "%s: nothing written" % label)

unavailable = [m for m in METHODS if not m.available]
bad_parameters = [
    (["-m", "terrain", "--dimension", "7"], 2, "out of range [2, 3]"),
    (["-m", "delaunay", "--tolerance", "-1"], 2, "out of range"),
    (["-m", "delaunay", "--tolerance", "abc"], 2, "not a number"),
    (["-m", "delaunay", "--generate-voronoi", "maybe"], 2, "not a boolean"),
    (["-m", "delaunay", "--projection-plane", "diagonal"], 2, "best-fit-plane"),
    (["-m", "delaunay", "--set", "NoSuchParameter=1"], 2, "unknown parameter"),
    (["-m", "delaunay", "--set", "Dimension"], 2, "Name=value"),
    (["-m", "delaunay", "--no-such-option", "1"], 2, "unrecognized arguments"),
    (["-m", "no-such-method"], 2, "unknown method"),
    ([], 2, "method is required"),
    (["-m", "delaunay", "-o", path("mesh.xyz")], 2, "unknown mesh format"),
    (["-m", "delaunay", "--png", path("picture.jpg")], 2, "PNG"),
    (["-m", "delaunay", "--size", "huge"], 2, "WxH"),
] + [(["-m", m.name], 4, "not available in this build") for m in unavailable]
for args, expected, text in bad_parameters:
    code, out, err = run([path("cloud.xyz")] + args)
    check(code == expected, "%s: exit code %d (got %d; %r)" % (args, expected, code, err))
    check(text in err, "%s: message has '%s' (%r)" % (args, text, err))
    check("Traceback" not in err, "%s: no traceback" % (args,))
check(run(["--list-methods"])[0] == 0, "--list-methods")
code, out, _ = run(["-m", "delaunay", "--help"])
check(code == 0 and "--projection-plane" in out and "Default 0: only exact duplicates" in out,
      "-m delaunay --help lists the parameters with the class documentation")


# Every parameter of every method this build has is an option of the command, and a value given
# as text (what the options carry) reaches the filter: each parameter set to a value other than
# its default, read back from the filter's getter.
def other_value(parameter):
    """(text, expected value) different from the default, or None when there is none."""
    default = parameter.default
    if parameter.kind == "bool":
        return ("off", False) if default else ("on", True)
    if parameter.choices:
        for name, value in parameter.choices.items():
            if value != default:
                return name, value
    if parameter.kind in ("int", "float"):
        low, high = parameter.minimum, parameter.maximum
        step = 1 if parameter.kind == "int" else 0.5
        for candidate in (default + step, default - step, (low + high) / 2 if low is not None
                          else default * 2 + 1):
            if parameter.kind == "int":
                candidate = int(candidate)
            if candidate != default and (low is None or low <= candidate <= high):
                return repr(candidate), candidate
    return None


set_checked = 0
for method in METHODS:
    if not method.available:
        continue
    parameters = method.parameters()
    code, out, _ = run(["-m", method.name, "--help"])
    check(code == 0 and len(parameters) > 0, "%s: --help and parameters" % method.name)
    for parameter in parameters:
        check(parameter.option in out, "%s --help lists %s" % (method.name, parameter.option))
        alternative = other_value(parameter)
        if alternative is None:
            continue
        text, expected = alternative
        algorithm = make_filter(method, {parameter.option[2:]: text})
        got = getattr(algorithm, "Get" + parameter.name)()
        check(got == expected, "%s %s %s reaches the filter (got %r, expected %r)"
              % (method.name, parameter.option, text, got, expected))
        set_checked += 1
        if parameter.kind == "float" and parameter.maximum is not None \
                and parameter.maximum >= 1e299:
            # VTK_DOUBLE_MAX is shown as inf, and inf is accepted for it.
            algorithm = make_filter(method, {parameter.name: "inf"})
            check(getattr(algorithm, "Get" + parameter.name)() == parameter.maximum,
                  "%s %s inf = the class's maximum" % (method.name, parameter.option))
    ranged = [p for p in parameters if p.minimum is not None and p.maximum < 1e299
              and p.kind == "float"]
    if ranged:
        code, _, err = run([path("cloud.xyz"), "-m", method.name, ranged[0].option,
                            repr(ranged[0].maximum * 2 + 1)])
        check(code == 2 and "out of range" in err, "%s %s beyond its range: exit 2 (%d, %r)"
              % (method.name, ranged[0].option, code, err))
print("parameters set through their option text and read back: %d" % set_checked)
check(set_checked >= 30, "the parameters of the methods were checked")

# The picture: offscreen (re-run under xvfb-run when there is no display).
png = path("terrain.png")
code, out, err = run([path("writer-binary.pcd"), "-m", "terrain", "--png", png,
                      "--size", "320x240", "--show-unused"])
if check(code == 0 and os.path.isfile(png), "PNG written (exit %d, %r)" % (code, err)):
    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    check(image.GetDimensions()[:2] == (320, 240), "PNG is 320 x 240")
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    drawn = np.any(pixels != 255, axis=1).mean()
    check(0.05 < drawn < 0.95, "the mesh covers part of the picture (%.2f)" % drawn)

# Every method of this build on a sphere cloud with normals (new filters join by the table).
sphere = rng.normal(size=(2000, 3))
sphere /= np.linalg.norm(sphere, axis=1)[:, None]
write_cloud(sphere, path("sphere.ply"), normals=sphere)
for method in METHODS:
    if not method.available:
        continue
    output = path("sphere-%s.vtp" % method.name)
    code, out, err = run([path("sphere.ply"), "-m", method.name, "-o", output, "-q"])
    check("Traceback" not in err, "%s: no traceback" % method.name)
    check(code == 0, "%s on a sphere: exit 0 (got %d: %r)" % (method.name, code, err))
    if code == 0:
        mesh = read_mesh(output)
        check(mesh.GetNumberOfPolys() > 0, "%s: triangles" % method.name)
        check(mesh.GetNumberOfPoints() == 2000, "%s: every point passed through" % method.name)
        check("quality:" in out, "%s: summary printed" % method.name)
# The greedy method with parameters given as a user types them (a named choice, a count, inf).
if any(m.name == "greedy" and m.available for m in METHODS):
    code, out, err = run([path("sphere.ply"), "-m", "greedy", "--crossing-test", "on",
                          "--number-of-neighbors", "12", "--maximum-hole-diameter", "inf",
                          "--set", "FillHoles=on", "-o", path("sphere-greedy-set.vtp"), "-q"])
    check(code == 0 and "quality:" in out, "greedy with parameters: exit 0 (%d, %r)"
          % (code, err))
    if code == 0:
        check(read_mesh(path("sphere-greedy-set.vtp")).GetNumberOfPolys() > 0,
              "greedy with parameters: triangles")

# Ctrl-C while the filter runs: SIGINT once the progress bar shows the filter under way (10^6
# points keep it busy for seconds after that); the filter aborts, the command exits 130.
big = rng.normal(size=(1000000, 3))
write_cloud(big, path("big.ply"))
process = subprocess.Popen([COMMAND, path("big.ply"), "-m", "delaunay", "--progress", "-o",
                            path("big-mesh.vtp")], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
seen = b""
while b"delaunay " not in seen or b"%" not in seen.split(b"delaunay ")[-1]:
    chunk = os.read(process.stderr.fileno(), 4096)
    if not chunk:
        break
    seen += chunk
process.send_signal(signal.SIGINT)
out, err = process.communicate(timeout=300)
err = (seen + err).decode(errors="replace")
check(process.returncode == 130, "Ctrl-C: exit code 130 (got %d)" % process.returncode)
check("interrupted" in err and "Traceback" not in err, "Ctrl-C: 'interrupted' (%r)" % err[-200:])
check(not os.path.exists(path("big-mesh.vtp")), "Ctrl-C: nothing written")

if not os.environ.get("PCS_KEEP"): shutil.rmtree(work, ignore_errors=True)
print("work dir", work)
finish()
