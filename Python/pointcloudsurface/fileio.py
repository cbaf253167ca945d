"""Point cloud readers and mesh writers of the ``pointcloud-surface`` command line.

Clouds (``read_cloud`` / ``write_cloud``), chosen by the file extension:

- ``.xyz``, ``.txt``, ``.pts``, ``.pwn``: text, one point a line, ``x y z [nx ny nz] [more]``,
  separated by white space, commas or semicolons; ``#`` and ``//`` start comment lines.
- ``.csv``: the same table; a first line that is not all numbers is a header whose names choose
  the columns (``x y z``, ``nx ny nz`` / ``normal_x ...``; other columns become point data).
- ``.ply``: ASCII, binary little- and big-endian; element ``vertex`` with ``x y z``, normals
  ``nx ny nz`` (or ``normal_x ...``) and any other scalar property as point data; faces are read
  by ``read_mesh``. Coordinates keep their precision (float or double).
- ``.pcd`` (Point Cloud Library): ``DATA ascii``, ``binary`` and ``binary_compressed``; fields
  ``x y z`` and ``normal_x normal_y normal_z``; other fields (rgb, intensity, curvature...) are
  passed as point data, padding fields ``_`` are skipped.
- ``.off``: the vertices of an OFF file (faces by ``read_mesh``).
- ``.vtp``, ``.vtk`` (legacy), ``.vtu``: the points and point data of any VTK point set.

Meshes (``write_mesh`` / ``read_mesh``): ``.vtp``, ``.vtk``, ``.ply``, ``.stl``, ``.obj``.

Text, PLY, PCD and OFF are parsed here with numpy rather than with vtkPLYReader, which stores
coordinates as float and crashed on a truncated ASCII file in VTK 9.2, and because VTK 9.2 has no
PCD reader. Any problem with a file raises ``ReadError`` with the file name, the line (text) or
the byte counts (binary) and what was expected. Writing uses VTK's writers (vtkPLYWriter stores
float coordinates) except for the text and PCD formats, which VTK does not write.
"""
import io
import os
import re
import struct
import warnings

import numpy as np

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPointSet, vtkPolyData

from .arrays import points_to_polydata

__all__ = [
    "ReadError", "WriteError", "MessageCollector", "CapturedVTKMessages", "read_cloud",
    "write_cloud", "read_mesh", "write_mesh",
    "CLOUD_READ_FORMATS", "CLOUD_WRITE_FORMATS", "MESH_READ_FORMATS", "MESH_WRITE_FORMATS",
]

TEXT_EXTENSIONS = (".xyz", ".txt", ".pts", ".pwn")
CLOUD_READ_FORMATS = TEXT_EXTENSIONS + (".csv", ".ply", ".pcd", ".off", ".vtp", ".vtk", ".vtu")
CLOUD_WRITE_FORMATS = TEXT_EXTENSIONS + (".csv", ".ply", ".pcd", ".vtp", ".vtk")
MESH_READ_FORMATS = (".vtp", ".vtk", ".ply", ".stl", ".obj", ".off")
MESH_WRITE_FORMATS = (".vtp", ".vtk", ".ply", ".stl", ".obj")

_NORMAL_NAMES = (("nx", "ny", "nz"), ("normal_x", "normal_y", "normal_z"),
                 ("normalx", "normaly", "normalz"))


class ReadError(Exception):
    """A file that cannot be read as a point cloud or mesh (missing, unreadable, corrupt)."""


class WriteError(Exception):
    """A file that cannot be written."""


def _extension(path, allowed, what):
    ext = os.path.splitext(path)[1].lower()
    if ext not in allowed:
        raise (ReadError if what.startswith("read") else WriteError)(
            "%s: cannot %s '%s' files (known: %s)" % (path, what, ext or "extension-less",
                                                     " ".join(allowed)))
    return ext


def _read_bytes(path):
    if not os.path.exists(path):
        raise ReadError("%s: no such file" % path)
    if os.path.isdir(path):
        raise ReadError("%s: is a directory" % path)
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError as error:
        raise ReadError("%s: cannot read: %s" % (path, error.strerror or error)) from None


def _decode_text(path, data):
    if b"\0" in data:
        raise ReadError("%s: binary data in a text file" % path)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def _to_float(path, rows, first_line_numbers, ncols):
    """rows: list of token lists, all of length ncols; a ReadError names the first bad token."""
    try:
        return np.array(rows, dtype=np.float64).reshape(len(rows), ncols)
    except ValueError:
        for row, number in zip(rows, first_line_numbers):
            for token in row:
                try:
                    float(token)
                except ValueError:
                    raise ReadError("%s: line %d: '%s' is not a number" % (path, number, token)) \
                        from None
        raise


