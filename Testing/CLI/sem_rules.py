"""Slicer Execution Model (SEM) rules, re-implemented for the CLI tests.

This module is our own reading of `shared/reference/slicer-conventions.md`
(sections 1, 2.2, 2.5 and 2.7). It lets the tests look at a CLI the way 3D
Slicer does, without Slicer:

- `check_module_xml` mirrors SEM's ModuleDescriptionParser (the code Slicer and
  GenerateCLP use; the published XSD does not compile) plus the project's
  rules (every point declares its coordinateSystem);
- `slicer_argv` builds the argument vector exactly as
  vtkSlicerCLIModuleLogic::ApplyTask does for an executable CLI;
- `parse_progress` reads the progress tags the way Slicer does and applies
  Slicer's stripping regexes;
- `read_return_parameters` reads a `--returnparameterfile` like
  ModuleDescription::ReadParameterFile;
- `read_nrrd` is a minimal reader for the NRRD files ITK writes.

Only the Python standard library and numpy are used.
"""

import gzip
import bz2
import os
import random
import re
import string
import xml.parsers.expat

import numpy as np

# --------------------------------------------------------------------------
# The vocabulary of the parser (conventions section 1)
# --------------------------------------------------------------------------

MODULE_ELEMENTS = {
    "category", "title", "description", "version", "documentation-url",
    "license", "contributor", "acknowledgements", "index", "location",
    "parameters",
}
GROUP_CHILDREN = {"label", "description"}

# Tag -> attributes the parser accepts (conventions table 1.3). An empty set
# means attributes are ignored by the parser: we report them, because an
# attribute that does nothing is a mistake in the XML.
PARAMETER_ATTRIBUTES = {
    "integer": {"hidden", "multiple"},
    "float": {"hidden", "multiple"},
    "double": {"hidden", "multiple"},
    "string": {"hidden", "multiple"},
    "boolean": {"hidden"},
    "integer-vector": set(),
    "float-vector": set(),
    "double-vector": set(),
    "string-vector": set(),
    "integer-enumeration": {"hidden"},
    "float-enumeration": {"hidden"},
    "double-enumeration": {"hidden"},
    "string-enumeration": {"hidden"},
    "point": {"multiple", "coordinateSystem"},
    "region": {"multiple", "coordinateSystem"},
    "pointfile": {"multiple", "fileExtensions", "coordinateSystem", "type"},
    "file": {"multiple", "fileExtensions"},
    "directory": {"multiple"},
    "image": {"multiple", "type", "fileExtensions", "hidden", "reference"},
    "geometry": {"multiple", "aggregate", "type", "fileExtensions", "reference"},
    "transform": {"multiple", "type", "fileExtensions", "reference"},
    "table": {"multiple", "hidden", "reference", "type", "fileExtensions"},
    "measurement": {"multiple", "hidden", "reference", "type", "fileExtensions"},
}
# In the SEM XSD but rejected by the parser as unrecognised elements.
REJECTED_TAGS = {"boolean-vector", "point-vector", "region-vector"}

ATTRIBUTE_VALUES = {
    "hidden": {"true", "false"},
    "multiple": {"true", "false"},
    "aggregate": {"true", "false"},
    "coordinateSystem": {"ras", "lps", "ijk"},
}
TYPE_VALUES = {
    "image": {"any", "scalar", "label", "tensor", "diffusion-weighted", "vector",
              "signal", "multichannel", "dynamic-contrast-enhanced"},
    "geometry": {"model", "fiberbundle"},
    "transform": {"linear", "nonlinear", "bspline"},
    "table": {"color"},
    "pointfile": {"point", "line", "angle", "curve", "closedcurve", "any"},
    "measurement": None,  # free text in the parser
}

PARAMETER_CHILDREN = {
    "name", "flag", "longflag", "index", "label", "description", "default",
    "channel", "constraints", "element", "reference",
}
CONSTRAINT_CHILDREN = {"minimum", "maximum", "step"}

FILE_LIKE_TAGS = {"image", "geometry", "transform", "table", "measurement",
                  "pointfile", "file"}
NODE_TAGS = {"image", "geometry", "transform", "table", "measurement", "pointfile"}
ENUMERATION_TAGS = {"integer-enumeration", "float-enumeration",
                    "double-enumeration", "string-enumeration"}
