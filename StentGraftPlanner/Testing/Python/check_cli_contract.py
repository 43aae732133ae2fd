#!/usr/bin/python3
"""The scripted module and the CLIs' XML agree (the XML is the single source of truth).

Usage: check_cli_contract.py MODULE_DIR StentGraftSimulation.xml SyntheticAorticPhantom.xml

- every parameter the module sends to StentGraftSimulation is declared, with an XML type that
  carries what is sent (a node role's node class, a string, a comma list, a file path), and the
  points declare coordinateSystem="ras" (the markups' own coordinates);
- every CLI setting's default equals the XML <default>, and an enumeration offers the same values;
- every CLI number setting's widget in the .ui offers only values the CLI accepts: its range lies
  within the XML's <constraints>, and equals it where the widget's decimals can show the bounds;
- every float setting is sent as text, not as a Python float (slicer.cli would pass it through
  SetParameterAsDouble, which keeps six significant digits);
- every return value the module reads is an XML return parameter (channel output, no flag), and it
  reads the CLI's "not measured" text (-1, none) as missing exactly where the XML's description
  leaves no other reading: -1 where the description says "-1 when ..." or the quantity cannot be
  negative (in mm, in degrees, a tortuosity ratio), not where it is signed (in percent, in HU);
  "none" where the description does not offer none as a value; its display unit is the XML's; a
  diameter is labelled with the wall its description names (outer wall, lumen, or neither for a
  device size); an XML <boolean> is read as a verdict, with no "not measured" text;
- every point-data array the module colours a model by is named in that output's XML description,
  and the simulated graft's ComponentRole codes and their words are the XML's (Appearance);
- the module's dependencies name none of the extension's CLIs (Slicer's generic module tests run
  with --disable-cli-modules, and a module whose dependency is not loaded is not loaded at all);
- every parameter StentGraftPlannerTest passes to SyntheticAorticPhantom, and its seedRas return,
  is declared there.
A planted defect (an undeclared name) must be rejected too. Exit code 0 when all pass.
"""
import ast
import os
import re
import sys
import xml.etree.ElementTree as ET

NODE_TAGS = {
    "vtkMRMLScalarVolumeNode": ("image", None),
    "vtkMRMLLabelMapVolumeNode": ("image", "label"),
    "vtkMRMLModelNode": ("geometry", None),
    "vtkMRMLTableNode": ("table", None),
}


def xmlParameters(path):
    """name -> dict(tag, attributes, default, channel, flagged, elements) of a SEM XML file."""
    parameters = {}
    for group in ET.parse(path).getroot().iter("parameters"):
        for element in group:
            if element.tag in ("label", "description"):
                continue
            name = element.findtext("name") or element.findtext("longflag")
            parameters[name] = {
                "tag": element.tag,
                "attributes": element.attrib,
                "default": element.findtext("default"),
                "channel": element.findtext("channel"),
                "flagged": any(element.find(t) is not None for t in ("flag", "longflag", "index")),
                "elements": [e.text for e in element.findall("element")],
                "description": " ".join((element.findtext("description") or "").split()),
                "minimum": element.findtext("constraints/minimum"),
                "maximum": element.findtext("constraints/maximum"),
            }
    return parameters