# --------------------------------------------------------------------------------------------
# Text tables: .xyz .txt .pts .pwn .csv
_SEPARATORS = re.compile(r"[,;\s]+")


def _is_number(token):
    try:
        float(token)
        return True
    except ValueError:
        return False


def _normalized(name):
    return re.sub(r"[^a-z0-9_]", "", name.strip().strip("\"'").lower())


def _read_table(path, allow_header):
    text = _decode_text(path, _read_bytes(path))
    fast = _read_table_fast(path, text, allow_header)
    if fast is not None:
        return fast
    # Line by line: finds the line and the value of a problem for the message.
    header = None
    rows, numbers = [], []
    for number, line in enumerate(text.splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#") or line.startswith("//"):
            continue
        tokens = [t for t in _SEPARATORS.split(line) if t]
        if header is None and not rows and allow_header and not all(map(_is_number, tokens)):
            header = [_normalized(t) for t in tokens]
            header_line = number
            continue
        if rows and len(tokens) != len(rows[0]):
            raise ReadError("%s: line %d: %d values, the lines before have %d"
                            % (path, number, len(tokens), len(rows[0])))
        rows.append(tokens)
        numbers.append(number)
    if not rows:
        raise ReadError("%s: no points (an empty file or only comments)" % path)
    ncols = len(rows[0])
    if header is not None and len(header) != ncols:
        raise ReadError("%s: line %d: the header has %d names, the data %d columns"
                        % (path, header_line, len(header), ncols))
    if ncols < 3:
        raise ReadError("%s: line %d: %d value(s); a point needs x y z"
                        % (path, numbers[0], ncols))
    return header, _to_float(path, rows, numbers, ncols)


def _read_table_fast(path, text, allow_header):
    """numpy's C parser on the whole table; None when the table is not clean (then the line by
    line reader finds and names the problem)."""
    position = 0
    header = None
    while position < len(text):  # the first line that is not empty or a comment
        end = text.find("\n", position)
        end = len(text) if end < 0 else end
        line = text[position:end].strip()
        if line and not line.startswith("#") and not line.startswith("//"):
            tokens = [t for t in _SEPARATORS.split(line) if t]
            if allow_header and not all(map(_is_number, tokens)):
                header = [_normalized(t) for t in tokens]
                position = end + 1
            break
        position = end + 1
    body = text[position:]
    if "," in body or ";" in body:
        body = body.replace(",", " ").replace(";", " ")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # "empty input file" is a warning in numpy
            table = np.loadtxt(io.StringIO(body), dtype=np.float64, comments=("#", "//"),
                               ndmin=2)
    except (ValueError, UserWarning):
        return None
    if table.shape[0] == 0 or table.shape[1] < 3:
        return None
    if header is not None and len(header) != table.shape[1]:
        return None
    return header, table


def _cloud_from_columns(path, names, table):
    """names: one (normalized) name per column; x y z required, normals optional."""
    index = {name: i for i, name in enumerate(names)}
    xyz = []
    for axis in ("x", "y", "z"):
        for candidate in (axis, "p" + axis, "pos" + axis, "pos_" + axis, "point_" + axis,
                          "position_" + axis, axis + "_coord"):
            if candidate in index:
                xyz.append(index[candidate])
                break
        else:
            raise ReadError("%s: no column named %s in the header (%s)"
                            % (path, axis, " ".join(names)))
    normals = None
    for triple in _NORMAL_NAMES:
        if all(n in index for n in triple):
            normals = [index[n] for n in triple]
            break
    used = set(xyz) | set(normals or [])
    extra = {names[i]: table[:, i].copy() for i in range(len(names)) if i not in used}
    return points_to_polydata(table[:, xyz], None if normals is None else table[:, normals],
                              point_data=extra)


def _cloud_from_table(path, header, table):
    if header is not None:
        return _cloud_from_columns(path, header, table)
    ncols = table.shape[1]
    normals = None
    extra = {}
    first_extra = 3
    if ncols >= 6:
        candidate = table[:, 3:6]
        # x y z nx ny nz: unit (or zero) normals. Anything else (colours...) is point data.
        if np.all(np.abs(candidate[np.isfinite(candidate)]) <= 1.0 + 1e-3):
            normals = candidate
            first_extra = 6
    for i in range(first_extra, ncols):
        extra["column%d" % (i + 1)] = table[:, i].copy()
    return points_to_polydata(table[:, :3], normals, point_data=extra)


# --------------------------------------------------------------------------------------------
# PLY
_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


def _ply_header(path, data):
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ReadError("%s: not a PLY file (no 'ply' ... 'end_header')" % path)
    newline = data.find(b"\n", end)
    body = newline + 1 if newline >= 0 else len(data)
    lines = data[:end].decode("latin-1").splitlines()
    fmt, elements = None, []
    for number, line in enumerate(lines, 1):
        words = line.split()
        if not words or words[0] in ("ply", "comment", "obj_info"):
            continue
        if words[0] == "format" and len(words) >= 2:
            fmt = words[1]
        elif words[0] == "element" and len(words) == 3 and words[2].isdigit():
            elements.append({"name": words[1], "count": int(words[2]), "props": []})
        elif words[0] == "property" and elements and len(words) == 3 and words[1] in _PLY_TYPES:
            elements[-1]["props"].append((words[2], _PLY_TYPES[words[1]], None))
        elif (words[0] == "property" and elements and len(words) == 5 and words[1] == "list"
              and words[2] in _PLY_TYPES and words[3] in _PLY_TYPES):
            elements[-1]["props"].append((words[4], _PLY_TYPES[words[3]], _PLY_TYPES[words[2]]))
        else:
            raise ReadError("%s: header line %d: cannot understand '%s'" % (path, number, line))
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise ReadError("%s: unknown PLY format '%s'" % (path, fmt))
    return fmt, elements, body


def _ply_ascii(path, data, elements, body):
    tokens = data[body:].split()
    position = 0
    result = {}
    for element in elements:
        props, count = element["props"], element["count"]
        if all(p[2] is None for p in props):
            n = len(props) * count
            if position + n > len(tokens):
                raise ReadError("%s: element '%s': %d values expected, the file has %d "
                                "(truncated)" % (path, element["name"], n,
                                                 len(tokens) - position))
            try:
                block = np.array(tokens[position:position + n], dtype=np.float64)
            except ValueError:
                raise ReadError("%s: element '%s': a value is not a number"
                                % (path, element["name"])) from None
            block = block.reshape(count, len(props))
            result[element["name"]] = {p[0]: block[:, i] for i, p in enumerate(props)}
            position += n
            continue
        columns = {p[0]: [] for p in props}
        try:
            for _ in range(count):
                for name, _type, count_type in props:
                    if count_type is None:
                        columns[name].append(float(tokens[position]))
                        position += 1
                    else:
                        k = int(tokens[position])
                        if k < 0:
                            raise ValueError
                        items = tokens[position + 1:position + 1 + k]
                        columns[name].append([int(t) for t in items])
                        if len(columns[name][-1]) != k:
                            raise IndexError
                        position += 1 + k
        except IndexError:
            raise ReadError("%s: element '%s': the file ends early" % (path, element["name"])) \
                from None
        except ValueError:
            raise ReadError("%s: element '%s': a value is not a number"
                            % (path, element["name"])) from None
        result[element["name"]] = columns
    return result


def _ply_binary(path, data, elements, body, endian):
    position = body
    result = {}
    for element in elements:
        props, count, name = element["props"], element["count"], element["name"]
        if all(p[2] is None for p in props):
            dtype = np.dtype([(p[0], endian + p[1]) for p in props])
            need = dtype.itemsize * count
            if position + need > len(data):
                raise ReadError("%s: element '%s': %d bytes expected, the file has %d left "
                                "(truncated)" % (path, name, need, len(data) - position))
            block = np.frombuffer(data, dtype=dtype, count=count, offset=position)
            result[name] = {p[0]: block[p[0]].astype(np.float64) for p in props}
            position += need
            continue
        # Lists (faces): fast path when the only property is a list of one length throughout.
        if len(props) == 1 and count > 0:
            pname, item, count_type = props[0]
            ct, it = np.dtype(endian + count_type), np.dtype(endian + item)
            if position + ct.itemsize <= len(data):
                k = int(np.frombuffer(data, dtype=ct, count=1, offset=position)[0])
                dtype = np.dtype([("n", ct), ("v", it, (k,))]) if k > 0 else None
                if dtype is not None and position + dtype.itemsize * count <= len(data):
                    block = np.frombuffer(data, dtype=dtype, count=count, offset=position)
                    if np.all(block["n"] == k):
                        result[name] = {pname: block["v"].astype(np.int64)}
                        position += dtype.itemsize * count
                        continue
        columns = {p[0]: [] for p in props}
        try:
            for _ in range(count):
                for pname, item, count_type in props:
                    if count_type is None:
                        t = np.dtype(endian + item)
                        columns[pname].append(
                            float(np.frombuffer(data, dtype=t, count=1, offset=position)[0]))
                        position += t.itemsize
                    else:
                        ct, it = np.dtype(endian + count_type), np.dtype(endian + item)
                        k = int(np.frombuffer(data, dtype=ct, count=1, offset=position)[0])
                        position += ct.itemsize
                        if k < 0:
                            raise ValueError
                        columns[pname].append(
                            np.frombuffer(data, dtype=it, count=k, offset=position).tolist())
                        position += it.itemsize * k
        except ValueError:
            raise ReadError("%s: element '%s': the file ends early or has a negative list "
                            "length (truncated or corrupt)" % (path, name)) from None
        result[name] = columns
    return result


def _read_ply(path):
    data = _read_bytes(path)
    fmt, elements, body = _ply_header(path, data)
    if fmt == "ascii":
        values = _ply_ascii(path, data, elements, body)
    else:
        values = _ply_binary(path, data, elements, body,
                             "<" if fmt == "binary_little_endian" else ">")
    vertex = values.get("vertex")
    if vertex is None:
        raise ReadError("%s: no 'vertex' element" % path)
    names = list(vertex.keys())
    if not all(axis in vertex for axis in "xyz"):
        raise ReadError("%s: the vertex element has no x, y, z (%s)" % (path, " ".join(names)))
    table = np.column_stack([np.asarray(vertex[n], dtype=np.float64) for n in names]) \
        if names else np.zeros((0, 0))
    if table.shape[0] == 0:
        raise ReadError("%s: no points (element vertex 0)" % path)
    cloud = _cloud_from_columns(path, [_normalized(n) for n in names], table)
    faces = values.get("face") or {}
    lists = faces.get("vertex_indices", faces.get("vertex_index"))
    if lists is None:
        lists = next(iter(faces.values()), [])
    return cloud, lists


# --------------------------------------------------------------------------------------------
# PCD (Point Cloud Library)
_PCD_TYPES = {("F", 4): "f4", ("F", 8): "f8", ("I", 1): "i1", ("I", 2): "i2", ("I", 4): "i4",
              ("I", 8): "i8", ("U", 1): "u1", ("U", 2): "u2", ("U", 4): "u4", ("U", 8): "u8"}


def _lzf_decompress(path, src, size):
    """LZF (liblzf) decompression, as PCD's binary_compressed uses it."""
    out = bytearray()
    i, n = 0, len(src)
    try:
        while i < n:
            ctrl = src[i]
            i += 1
            if ctrl < 32:  # literal run of ctrl + 1 bytes
                if i + ctrl + 1 > n:
                    raise IndexError
                out += src[i:i + ctrl + 1]
                i += ctrl + 1
            else:  # back reference
                length = ctrl >> 5
                if length == 7:
                    length += src[i]
                    i += 1
                ref = len(out) - ((ctrl & 0x1F) << 8) - src[i] - 1
                i += 1
                if ref < 0:
                    raise IndexError
                for _ in range(length + 2):  # may overlap itself: byte by byte
                    out.append(out[ref])
                    ref += 1
    except IndexError:
        raise ReadError("%s: corrupt compressed data" % path) from None
    if len(out) != size:
        raise ReadError("%s: compressed data gives %d bytes, the header says %d"
                        % (path, len(out), size))
    return bytes(out)


def _read_pcd(path):
    data = _read_bytes(path)
    header = {}
    position = 0
    number = 0
    while True:
        end = data.find(b"\n", position)
        if end < 0:
            raise ReadError("%s: not a PCD file (no DATA line in the header)" % path)
        number += 1
        line = data[position:end].decode("latin-1").strip()
        position = end + 1
        if not line or line.startswith("#"):
            continue
        words = line.split()
        key = words[0].upper()
        if key not in ("VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT",
                       "VIEWPOINT", "POINTS", "DATA"):
            raise ReadError("%s: header line %d: unknown PCD keyword '%s'"
                            % (path, number, words[0]))
        header[key] = words[1:]
        if key == "DATA":
            break
    for key in ("FIELDS", "SIZE", "TYPE"):
        if key not in header:
            raise ReadError("%s: PCD header without %s" % (path, key))
    fields = header["FIELDS"]
    k = len(fields)
    counts = header.get("COUNT", ["1"] * k)
    try:
        sizes = [int(s) for s in header["SIZE"]]
        counts = [int(c) for c in counts]
        if "POINTS" in header:
            npoints = int(header["POINTS"][0])
        else:
            npoints = int(header["WIDTH"][0]) * int(header.get("HEIGHT", ["1"])[0])
    except (ValueError, IndexError, KeyError):
        raise ReadError("%s: PCD header: SIZE, COUNT, POINTS (or WIDTH/HEIGHT) must be integers"
                        % path) from None
    types = [t.upper() for t in header["TYPE"]]
    if not (len(sizes) == len(types) == len(counts) == k) or npoints < 0:
        raise ReadError("%s: PCD header: FIELDS, SIZE, TYPE and COUNT differ in length" % path)
    try:
        dtypes = [np.dtype("<" + _PCD_TYPES[(t, s)]) for t, s in zip(types, sizes)]
    except KeyError:
        raise ReadError("%s: PCD header: unsupported TYPE/SIZE %s/%s"
                        % (path, " ".join(types), " ".join(map(str, sizes)))) from None
    mode = (header["DATA"] or [""])[0].lower()
    columns = {}
    if mode == "ascii":
        tokens = data[position:].split()
        width = sum(counts)
        if len(tokens) < width * npoints:
            raise ReadError("%s: %d points of %d values expected, the file has %d values"
                            % (path, npoints, width, len(tokens)))
        try:
            table = np.array(tokens[:width * npoints], dtype=np.float64).reshape(npoints, width)
        except ValueError:
            raise ReadError("%s: a data value is not a number" % path) from None
        column = 0
        for name, c, dt in zip(fields, counts, dtypes):
            # The stored value is of the field's type (F 4: the float nearest the text).
            columns[name] = table[:, column:column + c].astype(dt).astype(np.float64) \
                if dt.kind == "f" else table[:, column:column + c]
            column += c
    elif mode in ("binary", "binary_compressed"):
        if mode == "binary_compressed":
            if position + 8 > len(data):
                raise ReadError("%s: truncated compressed PCD" % path)
            compressed, size = struct.unpack("<II", data[position:position + 8])
            if position + 8 + compressed > len(data):
                raise ReadError("%s: compressed block of %d bytes, the file has %d left"
                                % (path, compressed, len(data) - position - 8))
            raw = _lzf_decompress(path, data[position + 8:position + 8 + compressed], size)
            offset = 0  # structure of arrays: each field's values one after the other
            for name, dt, c in zip(fields, dtypes, counts):
                need = dt.itemsize * c * npoints
                if offset + need > len(raw):
                    raise ReadError("%s: compressed data too short for %d points" % (path, npoints))
                columns[name] = np.frombuffer(raw, dtype=dt, count=c * npoints,
                                              offset=offset).reshape(npoints, c)
                offset += need
        else:
            record = np.dtype([("f%d" % i, dt, (c,)) for i, (dt, c) in
                               enumerate(zip(dtypes, counts))])
            need = record.itemsize * npoints
            if position + need > len(data):
                raise ReadError("%s: %d points of %d bytes expected, the file has %d bytes left "
                                "(truncated)" % (path, npoints, record.itemsize,
                                                 len(data) - position))
            block = np.frombuffer(data, dtype=record, count=npoints, offset=position)
            for i, name in enumerate(fields):
                columns[name] = block["f%d" % i].reshape(npoints, counts[i])
    else:
        raise ReadError("%s: unknown PCD DATA mode '%s'" % (path, mode))
    lowered = {name.lower(): name for name in fields}
    if not all(axis in lowered for axis in "xyz"):
        raise ReadError("%s: PCD fields have no x, y, z (%s)" % (path, " ".join(fields)))
    if npoints == 0:
        raise ReadError("%s: no points (POINTS 0)" % path)

    def column(name):
        return np.asarray(columns[lowered[name]][:, 0], dtype=np.float64)

    xyz = np.column_stack([column(a) for a in "xyz"])
    normals = None
    for triple in _NORMAL_NAMES:
        if all(n in lowered for n in triple):
            normals = np.column_stack([column(n) for n in triple])
            used = set(triple)
            break
    else:
        used = set()
    extra = {}
    for name in fields:
        if name == "_" or name.lower() in used or name.lower() in "xyz":
            continue
        values = columns[name]
        extra[name] = values[:, 0].copy() if values.shape[1] == 1 else values.copy()
    return points_to_polydata(xyz, normals, point_data=extra)


# --------------------------------------------------------------------------------------------
# OFF
def _read_off(path):
    text = _decode_text(path, _read_bytes(path))
    tokens = []
    for line in text.splitlines():
        line = line.split("#", 1)[0]
        tokens.extend(line.split())
    if not tokens or not tokens[0].endswith("OFF"):
        raise ReadError("%s: not an OFF file (no OFF keyword)" % path)
    kind = tokens[0]
    position = 1
    try:
        nv, nf = int(tokens[1]), int(tokens[2])
        position = 4
        width = 3 + (3 if "N" in kind else 0) + (4 if "C" in kind else 0)
        if nv <= 0:
            raise ReadError("%s: no points (0 vertices)" % path)
        block = np.array(tokens[position:position + width * nv], dtype=np.float64)
        if block.size != width * nv:
            raise IndexError
        block = block.reshape(nv, width)
        position += width * nv
        faces = []
        for _ in range(nf):
            k = int(tokens[position])
            faces.append([int(t) for t in tokens[position + 1:position + 1 + k]])
            if len(faces[-1]) != k:
                raise IndexError
            position += 1 + k
    except (IndexError, ValueError):
        raise ReadError("%s: OFF data ends early or is not numeric (corrupt)" % path) from None
    normals = block[:, 3:6] if "N" in kind else None
    return points_to_polydata(block[:, :3], normals), faces


# --------------------------------------------------------------------------------------------
# VTK files
class MessageCollector:
    """Observes ErrorEvent and WarningEvent of a VTK object: the messages are kept (in
    ``errors`` and ``warnings``) instead of being printed by vtkOutputWindow."""

    def __init__(self, vtk_object):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING

        self.errors = []
        self.warnings = []

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.errors.append(vtk_message(message or "error"))

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, message):
            self.warnings.append(vtk_message(message or "warning"))

        self._callbacks = (on_error, on_warning)  # keep the Python callables alive
        vtk_object.AddObserver(vtkCommand.ErrorEvent, on_error)
        vtk_object.AddObserver(vtkCommand.WarningEvent, on_warning)


