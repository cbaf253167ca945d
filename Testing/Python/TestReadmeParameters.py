"""The README's parameter tables agree with the wrapped classes.

Every section ``## vtkSomething`` of README.md whose class is in the ``pointcloudsurface``
package is read; its tables with the header ``| parameter | default | range | ...`` give, per
row, a parameter name, a default and a range. Each row must name a parameter of the class, its
default must equal ``Get<Name>()`` of a new instance and its range the clamp range
(``Get<Name>MinValue()`` / ``Get<Name>MaxValue()``), on/off rows a boolean, enumerations the
class's named values; every numeric, boolean or string parameter of the class must have a row.
The class documentation (each setter's docstring) must state the same "Default X; range [a, b]"
where it states them for that parameter alone (check_statements, also used by TestPluginLoad on
the XML's property documentation).
The ParaView XML is compared with the same classes by PointCloudSurface-PluginLoad, so README,
class and proxy cannot drift apart. No rendering.

Usage: python3 TestReadmeParameters.py <README.md>

Formats understood (those of the README): defaults ``3``, ``1.0``, ``1/3``, ``0 (automatic)``,
``on``, ``` `XY_PLANE` (0) ```, ``Automatic (2)``, ``Perimeter``, ``VTK_DOUBLE_MAX (no limit)``;
ranges ``[0, 1]``, ``[0, VTK_DOUBLE_MAX] s``, ``[1, 179] degrees``, ``[0, max]``, ``on / off``,
``2 or 3``, ``0 `XY_PLANE`, 1 `BEST_FIT_PLANE` ``, ``Off (0), On (1), Automatic (2)``,
``Perimeter, Area, Circumradius``. Rows whose first cell is not a backquoted name are not
parameters and are skipped; rows of object parameters (``Locator``) are checked for existence
only.
"""
import re
import sys

import pointcloudsurface
from pointcloudsurface.methods import discover_parameters, _same_name

VTK_INT_MAX = 2**31 - 1
VTK_DOUBLE_MAX = 1.0e299  # vtkType.h defines it so (not DBL_MAX)
UNBOUNDED = object()  # "max", "inf": the largest value of the parameter's type

failures = []
checked = 0


def fail(message):
    failures.append(message)
    print("FAILED: " + message)


class Unparsed(ValueError):
    pass


def split_row(line):
    cells = line.strip().strip("|").split("|")
    return [c.strip() for c in cells]


def read_tables(readme):
    """{class name: [(line number, name, default text, range text), ...]} from the sections."""
    tables = {}
    section = None
    header = False
    lines = open(readme, encoding="utf-8").read().splitlines()
    for number, line in enumerate(lines, 1):
        if line.startswith("## ") or line.startswith("# "):
            match = re.match(r"^## (vtk\w+)\s*$", line)
            section = match.group(1) if match else None
            header = False
            continue
        if section is None:
            continue
        if not line.lstrip().startswith("|"):
            header = False
            continue
        cells = split_row(line)
        if [c.lower() for c in cells[:3]] == ["parameter", "default", "range"]:
            header = True
            tables.setdefault(section, [])
            continue
        if not header or re.match(r"^:?-+:?$", cells[0]):
            continue
        name = re.match(r"^`(\w+)`$", cells[0])
        if not name or len(cells) < 3:
            continue  # not a parameter row
        tables[section].append((number, name.group(1), cells[1], cells[2]))
    return tables


