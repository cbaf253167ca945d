"""The README's parameter tables agree with the wrapped classes.

Every section ``## vtkSomething`` of README.md whose class is in the ``pointcloudsurface``
package is read; its tables with the header ``| parameter | default | range | ...`` give, per
row, a parameter name, a default and a range. Each row must name a parameter of the class, its
default must equal ``Get<Name>()`` of a new instance and its range the clamp range
(``Get<Name>MinValue()`` / ``Get<Name>MaxValue()``), on/off rows a boolean, enumerations the
class's named values; every numeric, boolean or string parameter of the class must have a row.
The class documentation (each setter's ``///@{`` group comment, read from the header
Filters/<class>.h beside the README: the wrapped docstrings are truncated) must state every
parameter's default and, for a clamped non-boolean, its range, equal to the class's:
"Default X; range [a, b]", "Default Automatic (2)", "Automatic (2, the default)", "3 (default)",
"Range [a, b]"; a group comment of two parameters "Defaults a and b; ranges [..] and [..]" in
the order the comment names them (check_statements, also used by TestPluginLoad on the XML's
property documentation). An enumeration's documentation names each of the class's values with
its number ("Off (0)", "CROSSING_TEST_ON (1)"), check_choices (also used for the XML entries).
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
import os
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
# Other ways the documentation names a default: "Default Automatic (2)", "XY_PLANE (0, default)",
# "Automatic (2, the default)", "3 (default)".
STATED_NAMED_DEFAULT = re.compile(r"\bDefault\s+([A-Za-z_]\w*)\s+\((-?\d+)\)")
STATED_DEFAULT_AFTER = re.compile(r"(?<![\w.])([A-Za-z_]\w*|-?\d+(?:\.\d+)?)\s+"
                                  r"\((?:(-?\d+),\s*)?(?:the\s+)?default\b")
STATED_RANGE = re.compile(r"\b[Rr]ange\s+\[([^,\]]+),\s*([^\]]+)\]")
# Several parameters in one text: "Defaults 1/3 and 3 ...; ranges [0, 1] and [1, 1000]".
STATED_DEFAULTS = re.compile(r"\bDefaults\s+(\S+)\s+and\s+(\S+)")
STATED_RANGES = re.compile(r"\branges\s+\[([^,\]]+),\s*([^\]]+)\]\s+and\s+"
                           r"\[([^,\]]+),\s*([^\]]+)\]")


def choice_named(text, parameter):
    """The class's value for the enumeration name ``text`` ("Automatic", "XY_PLANE",
    "CROSSING_TEST_AUTOMATIC", "Best-fit plane"), or None: equal names, or a prefixed constant
    ending with the class's name."""
    plain = re.sub(r"[-_\s]", "", text).lower()
    for key, value in parameter.choices.items():
        key = re.sub(r"[-_\s]", "", key).lower()
        if plain == key or (plain.endswith(key) and "_" in text):
            return value
    return None


def statements(text, parameter, index=0):
    """(default text or None, (minimum text, maximum text) or None) that ``text`` states for
    ``parameter``; ``index`` picks the parameter in texts stating several ("Defaults a and b")."""
    text = " ".join(text.split())
    default = None
    if re.search(r"\bDefaults\b", text):
        found = STATED_DEFAULTS.search(text)
        if found:
            default = found.group(1 + index).rstrip(";,.")
    else:
        defaults = STATED_DEFAULT.findall(text)
        named = STATED_NAMED_DEFAULT.findall(text)
        after = STATED_DEFAULT_AFTER.findall(text)
        if len(defaults) + len(named) + len(after) == 1:
            if defaults:
                default = defaults[0]
            elif named:
                default = "%s (%s)" % named[0]
            else:
                default = after[0][0] + (" (%s)" % after[0][1] if after[0][1] else "")
    bounds = None
    if re.search(r"\branges\b", text):
        found = STATED_RANGES.search(text)
        if found:
            bounds = (found.group(1 + 2 * index).strip(), found.group(2 + 2 * index).strip())
    else:
        ranges = STATED_RANGE.findall(text)
        if len(ranges) == 1:
            bounds = (ranges[0][0].strip(), ranges[0][1].strip())
    return default, bounds