def _observe_errors(algorithm):
    return MessageCollector(algorithm)


def vtk_message(text):
    """The message part of a VTK error text ("ERROR: In file, line N\\nclass (0x..): text",
    "Generic Warning: In file, line N\\ntext")."""
    text = str(text).strip()
    match = re.search(r"\(0x[0-9a-fA-F]+\):\s*(.*)", text, re.S)
    if match:
        text = match.group(1)
    else:
        text = re.sub(r"^[\w ]*(Warning|Error|ERROR):\s*In [^\n]*, line \d+\s*", "", text)
    return " ".join(text.split())


class CapturedVTKMessages:
    """Context manager: the errors and warnings that VTK objects without an observer send to
    vtkOutputWindow (e.g. the readers a vtkDataSetReader creates inside) are collected in
    ``errors`` / ``warnings`` instead of being printed."""

    def __enter__(self):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING, vtkLogger, vtkOutputWindow

        self.errors, self.warnings = [], []

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.errors.append(vtk_message(message or "error"))

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, message):
            self.warnings.append(vtk_message(message or "warning"))

        self._window = vtkOutputWindow.GetInstance()
        self._callbacks = (on_error, on_warning)
        self._tags = (self._window.AddObserver(vtkCommand.ErrorEvent, on_error),
                      self._window.AddObserver(vtkCommand.WarningEvent, on_warning))
        self._mode = self._window.GetDisplayMode()
        self._verbosity = vtkLogger.GetCurrentVerbosityCutoff()
        self._window.SetDisplayModeToNever()
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        return self

    def __exit__(self, *exc):
        from vtkmodules.vtkCommonCore import vtkLogger

        for tag in self._tags:
            self._window.RemoveObserver(tag)
        self._window.SetDisplayMode(self._mode)
        vtkLogger.SetStderrVerbosity(self._verbosity)
        return False