VECTOR_TAGS = {"integer-vector", "float-vector", "double-vector", "string-vector"}
SCALAR_NUMBER_TAGS = {"integer", "float", "double"}

# Arguments GenerateCLP and TCLAP add to every module; a parameter must not
# reuse them.
RESERVED_LONGFLAGS = {"xml", "echo", "processinformationaddress",
                      "returnparameterfile", "help", "version", "ignore_rest"}
RESERVED_FLAGS = {"h"}

IDENTIFIER = re.compile(r"[_A-Za-z][_A-Za-z0-9]*\Z")
INTEGER = re.compile(r"[+-]?\d+\Z")
FLOAT = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")


class _Node:
    """One XML element with what the checks need (expat keeps line numbers)."""

    def __init__(self, tag, attrs, line, parent):
        self.tag = tag
        self.attrs = attrs
        self.line = line
        self.parent = parent
        self.children = []
        self.text = ""

    def child(self, tag):
        for node in self.children:
            if node.tag == tag:
                return node
        return None

    def child_text(self, tag):
        node = self.child(tag)
        return None if node is None else node.text.strip()


def _parse_tree(raw):
    """Parse with expat (SEM's parser); return the root _Node or raise."""
    parser = xml.parsers.expat.ParserCreate()
    stack = []
    root = []

    def start(tag, attrs):
        node = _Node(tag, attrs, parser.CurrentLineNumber, stack[-1] if stack else None)
        if stack:
            stack[-1].children.append(node)
        else:
            root.append(node)
        stack.append(node)

    def end(tag):
        stack.pop()

    def data(text):
        if stack:
            stack[-1].text += text

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = data
    parser.Parse(raw.encode("utf-8") if isinstance(raw, str) else raw, True)
    return root[0]


def _is_number(text, integer):
    return bool((INTEGER if integer else FLOAT).match(text.strip()))


def _check_value(tag, text, where, problems):
    """Check that a <default> (or <element>) parses as the declared type."""
    text = text.strip()
    if tag in ("integer", "integer-enumeration"):
        if not _is_number(text, True):
            problems.append(f"{where}: '{text}' is not an integer")
    elif tag in ("float", "double", "float-enumeration", "double-enumeration"):
        if not _is_number(text, False):
            problems.append(f"{where}: '{text}' is not a number")
    elif tag == "boolean":
        if text not in ("true", "false"):
            problems.append(f"{where}: '{text}' is not true or false")
    elif tag in ("integer-vector", "float-vector", "double-vector", "point", "region"):
        items = text.split(",")
        integer = tag == "integer-vector"
        bad = [item for item in items if not _is_number(item, integer)]
        if bad:
            kind = "integers" if integer else "numbers"
            problems.append(f"{where}: '{text}' is not a comma list of {kind}")
        elif tag == "point" and len(items) % 3:
            problems.append(f"{where}: '{text}' does not hold x,y,z triples")
        elif tag == "region" and len(items) not in (6, 15):
            problems.append(f"{where}: '{text}' is not cx,cy,cz,rx,ry,rz[,9 axes]")


def _describe_parameter(node):
    cs = node.attrs.get("coordinateSystem")
    param = {
        "tag": node.tag,
        "name": node.child_text("name"),
        "flag": None,
        "longflag": None,
        "index": None,
        "channel": node.child_text("channel"),
        "multiple": node.attrs.get("multiple") == "true",
        "coordinateSystem": cs,
        "default": node.child_text("default"),
        "type": node.attrs.get("type"),
        "fileExtensions": node.attrs.get("fileExtensions"),
        "elements": [e.text.strip() for e in node.children if e.tag == "element"],
        "line": node.line,
    }
    flag = node.child_text("flag")
    if flag is not None:
        param["flag"] = flag.lstrip("-")
    longflag = node.child_text("longflag")
    if longflag is not None:
        param["longflag"] = longflag.lstrip("-")
    index = node.child_text("index")
    if index is not None:
        param["index"] = int(index) if INTEGER.match(index) else index
    if param["name"] is None and param["longflag"]:
        param["name"] = param["longflag"]  # the parser's fallback
    param["is_return"] = (param["channel"] == "output" and not param["flag"]
                          and not param["longflag"] and param["index"] is None)
    return param