def number_of(text, parameter, where):
    """The value written in ``text`` (a default or a range bound) for ``parameter``:
    a float, an int, UNBOUNDED, or raise Unparsed."""
    raw = text
    text = text.replace("`", "").strip()
    text = re.sub(r"\s+(degrees|s)$", "", text)  # units after a bound
    lowered = text.lower()
    if lowered in ("on", "true"):
        return 1
    if lowered in ("off", "false"):
        return 0
    if lowered in ("max", "inf"):
        return UNBOUNDED
    if lowered == "vtk_double_max":
        return VTK_DOUBLE_MAX
    if lowered == "vtk_int_max":
        return VTK_INT_MAX
    # "0 `XY_PLANE`" (number, then its name)
    numbered = re.match(r"^(-?\d+)\s+([A-Za-z_]\w*)$", text)
    if numbered:
        for key, value in parameter.choices.items():
            if _same_name(numbered.group(2), key) and value != int(numbered.group(1)):
                fail("%s: %s is %s in the class, not %s"
                     % (where, numbered.group(2), value, numbered.group(1)))
        if parameter.choices and not any(_same_name(numbered.group(2), key)
                                         for key in parameter.choices):
            raise Unparsed("%s: '%s' is not a named value of %s (class: %s)"
                           % (where, raw, parameter.name, ", ".join(parameter.choices)))
        return int(numbered.group(1))
    # A leading number: "3", "1.0", "1/3", "0 (automatic)", "1e-6"; or "VTK_DOUBLE_MAX (no limit)".
    match = re.match(r"^(-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)(?:\s*/\s*(\d+(?:\.\d*)?))?(\s|$|\()",
                     text)
    if match:
        value = float(match.group(1))
        if match.group(2):
            value /= float(match.group(2))
        return int(value) if value == int(value) and "." not in match.group(1) \
            and not match.group(2) and "e" not in lowered else value
    head = text.split("(")[0].strip()
    if head.lower() in ("max", "inf"):
        return UNBOUNDED
    if head.lower() == "vtk_double_max":
        return VTK_DOUBLE_MAX
    if head.lower() == "vtk_int_max":
        return VTK_INT_MAX
    # A named value, with or without its number: "`XY_PLANE` (0)", "Automatic (2)", "Perimeter".
    named = re.match(r"^([A-Za-z_]\w*)\s*(?:\((-?\d+)\))?$", text)
    if named:
        choice = None
        for key, value in parameter.choices.items():
            if _same_name(named.group(1), key):
                choice = value
        if choice is None and parameter.choices:
            raise Unparsed("%s: '%s' is not a named value of %s (class: %s)"
                           % (where, raw, parameter.name, ", ".join(parameter.choices)))
        if named.group(2) is not None:
            if choice is not None and choice != int(named.group(2)):
                fail("%s: %s is %s in the class, not %s" % (where, named.group(1), choice,
                                                            named.group(2)))
            return int(named.group(2))
        if choice is not None:
            return choice
        raise Unparsed("%s: '%s' is not a named value of %s (class: %s)"
                       % (where, raw, parameter.name, ", ".join(parameter.choices) or "none"))
    raise Unparsed("%s: cannot read a value in '%s'" % (where, raw))


def same(written, actual):
    if written is UNBOUNDED:
        # VTK_DOUBLE_MAX, VTK_FLOAT_MAX or VTK_INT_MAX
        return actual >= 0.99e38 or actual == VTK_INT_MAX
    if isinstance(actual, bool):
        actual = int(actual)
    if written == actual:
        return True
    return abs(written - actual) <= 1e-9 * max(abs(written), abs(actual))


def show(value):
    return "max" if value is UNBOUNDED else repr(value)


def check_row(cls, instance, parameters, row):
    global checked
    line, name, default_text, range_text = row
    where = "README.md:%d %s.%s" % (line, cls.__name__, name)
    if not hasattr(instance, "Set" + name) or not hasattr(instance, "Get" + name):
        fail("%s: the class has no Set%s/Get%s (renamed or removed parameter?)"
             % (where, name, name))
        return
    parameter = next((p for p in parameters if p.name == name), None)
    if parameter is None:
        # An object parameter (a locator...): the row documents it, nothing to compare.
        value = getattr(instance, "Get" + name)()
        if value is not None and not hasattr(value, "IsA"):
            fail("%s: Get%s() returns %r, neither a parameter nor an object"
                 % (where, name, value))
        return
    actual_default = getattr(instance, "Get" + name)()
    has_clamp = parameter.minimum is not None
    is_boolean = hasattr(instance, name + "On") and hasattr(instance, name + "Off")
    try:
        default = number_of(default_text, parameter, where + " default")
        if parameter.kind == "str":
            pass
        elif not same(default, actual_default):
            fail("%s: README default %s (%r), class default %r"
                 % (where, show(default), default_text, actual_default))
        checked_range = range_text.replace("`", "").strip()
        if re.match(r"^on\s*/\s*off$", checked_range, re.I):
            if not is_boolean:
                fail("%s: README range on/off, but the class has no %sOn/%sOff"
                     % (where, name, name))
            if has_clamp and (parameter.minimum, parameter.maximum) != (0, 1):
                fail("%s: on/off, but the clamp range is [%r, %r]"
                     % (where, parameter.minimum, parameter.maximum))
            if actual_default not in (0, 1):
                fail("%s: on/off, but the default is %r" % (where, actual_default))
        else:
            bracket = re.match(r"^\[([^,\]]+),([^\]]+)\]", checked_range)
            if bracket:
                values = [number_of(bracket.group(1).strip(), parameter, where + " minimum"),
                          number_of(bracket.group(2).strip(), parameter, where + " maximum")]
                listed = None
            else:
                items = [i.strip() for i in re.split(r",|\bor\b", range_text) if i.strip()]
                if len(items) < 2:
                    raise Unparsed("%s: cannot read the range '%s'" % (where, range_text))
                listed = [number_of(i, parameter, where + " range") for i in items]
                values = [min(listed), max(listed)]
            if not has_clamp:
                fail("%s: README range %s, but the class has no clamp (Get%sMinValue)"
                     % (where, range_text, name))
            else:
                if not same(values[0], parameter.minimum) or \
                        not same(values[1], parameter.maximum):
                    fail("%s: README range [%s, %s] (%r), class clamp [%r, %r]"
                         % (where, show(values[0]), show(values[1]), range_text,
                            parameter.minimum, parameter.maximum))
                if listed is not None and parameter.choices and \
                        sorted(listed) != sorted(parameter.choices.values()):
                    fail("%s: README lists %s, the class's named values are %s"
                         % (where, sorted(listed), parameter.choices))
        checked += 1
    except Unparsed as error:
        fail(str(error))