def _vtk_reader(path, ext):
    from vtkmodules.vtkIOLegacy import vtkDataSetReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader

    data = _read_bytes(path)  # existence and permission, with the usual message
    if ext == ".vtk":
        if not data.startswith(b"# vtk DataFile"):
            raise ReadError("%s: not a legacy VTK file (no '# vtk DataFile' line)" % path)
        reader = vtkDataSetReader()
    else:
        if b"<VTKFile" not in data[:1024]:
            raise ReadError("%s: not a VTK XML file (no <VTKFile> element)" % path)
        reader = vtkXMLPolyDataReader() if ext == ".vtp" else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    errors = _observe_errors(reader)
    with CapturedVTKMessages() as captured:
        reader.Update()
    output = reader.GetOutputDataObject(0)
    # The legacy readers report read errors ("Error reading binary data!") as warnings.
    problems = errors.errors + captured.errors + (
        errors.warnings + captured.warnings if ext == ".vtk" else [])
    if problems:
        raise ReadError("%s: %s" % (path, problems[0]))
    if output is None or not output.IsA("vtkPointSet"):
        raise ReadError("%s: holds no point set (%s)"
                        % (path, output.GetClassName() if output else "nothing"))
    return output


def _cloud_from_pointset(path, dataset):
    n = dataset.GetNumberOfPoints()
    if n == 0:
        raise ReadError("%s: no points" % path)
    cloud = points_to_polydata(vtk_to_numpy(dataset.GetPoints().GetData()).reshape(n, 3))
    source = dataset.GetPointData()
    target = cloud.GetPointData()
    for i in range(source.GetNumberOfArrays()):
        array = source.GetAbstractArray(i)
        if array is not None and array.GetNumberOfTuples() == n:
            target.AddArray(array)
    normals = source.GetNormals()
    if normals is None:
        candidate = source.GetArray("Normals")
        if candidate is not None and candidate.GetNumberOfComponents() == 3:
            normals = candidate
    if normals is not None:
        target.SetNormals(normals)
    return cloud


