"""The planning panel's settings and the parameter dictionary for the StentGraftSimulation CLI.

Each setting has a name, a kind, a default and the name of the widget in
``Resources/UI/StentGraftPlanner.ui`` that edits it. Settings whose ``cli`` flag is set go to
the CLI under the same name, so their names and defaults must equal the ``<name>`` and
``<default>`` of ``CLI/StentGraftSimulation.xml`` (the single source of truth; a CTest test
compares the two, and each widget's range with the XML's ``<constraints>``). The others are
combined into one CLI argument each (``device``, ``proximalOversizingRange``), or sent only when
set (``deviceCatalog``, ``neckRules``: an empty path leaves the CLI on the file installed beside it).

Settings are stored in the module's parameter node as strings (``settingsToStrings`` and
``settingsFromStrings``), so the panel state is saved with the scene; a scene from an older
version, or a hand-edited one, falls back to the default for a missing or unreadable value.

Nothing here imports Slicer: nodes are passed through as opaque objects.
"""

import collections
import json
import math
import os

Setting = collections.namedtuple("Setting", "name kind default widget cli choices")
Setting.__doc__ = """One panel setting.

name: parameter-node key, and the CLI parameter name when ``cli`` is true.
kind: "float", "int", "enum" or "str".
default: the value of a new scene (the XML default for CLI settings).
widget: object name of the widget in StentGraftPlanner.ui.
cli: whether the value goes to the CLI under ``name``.
choices: the allowed values of an "enum" (else an empty tuple).
"""


def _setting(name, kind, default, widget, cli=True, choices=()):
    return Setting(name, kind, default, widget, cli, tuple(choices))


#: Device family value meaning "let the CLI choose from the catalogue".
AUTO_DEVICE = "auto"

#: Device families of the bundled catalogue, offered when the catalogue file cannot be read.
FALLBACK_DEVICE_FAMILIES = ("Endurant II", "Excluder (C3)", "Excluder Conformable", "Zenith Flex")

