#!/usr/bin/python3
"""The scripted module and the CLIs' XML agree (the XML is the single source of truth).

Usage: check_cli_contract.py MODULE_DIR StentGraftSimulation.xml SyntheticAorticPhantom.xml

- every parameter the module sends to StentGraftSimulation is declared, with an XML type that
  carries what is sent (a node role's node class, a string, a comma list, a file path), and the
  points declare coordinateSystem="ras" (the markups' own coordinates);
- every CLI setting's default equals the XML <default>, and an enumeration offers the same values;
- every return value the module reads is an XML return parameter (channel output, no flag);
- every parameter StentGraftPlannerTest passes to SyntheticAorticPhantom, and its seedRas return,
  is declared there.
A planted defect (an undeclared name) must be rejected too. Exit code 0 when all pass.
"""
import ast
import os
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
            }
    return parameters


def sentParameterProblems(Settings, declared):
    """Problems of the dictionary the module builds with every optional input given."""
    nodes = {role.name: role for role in Settings.NODE_ROLES}
    settings = dict(Settings.defaultSettings(), deviceCatalogPath="/x/devices.json")
    sent = Settings.buildCliParameters(settings, nodes, {"seed": 1, "lowestRenalOstium": 1}, "/x/report.json")
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
        elif name in ("outputReport", "deviceCatalog"):
            channel = "output" if name == "outputReport" else "input"
            if tag != "file" or parameter["channel"] != channel:
                problems.append("%s must be a <file> with channel %s (a path passed unchanged)" % (name, channel))
        elif name == "proximalOversizingRange":
            if tag not in ("float-vector", "double-vector"):
                problems.append("proximalOversizingRange is a <%s>, expected a float-vector (\"10,20\")" % tag)
        elif name == "device":
            if tag != "string":
                problems.append("device is a <%s>, expected a <string> (\"auto\", \"Family\", \"Family:diameter\")" % tag)
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


def returnValueProblems(Results, declared):
    problems = []
    for item in Results.RETURN_VALUES:
        parameter = declared.get(item.name)
        if parameter is None or parameter["channel"] != "output" or parameter["flagged"]:
            problems.append("the module reads the return parameter %s, which the XML does not declare as one "
                            "(channel output, no flag, longflag or index)" % item.name)
            continue
        wanted = ("string",) if item.kind == "str" else ("float", "double")
        if parameter["tag"] not in wanted:
            problems.append("return parameter %s is a <%s>, expected %s" % (item.name, parameter["tag"], " or ".join(wanted)))
    return problems


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
    sys.path.insert(0, moduleDir)
    from StentGraftPlannerLib import Results, Settings

    declared = xmlParameters(simulationXml)
    with open(os.path.join(moduleDir, "StentGraftPlanner.py")) as f:
        moduleSource = f.read()
    checks = [
        ("parameters sent to StentGraftSimulation are declared with fitting types", sentParameterProblems(Settings, declared)),
        ("CLI setting defaults equal the XML defaults", settingDefaultProblems(Settings, declared)),
        ("return values read are XML return parameters", returnValueProblems(Results, declared)),
        ("the self-test's phantom parameters are declared", phantomProblems(moduleSource, xmlParameters(phantomXml))),
    ]
    planted = dict(declared)
    planted.pop("seed")
    checks.append(("planted defect, an undeclared seed, is rejected",
                   [] if sentParameterProblems(Settings, planted) else ["not rejected"]))
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
