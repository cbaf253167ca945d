"""pointcloud-surface: reconstruct a surface from a point cloud file.

    pointcloud-surface INPUT -m METHOD [-o OUTPUT] [--png PICTURE] [--PARAMETER VALUE ...]
                       [--set Name=value ...]

Reads INPUT (.xyz .txt .pts .pwn: "x y z [nx ny nz]"; .csv with or without a header; .ply and
.pcd, ASCII or binary; .off; .vtp .vtk .vtu), runs the filter of METHOD, prints a one-line
quality summary (vtkReconstructionQuality) and writes the mesh (.vtp .ply .stl .obj .vtk) and an
offscreen PNG picture. Every parameter of the method's filter is an option (see
``pointcloud-surface -m METHOD --help``) and can also be given as --set Name=value with its C++
name. A progress bar is drawn on the terminal from the filter's VTK progress events; Ctrl-C asks
the filter to abort.

Exit codes: 0 success; 1 the reconstruction failed (filter error, no triangles); 2 usage error
(unknown option or method, wrong parameter value); 3 unreadable or corrupt input file; 4 method
not available in this build; 5 an output cannot be written; 130 interrupted.

Also: python3 -m pointcloudsurface.cli ... (with the package on PYTHONPATH).
"""
import argparse
import os
import shutil
import signal
import sys
import time

PROGRAM = "pointcloud-surface"
EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_INPUT, EXIT_UNAVAILABLE, EXIT_OUTPUT = 0, 1, 2, 3, 4, 5
EXIT_INTERRUPTED = 130
EXIT_CODES_HELP = """exit codes: 0 success; 1 the reconstruction failed (filter error, no
triangles); 2 usage error (unknown option or method, wrong parameter value); 3 unreadable or
corrupt input file; 4 method not available in this build; 5 an output cannot be written;
130 interrupted."""
_XVFB_MARK = "POINTCLOUDSURFACE_CLI_UNDER_XVFB"


class CliError(Exception):
    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


# --------------------------------------------------------------------------------------------
class ProgressBar:
    """A one-line bar on ``stream`` redrawn from VTK ProgressEvent (at most every 1 % or 0.1 s).
    Disabled: draws nothing."""

    def __init__(self, stream, enabled, width=30):
        self.stream = stream
        self.enabled = enabled
        self.width = width
        self.label = ""
        self.start = time.perf_counter()
        self.last = (-1.0, 0.0)
        self.open = False

    def begin(self, label):
        self.label = label
        self.start = time.perf_counter()
        self.last = (-1.0, 0.0)
        self.update(0.0)

    def update(self, fraction):
        if not self.enabled:
            return
        fraction = min(max(float(fraction), 0.0), 1.0)
        now = time.perf_counter()
        if fraction == self.last[0] or (
                fraction < 1.0 and fraction - self.last[0] < 0.01 and now - self.last[1] < 0.1):
            return
        self.last = (fraction, now)
        filled = int(round(fraction * self.width))
        self.stream.write("\r%-14s [%s%s] %3d%% %6.1f s" % (
            self.label, "#" * filled, "-" * (self.width - filled), int(fraction * 100),
            now - self.start))
        self.stream.flush()
        self.open = True

    def end(self, completed=True):
        if self.enabled and self.open:
            if completed:
                self.update(1.0)
            self.stream.write("\n")
            self.stream.flush()
        self.open = False


class _Interrupt:
    """SIGINT sets a flag; the progress observer then asks the running filter to abort."""

    def __init__(self):
        self.requested = False
        self.previous = None

    def __enter__(self):
        def handler(signum, frame):
            if self.requested:  # second Ctrl-C: give up at once
                raise KeyboardInterrupt
            self.requested = True

        try:
            self.previous = signal.signal(signal.SIGINT, handler)
        except ValueError:  # not the main thread
            self.previous = None
        return self

    def __exit__(self, *exc):
        if self.previous is not None:
            signal.signal(signal.SIGINT, self.previous)
        return False


