#!/usr/bin/python3
"""Checks of the Slicer-only code that need no Slicer.

  check_slicer_module.py compile MODULE_DIR
      StentGraftPlanner.py and StentGraftPlannerLib/*.py compile (py_compile), and pyflakes
      (required: Debian python3-pyflakes; the check fails without it) finds no undefined or unused
      names.
  check_slicer_module.py ui MODULE_DIR
      Every widget StentGraftPlanner.py uses (``self.ui.<name>``) and every settings widget of
      StentGraftPlannerLib.Settings exists in Resources/UI/StentGraftPlanner.ui; settings widgets
      are of a class that holds their kind (a QDoubleSpinBox for a float, ...), hold their default
      within range and at their precision, and a combo box offers exactly an enumeration's values;
      every MRML widget receives the scene from the root widget; the root is a qMRMLWidget.
  check_slicer_module.py calls MODULE_DIR
      StentGraftPlanner.py's Slicer calls outside its self-test (issue 14 items 2 to 4): every CLI
      run starts through StentGraftPlannerLib.CliRun.startCli (no display update; the CLI looked up
      by CliRun.cliModule, never as slicer.modules.stentgraftsimulation), every
      setSliceViewerLayers clears the label layer (label=None), and the scene's StartCloseEvent
      handler reaches PlanningRun.abandon (which test_cli_run.py shows cancels the CLI node and
      removes its observers).

Each check also runs on a planted defect and must reject it, so a check that cannot fail is caught.
Exit code 0 when everything passes.
"""
import ast
import os
import py_compile
import sys
import tempfile
import xml.etree.ElementTree as ET

MODULE = "StentGraftPlanner"


def compileProblems(paths):
    problems = []
    with tempfile.TemporaryDirectory() as scratch:  # byte code goes nowhere near the source tree
        for index, path in enumerate(paths):
            try:
                py_compile.compile(path, cfile=os.path.join(scratch, "%d.pyc" % index), doraise=True)
            except py_compile.PyCompileError as error:
                problems.append(str(error))
    return problems


def pyflakesProblems(paths):
    try:
        from pyflakes import api, reporter
    except ImportError:
        return None
    import io

    out = io.StringIO()
    count = api.checkRecursive(paths, reporter.Reporter(out, out))
    return [line for line in out.getvalue().splitlines() if line.strip()] if count else []


def usedUiNames(source):
    """Names accessed as self.ui.<name> in the module source."""
    names = set()
    for node in ast.walk(ast.parse(source)):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Attribute) and node.value.attr == "ui"
                and isinstance(node.value.value, ast.Name) and node.value.value.id == "self"):
            names.add(node.attr)
    return names


def uiWidgets(uiText):
    """(root class, {name: element}, connections) of a Qt Designer file."""
    root = ET.fromstring(uiText)
    top = root.find("widget")
    widgets = {w.get("name"): w for w in root.iter("widget")}
    connections = [(c.findtext("sender"), c.findtext("signal"), c.findtext("receiver"), c.findtext("slot"))
                   for c in root.iter("connection")]
    return top.get("class"), top.get("name"), widgets, connections


def propertyValue(widget, name):
    for prop in widget.findall("property"):
        if prop.get("name") == name:
            child = list(prop)[0]
            return child.text
    return None


SPIN_CLASSES = {"float": ("QDoubleSpinBox", "ctkDoubleSpinBox", "ctkSliderWidget"), "int": ("QSpinBox",),
                "enum": ("QComboBox", "ctkComboBox"), "str": ("QComboBox", "ctkComboBox", "ctkPathLineEdit", "QLineEdit")}


def settingWidgetProblems(settings, widgets):
    problems = []
    for setting in settings:
        widget = widgets.get(setting.widget)
        if widget is None:
            continue  # reported as a missing name
        cls = widget.get("class")
        if cls not in SPIN_CLASSES[setting.kind]:
            problems.append("%s (%s setting %s) is a %s, expected one of %s"
                            % (setting.widget, setting.kind, setting.name, cls, ", ".join(SPIN_CLASSES[setting.kind])))
            continue
        if setting.kind in ("float", "int"):
            # Qt's defaults when a property is absent: range 0-99, two decimals.
            minimum = float(propertyValue(widget, "minimum") or 0)
            maximum = float(propertyValue(widget, "maximum") or 99)
            value = propertyValue(widget, "value")
            if not minimum <= setting.default <= maximum:
                problems.append("%s: default %r of %s lies outside the widget's range %g-%g"
                                % (setting.widget, setting.default, setting.name, minimum, maximum))
            if value is None or float(value) != setting.default:
                problems.append("%s shows %s, but the default of %s is %r" % (setting.widget, value, setting.name, setting.default))
            if setting.kind == "float":
                decimals = int(propertyValue(widget, "decimals") or 2)
                if round(setting.default, decimals) != setting.default:
                    problems.append("%s has %d decimals, too few for the default %r of %s"
                                    % (setting.widget, decimals, setting.default, setting.name))
        if setting.kind == "enum":
            items = [item.findtext("property/string") for item in widget.findall("item")]
            if items != list(setting.choices):
                problems.append("%s offers %s, but %s allows %s" % (setting.widget, items, setting.name, list(setting.choices)))
    return problems