def _check_parameter(node, problems):
    """Rules for one parameter element; returns its param dict."""
    tag = node.tag
    where = f"line {node.line} <{tag}>"
    allowed = PARAMETER_ATTRIBUTES[tag]
    for attr, value in node.attrs.items():
        if attr not in allowed:
            problems.append(f"{where}: attribute '{attr}' is not accepted on <{tag}>")
            continue
        if attr in ATTRIBUTE_VALUES and value not in ATTRIBUTE_VALUES[attr]:
            problems.append(f"{where}: {attr}=\"{value}\" is not one of "
                            f"{sorted(ATTRIBUTE_VALUES[attr])}")
        if attr == "type" and TYPE_VALUES.get(tag) and value not in TYPE_VALUES[tag]:
            problems.append(f"{where}: type=\"{value}\" is not one of {sorted(TYPE_VALUES[tag])}")
        if attr == "fileExtensions":
            exts = value.split(",")
            if not all(re.match(r"\.[A-Za-z0-9.]+\Z", ext.strip()) for ext in exts):
                problems.append(f"{where}: fileExtensions=\"{value}\" is not a comma list "
                                "of extensions with leading dots")

    for child in node.children:
        if child.tag not in PARAMETER_CHILDREN:
            problems.append(f"line {child.line}: unrecognized element <{child.tag}> "
                            f"inside <{tag}>")
        if child.tag == "constraints":
            for grandchild in child.children:
                if grandchild.tag not in CONSTRAINT_CHILDREN:
                    problems.append(f"line {grandchild.line}: unrecognized element "
                                    f"<{grandchild.tag}> inside <constraints>")
        elif child.children:
            problems.append(f"line {child.line}: <{child.tag}> must not contain elements")
        if child.tag == "reference":
            # SEM's forward-reference element is <reference role="R" parameter="P"/>;
            # its text is never read. "Place this output next to parameter P"
            # is the reference="P" attribute instead.
            if set(child.attrs) != {"role", "parameter"}:
                problems.append(f"line {child.line}: <reference> needs exactly the "
                                "attributes role and parameter (its text is ignored; "
                                f"use the attribute reference=\"...\" on <{tag}> to "
                                "place an output next to another parameter's node)")
            elif child.text.strip():
                problems.append(f"line {child.line}: <reference> text is ignored")
        counted = ("name", "flag", "longflag", "index", "channel", "default", "label",
                   "description", "constraints")
        if child.tag in counted and sum(c.tag == child.tag for c in node.children) > 1:
            problems.append(f"line {child.line}: <{child.tag}> appears more than once "
                            f"in <{tag}>")

    param = _describe_parameter(node)
    name = param["name"]
    where = f"line {node.line} <{tag}> '{name}'"

    raw_name = node.child_text("name")
    if raw_name is not None and not IDENTIFIER.match(raw_name):
        problems.append(f"{where}: <name> '{raw_name}' is not an identifier")
    if name is None:
        problems.append(f"{where}: no <name> and no <longflag>")
    if param["flag"] is not None and len(param["flag"]) != 1:
        problems.append(f"{where}: <flag> '{param['flag']}' is not one character")
    if param["longflag"] is not None and not IDENTIFIER.match(param["longflag"]):
        problems.append(f"{where}: <longflag> '{param['longflag']}' is not an identifier")
    has_flag = bool(param["flag"]) or bool(param["longflag"])
    if param["index"] is not None:
        if has_flag:
            problems.append(f"{where}: <index> and <flag>/<longflag> are mutually exclusive")
        if not isinstance(param["index"], int) or param["index"] < 0:
            problems.append(f"{where}: <index> '{param['index']}' is not an integer >= 0")
        if tag in ("point", "region"):
            problems.append(f"{where}: a <{tag}> cannot be an index parameter")
    if param["flag"] and not param["longflag"]:
        problems.append(f"{where}: flagged parameter has no <longflag>")
    if param["longflag"] in RESERVED_LONGFLAGS or param["flag"] in RESERVED_FLAGS:
        problems.append(f"{where}: flag collides with an argument GenerateCLP/TCLAP adds")

    channel = param["channel"]
    if channel is not None and channel not in ("input", "output"):
        problems.append(f"{where}: <channel> '{channel}' is not input or output")
    if tag in FILE_LIKE_TAGS and channel not in ("input", "output"):
        problems.append(f"{where}: a <{tag}> needs <channel>input</channel> or output")
    if not has_flag and param["index"] is None and not param["is_return"]:
        problems.append(f"{where}: no flag, longflag or index, and not a return "
                        "parameter (channel output): it can never be set")
    if param["is_return"] and (tag in FILE_LIKE_TAGS or tag in ("directory", "point", "region")):
        problems.append(f"{where}: a <{tag}> output needs a flag or an index; "
                        "return parameters are scalars, vectors or enumerations")

    if node.attrs.get("coordinateSystem") == "ijk":
        problems.append(f"{where}: coordinateSystem=\"ijk\" parses, but Slicer logs it as "
                        "invalid and sends LPS")
    if tag in ("point", "region", "pointfile") and "coordinateSystem" not in node.attrs:
        problems.append(f"{where}: coordinateSystem is not declared (project rule; "
                        "Slicer sends LPS when it is absent)")

    if tag in ENUMERATION_TAGS:
        if not param["elements"]:
            problems.append(f"{where}: enumeration without <element>s")
        for element in param["elements"]:
            _check_value(tag, element, f"{where} <element>", problems)
        if param["default"] is not None and param["default"] not in param["elements"]:
            problems.append(f"{where}: <default> '{param['default']}' is not one of the "
                            f"<element>s {param['elements']}")
    elif param["elements"]:
        problems.append(f"{where}: <element> is only allowed in enumerations")

    if param["default"] is not None:
        _check_value(tag, param["default"], f"{where} <default>", problems)

    constraints = node.child("constraints")
    if constraints is not None:
        if tag not in SCALAR_NUMBER_TAGS:
            problems.append(f"{where}: <constraints> only apply to integer, float, double")
        bounds = {}
        for bound in ("minimum", "maximum", "step"):
            text = constraints.child_text(bound)
            if text is None:
                continue
            if not _is_number(text, False):
                problems.append(f"{where}: <{bound}> '{text}' is not a number")
            else:
                bounds[bound] = float(text)
        if "minimum" in bounds and "maximum" in bounds and bounds["minimum"] > bounds["maximum"]:
            problems.append(f"{where}: <minimum> is greater than <maximum>")
        default = param["default"]
        if default is not None and _is_number(default, False):
            value = float(default)
            if value < bounds.get("minimum", value) or value > bounds.get("maximum", value):
                problems.append(f"{where}: <default> {default} lies outside the constraints")
    return param