# --------------------------------------------------------------------------------------------
def read_cloud(path):
    """The point cloud in ``path`` as a vtkPolyData: points (float64), one vertex cell per point,
    normals as the active "Normals" array when the file has them, other values as point data.
    Raises ReadError with a clear message for a missing, unreadable, empty or corrupt file."""
    path = os.fspath(path)
    ext = _extension(path, CLOUD_READ_FORMATS, "read point clouds from")
    if ext in TEXT_EXTENSIONS or ext == ".csv":
        header, table = _read_table(path, allow_header=True)
        return _cloud_from_table(path, header, table)
    if ext == ".ply":
        return _read_ply(path)[0]
    if ext == ".pcd":
        return _read_pcd(path)
    if ext == ".off":
        return _read_off(path)[0]
    return _cloud_from_pointset(path, _vtk_reader(path, ext))


def _cloud_arrays(cloud):
    n = cloud.GetNumberOfPoints()
    xyz = vtk_to_numpy(cloud.GetPoints().GetData()).reshape(n, 3) if n else np.zeros((0, 3))
    normals = cloud.GetPointData().GetNormals()
    nxyz = vtk_to_numpy(normals).reshape(n, 3) if normals is not None and n else None
    return np.asarray(xyz, dtype=np.float64), nxyz