def _run(algorithm, label, bar, interrupt, warn):
    """Updates ``algorithm`` with the progress bar; returns its MessageCollector."""
    from vtkmodules.vtkCommonCore import vtkCommand

    from .fileio import MessageCollector

    messages = MessageCollector(algorithm)

    def on_progress(caller, event):
        if interrupt.requested:
            caller.SetAbortExecute(1)
            return
        bar.update(caller.GetProgress())

    algorithm.AddObserver(vtkCommand.ProgressEvent, on_progress)
    bar.begin(label)
    algorithm.Update()
    bar.end(completed=not interrupt.requested)
    for warning in messages.warnings:
        warn("warning: %s: %s" % (algorithm.GetClassName(), warning))
    if interrupt.requested:
        raise CliError("interrupted", EXIT_INTERRUPTED)
    return messages


# --------------------------------------------------------------------------------------------
def _base_parser(add_help):
    from .fileio import CLOUD_READ_FORMATS, MESH_WRITE_FORMATS

    parser = argparse.ArgumentParser(
        prog=PROGRAM, add_help=add_help, allow_abbrev=False,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Reconstruct a triangle surface from an unorganized 3D point cloud.",
        epilog=_methods_epilog() + "\n\n" + EXIT_CODES_HELP)
    parser.add_argument("input", nargs="?", metavar="INPUT",
                        help="point cloud file (%s)" % " ".join(CLOUD_READ_FORMATS))
    parser.add_argument("-m", "--method", metavar="METHOD",
                        help="reconstruction method (see the list below)")
    parser.add_argument("-o", "--output", metavar="MESH",
                        help="write the mesh (%s)" % " ".join(MESH_WRITE_FORMATS))
    parser.add_argument("--png", metavar="PICTURE",
                        help="write an offscreen picture of the mesh (PNG; needs an X display, "
                             "else the command re-runs itself under xvfb-run -a)")
    parser.add_argument("--size", default="1024x768", metavar="WxH",
                        help="picture size in pixels (default 1024x768)")
    parser.add_argument("--show-unused", action="store_true",
                        help="draw the cloud points that no triangle uses as dots in the picture")
    parser.add_argument("--set", action="append", default=[], metavar="Name=value",
                        help="set any parameter of the method's filter by its C++ name "
                             "(repeatable; e.g. --set Tolerance=1e-6)")
    parser.add_argument("--ascii", action="store_true",
                        help="write ASCII instead of binary (.vtp .vtk .ply .stl)")
    parser.add_argument("--reference", metavar="FILE",
                        help="also measure distances to this reference surface or cloud")
    parser.add_argument("--distances", action="store_true",
                        help="also measure distances between the mesh and the input cloud")
    progress = parser.add_mutually_exclusive_group()
    progress.add_argument("--progress", dest="progress", action="store_true", default=None,
                          help="draw the progress bar even when stderr is not a terminal")
    progress.add_argument("--no-progress", dest="progress", action="store_false",
                          help="no progress bar")
    parser.add_argument("-q", "--quiet", action="store_true",
                        help="print only the quality summary, warnings and errors")
    parser.add_argument("--list-methods", action="store_true",
                        help="list the methods and whether this build has them, then exit")
    return parser


def _methods_epilog():
    from .methods import METHODS

    lines = ["methods (\"-m METHOD --help\" lists a method's parameters):"]
    for method in METHODS:
        state = "" if method.available else "  [not available in this build]"
        lines.append("  %-14s %s (%s)%s" % (method.name, method.summary, method.class_name, state))
    return "\n".join(lines)