def check_module_xml(raw):
    """Check a module description the way SEM's parser (plus project rules) does.

    raw: the XML text (str), e.g. the stdout of `EXE --xml`.
    Returns (params, problems): params lists one dict per parameter in
    document order (tag, name, flag, longflag, index, channel, multiple,
    coordinateSystem, default, is_return, type, fileExtensions, plus elements
    and line); problems lists human-readable rule violations (empty = OK).
    """
    problems = []
    if not raw.startswith("<?xml "):
        problems.append("the document does not start with '<?xml ' at byte 0 "
                        "(SEM does strncmp(xml, \"<?xml \", 6))")
    try:
        root = _parse_tree(raw.lstrip())
    except xml.parsers.expat.ExpatError as error:
        problems.append(f"not well-formed XML: {error}")
        return [], problems

    if root.tag != "executable":
        problems.append(f"the root element is <{root.tag}>, not <executable>")
        return [], problems

    params = []
    for node in root.children:
        if node.tag not in MODULE_ELEMENTS:
            problems.append(f"line {node.line}: unrecognized element <{node.tag}> "
                            "inside <executable>")
            continue
        if node.tag != "parameters":
            if node.children:
                problems.append(f"line {node.line}: <{node.tag}> must not contain elements")
            continue
        if set(node.attrs) - {"advanced"}:
            problems.append(f"line {node.line}: <parameters> accepts only the attribute "
                            "advanced (the parser ignores it when anything else is present)")
        if node.attrs.get("advanced", "false") not in ("true", "false"):
            problems.append(f"line {node.line}: advanced=\"{node.attrs['advanced']}\" "
                            "is not true or false")
        if not (node.child_text("label") or ""):
            problems.append(f"line {node.line}: <parameters> has no <label>")
        for child in node.children:
            if child.tag in GROUP_CHILDREN:
                continue
            if child.tag in PARAMETER_ATTRIBUTES:
                params.append(_check_parameter(child, problems))
            elif child.tag in REJECTED_TAGS:
                problems.append(f"line {child.line}: <{child.tag}> is in the XSD but the "
                                "parser rejects it")
            else:
                problems.append(f"line {child.line}: unrecognized element <{child.tag}> "
                                "inside <parameters>")
    if not any(node.tag == "parameters" for node in root.children):
        problems.append("no <parameters> group")
    for required in ("title", "version"):
        if not (root.child_text(required) or ""):
            problems.append(f"<executable> has no <{required}>")

    for key, label in (("name", "name"), ("flag", "flag"), ("longflag", "longflag")):
        seen = {}
        for param in params:
            value = param[key]
            if not value:
                continue
            if value in seen:
                problems.append(f"duplicate {label} '{value}' (lines {seen[value]} and "
                                f"{param['line']})")
            else:
                seen[value] = param["line"]

    indexed = [p for p in params if isinstance(p["index"], int)]
    indices = [p["index"] for p in indexed]
    if len(set(indices)) != len(indices):
        problems.append(f"duplicate <index> values {indices}")
    elif indices != sorted(indices):
        problems.append(f"<index> order {indices} differs from document order: GenerateCLP "
                        "declares positional arguments in document order, Slicer passes "
                        "them in index order")
    return params, problems