def sentParameterProblems(Settings, declared):
    """Problems of the dictionary the module builds with every optional input given."""
    nodes = {role.name: role for role in Settings.NODE_ROLES}
    settings = dict(Settings.defaultSettings(), deviceCatalogPath="/x/devices.json", neckRulesPath="/x/rules.json")
    sent = Settings.buildCliParameters(settings, nodes, {name: 1 for name in Settings.POINT_ROLES}, "/x/report.json")
    problems = []
    for name, value in sent.items():
        parameter = declared.get(name)
        if parameter is None:
            problems.append("the module sends %s, which StentGraftSimulation.xml does not declare" % name)
            continue
        tag, attributes = parameter["tag"], parameter["attributes"]
        if isinstance(value, Settings.NodeRole):
            if value.nodeClass == "vtkMRMLMarkupsFiducialNode":
                expected = ("pointfile",) if value.channel == "output" else ("point",)
                if tag not in expected:
                    problems.append("%s is a <%s>, expected <%s> for a markups node" % (name, tag, expected[0]))
                elif tag == "point" and attributes.get("coordinateSystem") != "ras":
                    problems.append("%s must declare coordinateSystem=\"ras\" (Slicer sends LPS otherwise)" % name)
            else:
                wantTag, wantType = NODE_TAGS[value.nodeClass]
                if tag != wantTag and not (wantTag == "table" and tag == "measurement"):
                    problems.append("%s is a <%s>, expected <%s> for a %s" % (name, tag, wantTag, value.nodeClass))
                elif wantType and attributes.get("type") != wantType:
                    problems.append("%s must have type=\"%s\" for a %s" % (name, wantType, value.nodeClass))
            if (parameter["channel"] or "input") != value.channel:
                problems.append("%s has channel %s, the module treats it as %s" % (name, parameter["channel"], value.channel))
        elif name == "outputReport" or name in dict(Settings.FILE_PARAMETERS):
            channel = "output" if name == "outputReport" else "input"
            if tag != "file" or parameter["channel"] != channel:
                problems.append("%s must be a <file> with channel %s (a path passed unchanged)" % (name, channel))
        elif name == "proximalOversizingRange":
            if tag not in ("float-vector", "double-vector"):
                problems.append("proximalOversizingRange is a <%s>, expected a float-vector (\"10,20\")" % tag)
        elif name == "device":
            if tag != "string":
                problems.append("device is a <%s>, expected a <string> (\"auto\", \"Family\", \"Family:diameter\")" % tag)
        if isinstance(value, float):
            problems.append("%s is sent as a Python float: slicer.cli formats it with six significant digits; "
                            "send Settings.formatNumber(value)" % name)
    return problems


def settingDefaultProblems(Settings, declared):
    problems = []
    for setting in Settings.SETTINGS:
        parameter = declared.get(setting.name) if setting.cli else None
        if parameter is None:
            continue  # an undeclared CLI setting is reported by sentParameterProblems
        default = parameter["default"]
        if setting.kind in ("float", "int"):
            same = default is not None and float(default) == setting.default
        else:
            same = default == setting.default
        if not same:
            problems.append("%s: the module's default %r differs from the XML's %r" % (setting.name, setting.default, default))
        if setting.kind == "enum" and parameter["elements"] != list(setting.choices):
            problems.append("%s: the module offers %s, the XML %s" % (setting.name, list(setting.choices), parameter["elements"]))
    return problems


def widgetRangeProblems(Settings, declared, uiText):
    """A CLI number setting's widget must not offer a value the CLI rejects, nor hide one it accepts
    where the widget's precision could show it (e.g. deploymentOffsetMm: -30 to 60 mm)."""
    from check_slicer_module import propertyValue, uiWidgets

    widgets = uiWidgets(uiText)[2]
    problems = []
    for setting in Settings.SETTINGS:
        parameter = declared.get(setting.name) if setting.cli else None
        widget = widgets.get(setting.widget)
        if parameter is None or widget is None or setting.kind not in ("float", "int"):
            continue  # undeclared settings and missing widgets are reported by the other checks
        decimals = int(propertyValue(widget, "decimals") or (2 if setting.kind == "float" else 0))
        for bound, qtDefault, inside in (("minimum", 0.0, lambda w, x: w >= x), ("maximum", 99.0, lambda w, x: w <= x)):
            xmlText = parameter[bound]
            if xmlText is None:
                continue
            xmlValue = float(xmlText)
            widgetValue = float(propertyValue(widget, bound) or qtDefault)
            showable = round(xmlValue, decimals) == xmlValue
            if not inside(widgetValue, xmlValue) or (showable and widgetValue != xmlValue):
                problems.append("%s: the widget's %s is %g, the XML's %s of %s is %s"
                                % (setting.widget, bound, widgetValue, bound, setting.name, xmlText))
    return problems