SETTINGS = (
    # A lumen segmentation made elsewhere (issue 45): which of its labels are lumen; empty: every
    # non-zero voxel of a single-label map (the CLI refuses a map with several labels then).
    _setting("lumenLabels", "str", "", "lumenLabelsLineEdit"),
    # Lumen segmentation (XML group "Lumen segmentation").
    _setting("thresholdMode", "enum", "auto", "thresholdModeComboBox", choices=("auto", "manual")),
    _setting("lowerHu", "float", 200.0, "lowerHuSpinBox"),
    _setting("upperHu", "float", 600.0, "upperHuSpinBox"),
    _setting("windowSigmas", "float", 3.0, "windowSigmasSpinBox"),
    _setting("seedMinimumHu", "float", 150.0, "seedMinimumHuSpinBox"),
    _setting("leakOpeningRadiusMm", "float", 1.0, "leakOpeningRadiusMmSpinBox"),
    _setting("maximumLumenVolumeMl", "float", 1500.0, "maximumLumenVolumeMlSpinBox"),
    # Centerlines.
    _setting("spurLengthRatio", "float", 2.0, "spurLengthRatioSpinBox"),
    _setting("centerlineSmoothingMm", "float", 2.0, "centerlineSmoothingMmSpinBox"),
    _setting("centerlineStepMm", "float", 1.0, "centerlineStepMmSpinBox"),
    # Stent fitting (active contour).
    _setting("verticesPerRing", "int", 16, "verticesPerRingSpinBox"),
    _setting("ringSpacingMm", "float", 4.0, "ringSpacingMmSpinBox"),
    _setting("startRadiusMm", "float", 3.0, "startRadiusMmSpinBox"),
    _setting("measureBalloonRadiusMm", "float", 60.0, "measureBalloonRadiusMmSpinBox"),
    _setting("measureBalloonPressure", "float", 0.02, "measureBalloonPressureSpinBox"),
    _setting("stentBalloonPressure", "float", 5.0, "stentBalloonPressureSpinBox"),
    _setting("acmTau", "float", 0.15, "acmTauSpinBox"),
    _setting("wallWeight", "float", 5.0, "wallWeightSpinBox"),
    _setting("wallSofteningMm", "float", 1.0, "wallSofteningMmSpinBox"),
    _setting("acmMaxIterations", "int", 3000, "acmMaxIterationsSpinBox"),
    _setting("acmToleranceMm", "float", 0.005, "acmToleranceMmSpinBox"),
    # Device selection: combined into the CLI's device, proximalOversizingRange and deviceCatalog.
    _setting("deviceFamily", "str", AUTO_DEVICE, "deviceFamilyComboBox", cli=False),
    _setting("deviceDiameterMm", "float", 0.0, "deviceDiameterSpinBox", cli=False),
    _setting("oversizingMinPercent", "float", 10.0, "oversizingMinSpinBox", cli=False),
    _setting("oversizingMaxPercent", "float", 20.0, "oversizingMaxSpinBox", cli=False),
    # Deployment (XML group "Stent graft", issue 29): the side the main body goes up (auto: the wider
    # access vessel, then the less tortuous iliac), and where its proximal fabric edge is deployed,
    # in mm below the lower edge of the lowest renal ostium (negative: above; the CLI checks -30 to 60).
    _setting("ipsilateralSide", "enum", "auto", "ipsilateralSideComboBox", choices=("auto", "right", "left")),
    _setting("deploymentOffsetMm", "float", 0.0, "deploymentOffsetMmSpinBox"),
    _setting("deviceCatalogPath", "str", "", "deviceCatalogPathLineEdit", cli=False),
    # Hostile-neck rule set: the CLI's neckRules, sent only when a file is chosen.
    _setting("neckRulesPath", "str", "", "neckRulesPathLineEdit", cli=False),
    # Where the visual report (HTML) goes; empty: Slicer's temporary folder.
    _setting("reportFolder", "str", "", "reportFolderPathLineEdit", cli=False),
)

SETTINGS_BY_NAME = {s.name: s for s in SETTINGS}

NodeRole = collections.namedtuple("NodeRole", "name nodeClass channel required defaultName")
NodeRole.__doc__ = """A node the CLI reads or writes, kept as a parameter-node reference.

name: the CLI parameter name and the parameter-node reference role.
nodeClass: the MRML class to create for an output.
channel: "input" or "output".
required: an input the run cannot do without.
defaultName: the scene name given to a new output node.
"""

NODE_ROLES = (
    NodeRole("inputVolume", "vtkMRMLScalarVolumeNode", "input", True, ""),
    # Optional: without a point the CLI finds the aorta itself; the panel then places the seed used.
    NodeRole("seed", "vtkMRMLMarkupsFiducialNode", "input", False, ""),
    NodeRole("lowestRenalOstium", "vtkMRMLMarkupsFiducialNode", "input", False, ""),
    # Optional landmarks (issue 45): a given point replaces the one the plan finds. The panel's Re-plan
    # writes a landmark the surgeon moved into its point list here.
    NodeRole("aorticBifurcation", "vtkMRMLMarkupsFiducialNode", "input", False, ""),
    NodeRole("rightInternalIliacOrigin", "vtkMRMLMarkupsFiducialNode", "input", False, ""),
    NodeRole("leftInternalIliacOrigin", "vtkMRMLMarkupsFiducialNode", "input", False, ""),
    # Optional: a lumen segmentation made elsewhere, taken instead of region growing (lumenLabels).
    NodeRole("inputLumenSegmentation", "vtkMRMLLabelMapVolumeNode", "input", False, ""),
    NodeRole("outputLabelMap", "vtkMRMLLabelMapVolumeNode", "output", False, "Lumen"),
    # 1 lumen, 2 thrombus and wall, 3 calcification: everything inside the outer wall.
    NodeRole("outputWallLabelMap", "vtkMRMLLabelMapVolumeNode", "output", False, "Vessel wall"),
    # Point data ThrombusThicknessMm and Supported.
    NodeRole("outputOuterWallModel", "vtkMRMLModelNode", "output", False, "Outer wall surface"),
    NodeRole("outputCenterlines", "vtkMRMLModelNode", "output", False, "Centerlines"),
    NodeRole("outputLandmarks", "vtkMRMLMarkupsFiducialNode", "output", False, "Landmarks"),
    NodeRole("outputStentModel", "vtkMRMLModelNode", "output", False, "Fitted stent surface"),
    NodeRole("outputSimulatedStentModel", "vtkMRMLModelNode", "output", False, "Simulated stent graft"),
    NodeRole("outputMeasurements", "vtkMRMLTableNode", "output", False, "Measurements"),
    NodeRole("outputDiameterProfile", "vtkMRMLTableNode", "output", False, "Diameter profile"),
    # Axial slices: cross-sections along the centerline; coronal and sagittal: stretched views.
    NodeRole("outputStraightenedVolume", "vtkMRMLScalarVolumeNode", "output", False,
             "Straightened CT (aorta to right iliac)"),
)