def _add_parameter_options(parser, method, parameters):
    taken = set(parser._option_string_actions)
    group = parser.add_argument_group(
        "parameters of %s (%s); default and range from the class" % (method.name,
                                                                     method.class_name))
    for parameter in parameters:
        option = parameter.option
        if option in taken:
            option = "--filter-" + option[2:]
        metavar = {"bool": "on|off", "int": "N", "float": "X", "str": "TEXT",
                   "vector": "X,Y,Z"}[parameter.kind]
        if parameter.choices:
            metavar = "|".join(list(_kebab_choices(parameter)) + ["N"])
        default = parameter.default
        if parameter.name in method.presets:
            default = "%s (preset by this method; class default %s)" % (
                _show(method.presets[parameter.name]), _show(parameter.default))
        else:
            default = _show(default)
        help_text = "%s [default %s%s]" % (
            parameter.doc.replace("%", "%%"), default.replace("%", "%%"),
            ("; " + parameter.describe_range()).replace("%", "%%")
            if parameter.describe_range() else "")
        group.add_argument(option, dest="param:" + parameter.name, metavar=metavar,
                           default=None, help=help_text)


def _kebab_choices(parameter):
    from .methods import kebab

    return [kebab(name) for name in parameter.choices]


def _show(value):
    if isinstance(value, bool):
        return "on" if value else "off"
    if isinstance(value, tuple):
        return ",".join("%g" % v for v in value)
    if isinstance(value, (int, float)):
        from .methods import _short

        return _short(value)  # VTK_DOUBLE_MAX / VTK_INT_MAX as inf
    return str(value)


def _parse_size(text):
    try:
        width, height = (int(v) for v in text.lower().split("x"))
        if not (16 <= width <= 8192 and 16 <= height <= 8192):
            raise ValueError
        return width, height
    except ValueError:
        raise CliError("--size: '%s' is not WxH with 16 <= W, H <= 8192" % text, EXIT_USAGE) \
            from None


# --------------------------------------------------------------------------------------------
def quality_summary(fields):
    """The one-line summary of vtkReconstructionQuality's field data ({name: value})."""
    def count(name):
        return int(fields.get(name, 0))

    triangles = count("NumberOfTriangles")
    used = count("NumberOfUsedPoints")
    coverage = fields.get("Coverage", 0.0)
    points = int(round(used / coverage)) if coverage > 0 else fields.get("_points", 0)
    def plural(n, word):
        return "%d %s%s" % (n, word, "" if n == 1 else "s")

    parts = [plural(triangles, "triangle"),
             "coverage %.1f%% (%d of %d points used)" % (100.0 * coverage, used, points),
             "%s (%s)" % (plural(count("NumberOfBoundaryEdges"), "boundary edge"),
                          plural(count("NumberOfBoundaryLoops"), "loop")),
             "non-manifold: %s, %s" % (plural(count("NumberOfNonManifoldEdges"), "edge"),
                                       plural(count("NumberOfNonManifoldVertices"), "vertex")
                                       .replace("vertexs", "vertices")),
             plural(count("NumberOfConnectedComponents"), "component"),
             "Euler characteristic %d" % count("EulerCharacteristic")]
    genus = count("Genus")
    if genus >= 0:
        parts.append("genus %d" % genus)
    elif count("NumberOfNonManifoldEdges") or count("NumberOfNonManifoldVertices"):
        parts.append("genus n/a (non-manifold)")
    elif count("NumberOfBoundaryEdges"):
        parts.append("genus n/a (open)")
    else:
        parts.append("genus n/a (non-orientable)")
    if count("NumberOfDegenerateTriangles"):
        parts.append(plural(count("NumberOfDegenerateTriangles"), "degenerate triangle"))
    if "Hausdorff" in fields:
        parts.append("Hausdorff %.4g (%.3g x spacing), mean accuracy %.4g, mean completeness %.4g"
                     % (fields["Hausdorff"], fields.get("HausdorffOverSpacing", float("nan")),
                        fields.get("AccuracyMean", float("nan")),
                        fields.get("CompletenessMean", float("nan"))))
    return "quality: " + " | ".join(parts)