def uiProblems(source, uiText, settings):
    rootClass, rootName, widgets, connections = uiWidgets(uiText)
    problems = []
    if rootClass != "qMRMLWidget":
        problems.append("the root widget is a %s, expected qMRMLWidget (it hands the scene to its children)" % rootClass)
    used = usedUiNames(source) | {s.widget for s in settings}
    for name in sorted(used - set(widgets)):
        problems.append("the code uses self.ui.%s, which is not a widget in the .ui file" % name)
    problems += settingWidgetProblems(settings, widgets)
    sceneReceivers = {r for s, sig, r, slot in connections
                      if s == rootName and sig == "mrmlSceneChanged(vtkMRMLScene*)" and slot == "setMRMLScene(vtkMRMLScene*)"}
    for name, widget in sorted(widgets.items()):
        if widget.get("class").startswith(("qMRML", "qSlicer")) and name != rootName and name not in sceneReceivers:
            problems.append("%s (%s) never receives the scene: connect mrmlSceneChanged to its setMRMLScene"
                            % (name, widget.get("class")))
    return problems


def dottedName(node):
    """'slicer.cli.run' for the expression slicer.cli.run, '' for anything but names and attributes."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = dottedName(node.value)
        return inner + "." + node.attr if inner else ""
    return ""


def calledNames(function):
    """Last parts of the names a function calls ('abandon' for run.abandon())."""
    return {call.func.attr if isinstance(call.func, ast.Attribute) else dottedName(call.func)
            for call in ast.walk(function) if isinstance(call, ast.Call)}


def slicerCallProblems(source):
    tree = ast.parse(source)
    classes = [node for node in tree.body if isinstance(node, ast.ClassDef)]
    # The self-test runs other CLIs (the phantom) its own way; the panel's code is everything else.
    code = [node for node in tree.body if not (isinstance(node, ast.ClassDef) and node.name.endswith("Test"))]
    methods = {}
    for cls in classes:
        if not cls.name.endswith("Test"):
            for item in cls.body:
                if isinstance(item, ast.FunctionDef):
                    methods.setdefault(item.name, []).append(item)
    problems = []
    handlers = []
    for node in (inner for top in code for inner in ast.walk(top)):
        name = dottedName(node.func) if isinstance(node, ast.Call) else ""
        if name in ("slicer.cli.run", "slicer.cli.runSync", "slicer.cli.runAsync"):
            problems.append("line %d calls %s: start the CLI through CliRun.startCli (update_display=False, "
                            "the CLI looked up when the run starts)" % (node.lineno, name))
        elif name.endswith("setSliceViewerLayers"):
            label = [k.value for k in node.keywords if k.arg == "label"]
            if not (label and isinstance(label[0], ast.Constant) and label[0].value is None):
                problems.append("line %d: setSliceViewerLayers without label=None keeps the lumen label map on "
                                "every slice view's label layer" % node.lineno)
        elif name.endswith("addObserver") and any(dottedName(a).endswith("StartCloseEvent") for a in node.args):
            handlers += [dottedName(a).split(".")[-1] for a in node.args[2:3]]
        if isinstance(node, ast.Attribute) and dottedName(node) == "slicer.modules.stentgraftsimulation":
            problems.append("line %d names slicer.modules.stentgraftsimulation: look it up with CliRun.cliModule, "
                            "which says what to do when the CLI is not loaded" % node.lineno)
    if not handlers:
        problems.append("no StartCloseEvent observer of the scene: a run in flight outlives the scene")
    for handler in handlers:
        reached, pending = set(), [handler]
        while pending:  # the names the handler calls, through the module's own methods
            name = pending.pop()
            for function in methods.get(name, []):
                for called in calledNames(function) - reached:
                    reached.add(called)
                    pending.append(called)
        if handler not in methods:
            problems.append("the StartCloseEvent handler %s is not a method of the module" % handler)
        elif "abandon" not in reached:
            problems.append("the StartCloseEvent handler %s never reaches PlanningRun.abandon: the CLI keeps running "
                            "and writes into the closed scene's nodes" % handler)
    return problems


def runCalls(moduleDir):
    with open(os.path.join(moduleDir, MODULE + ".py")) as f:
        source = f.read()
    ok = report("CLI runs go through CliRun.startCli, the label layer is cleared, scene close abandons the run",
                slicerCallProblems(source))
    planted = {
        "a direct slicer.cli.run": ("CliRun.startCli(slicer.cli, slicer.modules, parameters, waitForCompletion=False)",
                                    "slicer.cli.run(slicer.modules.stentgraftsimulation, None, parameters)"),
        "setSliceViewerLayers keeping the label layer": ("background=inputVolume, label=None)", "background=inputVolume)"),
        "a scene close that leaves the run going": ("self._abandonRun(\"The planning run was cancelled: the scene was closed.\")",
                                                   "pass"),
    }
    for what, (old, new) in planted.items():
        if source.count(old) != 1:
            ok &= report("planted defect, %s, can be planted" % what, ["%r is not in %s.py once; update this check" % (old, MODULE)])
            continue
        problems = slicerCallProblems(source.replace(old, new))
        ok &= report("planted defect, %s, is rejected" % what, [] if problems else ["not rejected"])
    return ok


def report(title, problems):
    print("%s: %s" % ("PASS" if not problems else "FAIL", title))
    for problem in problems:
        print("    " + problem)
    return not problems


def runCompile(moduleDir):
    paths = [os.path.join(moduleDir, MODULE + ".py")]
    libDir = os.path.join(moduleDir, MODULE + "Lib")
    paths += sorted(os.path.join(libDir, f) for f in os.listdir(libDir) if f.endswith(".py"))
    ok = report("%d files compile" % len(paths), compileProblems(paths))
    flakes = pyflakesProblems(paths)
    if flakes is None:
        # scripts/common.sh installs it; a check that silently did not run would be a pass nobody earned.
        ok &= report("pyflakes is installed (Debian python3-pyflakes)", ["import pyflakes failed"])
    else:
        ok &= report("pyflakes finds no undefined or unused names", flakes)
        with tempfile.TemporaryDirectory() as scratch:
            unused = os.path.join(scratch, "Unused.py")
            with open(unused, "w") as f:
                f.write("import os\n\nprint(undefinedName)\n")
            ok &= report("planted unused import and undefined name are found",
                         [] if len(pyflakesProblems([unused]) or []) >= 2 else ["not found"])
    with tempfile.TemporaryDirectory() as scratch:
        broken = os.path.join(scratch, "Broken.py")
        with open(broken, "w") as f:
            f.write("def f(:\n    pass\n")
        ok &= report("planted syntax error is rejected", [] if compileProblems([broken]) else ["not rejected"])
    return ok


def runUi(moduleDir):
    sys.path.insert(0, moduleDir)
    from StentGraftPlannerLib import Settings

    with open(os.path.join(moduleDir, MODULE + ".py")) as f:
        source = f.read()
    with open(os.path.join(moduleDir, "Resources", "UI", MODULE + ".ui")) as f:
        uiText = f.read()
    used = usedUiNames(source)
    ok = report("%d widget names used by the code and %d settings widgets are in the .ui, with sound kinds, "
                "defaults and scene connections" % (len(used), len(Settings.SETTINGS)),
                uiProblems(source, uiText, Settings.SETTINGS))
    planted = {
        "a widget name missing from the .ui": (source + "\nself.ui.noSuchWidget.show()\n", uiText, Settings.SETTINGS),
        "a default outside the widget's range": (source, uiText, [Settings.SETTINGS_BY_NAME["maximumLumenVolumeMl"]._replace(default=1e9)]),
        "too few decimals": (source, uiText, [Settings.SETTINGS_BY_NAME["ringSpacingMm"]._replace(default=4.00001)]),
        "an enumeration value the combo box lacks": (source, uiText, [Settings.SETTINGS_BY_NAME["thresholdMode"]._replace(choices=("auto", "manual", "x"))]),
        "a scene connection removed": (source, uiText.replace("<receiver>seedSelector</receiver>", "<receiver>applyButton</receiver>"), Settings.SETTINGS),
    }
    for what, (plantedSource, plantedUi, settings) in planted.items():
        problems = uiProblems(plantedSource, plantedUi, settings)
        ok &= report("planted defect, %s, is rejected" % what, [] if problems else ["not rejected"])
    return ok


if __name__ == "__main__":
    modes = {"compile": runCompile, "ui": runUi, "calls": runCalls}
    if len(sys.argv) != 3 or sys.argv[1] not in modes:
        sys.exit(__doc__)
    passed = modes[sys.argv[1]](os.path.abspath(sys.argv[2]))
    sys.exit(0 if passed else 1)