def _as_cloud(cloud_or_points, normals):
    if isinstance(cloud_or_points, vtkPointSet):
        return cloud_or_points
    return points_to_polydata(cloud_or_points, normals)


def _float32_exact(values):
    with np.errstate(over="ignore", invalid="ignore"):
        return bool(np.all((values.astype(np.float32).astype(np.float64) == values)
                           | ~np.isfinite(values)))


def write_cloud(cloud_or_points, path, normals=None, binary=True):
    """Writes a cloud (vtkPointSet, or an (N, 3) array with optional normals) to ``path``.

    Text formats and CSV write every value with 17 significant digits (exact round trip);
    PCD writes F 4 fields when every value is exactly a float, else F 8 (``binary`` chooses
    DATA binary or ascii); PLY goes through vtkPLYWriter (float coordinates and normals);
    .vtp / .vtk through VTK's XML / legacy writers."""
    path = os.fspath(path)
    ext = _extension(path, CLOUD_WRITE_FORMATS, "write point clouds to")
    cloud = _as_cloud(cloud_or_points, normals)
    xyz, nxyz = _cloud_arrays(cloud)
    table = xyz if nxyz is None else np.column_stack([xyz, nxyz])
    try:
        if ext in TEXT_EXTENSIONS or ext == ".csv":
            header = ""
            if ext == ".csv":
                header = "x,y,z" + (",nx,ny,nz" if nxyz is not None else "")
            np.savetxt(path, table, fmt="%.17g", delimiter="," if ext == ".csv" else " ",
                       header=header, comments="")
            return
        if ext == ".pcd":
            _write_pcd(path, table, nxyz is not None, binary)
            return
    except OSError as error:
        raise WriteError("%s: cannot write: %s" % (path, error.strerror or error)) from None
    polydata = cloud
    if not isinstance(cloud, vtkPolyData):
        polydata = points_to_polydata(xyz, nxyz)
    write_mesh(polydata, path, binary=binary)