NODE_ROLES_BY_NAME = {r.name: r for r in NODE_ROLES}

#: The point inputs (markups nodes), each sent only when it holds a selected point: without a seed the
#: CLI finds the aorta itself (seedSource automatic), without a landmark it finds the landmark.
POINT_ROLES = tuple(r.name for r in NODE_ROLES if r.channel == "input" and r.nodeClass == "vtkMRMLMarkupsFiducialNode")
OUTPUT_ROLES = tuple(r for r in NODE_ROLES if r.channel == "output")

#: CLI parameter of the JSON report (a ``file`` output: Slicer passes the path unchanged).
REPORT_PARAMETER = "outputReport"

#: CLI parameter of the visual report (HTML, a ``file`` output like the JSON one).
REPORT_HTML_PARAMETER = "outputReportHtml"

#: CLI parameter of the configuration the run simulated (JSON, the format --configuration reads: the
#: panel's editable order list, EditConfiguration.py).
CONFIGURATION_OUTPUT_PARAMETER = "outputConfiguration"


def configurationPath(reportPath):
    """Where a run writes the configuration it simulated: beside its temporary JSON report."""
    root, _ = os.path.splitext(str(reportPath))
    return root + "-configuration.json"


def reportHtmlPath(folder, temporaryFolder, volumeName, stamp):
    """Where a run's visual report goes: ``folder`` (the reportFolder setting) or, when it is empty,
    ``temporaryFolder`` (Slicer's), named after the volume and ``stamp`` (e.g. 20261202-131500) so
    that a later run does not overwrite an earlier report. Characters a file name cannot hold
    become "_"."""
    safe = "".join(c if c.isalnum() or c in "-_." else "_" for c in (volumeName or "volume")) or "volume"
    return os.path.join(folder or temporaryFolder, "StentGraftPlanner-%s-%s.html" % (safe, stamp))

#: Optional input files: CLI parameter -> the setting holding its path (sent only when not empty).
FILE_PARAMETERS = (("deviceCatalog", "deviceCatalogPath"), ("neckRules", "neckRulesPath"))

#: How far apart the oversizing bounds may lie, in percent of the vessel diameter.
OVERSIZING_RANGE_PERCENT = (0.0, 50.0)