def module_info(raw):
    """Module-level text elements (title, version, ...) of a module description."""
    root = _parse_tree(raw.lstrip())
    return {node.tag: node.text.strip() for node in root.children
            if node.tag in MODULE_ELEMENTS and node.tag != "parameters"}


# --------------------------------------------------------------------------
# Command line (conventions 2.2 and 2.4)
# --------------------------------------------------------------------------

def slicer_return_parameter_file(directory):
    """A path like Slicer's: <tmp>/<pid>_<10 random [0-9A-Za-z]>.params."""
    alphabet = string.digits + string.ascii_letters
    token = "".join(random.SystemRandom().choice(alphabet) for _ in range(10))
    return os.path.join(directory, f"{os.getpid()}_{token}.params")


def _format_number(value):
    # std::ostream default precision: 6 significant digits, like printf %g.
    return "%g" % float(value)


def _point_text(point, coordinate_system):
    """One point as Slicer writes it; `point` holds the node's RAS coordinates."""
    x, y, z = (float(v) for v in point[:3])
    if coordinate_system != "ras":
        # "lps", absent or empty (and the unsupported "ijk"): Slicer negates x, y.
        x, y = -x, -y
    rest = [float(v) for v in point[3:]]
    return ",".join(_format_number(v) for v in [x, y, z] + rest)


def _value_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return ",".join(_value_text(v) for v in value)
    return str(value)


def slicer_argv(exe, params, values, retfile):
    """The argv vtkSlicerCLIModuleLogic builds for an executable CLI.

    exe: path of the executable. params: from check_module_xml.
    values: parameter name -> value, as the Slicer parameter node would hold
    it; parameters not given take their XML <default> (Slicer initialises the
    node from the XML), except node-type parameters (image, file, ...), which
    are passed only when given. Points are given in RAS (the markups node's
    own coordinates) as [x, y, z] or, with multiple="true", a list of those;
    a string is passed unchanged. retfile: the return-parameter file path,
    used only when the module has return parameters.
    """
    argv = [exe]
    if any(p["is_return"] for p in params):
        argv += ["--returnparameterfile", retfile]

    for param in params:
        if param["is_return"] or not (param["flag"] or param["longflag"]):
            continue
        tag, name = param["tag"], param["name"]
        flag = "--" + param["longflag"] if param["longflag"] else "-" + param["flag"]
        given = name in values
        value = values[name] if given else param["default"]
        if tag == "boolean":
            if value is True or value == "true":
                argv.append(flag)
        elif tag in ("point", "region"):
            if not given or value is None:
                continue
            if isinstance(value, str):
                argv += [flag, value]
                continue
            points = value if value and isinstance(value[0], (list, tuple)) else [value]
            if not param["multiple"]:
                points = points[:1]
            for point in points:
                argv += [flag, _point_text(point, param["coordinateSystem"])]
        elif tag in NODE_TAGS:
            if given and value:
                items = value if param["multiple"] and isinstance(value, (list, tuple)) else [value]
                for item in items:
                    argv += [flag, str(item)]
        elif tag in SCALAR_NUMBER_TAGS or tag in ENUMERATION_TAGS:
            if value is not None and _value_text(value) != "":
                if param["multiple"] and isinstance(value, (list, tuple)):
                    for item in value:
                        argv += [flag, _value_text(item)]
                else:
                    argv += [flag, _value_text(value)]
        else:  # file, directory, string, *-vector: only when non-empty
            if value is not None and _value_text(value) != "":
                if param["multiple"] and tag in ("file", "directory", "string") \
                        and isinstance(value, (list, tuple)):
                    for item in value:
                        argv += [flag, str(item)]
                else:
                    argv += [flag, _value_text(value)]

    indexed = sorted((p for p in params if isinstance(p["index"], int)),
                     key=lambda p: p["index"])
    for param in indexed:
        value = values.get(param["name"])
        if value is None and param["tag"] not in FILE_LIKE_TAGS:
            value = param["default"]
        if value is None or _value_text(value) == "":
            raise ValueError(f"No input data assigned to \"{param['name']}\"")
        argv.append(_value_text(value))
    return argv