def _write_pcd(path, table, has_normals, binary):
    fields = ["x", "y", "z"] + (["normal_x", "normal_y", "normal_z"] if has_normals else [])
    single = _float32_exact(table)
    size = 4 if single else 8
    lines = ["# .PCD v0.7 - Point Cloud Data file format (written by pointcloudsurface)",
             "VERSION 0.7", "FIELDS " + " ".join(fields),
             "SIZE " + " ".join([str(size)] * len(fields)),
             "TYPE " + " ".join(["F"] * len(fields)), "COUNT " + " ".join(["1"] * len(fields)),
             "WIDTH %d" % table.shape[0], "HEIGHT 1", "VIEWPOINT 0 0 0 1 0 0 0",
             "POINTS %d" % table.shape[0], "DATA " + ("binary" if binary else "ascii")]
    with open(path, "wb") as f:
        f.write(("\n".join(lines) + "\n").encode("ascii"))
        if binary:
            f.write(np.ascontiguousarray(table, dtype="<f4" if single else "<f8").tobytes())
        else:
            np.savetxt(f, table, fmt="%.9g" if single else "%.17g")


def read_mesh(path):
    """A triangle (polygon) mesh from .vtp, .vtk, .ply, .stl, .obj or .off as a vtkPolyData.
    Raises ReadError for a missing, unreadable or corrupt file."""
    path = os.fspath(path)
    ext = _extension(path, MESH_READ_FORMATS, "read meshes from")
    if ext in (".ply", ".off"):
        cloud, faces = _read_ply(path) if ext == ".ply" else _read_off(path)
        mesh = vtkPolyData()
        mesh.SetPoints(cloud.GetPoints())
        mesh.GetPointData().ShallowCopy(cloud.GetPointData())
        from vtkmodules.vtkCommonDataModel import vtkCellArray

        polys = vtkCellArray()
        n = cloud.GetNumberOfPoints()
        for face in faces:
            face = [int(i) for i in face]
            if any(i < 0 or i >= n for i in face):
                raise ReadError("%s: a face refers to vertex %d of %d" %
                                (path, next(i for i in face if i < 0 or i >= n), n))
            polys.InsertNextCell(len(face), face)
        mesh.SetPolys(polys)
        return mesh
    if ext in (".vtp", ".vtk"):
        data = _vtk_reader(path, ext)
        if not isinstance(data, vtkPolyData):
            from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter

            geometry = vtkGeometryFilter()
            geometry.SetInputData(data)
            geometry.Update()
            data = geometry.GetOutput()
        return data
    from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader

    _read_bytes(path)
    reader = vtkSTLReader() if ext == ".stl" else vtkOBJReader()
    reader.SetFileName(path)
    errors = _observe_errors(reader)
    with CapturedVTKMessages() as captured:
        reader.Update()
    if errors.errors or captured.errors:
        raise ReadError("%s: %s" % (path, (errors.errors + captured.errors)[0]))
    return reader.GetOutput()