def appearanceProblems(Appearance, declared):
    """The arrays the module colours models by are the CLI's, and ComponentRole's codes are the XML's."""
    problems = []
    for role, look in Appearance.LOOKS.items():
        if look.scalars and role in declared and not re.search(r"\b%s\b" % re.escape(look.scalars),
                                                               declared[role]["description"]):
            problems.append("%s is coloured by %s, which its XML description does not name" % (role, look.scalars))
    description = (declared.get("outputSimulatedStentModel") or {}).get("description", "")
    match = re.search(r"ComponentRole \(([^)]*)\)", description)
    if match is None:
        return problems + ["the XML's outputSimulatedStentModel names no 'ComponentRole (0 ..., 1 ...)' codes"]
    codes = [tuple(item.strip().split(" ", 1)) for item in match.group(1).split(",")]
    expected = [(str(index), role.name) for index, role in enumerate(Appearance.COMPONENT_ROLES)]
    if codes != expected:
        problems.append("ComponentRole codes: the XML gives %s, Appearance.COMPONENT_ROLES %s" % (codes, expected))
    return problems


#: Phrases of an XML return value's description that say -1 cannot be a value (the quantity cannot
#: be negative), with the display unit they imply ("" for a ratio).
NON_NEGATIVE_PHRASES = (("in mm", "mm"), ("in degrees", "deg"), ("in mL", "mL"), ("(1 = straight)", ""))
#: Phrases that say the quantity is signed, so that -1 is a value unless the XML says otherwise.
SIGNED_PHRASES = (("in percent", "%"), ("in HU", "HU"))


def expectedMissing(parameter):
    """(missing text, unit or None, problem or None) that the XML description implies for a return value."""
    description = parameter["description"]
    if parameter["tag"] == "boolean":
        return None, None, None  # true or false; an unreadable text is "not determined", not a value
    if parameter["tag"] == "string":
        # "none" is a value where the description offers it ("... or none when ..."), else "not had".
        return (None if re.search(r"\bnone\b", description) else "none"), None, None
    unit = None
    for phrase, phraseUnit in NON_NEGATIVE_PHRASES + SIGNED_PHRASES:
        if phrase in description:
            unit = phraseUnit if unit is None else unit
    if re.search(r"(^|[\s;(])-1 when\b", description):
        return "-1", unit, None
    if any(phrase in description for phrase, _ in NON_NEGATIVE_PHRASES):
        return "-1", unit, None
    if any(phrase in description for phrase, _ in SIGNED_PHRASES):
        return None, unit, None
    return None, None, ("cannot tell from the XML description whether -1 can be a value: %r; say \"-1 when ...\" "
                        "or give the unit, or extend NON_NEGATIVE_PHRASES/SIGNED_PHRASES" % description)


def expectedWall(name, parameter):
    """The wall a return value's description names: Results.OUTER_WALL for an outer-wall diameter,
    Results.LUMEN for a lumen diameter, "" for anything else (lengths, volumes, device sizes)."""
    description = parameter["description"]
    if "Diameter" not in name:
        return ""
    if re.search(r"outer[- ]wall", description):
        return "outer"
    if "lumen diameter" in description:
        return "lumen"
    return ""


def returnValueProblems(Results, declared, returnValues=None):
    problems = []
    for item in Results.RETURN_VALUES if returnValues is None else returnValues:
        parameter = declared.get(item.name)
        if parameter is None or parameter["channel"] != "output" or parameter["flagged"]:
            problems.append("the module reads the return parameter %s, which the XML does not declare as one "
                            "(channel output, no flag, longflag or index)" % item.name)
            continue
        wanted = {"str": ("string",), "bool": ("boolean",)}.get(item.kind, ("float", "double"))
        if parameter["tag"] not in wanted:
            problems.append("return parameter %s is a <%s>, expected %s" % (item.name, parameter["tag"], " or ".join(wanted)))
            continue
        missing, unit, problem = expectedMissing(parameter)
        if problem:
            problems.append("%s: %s" % (item.name, problem))
        elif item.missing != missing:
            problems.append("%s: the module reads %s as missing, the XML description implies %s (%r)"
                            % (item.name, _missingText(item.missing), _missingText(missing), parameter["description"]))
        if unit is not None and item.unit != unit:
            problems.append("%s: the module shows it in %r, the XML gives %r" % (item.name, item.unit, unit))
        wall = expectedWall(item.name, parameter)
        if item.wall != wall:
            problems.append("%s: the module labels it with the wall %r, the XML description names %r (%r)"
                            % (item.name, item.wall, wall, parameter["description"]))
    return problems