def _field_values(dataset):
    fd = dataset.GetFieldData()
    values = {}
    for i in range(fd.GetNumberOfArrays()):
        array = fd.GetArray(i)
        if array is not None and array.GetNumberOfTuples() > 0:
            values[array.GetName()] = array.GetTuple1(0)
    return values


def _counters(algorithm):
    """The filter's read-only GetNumberOf...() counts (input points, duplicates, ...)."""
    from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm

    base = set(dir(vtkPolyDataAlgorithm))
    values = []
    for name in sorted(dir(algorithm)):
        if (name.startswith("GetNumberOf") and name not in base
                and not hasattr(algorithm, "Set" + name[3:])):
            try:
                value = getattr(algorithm, name)()
            except TypeError:
                continue
            if isinstance(value, int) and not isinstance(value, bool):
                values.append((name[11:], value))
    return values


def _unused_points(mesh):
    import numpy as np

    from .arrays import points_to_polydata, polydata_to_arrays

    points, triangles = polydata_to_arrays(mesh)
    used = np.zeros(points.shape[0], dtype=bool)
    used[triangles.reshape(-1)] = True
    return points_to_polydata(points[~used & np.all(np.isfinite(points), axis=1)])


def _rerun_under_xvfb(argv):
    xvfb = shutil.which("xvfb-run")
    if xvfb is None or os.environ.get(_XVFB_MARK):
        raise CliError("--png needs an X display and xvfb-run is not installed "
                       "(apt-get install xvfb xauth, or set DISPLAY)", EXIT_USAGE)
    env = dict(os.environ)
    env[_XVFB_MARK] = "1"
    sys.stdout.flush()
    sys.stderr.flush()
    os.execvpe(xvfb, [xvfb, "-a", sys.executable, "-m", "pointcloudsurface.cli"] + argv, env)


# --------------------------------------------------------------------------------------------
def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        return _main(argv)
    except CliError as error:
        if error.code == EXIT_INTERRUPTED:
            print("%s: interrupted" % PROGRAM, file=sys.stderr)
        else:
            print("%s: error: %s" % (PROGRAM, error), file=sys.stderr)
        return error.code
    except KeyboardInterrupt:
        print("%s: interrupted" % PROGRAM, file=sys.stderr)
        return EXIT_INTERRUPTED