# --------------------------------------------------------------------------
# Progress reporting on stdout (conventions 2.7)
# --------------------------------------------------------------------------

STRIPPED_TAGS = ("filter-progress", "filter-stage-progress", "filter-name",
                 "filter-comment", "filter-time", "filter-start", "filter-end")
_TOKEN = re.compile(r"<(filter-progress|filter-stage-progress)>([^<]*)</\1>"
                    r"|<filter-start>(.*?)</filter-start>"
                    r"|<filter-end>(.*?)</filter-end>", re.S)


def _inner(block, tag):
    match = re.search(rf"<{tag}>([^<]*)</{tag}>", block)
    return None if match is None else match.group(1)


def _atof(text):
    match = re.match(r"\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", text)
    return float(match.group(0)) if match else 0.0


def parse_progress(stdout):
    """Parse a CLI's stdout like Slicer does.

    Returns a dict with:
      progress: the <filter-progress> values in order (parsed like atof);
      stage_progress: the <filter-stage-progress> values;
      stages: [{name, comment}] for each <filter-start> block (comment without
              the surrounding spaces and quotes);
      ends: [{name, time}] for each <filter-end> block (time None if absent);
      events: ("progress", v) / ("start", name) / ("end", name) in order;
      stripped: stdout after Slicer's RemoveProgressInfoFromProcessOutput;
      leftover: the "<filter-..." fragments still present after stripping.
    """
    result = {"progress": [], "stage_progress": [], "stages": [], "ends": [], "events": []}
    for match in _TOKEN.finditer(stdout):
        if match.group(1):
            value = _atof(match.group(2))
            key = "progress" if match.group(1) == "filter-progress" else "stage_progress"
            result[key].append(value)
            if key == "progress":
                result["events"].append(("progress", value))
        elif match.group(3) is not None:
            block = match.group(3)
            name = (_inner(block, "filter-name") or "").strip()
            comment = (_inner(block, "filter-comment") or "").strip().strip('"').strip()
            result["stages"].append({"name": name, "comment": comment})
            result["events"].append(("start", name))
        else:
            block = match.group(4)
            name = (_inner(block, "filter-name") or "").strip()
            time_text = _inner(block, "filter-time")
            time = None if time_text is None else _atof(time_text)
            result["ends"].append({"name": name, "time": time})
            result["events"].append(("end", name))

    stripped = stdout
    for tag in STRIPPED_TAGS:
        stripped = re.sub(rf"<{tag}>[^<]*</{tag}>[ \t\n\r]*", "", stripped)
    result["stripped"] = stripped
    result["leftover"] = re.findall(r"</?filter-[^\s>]*>?", stripped)
    return result


# --------------------------------------------------------------------------
# Return-parameter file (conventions 2.5)
# --------------------------------------------------------------------------

def read_return_parameters(path):
    """name -> value (strings) from a `name = value` file; split at the first '='."""
    values = {}
    with open(path, encoding="utf-8") as handle:
        for line in handle:
            line = line.rstrip("\r\n")
            if "=" not in line:
                continue
            key, value = line.split("=", 1)
            key = key.strip(" \t")
            if key:
                values[key] = value.strip(" \t")
    return values


# --------------------------------------------------------------------------
# NRRD (what ITK's NrrdImageIO writes)
# --------------------------------------------------------------------------