STATED_DEFAULT = re.compile(r"\bDefault\s+(on|off|VTK_DOUBLE_MAX|VTK_INT_MAX|"
                            r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?:/\d+)?)(?![\w/])")
STATED_RANGE = re.compile(r"\brange\s+\[([^,\]]+),\s*([^\]]+)\]")


def check_statements(where, text, parameter, actual_default):
    """The default and range a documentation text states in the project's usual words
    ("Default 0.5; range [0, 1]"), when it states them for this parameter alone, against the
    class. Texts of several parameters ("Defaults 1/3 and 3", "ranges ...") and named defaults
    are skipped. Returns the number of statements checked (used by TestPluginLoad for the XML)."""
    checked_here = 0
    text = " ".join(text.split())
    defaults = STATED_DEFAULT.findall(text)
    if len(defaults) == 1 and not re.search(r"\bDefaults\b", text):
        try:
            value = number_of(defaults[0], parameter, where + " stated default")
            if not same(value, actual_default):
                fail("%s: the documentation says 'Default %s', the class default is %r"
                     % (where, defaults[0], actual_default))
            checked_here += 1
        except Unparsed as error:
            fail(str(error))
    ranges = STATED_RANGE.findall(text)
    if len(ranges) == 1 and not re.search(r"\branges\b", text) \
            and parameter.minimum is not None:
        try:
            low = number_of(ranges[0][0].strip(), parameter, where + " stated minimum")
            high = number_of(ranges[0][1].strip(), parameter, where + " stated maximum")
            if not same(low, parameter.minimum) or not same(high, parameter.maximum):
                fail("%s: the documentation says 'range [%s, %s]', the clamp is [%r, %r]"
                     % (where, ranges[0][0], ranges[0][1], parameter.minimum,
                        parameter.maximum))
            checked_here += 1
        except Unparsed as error:
            fail(str(error))
    return checked_here


def main():
    readme = sys.argv[1]
    tables = read_tables(readme)
    classes = sorted(n for n in dir(pointcloudsurface)
                     if n.startswith("vtk") and isinstance(getattr(pointcloudsurface, n), type))
    if not classes:
        fail("no class in the pointcloudsurface package")
    stated = [0]
    for class_name in classes:
        cls = getattr(pointcloudsurface, class_name)
        parameters = discover_parameters(cls)
        rows = tables.get(class_name)
        if rows is None:
            if parameters:
                fail("README.md has no parameter table in a section '## %s' (parameters: %s)"
                     % (class_name, ", ".join(p.name for p in parameters)))
            continue
        instance = cls()
        names = [row[1] for row in rows]
        for duplicate in sorted({n for n in names if names.count(n) > 1}):
            fail("README.md %s: %s has more than one row" % (class_name, duplicate))
        for row in rows:
            check_row(cls, instance, parameters, row)
        for parameter in parameters:
            if parameter.name not in names:
                fail("README.md %s: no row for the parameter %s (default %r)"
                     % (class_name, parameter.name, parameter.default))
        # The class documentation (the setters' docstrings) states the same default and range.
        for parameter in parameters:
            stated[0] += check_statements("%s.%s documentation" % (class_name, parameter.name),
                                          parameter.doc, parameter, parameter.default)
        print("%s: %d rows, %d parameters of the class" % (class_name, len(rows), len(parameters)))
    for class_name in sorted(set(tables) - set(classes)):
        print("note: section %s has a parameter table but the class is not in this build"
              % class_name)
    if failures:
        print("FAILED: %d disagreement(s) between README.md and the classes" % len(failures))
        return 1
    print("README parameter tables agree with the classes: %d rows checked; the class "
          "documentation states the same: %d defaults and ranges checked" % (checked, stated[0]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