def _missingText(missing):
    return "no text" if missing is None else repr(missing)


def computedValueProblems(Results):
    """A computed value's operands, and a verdict's quantities, are read values that can be missing
    themselves."""
    names = {item.name: item for item in Results.RETURN_VALUES}
    problems = []
    for name, operands in Results.COMPUTED_FROM.items():
        for operand in (name,) + tuple(operands):
            if operand not in names:
                problems.append("COMPUTED_FROM names %s, which the module does not read" % operand)
        if name in names and names[name].missing is not None:
            problems.append("%s reads -1 as missing already; COMPUTED_FROM is for signed values" % name)
    for name, quantities in Results.DECIDED_FROM.items():
        for quantity in (name,) + tuple(quantities):
            if quantity not in names:
                problems.append("DECIDED_FROM names %s, which the module does not read" % quantity)
        if name in names and names[name].kind != "bool":
            problems.append("DECIDED_FROM is for verdicts (XML <boolean>); %s is a %s" % (name, names[name].kind))
    return problems


def moduleDependencies(moduleSource):
    """The list assigned to self.parent.dependencies in StentGraftPlanner.py, or None if there is none."""
    for node in ast.walk(ast.parse(moduleSource)):
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Attribute) and target.attr == "dependencies":
                    return ast.literal_eval(node.value)
    return None


def dependencyProblems(moduleSource, cliNames):
    dependencies = moduleDependencies(moduleSource)
    if dependencies is None:
        return ["StentGraftPlanner.py assigns no self.parent.dependencies list any more; update this check"]
    return ["the module depends on the CLI %s: Slicer's generic module tests run with --disable-cli-modules and "
            "would not load the module; look the CLI up when a run starts instead" % name
            for name in dependencies if name in cliNames]


def phantomProblems(moduleSource, declared):
    """Keys of the dict literal in StentGraftPlannerTest._phantom, and seedRas, against the phantom XML."""
    used = {"seedRas"}
    for node in ast.walk(ast.parse(moduleSource)):
        if isinstance(node, ast.FunctionDef) and node.name == "_phantom":
            for inner in ast.walk(node):
                if isinstance(inner, ast.Dict):
                    used |= {k.value for k in inner.keys if isinstance(k, ast.Constant)}
    if len(used) < 3:
        return ["StentGraftPlannerTest._phantom passes no parameter dictionary any more; update this check"]
    return ["StentGraftPlannerTest uses %s, which SyntheticAorticPhantom.xml does not declare" % name
            for name in sorted(used - set(declared))]