def formatNumber(value):
    """A float as the CLI reads it: shortest round-trip text, no exponent for ordinary values."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


def defaultSettings():
    """Every setting at its default, as a new dict."""
    return {s.name: s.default for s in SETTINGS}


def _parse(setting, text):
    if setting.kind == "float":
        value = float(text)
        if not math.isfinite(value):
            raise ValueError(text)
        return value
    if setting.kind == "int":
        return int(text)
    if setting.kind == "enum":
        if text not in setting.choices:
            raise ValueError(text)
        return text
    return str(text)


def settingsToStrings(settings):
    """The settings as parameter-node strings (only known names; unknown keys raise KeyError)."""
    strings = {}
    for name, value in settings.items():
        setting = SETTINGS_BY_NAME[name]
        strings[name] = formatNumber(value) if setting.kind == "float" else str(value)
    return strings


def settingsFromStrings(strings):
    """Settings read back from parameter-node strings.

    strings: a mapping name -> str (a missing name, ``None`` or an empty string mean "not set").
    Returns ``(settings, problems)``: every setting, with the default where the stored text was
    missing or unreadable, and one message for each unreadable value (so the caller can log it).
    """
    settings = defaultSettings()
    problems = []
    for setting in SETTINGS:
        text = strings.get(setting.name)
        if text is None or (text == "" and setting.kind != "str"):
            continue
        try:
            settings[setting.name] = _parse(setting, text)
        except ValueError:
            problems.append(
                "Stored value %r of %s is not a valid %s; using the default %r."
                % (text, setting.name, setting.kind, setting.default)
            )
    return settings, problems


def deviceArgument(family, diameterMm):
    """The CLI's ``device`` string: "auto", "Family" or "Family:diameter" (diameter in mm).

    A diameter of 0 (or less) leaves the size to the CLI's oversizing rule. A family name may not
    contain ":" (the CLI's separator); that raises ValueError.
    """
    family = (family or "").strip()
    if not family or family.lower() == AUTO_DEVICE:
        return AUTO_DEVICE
    if ":" in family:
        raise ValueError(
            "Device family %r contains ':', which separates family and diameter in the CLI's device "
            "argument; choose a family from the catalogue." % family
        )
    if diameterMm and diameterMm > 0:
        return "%s:%s" % (family, formatNumber(diameterMm))
    return family


def catalogFamilies(text):
    """The device family names of a catalogue file's JSON text, in file order, for the selector.

    Accepts a top-level list of entries or an object holding one under "families" or "devices";
    an entry's name is its "family" (or "name") field. The CLI validates the catalogue in full;
    this only needs the names, and raises ValueError when it finds none.
    """
    data = json.loads(text)
    if isinstance(data, dict):
        data = data.get("families", data.get("devices"))
    names = []
    for entry in data if isinstance(data, list) else []:
        name = entry.get("family", entry.get("name")) if isinstance(entry, dict) else None
        if isinstance(name, str) and name.strip() and name.strip() not in names:
            names.append(name.strip())
    if not names:
        raise ValueError("The device catalogue lists no device family (no entry with a 'family' name).")
    return names


def validateSettings(settings):
    """Raise ValueError, naming the value and what is expected, for settings the CLI would reject.

    Only cross-setting rules and the panel's own settings are checked here; each numeric CLI
    range is checked by the CLI itself (STYLE.md B4), which reports it through the error text.
    """
    if settings["thresholdMode"] == "manual" and not settings["lowerHu"] < settings["upperHu"]:
        raise ValueError(
            "Lower threshold %s HU is not below the upper threshold %s HU; in manual threshold mode "
            "lowerHu must be less than upperHu: lower it or raise upperHu."
            % (formatNumber(settings["lowerHu"]), formatNumber(settings["upperHu"]))
        )
    low, high = settings["oversizingMinPercent"], settings["oversizingMaxPercent"]
    lowest, highest = OVERSIZING_RANGE_PERCENT
    if not (lowest <= low < high <= highest):
        raise ValueError(
            "Proximal oversizing range %s-%s %% is not valid; it must satisfy %s <= minimum < maximum "
            "<= %s %% (10-20 %% is the usual range): correct the two values."
            % (formatNumber(low), formatNumber(high), formatNumber(lowest), formatNumber(highest))
        )
    if settings["deviceDiameterMm"] < 0:
        raise ValueError(
            "Forced main-body diameter %s mm is negative; give 0 to let the catalogue choose, or the "
            "diameter of an available size." % formatNumber(settings["deviceDiameterMm"])
        )
    deviceArgument(settings["deviceFamily"], settings["deviceDiameterMm"])


def buildCliParameters(settings, nodes, pointCounts, reportPath, reportHtmlPath=None):
    """The parameter dictionary for ``slicer.cli.run(slicer.modules.stentgraftsimulation, ...)``.

    settings: a dict as from ``defaultSettings`` (all names present).
    nodes: role name -> node (opaque here; ``None`` or missing when not selected).
    pointCounts: role name -> number of selected control points, for the markups inputs
        (POINT_ROLES); Slicer sends only the first selected point of a non-multiple ``point``.
    reportPath: where the CLI writes its JSON report (a temporary file); the configuration it simulated
        goes beside it (``configurationPath``).
    reportHtmlPath: where it writes the visual report (``reportHtmlPath()``); None: not asked for.

    A point list (seed or landmark) that is missing or empty is left out: the CLI then finds the aorta
    or the landmark itself. An input lumen segmentation goes as its node, with lumenLabels.
    Raises ValueError when a required input is missing, or a setting rule is broken (``validateSettings``). Floats go as text formatted by ``formatNumber`` (slicer.cli
    hands a Python float to ``SetParameterAsDouble``, which keeps six significant digits:
    acmToleranceMm 0.00123456789 would reach the CLI as 0.00123457, 1234567.0 as 1.23457e+06),
    integers as int and the combined arguments as pre-joined strings (slicer.cli turns a list into
    "a, b" with spaces).
    """
    validateSettings(settings)
    if nodes.get("inputVolume") is None:
        raise ValueError("No CT volume is selected; choose the CT angiography volume in Inputs.")
    parameters = {}
    for setting in SETTINGS:
        if setting.cli:
            value = settings[setting.name]
            parameters[setting.name] = {"float": formatNumber, "int": int}.get(setting.kind, str)(value)
    parameters["device"] = deviceArgument(settings["deviceFamily"], settings["deviceDiameterMm"])
    parameters["proximalOversizingRange"] = "%s,%s" % (
        formatNumber(settings["oversizingMinPercent"]),
        formatNumber(settings["oversizingMaxPercent"]),
    )
    for parameter, setting in FILE_PARAMETERS:
        if settings[setting]:
            parameters[parameter] = settings[setting]
    for role in NODE_ROLES:
        node = nodes.get(role.name)
        if node is None:
            if role.channel == "output":
                raise ValueError("No node for the output %s; the logic creates one before the run." % role.name)
            continue
        if role.name in POINT_ROLES and pointCounts.get(role.name, 0) < 1:
            continue  # no point placed: the CLI finds the aorta (seed) or the landmark itself
        parameters[role.name] = node
    parameters[REPORT_PARAMETER] = str(reportPath)
    parameters[CONFIGURATION_OUTPUT_PARAMETER] = configurationPath(reportPath)
    if reportHtmlPath:
        parameters[REPORT_HTML_PARAMETER] = str(reportHtmlPath)
    return parameters


def cliParametersCreatingOutputs(settings, inputNodes, pointCounts, outputNode, reportPath, reportHtmlPath=None):
    """``buildCliParameters`` for a run whose output nodes are made on demand: the settings and the
    input volume are checked first (ValueError, as ``buildCliParameters``), and only then is
    ``outputNode(role)`` called once per output role (a NodeRole of OUTPUT_ROLES) for the node the
    CLI writes into. So a run refused for its settings leaves no empty node in the scene.

    inputNodes: role name -> node for the inputs (``None`` or missing when not selected).
    """
    validateSettings(settings)
    if inputNodes.get("inputVolume") is None:
        raise ValueError("No CT volume is selected; choose the CT angiography volume in Inputs.")
    nodes = {name: node for name, node in inputNodes.items() if NODE_ROLES_BY_NAME[name].channel == "input"}
    for role in OUTPUT_ROLES:
        nodes[role.name] = outputNode(role)
    return buildCliParameters(settings, nodes, pointCounts, reportPath, reportHtmlPath)