_NRRD_TYPES = {
    np.int8: ("signed char", "int8", "int8_t"),
    np.uint8: ("uchar", "unsigned char", "uint8", "uint8_t"),
    np.int16: ("short", "short int", "signed short", "signed short int", "int16", "int16_t"),
    np.uint16: ("ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"),
    np.int32: ("int", "signed int", "int32", "int32_t"),
    np.uint32: ("uint", "unsigned int", "uint32", "uint32_t"),
    np.int64: ("longlong", "long long", "long long int", "signed long long",
               "signed long long int", "int64", "int64_t"),
    np.uint64: ("ulonglong", "unsigned long long", "unsigned long long int",
                "uint64", "uint64_t"),
    np.float32: ("float",),
    np.float64: ("double",),
}
NRRD_DTYPES = {name: dtype for dtype, names in _NRRD_TYPES.items() for name in names}


def _vector(text):
    text = text.strip()
    if text == "none":
        return None
    return [float(v) for v in text.strip("()").split(",")]


def read_nrrd(path):
    """Read an attached-header NRRD file.

    Returns (array, header). The array is indexed [k, j, i]: the file's
    fastest axis comes last (so a leading component axis, as in a vector
    image, becomes the last array axis). header holds the raw fields (lower-case keys) and the
    parsed geometry: 'sizes' (list of int, file order i, j, k), 'spacing'
    (per axis, mm), 'origin' (list or None), 'directions' (rows are the
    'space directions' vectors in mm, or None).
    """
    with open(path, "rb") as handle:
        content = handle.read()
    if not content.startswith(b"NRRD000"):
        raise ValueError(f"{path}: not a NRRD file (no NRRD000x magic)")
    header = {}
    position = 0
    lines = []
    while True:
        end = content.find(b"\n", position)
        if end < 0:
            raise ValueError(f"{path}: header does not end with an empty line")
        line = content[position:end].decode("latin-1").rstrip("\r")
        position = end + 1
        if line == "":
            break
        lines.append(line)
    header["magic"] = lines[0]
    for line in lines[1:]:
        if line.startswith("#"):
            continue
        if ":=" in line:
            key, value = line.split(":=", 1)
            header[key.strip()] = value
        elif ": " in line:
            key, value = line.split(": ", 1)
            header[key.strip().lower()] = value.strip()
    if "data file" in header or "datafile" in header:
        raise ValueError(f"{path}: detached data files are not supported")

    dtype = NRRD_DTYPES.get(header["type"].strip())
    if dtype is None:
        raise ValueError(f"{path}: unsupported type '{header['type']}'")
    dtype = np.dtype(dtype)
    endian = header.get("endian", "little")
    if dtype.itemsize > 1:
        dtype = dtype.newbyteorder("<" if endian == "little" else ">")
    sizes = [int(v) for v in header["sizes"].split()]
    if len(sizes) != int(header["dimension"]):
        raise ValueError(f"{path}: 'sizes' does not match 'dimension'")

    data = content[position:]
    encoding = header.get("encoding", "raw")
    if encoding == "raw":
        pass
    elif encoding in ("gzip", "gz"):
        data = gzip.decompress(data)
    elif encoding in ("bzip2", "bz2"):
        data = bz2.decompress(data)
    else:
        raise ValueError(f"{path}: unsupported encoding '{encoding}'")
    count = int(np.prod(sizes))
    needed = count * dtype.itemsize
    if len(data) < needed:
        raise ValueError(f"{path}: {len(data)} bytes of data, {needed} expected")
    if "byte skip" in header and encoding == "raw":
        skip = int(header["byte skip"])
        data = data[-needed:] if skip == -1 else data[skip:]
    array = np.frombuffer(data[:needed], dtype=dtype).reshape(sizes[::-1])
    array = array.astype(dtype.newbyteorder("="))

    header["sizes"] = sizes
    directions = None
    if "space directions" in header:
        vectors = re.findall(r"\([^)]*\)|none", header["space directions"])
        parsed = [_vector(v) for v in vectors]
        directions = [v for v in parsed if v is not None]
    header["directions"] = directions
    if directions:
        header["spacing"] = [float(np.linalg.norm(v)) for v in directions]
    elif "spacings" in header:
        header["spacing"] = [float(v) for v in header["spacings"].split() if v != "nan"]
    else:
        header["spacing"] = [1.0] * len(sizes)
    header["origin"] = _vector(header["space origin"]) if "space origin" in header else None
    return array, header