def check_statements(where, text, parameter, actual_default, index=0, required=False):
    """The default and range a documentation text states ("Default 0.5; range [0, 1]",
    "Automatic (2, the default) ... Range [0, 2]", "Defaults 1/3 and 3; ranges [0, 1] and
    [1, 1000]" for the index-th of two parameters, in the order the text names them) against the class. Texts stating several
    defaults or ranges otherwise are skipped, unless ``required`` (the class documentation):
    then a parameter whose text states no default, or a clamped non-boolean one that states no
    range, fails. Returns the number of statements checked (used by TestPluginLoad for the
    XML)."""
    checked_here = 0
    default, bounds = statements(text, parameter, index)
    if default is not None:
        try:
            named = re.match(r"^([A-Za-z_]\w*)(?:\s+\((-?\d+)\))?$", default)
            if named and named.group(1).lower() not in ("on", "off", "vtk_double_max",
                                                         "vtk_int_max"):
                value = choice_named(named.group(1), parameter)
                if value is None:
                    raise Unparsed("%s: the stated default '%s' is not a named value of %s "
                                   "(class: %s)" % (where, default, parameter.name,
                                                    ", ".join(parameter.choices) or "none"))
                if named.group(2) is not None and int(named.group(2)) != value:
                    fail("%s: the documentation says %s is %s, the class %s"
                         % (where, named.group(1), named.group(2), value))
            else:
                value = number_of(default, parameter, where + " stated default")
            if not same(value, actual_default):
                fail("%s: the documentation states the default %s, the class default is %r"
                     % (where, default, actual_default))
            checked_here += 1
        except Unparsed as error:
            fail(str(error))
    elif required:
        fail("%s: the documentation states no default (write 'Default X')" % where)
    if bounds is not None and parameter.minimum is not None:
        try:
            low = number_of(bounds[0], parameter, where + " stated minimum")
            high = number_of(bounds[1], parameter, where + " stated maximum")
            if not same(low, parameter.minimum) or not same(high, parameter.maximum):
                fail("%s: the documentation says 'range [%s, %s]', the clamp is [%r, %r]"
                     % (where, bounds[0], bounds[1], parameter.minimum, parameter.maximum))
            checked_here += 1
        except Unparsed as error:
            fail(str(error))
    elif required and parameter.minimum is not None and parameter.kind != "bool":
        fail("%s: the documentation states no range (write 'range [a, b]'; clamp [%r, %r])"
             % (where, parameter.minimum, parameter.maximum))
    elif bounds is not None and parameter.kind not in ("bool", "str"):
        fail("%s: the documentation states a range [%s, %s], the class has no clamp"
             % (where, bounds[0], bounds[1]))
    return checked_here


def check_choices(where, pairs, parameter):
    """An enumeration written as (name, value) pairs (the class documentation's "Off (0)",
    the XML's Entry text and value) names exactly the class's values, each with its value."""
    if not parameter.choices:
        return 0
    values = sorted(value for _, value in pairs)
    if values != sorted(parameter.choices.values()):
        fail("%s: lists the values %s, the class's are %s (%s)"
             % (where, values, sorted(parameter.choices.values()), parameter.choices))
    for name, value in pairs:
        if choice_named(name, parameter) is None:
            fail("%s: '%s' is not a name of the class's values (%s)"
                 % (where, name, ", ".join(parameter.choices)))
        elif choice_named(name, parameter) != value:
            fail("%s: '%s' is %s there, %s in the class"
                 % (where, name, value, choice_named(name, parameter)))
    return len(pairs)


def documented_choices(text, parameter):
    """The (name, value) pairs of an enumeration the documentation writes as "NAME (n" ("Off
    (0)", "XY_PLANE (0, default)"), keeping the names that are the class's or the number's."""
    text = " ".join(text.split())
    pairs = []
    for name, value in re.findall(r"\b([A-Za-z_]\w*)\s+\((-?\d+)\b", text):
        if choice_named(name, parameter) is not None:
            pairs.append((name, int(value)))
    return sorted(set(pairs), key=lambda pair: pair[1])


def header_docs(header):
    """{parameter name: its documentation in the class header}: the comment of each ``///@{``
    group holding a setter (vtkSet*Macro or ``void SetX(``). The wrapped classes' docstrings
    are truncated (VTK's wrapper cuts long comments), so the header itself is read."""
    docs = {}
    try:
        source = open(header, encoding="utf-8").read()
    except OSError:
        return docs
    for group in re.findall(r"///@\{(.*?)///@\}", source, re.S):
        comments = re.findall(r"/\*\*(.*?)\*/", group, re.S)
        comments += [line.strip()[3:] for line in group.splitlines()
                     if line.strip().startswith("///")]
        text = " ".join(" ".join(re.sub(r"^\s*\*", "", line) for line in comment.splitlines())
                        for comment in comments)
        for name in re.findall(r"\bvtkSet\w*Macro\(\s*(\w+)|\bvoid\s+Set(\w+)\s*\(", group):
            docs.setdefault(name[0] or name[1], " ".join(text.split()))
    return docs


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
        header = os.path.join(os.path.dirname(os.path.abspath(readme)), "Filters",
                              class_name + ".h")
        docs = header_docs(header)
        if not docs:
            fail("%s: no parameter documentation read from %s" % (class_name, header))
        names = [row[1] for row in rows]
        for duplicate in sorted({n for n in names if names.count(n) > 1}):
            fail("README.md %s: %s has more than one row" % (class_name, duplicate))
        for row in rows:
            check_row(cls, instance, parameters, row)
        for parameter in parameters:
            if parameter.name not in names:
                fail("README.md %s: no row for the parameter %s (default %r)"
                     % (class_name, parameter.name, parameter.default))
        # The class documentation (the setters' docstrings) states the same default and range,
        # for every parameter; a text shared by a group of parameters ("Defaults a and b")
        # states them in the order the text names them. Enumerations name each value with its number.
        for parameter in parameters:
            if parameter.kind in ("str", "vector"):
                continue
            where = "%s.%s documentation" % (class_name, parameter.name)
            doc = docs.get(parameter.name)
            if doc is None:
                fail("%s: no documentation in %s" % (where, header))
                continue
            group = sorted((p.name for p in parameters if docs.get(p.name) == doc),
                           key=lambda name: (doc.find(name), name))
            stated[0] += check_statements(where, doc, parameter, parameter.default,
                                          index=group.index(parameter.name), required=True)
            if parameter.choices:
                stated[0] += check_choices(where, documented_choices(doc, parameter), parameter)
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
