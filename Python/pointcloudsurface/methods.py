"""The reconstruction methods of the command line and of ``reconstruct()``, as one table.

A method is a filter class of the module found by name, so a filter that is not built (yet)
is reported as "not available in this build" instead of failing at import. Its parameters are
discovered from the wrapped class: every ``SetX`` declared by the class itself (not inherited
from vtkPolyDataAlgorithm) whose ``GetX`` returns a number, a boolean, a string or a tuple of
numbers. Ranges come from the clamp macros (``GetXMinValue`` / ``GetXMaxValue``), named choices
from the ``SetXToY()`` methods, help text from the class documentation. A new filter therefore
joins the command line with one entry in METHODS.

    >>> from pointcloudsurface.methods import reconstruct
    >>> mesh = reconstruct(points, method="delaunay", Dimension=2)
"""
import re

__all__ = ["Method", "Parameter", "METHODS", "find_method", "available_methods",
           "ParameterError", "MethodNotAvailable", "make_filter", "reconstruct"]


class ParameterError(ValueError):
    """An unknown parameter, or a value of the wrong type or out of the class's range."""


class MethodNotAvailable(LookupError):
    """An unknown method, or one whose filter class is not in this build."""


class Method:
    """One row of the table: command-line name, filter class name, what it is, presets.

    presets: parameter values set before the user's (the user may override them).
    port: the output port holding the surface.
    """

    def __init__(self, name, class_name, summary, presets=None, port=0, aliases=()):
        self.name = name
        self.class_name = class_name
        self.summary = summary
        self.presets = dict(presets or {})
        self.port = port
        self.aliases = tuple(aliases)

    @property
    def filter_class(self):
        """The wrapped class, or None when the module of this build does not have it."""
        import pointcloudsurface

        return getattr(pointcloudsurface, self.class_name, None)

    @property
    def available(self):
        return self.filter_class is not None

    def parameters(self):
        """The class's own parameters, in declaration order of their setters (see module doc)."""
        cls = self.filter_class
        if cls is None:
            raise MethodNotAvailable(_not_available(self))
        return discover_parameters(cls)


METHODS = [
    Method("delaunay", "vtkIncrementalDelaunay3D",
           "exact Delaunay: the convex hull (Dimension 3) or the 2.5D terrain triangulation "
           "(Dimension 2) [Rodriguez et al. 2000 s2; Cocias et al. s3.1]",
           presets={"GenerateTetrahedra": False}),
    Method("terrain", "vtkIncrementalDelaunay3D",
           "the delaunay method in 2.5D: the lifted Delaunay triangulation of the points "
           "projected on the x-y plane (height fields, terrain scans)",
           presets={"GenerateTetrahedra": False, "Dimension": 2}),
    Method("peel", "vtkPerimeterPeelSurface",
           "perimeter peeling of the Delaunay tetrahedralization [Rodriguez et al. 2000 s3]"),
    Method("local-optimum", "vtkLocalOptimumGrowth",
           "mesh growing from a seed triangle by local optimum triangulation [Wang et al. 2013]"),
    Method("cdt-front", "vtkCDTAdvancingFront",
           "constrained-Delaunay advancing front with point normals [Huang, Wischgoll]"),
    Method("greedy", "vtkGreedySurfaceTriangulation",
           "greedy surface triangulation of badly scanned clouds [Emelyanov, Skala]"),
]


def find_method(name):
    """The Method called ``name`` (or one of its aliases); MethodNotAvailable if unknown or
    not built."""
    for method in METHODS:
        if name == method.name or name in method.aliases:
            if not method.available:
                raise MethodNotAvailable(_not_available(method))
            return method
    raise MethodNotAvailable("unknown method '%s' (methods: %s)"
                             % (name, ", ".join(m.name for m in METHODS)))


def available_methods():
    return [m for m in METHODS if m.available]


def _not_available(method):
    return ("method '%s' (%s) is not available in this build: the PointCloudSurface module "
            "was built without it (available: %s)"
            % (method.name, method.class_name,
               ", ".join(m.name for m in available_methods()) or "none"))