def main(moduleDir, simulationXml, phantomXml):
    # A CLI's module name is its XML file's (and executable's) base name.
    cliNames = {os.path.splitext(os.path.basename(path))[0] for path in (simulationXml, phantomXml)}
    sys.path.insert(0, moduleDir)
    from StentGraftPlannerLib import Appearance, Results, Settings

    declared = xmlParameters(simulationXml)
    with open(os.path.join(moduleDir, "StentGraftPlanner.py")) as f:
        moduleSource = f.read()
    with open(os.path.join(moduleDir, "Resources", "UI", "StentGraftPlanner.ui")) as f:
        uiText = f.read()
    checks = [
        ("parameters sent to StentGraftSimulation are declared with fitting types", sentParameterProblems(Settings, declared)),
        ("CLI setting defaults equal the XML defaults", settingDefaultProblems(Settings, declared)),
        ("CLI number widgets offer the XML's range", widgetRangeProblems(Settings, declared, uiText)),
        ("models are coloured by arrays the CLI writes, ComponentRole by the XML's codes",
         appearanceProblems(Appearance, declared)),
        ("return values read are XML return parameters, with 'not measured' read where the XML implies it",
         returnValueProblems(Results, declared)),
        ("computed values name read operands", computedValueProblems(Results)),
        ("the module's dependencies name no CLI", dependencyProblems(moduleSource, cliNames)),
        ("the self-test's phantom parameters are declared", phantomProblems(moduleSource, xmlParameters(phantomXml))),
    ]
    planted = dict(declared)
    planted.pop("seed")
    checks.append(("planted defect, an undeclared seed, is rejected",
                   [] if sentParameterProblems(Settings, planted) else ["not rejected"]))
    formatNumber = Settings.formatNumber
    Settings.formatNumber = float  # the defect of issue 14 item 7: floats handed to slicer.cli as floats
    try:
        floatsSent = sentParameterProblems(Settings, declared)
    finally:
        Settings.formatNumber = formatNumber
    checks.append(("planted defect, float settings sent as Python floats, is rejected",
                   [] if floatsSent else ["not rejected"]))
    byName = {item.name: item for item in Results.RETURN_VALUES}
    plantedValues = {
        "a signed conicity read -1 as missing": byName["neckConicity"]._replace(missing="-1"),
        "a diameter read -1 as a value": byName["rightIliacDiameter"]._replace(missing=None),
        "an angle documented '-1 when' read -1 as a value": byName["neckAngleAlpha"]._replace(missing=None),
        "a device 'none' read as missing": byName["recommendedDevice"]._replace(missing="none"),
        "an outer-wall diameter labelled lumen": byName["proximalNeckDiameter"]._replace(wall="lumen"),
        "a lumen diameter labelled outer wall": byName["leftIliacLumenDiameter"]._replace(wall="outer"),
        "a device size labelled outer wall": byName["mainBodyDiameter"]._replace(wall="outer"),
        "the hostile-neck verdict read as a number": byName["hostileNeck"]._replace(kind="float", missing="-1"),
        "the order list's 'none' (no main body) read as missing": byName["orderList"]._replace(missing="none"),
        "a limb length's -1 (not configured) read as a value": byName["rightLimbLength"]._replace(missing=None),
        "ifuStatus shown in degrees": byName["ifuStatus"]._replace(kind="float", unit="deg"),
    }
    for what, item in plantedValues.items():
        checks.append(("planted defect, %s, is rejected" % what,
                       [] if returnValueProblems(Results, declared, [item]) else ["not rejected"]))
    decided = Results.DECIDED_FROM
    Results.DECIDED_FROM = dict(decided, hostileNeck=decided["hostileNeck"] + ("neckThrombusArcPercent",))
    try:
        checks.append(("planted defect, a verdict decided on a value not read, is rejected",
                       [] if computedValueProblems(Results) else ["not rejected"]))
    finally:
        Results.DECIDED_FROM = decided
    offsetMaximum = "<double>60</double>"
    for what, maximum in (("wider", "<double>100</double>"), ("narrower", "<double>50</double>")):
        what, text = "a deployment offset widget %s than the XML's range" % what, uiText.replace(offsetMaximum, maximum)
        planted = widgetRangeProblems(Settings, declared, text) if text != uiText else []
        checks.append(("planted defect, %s, is rejected" % what, [] if planted else ["not rejected"]))
    roles = Appearance.COMPONENT_ROLES
    Appearance.COMPONENT_ROLES = (roles[1], roles[0]) + roles[2:]
    try:
        checks.append(("planted defect, two component roles swapped, is rejected",
                       [] if appearanceProblems(Appearance, declared) else ["not rejected"]))
    finally:
        Appearance.COMPONENT_ROLES = roles
    looks = Appearance.LOOKS
    Appearance.LOOKS = dict(looks,
                            outputSimulatedStentModel=looks["outputSimulatedStentModel"]._replace(scalars="Role"))
    try:
        checks.append(("planted defect, a model coloured by an array the CLI does not write, is rejected",
                       [] if appearanceProblems(Appearance, declared) else ["not rejected"]))
    finally:
        Appearance.LOOKS = looks
    checks.append(("planted defect, the CLI in the dependencies, is rejected",
                   [] if dependencyProblems(moduleSource.replace("dependencies = []", 'dependencies = ["StentGraftSimulation"]'),
                                            cliNames) else ["not rejected"]))
    failed = 0
    for title, problems in checks:
        print("%s: %s" % ("FAIL" if problems else "PASS", title))
        for problem in problems:
            print("    " + problem)
        failed += bool(problems)
    return failed


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    sys.exit(1 if main(*[os.path.abspath(a) for a in sys.argv[1:]]) else 0)