def _main(argv):
    from .fileio import (MESH_WRITE_FORMATS, ReadError, WriteError, read_cloud, read_mesh,
                         write_mesh, MESH_READ_FORMATS)
    from .methods import (METHODS, MethodNotAvailable, ParameterError, find_method,
                          make_filter)

    # Stage 1: which method (its parameters become options of stage 2).
    pre, _ = _base_parser(add_help=False).parse_known_args(argv)
    if pre.list_methods:
        for method in METHODS:
            print("%-14s %-30s %s" % (method.name, method.class_name,
                                      "available" if method.available
                                      else "not available in this build"))
        return EXIT_OK
    method = None
    if pre.method is not None:
        try:
            method = find_method(pre.method)
        except MethodNotAvailable as error:
            known = any(pre.method == m.name or pre.method in m.aliases for m in METHODS)
            raise CliError(str(error), EXIT_UNAVAILABLE if known else EXIT_USAGE) from None

    parser = _base_parser(add_help=True)
    parameters = method.parameters() if method else []
    if method:
        _add_parameter_options(parser, method, parameters)
    args = parser.parse_args(argv)  # exits with 2 and a message on unknown options
    if args.input is None:
        parser.error("the INPUT point cloud file is required")
    if method is None:
        parser.error("the reconstruction method is required: -m METHOD (one of %s)"
                     % ", ".join(m.name for m in METHODS if m.available))

    # Everything checkable before reading the input is checked first.
    values = {}
    try:
        for item in args.set:
            if "=" not in item:
                raise ParameterError("--set: '%s' is not Name=value" % item)
            name, text = item.split("=", 1)
            values[name.strip()] = text
        for key, text in vars(args).items():
            if key.startswith("param:") and text is not None:
                values[key[6:]] = text
        algorithm = make_filter(method, values)
    except ParameterError as error:
        raise CliError("%s (see %s -m %s --help)" % (error, PROGRAM, method.name),
                       EXIT_USAGE) from None
    if args.output:
        extension = os.path.splitext(args.output)[1].lower()
        if extension not in MESH_WRITE_FORMATS:
            raise CliError("-o %s: unknown mesh format '%s' (known: %s)"
                           % (args.output, extension, " ".join(MESH_WRITE_FORMATS)), EXIT_USAGE)
    size = _parse_size(args.size)
    if args.png:
        if not args.png.lower().endswith(".png"):
            raise CliError("--png %s: the picture is written as PNG: use a .png name"
                           % args.png, EXIT_USAGE)
        from .render import can_render

        if not can_render():
            _rerun_under_xvfb(argv)

    log = (lambda *a: None) if args.quiet else (lambda text: print(text, file=sys.stderr))

    def warn(text):
        print(text, file=sys.stderr)
    show_progress = args.progress if args.progress is not None else (
        not args.quiet and sys.stderr.isatty())
    bar = ProgressBar(sys.stderr, show_progress)

    try:
        start = time.perf_counter()
        cloud = read_cloud(args.input)
        reference = None
        if args.reference:
            if os.path.splitext(args.reference)[1].lower() in MESH_READ_FORMATS:
                reference = read_mesh(args.reference)
            else:
                reference = read_cloud(args.reference)
    except ReadError as error:
        raise CliError(str(error), EXIT_INPUT) from None
    has_normals = cloud.GetPointData().GetNormals() is not None
    log("read %d points%s from %s (%.2f s)" % (cloud.GetNumberOfPoints(),
                                               " with normals" if has_normals else "",
                                               args.input, time.perf_counter() - start))

    from pointcloudsurface import vtkReconstructionQuality

    with _Interrupt() as interrupt:
        algorithm.SetInputData(cloud)
        start = time.perf_counter()
        messages = _run(algorithm, method.name, bar, interrupt, warn)
        if messages.errors:
            raise CliError("%s: %s" % (method.class_name, "; ".join(messages.errors)),
                           EXIT_FAILED)
        seconds = time.perf_counter() - start
        mesh = algorithm.GetOutputDataObject(method.port)
        counters = ", ".join("%s %d" % (name, value) for name, value in _counters(algorithm))
        log("%s (%s): %.2f s%s" % (method.name, method.class_name, seconds,
                                   "; " + counters if counters else ""))

        quality = vtkReconstructionQuality()
        quality.SetInputData(mesh)
        if args.distances:
            reference = cloud
        if reference is not None:
            quality.SetReferenceData(reference)
        _run(quality, "quality", bar, interrupt, warn)
    fields = _field_values(quality.GetOutput())
    fields["_points"] = mesh.GetNumberOfPoints()
    print(quality_summary(fields))
    sys.stdout.flush()

    if int(fields.get("NumberOfTriangles", 0)) == 0:
        raise CliError("%s produced no triangles; nothing written" % method.name, EXIT_FAILED)
    if args.output:
        try:
            write_mesh(mesh, args.output, binary=not args.ascii)
        except WriteError as error:
            raise CliError(str(error), EXIT_OUTPUT) from None
        log("wrote %s" % args.output)
    if args.png:
        from .render import render_png

        folder = os.path.dirname(os.path.abspath(args.png))
        if not os.path.isdir(folder):
            raise CliError("--png %s: the folder %s does not exist" % (args.png, folder),
                           EXIT_OUTPUT)
        unused = _unused_points(mesh) if args.show_unused else None
        render_png(mesh, args.png, size=size, show_unused=unused)
        if not os.path.isfile(args.png) or os.path.getsize(args.png) == 0:
            raise CliError("--png %s: the picture could not be written" % args.png, EXIT_OUTPUT)
        log("wrote %s" % args.png)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