# --------------------------------------------------------------------------------------------
class Parameter:
    """A settable property of a filter class: name (CamelCase, as in C++ and ParaView), kind
    ('bool', 'int', 'float', 'str' or 'vector'), default, range (min, max) or None, named
    choices {name: value} for enumerations, and help text from the class documentation."""

    def __init__(self, name, kind, default, minimum=None, maximum=None, choices=None, doc=""):
        self.name = name
        self.kind = kind
        self.default = default
        self.minimum = minimum
        self.maximum = maximum
        self.choices = choices or {}
        self.doc = doc

    @property
    def option(self):
        """The command-line option: --kebab-case of the name."""
        return "--" + kebab(self.name)

    def describe_range(self):
        text = []
        if self.choices:
            text.append("choices: " + ", ".join("%s (%s)" % (kebab(k), v)
                                                for k, v in self.choices.items()))
        if self.minimum is not None:
            text.append("range [%s, %s]" % (_short(self.minimum), _short(self.maximum)))
        if self.kind == "bool":
            text.append("on/off")
        return "; ".join(text)

    def parse(self, text):
        """The value of ``text`` for this parameter (ParameterError when it does not fit)."""
        text = str(text).strip()
        if self.kind == "bool":
            lowered = text.lower()
            if lowered in ("1", "on", "true", "yes"):
                return True
            if lowered in ("0", "off", "false", "no"):
                return False
            raise ParameterError("%s: '%s' is not a boolean (on/off, true/false, 1/0)"
                                 % (self.name, text))
        if self.kind == "str":
            return text
        if self.kind == "vector":
            parts = [p for p in re.split(r"[,\s]+", text) if p]
            if len(parts) != len(self.default):
                raise ParameterError("%s: %d comma-separated numbers expected, got '%s'"
                                     % (self.name, len(self.default), text))
            try:
                return tuple(type(d)(float(p)) if isinstance(d, int) else float(p)
                             for p, d in zip(parts, self.default))
            except ValueError:
                raise ParameterError("%s: '%s' is not a list of numbers" % (self.name, text)) \
                    from None
        if self.choices:
            for name, value in self.choices.items():
                if _same_name(text, name):
                    return value
        unbounded = self._unbounded(text)
        if unbounded is not None:
            return unbounded
        try:
            if self.kind == "int":
                number = float(text)
                if number != int(number):
                    raise ValueError
                value = int(number)
            else:
                value = float(text)
        except (ValueError, OverflowError):
            expected = "an integer" if self.kind == "int" else "a number"
            if self.choices:
                expected += " or one of " + ", ".join(kebab(c) for c in self.choices)
            raise ParameterError("%s: '%s' is not %s" % (self.name, text, expected)) from None
        return self.check(value)

    def _unbounded(self, value):
        """The class's largest (smallest) value when ``value`` is +inf (-inf), written as text
        or as a number, and the range is unbounded on that side (VTK_DOUBLE_MAX, VTK_INT_MAX:
        shown as inf); else None."""
        if isinstance(value, str):
            try:
                value = float(value)
            except ValueError:
                return None
        if not isinstance(value, float) or value not in (float("inf"), float("-inf")):
            return None
        bound = self.maximum if value > 0 else self.minimum
        if bound is not None and _short(bound) in ("inf", "-inf"):
            return bound
        return None

    def check(self, value):
        """``value`` converted to this parameter's kind and checked against its range."""
        if self.kind == "bool":
            return bool(value)
        if self.kind in ("str", "vector"):
            return value
        if value != value:
            raise ParameterError("%s: NaN is not a valid value" % self.name)
        unbounded = self._unbounded(value)
        if unbounded is not None:
            return unbounded
        if self.minimum is not None and not (self.minimum <= value <= self.maximum):
            raise ParameterError("%s: %s is out of range [%s, %s]"
                                 % (self.name, _short(value), _short(self.minimum),
                                    _short(self.maximum)))
        return int(value) if self.kind == "int" else float(value)


def kebab(name):
    """GenerateTetrahedra -> generate-tetrahedra, XYPlane -> xy-plane."""
    name = re.sub(r"([a-z0-9])([A-Z])", r"\1-\2", name)
    name = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1-\2", name)
    return name.replace("_", "-").lower()


def _same_name(a, b):
    return re.sub(r"[-_\s]", "", a).lower() == re.sub(r"[-_\s]", "", b).lower()


def _short(value):
    if isinstance(value, float):
        if value >= 1e299:
            return "inf"
        if value <= -1e299:
            return "-inf"
        return "%g" % value
    if isinstance(value, int) and abs(value) >= 2**31 - 1:
        return "inf" if value > 0 else "-inf"
    return str(value)


def _doc_text(method):
    """The comment part of a wrapped method's docstring (after the signatures)."""
    doc = getattr(method, "__doc__", None) or ""
    lines = doc.splitlines()
    body = [l for l in lines if not re.match(r"^\s*(\w+\(.*\)\s*->|C\+\+:)", l)]
    return " ".join(" ".join(body).split())


_BASE_NAMES = None


def _base_names():
    global _BASE_NAMES
    if _BASE_NAMES is None:
        from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm

        _BASE_NAMES = set(dir(vtkPolyDataAlgorithm))
    return _BASE_NAMES