def write_mesh(mesh, path, binary=True):
    """Writes a vtkPolyData to .vtp, .vtk, .ply, .stl or .obj (binary where the format has it;
    STL keeps the triangles only, PLY and STL store float coordinates). Raises WriteError."""
    path = os.fspath(path)
    ext = _extension(path, MESH_WRITE_FORMATS, "write meshes to")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise WriteError("%s: the folder %s does not exist" % (path, folder))
    if ext == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

        writer = vtkXMLPolyDataWriter()
        if not binary:
            writer.SetDataModeToAscii()
    elif ext == ".vtk":
        from vtkmodules.vtkIOLegacy import vtkPolyDataWriter

        writer = vtkPolyDataWriter()
        writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
    elif ext == ".ply":
        from vtkmodules.vtkIOPLY import vtkPLYWriter

        writer = vtkPLYWriter()
        writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
        normals = mesh.GetPointData().GetNormals()
        if normals is not None and normals.GetDataType() != 10:  # VTK_FLOAT
            # vtkPLYWriter writes float normals only: a shallow copy with a float copy of them.
            from vtkmodules.vtkCommonCore import vtkFloatArray

            copy = vtkPolyData()
            copy.ShallowCopy(mesh)
            as_float = vtkFloatArray()
            as_float.DeepCopy(normals)
            as_float.SetName(normals.GetName())
            copy.GetPointData().SetNormals(as_float)
            mesh = copy
    elif ext == ".stl":
        from vtkmodules.vtkIOGeometry import vtkSTLWriter

        writer = vtkSTLWriter()
        writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
    else:
        from vtkmodules.vtkIOGeometry import vtkOBJWriter

        writer = vtkOBJWriter()
    writer.SetFileName(path)
    writer.SetInputData(mesh)
    errors = _observe_errors(writer)
    with CapturedVTKMessages() as captured:
        ok = writer.Write()
    if errors.errors or captured.errors or not ok:
        message = (errors.errors + captured.errors + ["the writer failed"])[0]
        raise WriteError("%s: %s" % (path, message))