def discover_parameters(cls):
    """Parameters of a wrapped filter class (see the module documentation)."""
    instance = cls()
    own = [n for n in dir(cls) if n not in _base_names()]
    # Keep the order of the wrapped methods' declaration where possible (dir() sorts names):
    # the class docstring lists nothing useful for that, so alphabetical order is used.
    parameters = []
    for setter in own:
        if not setter.startswith("Set") or "To" in setter[3:] and _is_choice_setter(cls, setter):
            continue
        name = setter[3:]
        getter = getattr(instance, "Get" + name, None)
        if getter is None:
            continue
        try:
            default = getter()
        except TypeError:
            continue
        if isinstance(default, bool):
            kind = "bool"
        elif isinstance(default, int):
            kind = "int"
        elif isinstance(default, float):
            kind = "float"
        elif isinstance(default, str):
            kind = "str"
        elif isinstance(default, tuple) and default and all(
                isinstance(v, (int, float)) for v in default):
            kind = "vector"
        else:
            continue  # objects (locators...), None
        minimum = maximum = None
        if hasattr(instance, "Get%sMinValue" % name) and kind in ("int", "float"):
            minimum = getattr(instance, "Get%sMinValue" % name)()
            maximum = getattr(instance, "Get%sMaxValue" % name)()
        choices = {}
        for other in own:
            prefix = "Set%sTo" % name
            if other.startswith(prefix) and len(other) > len(prefix):
                probe = cls()
                try:
                    getattr(probe, other)()
                except TypeError:
                    continue
                choices[other[len(prefix):]] = getattr(probe, "Get" + name)()
        parameters.append(Parameter(name, kind, default, minimum, maximum, choices,
                                    _doc_text(getattr(cls, setter))))
    # The wrapper gives a group's comment (///@{ ... ///@}) to its first method only: a
    # parameter documented together with another takes the comment that names it.
    for parameter in parameters:
        if not parameter.doc:
            pattern = re.compile(r"\b%s\b" % parameter.name)
            parameter.doc = next((other.doc for other in parameters
                                  if other.doc and pattern.search(other.doc)), "")
    return parameters


def _is_choice_setter(cls, setter):
    """SetXToY (an enumeration value) rather than a parameter whose name contains 'To'."""
    head = setter[:setter.rfind("To")]
    return hasattr(cls, head) and head != setter


def find_parameter(parameters, name):
    for parameter in parameters:
        if _same_name(parameter.name, name) or _same_name(kebab(parameter.name), name):
            return parameter
    raise ParameterError("unknown parameter '%s' (parameters: %s)"
                         % (name, ", ".join(p.name for p in parameters) or "none"))


def apply_parameters(algorithm, parameters, values):
    """Sets ``values`` ({name: value or text}) on ``algorithm`` after checking each one."""
    for name, value in values.items():
        parameter = find_parameter(parameters, name)
        if isinstance(value, str) and parameter.kind != "str":
            value = parameter.parse(value)
        else:
            value = parameter.check(value)
        setter = getattr(algorithm, "Set" + parameter.name)
        if parameter.kind == "vector":
            setter(*value)
        else:
            setter(value)


def make_filter(method, params=None):
    """A new filter of ``method`` (a Method or its name) with the presets and ``params``."""
    if not isinstance(method, Method):
        method = find_method(method)
    cls = method.filter_class
    if cls is None:
        raise MethodNotAvailable(_not_available(method))
    algorithm = cls()
    parameters = discover_parameters(cls)
    values = dict(method.presets)
    for name, value in (params or {}).items():
        # A user value replaces a preset given under any spelling of the same name.
        parameter = find_parameter(parameters, name)
        values.pop(parameter.name, None)
        values[parameter.name] = value
    apply_parameters(algorithm, parameters, values)
    return algorithm


def reconstruct(points, method="delaunay", normals=None, progress=None, **params):
    """Reconstructs a surface; returns the output mesh (vtkPolyData, all input points passed
    through, the surface as triangles).

    points: an (N, 3) array-like or any vtkPointSet; normals: optional (N, 3) array (arrays
    only); method: a name of METHODS ("delaunay", "terrain", "peel", "local-optimum",
    "cdt-front", "greedy": those built); params: filter parameters by their C++ name
    (``Dimension=2``, ``Tolerance=1e-6``) or in snake/kebab case; progress: optional callable
    progress(fraction) fed by the filter's ProgressEvent. Raises MethodNotAvailable,
    ParameterError (before running), RuntimeError when the filter reports an error.
    """
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonDataModel import vtkPointSet

    from .arrays import points_to_polydata
    from .fileio import MessageCollector

    method = method if isinstance(method, Method) else find_method(method)
    algorithm = make_filter(method, params)
    if isinstance(points, vtkPointSet):
        if normals is not None:
            raise ValueError("normals are taken from the point set's point data")
        cloud = points
    else:
        cloud = points_to_polydata(points, normals)
    algorithm.SetInputData(cloud)
    messages = MessageCollector(algorithm)
    if progress is not None:
        algorithm.AddObserver(vtkCommand.ProgressEvent,
                              lambda caller, event: progress(caller.GetProgress()))
    algorithm.Update()
    if messages.errors:
        raise RuntimeError("%s: %s" % (method.class_name, "; ".join(messages.errors)))
    for warning in messages.warnings:
        import warnings

        warnings.warn("%s: %s" % (method.class_name, warning), RuntimeWarning, stacklevel=2)
    output = algorithm.GetOutputDataObject(method.port)
    result = output.NewInstance()
    result.ShallowCopy(output)
    return result
