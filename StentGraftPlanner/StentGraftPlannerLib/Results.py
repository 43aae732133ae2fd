"""Reading what the StentGraftSimulation CLI returns, and formatting the device recommendation.

Four things come back from a run besides the nodes Slicer loads itself:

- return parameters (``--returnparameterfile``; read in Slicer with
  ``cliNode.GetParameterAsString(name)``): ``readReturnValues``;
- the measurements table (columns name, value, unit, definition, vessel, abscissaMm, the ring's
  min/max/area diameters, wall, estimated, then label and shown: the value in words and at
  clinical precision, which ``formatValue`` matches): ``estimatedNames`` reads which outer-wall diameters
  sit at a level less than 60 % supported, and ``resultsTableRows`` makes the panel's table of every
  return value with its wall (outer wall or lumen), "not measured" and the estimated flag;
- the diameter profile table (columns vessel, abscissaMm, meanDiameterMm, minDiameterMm,
  maxDiameterMm, areaDiameterMm; one row per centerline sample of aorta, rightIliac and leftIliac):
  ``profileSeries`` splits it into one series per vessel for the plot;
- the JSON report (``"format": "StentGraftPlanner.report/1"``): ``parseReport`` normalises it,
  treating every missing section as "not shown" rather than an error; ``withReportVerdicts`` lets
  its hostile-neck assessment tell a passed neck from an undecided one (the return value is false
  for both); ``recommendationLines``/``recommendationHtml`` turn it into the panel's text: the
  recommendation, its IFU status, each family's checks and the fit check, as sentences (its
  ``deployment``, the order list, is OrderList.py's).

Units: millimetres, degrees, percent and millilitres, as the CLI writes them. What a person reads is
at clinical precision (STYLE.md B10, the CLI's ValueText.h): 0.1 mm, 0.1 deg, 1 %, 0.01 for a ratio,
0.1 mL, in words. Coordinates in the report are LPS (the CLI's frame); nothing here converts them.
"""

import collections
import csv
import html
import io
import json
import math
import re

REPORT_FORMAT = "StentGraftPlanner.report/1"

ReturnValue = collections.namedtuple("ReturnValue", "name kind unit label missing wall", defaults=("",))
ReturnValue.__doc__ = """One return parameter of the CLI that the panel reads.

name: the XML <name>.
kind: "float", "str" or "bool" (an XML <boolean>: true or false).
unit: "mm", "deg", "%", "mL" or "" (a ratio), for display.
label: the panel's text; the two diameters of one level, outer wall and lumen, share it.
missing: the text the CLI writes when it does not have the value, where that text cannot be a
    real value (then it is read as None); None where it can, and is read as the value.
wall: OUTER_WALL for a diameter outer wall to outer wall, LUMEN for a lumen diameter, "" for
    anything else (lengths, angles, volumes, device sizes).
"""

#: The walls a diameter is measured on (ReturnValue.wall and the measurements table's wall column).
OUTER_WALL, LUMEN = "outer", "lumen"
WALL_TEXT = {OUTER_WALL: "outer wall", LUMEN: "lumen", "": ""}

#: The CLI writes every return value of the XML; one it does not have (not measured, a stage not
#: run) as -1 for a number, "none" for a text (Logic/Pipeline/PlanValues.h).
NOT_MEASURED = "-1"
NO_VALUE = "none"
#: The return value that names, comma-separated, every other one the run does not have ("none": it
#: has them all). It tells a signed value's real -1 (a conicity of -1 %) from "not measured"; a run
#: of a CLI without it (empty, or a text that is no list of names) is read by the texts above and the
#: inferences below.
NOT_MEASURED_LIST = "notMeasured"


def _number(name, unit, label, missing=NOT_MEASURED, wall=""):
    """A number that cannot be negative (diameter, length, angle, tortuosity, volume, arc, device
    size): its -1 is always "not measured". A signed one passes missing=None."""
    return ReturnValue(name, "float", unit, label, missing, wall)


def _text(name, label, missing=NO_VALUE):
    return ReturnValue(name, "str", "", label, missing)


def _flag(name, label):
    """An XML <boolean>: true or false, no "not measured" text; unreadable or empty reads as None."""
    return ReturnValue(name, "bool", "", label, None)


#: The diameters (a)-(f): outer wall (what the IFUs size on) and lumen, in pairs of one level.
DIAMETER_PAIRS = (
    ("proximalNeckDiameter", "proximalNeckLumenDiameter", "(a) proximal neck diameter"),
    ("neckDiameter15mm", "neckLumenDiameter15mm", "(b) neck diameter 15 mm below"),
    ("maxAneurysmDiameter", "maxAneurysmLumenDiameter", "(c) maximum aneurysm diameter"),
    ("distalNeckMinDiameter", "distalNeckMinLumenDiameter", "(d) distal neck minimum diameter"),
    ("rightIliacDiameter", "rightIliacLumenDiameter", "(e) right iliac diameter"),
    ("leftIliacDiameter", "leftIliacLumenDiameter", "(f) left iliac diameter"),
)

#: The CLI's return parameters this module reads, in display order. Which ones read -1 (or
#: "none") as missing, and which wall each diameter is on, follow the XML's descriptions;
#: check_cli_contract.py derives both from there.
RETURN_VALUES = tuple(
    item
    for outer, lumen, label in DIAMETER_PAIRS
    for item in (_number(outer, "mm", label, wall=OUTER_WALL), _number(lumen, "mm", label, wall=LUMEN))
) + (
    _number("proximalNeckLength", "mm", "proximal neck length"),
    _number("proximalSiteToBifurcationLength", "mm", "proximal site to bifurcation"),
    _number("rightIliacLength", "mm", "right iliac length"),
    _number("leftIliacLength", "mm", "left iliac length"),
    _number("neckAngleBeta", "deg", "infrarenal neck angle beta"),
    _number("neckAngleAlpha", "deg", "suprarenal neck angle alpha"),
    # (b - a) / a in percent: -1 % is a neck narrowing slightly downward, so -1 is a value here.
    _number("neckConicity", "%", "neck conicity", missing=None),
    _number("rightIliacTortuosity", "", "right iliac tortuosity index"),
    _number("leftIliacTortuosity", "", "left iliac tortuosity index"),
    _number("rightAccessMinDiameter", "mm", "right access minimum diameter", wall=LUMEN),
    _number("leftAccessMinDiameter", "mm", "left access minimum diameter", wall=LUMEN),
    _number("thrombusVolume", "mL", "thrombus volume, proximal site to bifurcation"),
    _number("sacVolume", "mL", "sac volume inside the outer wall"),
    _number("maxThrombusThickness", "mm", "maximum thrombus thickness"),
    _number("neckThrombusArc", "%", "neck thrombus arc (thicker than 2 mm)"),
    _number("neckCalcificationArc", "%", "neck calcification arc"),
    _flag("hostileNeck", "hostile neck"),
    _text("proximalSiteSource", "proximal site taken from"),
    # "none" is a result here: no family is within its instructions for use (NO_DEVICE).
    _text("recommendedDevice", "recommended device", missing=None),
    _number("mainBodyDiameter", "mm", "main body diameter"),
    _number("rightLimbDiameter", "mm", "right limb diameter"),
    _number("leftLimbDiameter", "mm", "left limb diameter"),
    # Issue 29: the ordered configuration. A limb length of 0 is a value: no limb on that side, the
    # main body's own ipsilateral leg lands there (ZERO_WORDS).
    _number("mainBodyLength", "mm", "main body length"),
    _number("rightLimbLength", "mm", "right limb length"),
    _number("leftLimbLength", "mm", "left limb length"),
    # "none" is a result of both: no family has a main body (VALUE_WORDS).
    _text("ipsilateralSideUsed", "main body introduced from", missing=None),
    _text("orderList", "order list", missing=None),
    _text("ifuStatus", "instructions for use (IFU)"),
)

#: Return values whose -1 (or "none") means "not measured" (derived from RETURN_VALUES).
NOT_MEASURED_NAMES = frozenset(item.name for item in RETURN_VALUES if item.missing is not None)

#: Signed values computed from others, in name -> operands: not measured when an operand is not
#: (the CLI then writes -1, which the signed value itself cannot tell from a measurement).
#: neckConicity is (b - a) / a of the XML, a = proximalNeckDiameter, b = neckDiameter15mm.
COMPUTED_FROM = {"neckConicity": ("proximalNeckDiameter", "neckDiameter15mm")}

#: Verdicts whose false the CLI also writes when a rule could not be decided (the XML's hostileNeck:
#: "false when it passes every rule, or when a rule could not be decided"), in name -> the values
#: its rules are decided on. A false is read as None ("not determined") when one of them is not
#: measured; a true stands, since one failed rule makes the verdict. The quantities are those of the
#: hostile-neck rule set (issue 12 item 4): neck length, diameter, angles beta and alpha, thrombus
#: and calcification arcs, reverse taper between (a) and (b).
DECIDED_FROM = {
    "hostileNeck": ("proximalNeckLength", "proximalNeckDiameter", "neckDiameter15mm", "neckAngleBeta",
                    "neckAngleAlpha", "neckThrombusArc", "neckCalcificationArc"),
}

#: The recommendedDevice value that means no family passed its IFU checks.
NO_DEVICE = "none"

#: The words of the CLI's ifuStatus (withinIfu is false both for a failed and for an unchecked
#: criterion; ifuStatus tells them apart), short and in full.
IFU_STATUS_WORDS = {"pass": "within IFU", "fail": "outside IFU", "indeterminate": "IFU not determined"}
IFU_STATUS_SENTENCES = {
    "pass": "within its instructions for use: every criterion met on measured values",
    "fail": "outside its instructions for use: a criterion failed on measured values",
    "indeterminate": "instructions for use not determined: no criterion failed, but one could not be checked "
    "(a value not measured, within its uncertainty, or sized on the lumen)",
}
_IFU_KINDS = {"pass": "ok", "fail": "fail", "indeterminate": "indeterminate"}

#: Text return values shown in words: name -> {the CLI's text: the panel's words}.
VALUE_WORDS = {
    "ifuStatus": {
        "pass": "within IFU: every criterion met on measured values",
        "fail": "outside IFU: a criterion failed on measured values",
        "indeterminate": "IFU not determined: no criterion failed, but one could not be checked",
    },
    "recommendedDevice": {NO_DEVICE: "none within its instructions for use"},
    "ipsilateralSideUsed": {"none": "no main body"},
    "orderList": {"none": "no main body"},
    "proximalSiteSource": {"notFound": "not known: no renal artery in view (place the lowest-renal landmark)"},
}

#: Numbers whose 0 is a verdict, not a measurement: name -> the words shown for it.
ZERO_WORDS = {
    "rightLimbLength": "no limb: the main body's ipsilateral leg lands on the right",
    "leftLimbLength": "no limb: the main body's ipsilateral leg lands on the left",
}

#: Decimals a person reads, per unit (the CLI's ClinicalText): 0.1 mm, 0.1 deg, 1 %, 0.01 for a
#: ratio ("" or "ratio"), 0.1 mL.
CLINICAL_DECIMALS = {"mm": 1, "deg": 1, "%": 0, "": 2, "ratio": 2, "mL": 1}

PROFILE_COLUMNS = ("abscissaMm", "meanDiameterMm", "minDiameterMm", "maxDiameterMm", "areaDiameterMm")
PROFILE_VESSELS = ("aorta", "rightIliac", "leftIliac")

PROXIMAL_SITE_SOURCES = {
    "landmark": "the lowest-renal landmark you placed",
    "renal": "the lowest renal artery found on the centerlines",
    "top": "the top of the aortic centerline: no renal artery was found, so place the lowest-renal "
    "landmark and run again for a true proximal neck",
    "notFound": "nowhere: no renal artery was found and the aorta runs on past the renal level, so the neck "
    "values and the deployment target are not measured; place the lowest-renal landmark and run again",
}


def _toFloat(text):
    """A finite float from text, or None (empty, unreadable, NaN or infinite)."""
    try:
        value = float(str(text).strip())
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def _toBool(text):
    """True or False from the CLI's true/false (and 1/0, yes/no, any case), or None."""
    return {"true": True, "1": True, "yes": True, "false": False, "0": False, "no": False}.get(
        str(text).strip().lower())


def _readListedValues(getParameterAsString, notMeasured):
    """The return values where the CLI named those it does not have: None for each of them and for
    an empty or unreadable text; every other text is the value, -1 and "none" included."""
    values = {}
    for item in RETURN_VALUES:
        text = (getParameterAsString(item.name) or "").strip()
        if item.name in notMeasured:
            values[item.name] = None
        elif item.kind == "str":
            values[item.name] = text or None
        elif item.kind == "bool":
            values[item.name] = _toBool(text)
        else:
            values[item.name] = _toFloat(text)
    return values


def readReturnValues(getParameterAsString):
    """The return values of a finished run.

    getParameterAsString: a function name -> str (``cliNode.GetParameterAsString`` in Slicer).
    Returns name -> float, str, bool or None. None where the CLI names the value in its
    ``notMeasured`` list (NOT_MEASURED_LIST) or the text is empty or unreadable; without that list (an
    older CLI) also where the CLI wrote its "not measured" text (-1, none) for a value that cannot take it
    (``ReturnValue.missing``), for a computed value one of whose operands is None
    (``COMPUTED_FROM``), and for a false verdict one of whose quantities is None (``DECIDED_FROM``).
    """
    listed = [name.strip() for name in (getParameterAsString(NOT_MEASURED_LIST) or "").split(",")]
    if all(re.fullmatch(r"[A-Za-z][A-Za-z0-9]*", name) for name in listed):  # a list of names, or none
        return _readListedValues(getParameterAsString, set(listed) - {NO_VALUE})
    values = {}
    for item in RETURN_VALUES:
        text = (getParameterAsString(item.name) or "").strip()
        if item.kind == "str":
            values[item.name] = None if not text or text == item.missing else text
            continue
        if item.kind == "bool":
            values[item.name] = _toBool(text)
            continue
        value = _toFloat(text)
        if value is not None and item.missing is not None and value == float(item.missing):
            value = None
        values[item.name] = value
    for name, operands in COMPUTED_FROM.items():
        if any(values[operand] is None for operand in operands):
            values[name] = None
    for name, quantities in DECIDED_FROM.items():
        if values[name] is False and any(values[quantity] is None for quantity in quantities):
            values[name] = None
    return values


def automaticSeed(getParameterAsString):
    """The seed the CLI found itself, as an (R, A, S) tuple in mm, or None when the run was given one
    (seedSource user) or the values cannot be read. getParameterAsString as for readReturnValues."""
    if (getParameterAsString("seedSource") or "").strip() != "automatic":
        return None
    parts = (getParameterAsString("seedUsed") or "").split(",")
    try:
        point = tuple(float(p) for p in parts)
    except ValueError:
        return None
    return point if len(point) == 3 and all(math.isfinite(c) for c in point) else None


def clinicalNumber(value, unit):
    """The number of ``value`` at the clinical precision of ``unit`` (CLINICAL_DECIMALS; 0.1 for
    another unit), without a sign when it rounds to zero ("0 %", not "-0 %")."""
    text = "%.*f" % (CLINICAL_DECIMALS.get(unit, 1), value)
    return text.lstrip("-") if float(text) == 0 else text


def formatValue(value, unit):
    """A value as a person reads it, at clinical precision with its unit, as the measurements table's
    shown column: "22.1 mm", "34.6°", "15 %", "1.01" (a ratio: unit "" or "ratio"), "135.2 mL";
    "Yes"/"No" for a verdict, a text as it is, "not measured" for None."""
    if value is None:
        return "not measured"
    if isinstance(value, bool):
        return "Yes" if value else "No"
    if isinstance(value, str):
        return value
    text = clinicalNumber(value, unit)
    if unit == "deg":
        return text + "°"
    return "%s %s" % (text, unit) if unit not in ("", "ratio") else text


def formatReturnValue(item, value):
    """``formatValue`` in words where the value is a verdict: "not determined" for a verdict (a bool)
    that is None, "not given" for a text that is None, VALUE_WORDS for a text, ZERO_WORDS for a
    number whose 0 means something."""
    if item.kind == "bool" and value is None:
        return "not determined"
    if item.kind == "str" and value is None:
        return "not given"
    if isinstance(value, str):
        return VALUE_WORDS.get(item.name, {}).get(value, value)
    if item.kind == "float" and value == 0 and item.name in ZERO_WORDS:
        return ZERO_WORDS[item.name]
    return formatValue(value, item.unit)


_RETURN_VALUE_NAMES = frozenset(item.name for item in RETURN_VALUES)


def _rowName(row):
    name = str(row.get("name") or "").strip()
    return name if name in _RETURN_VALUE_NAMES else None


def estimatedNames(measurementRows):
    """Names of the return values whose measurements-table row is marked estimated.

    measurementRows: dicts with the table's columns name and estimated (as ``readCsvRows`` gives
    them, or read from Slicer's table node). estimated is true (true, 1 or yes, any case) where an
    outer-wall diameter sits at a level less than 60 % of whose circumference was supported. Rows
    naming no return value, and a table without the column (an older CLI), mark nothing.
    """
    return {_rowName(row) for row in measurementRows if _rowName(row) and _toBool(row.get("estimated") or "")}


def tableWalls(measurementRows):
    """name -> wall (OUTER_WALL or LUMEN) of the return values whose measurements-table row names one.

    The CLI's row is the authority on what it measured: the neck length and conicity are on the
    outer wall where it was traced and on the lumen where it was not, which the return value alone
    does not say. An empty or unknown wall text gives no entry (the value keeps ReturnValue.wall).
    """
    walls = {}
    for row in measurementRows:
        wall = str(row.get("wall") or "").strip().lower()
        if _rowName(row) and wall in (OUTER_WALL, LUMEN):
            walls[_rowName(row)] = wall
    return walls


#: Column titles of the panel's results table (``resultsTableRows``).
RESULTS_COLUMNS = ("Measurement", "Value", "Wall", "Estimated")


def resultsTableRows(values, measurementRows=()):
    """The panel's results table: one row per return value, in RETURN_VALUES order.

    values: as from ``readReturnValues``; measurementRows: the measurements table's rows (for the
    wall and the estimated flag; ``tableWalls``, ``estimatedNames``). Each row is (label, value text,
    wall text, estimated text): the value as ``formatReturnValue`` shows it ("not measured",
    "Yes"/"No"/"not determined"); the wall "outer wall" or "lumen" as the table's row gives it, else
    as ReturnValue.wall ("" where no wall applies); "yes" where the table marks a measured value
    estimated, else "".
    """
    measurementRows = list(measurementRows)
    estimated, walls = estimatedNames(measurementRows), tableWalls(measurementRows)
    rows = []
    for item in RETURN_VALUES:
        value = values.get(item.name)
        flag = "yes" if item.name in estimated and value is not None else ""
        rows.append((item.label, formatReturnValue(item, value), WALL_TEXT[walls.get(item.name, item.wall)], flag))
    return rows


def readCsvRows(text):
    """Rows of a CSV table with a header line, as dicts (what Slicer's table node holds)."""
    return list(csv.DictReader(io.StringIO(text)))


def profileSeries(rows):
    """The diameter profile split into one series per vessel, each sorted along the vessel.

    rows: dicts with the columns vessel, abscissaMm, meanDiameterMm, minDiameterMm,
        maxDiameterMm and areaDiameterMm (values as text or numbers).
    Returns an ordered dict vessel -> dict column -> list of floats, vessels in the order aorta,
    rightIliac, leftIliac, then any other vessel in order of appearance. A row whose abscissa or
    mean diameter is unreadable is skipped; another unreadable column becomes NaN, which a plot
    leaves as a gap.
    """
    grouped = collections.OrderedDict((name, []) for name in PROFILE_VESSELS)
    for row in rows:
        vessel = str(row.get("vessel", "")).strip()
        abscissa, mean = _toFloat(row.get("abscissaMm")), _toFloat(row.get("meanDiameterMm"))
        if not vessel or abscissa is None or mean is None:
            continue
        values = {}
        for column in PROFILE_COLUMNS:
            value = _toFloat(row.get(column))
            values[column] = float("nan") if value is None else value
        grouped.setdefault(vessel, []).append(values)
    series = collections.OrderedDict()
    for vessel, samples in grouped.items():
        if not samples:
            continue
        samples.sort(key=lambda s: s["abscissaMm"])
        series[vessel] = {column: [s[column] for s in samples] for column in PROFILE_COLUMNS}
    return series


def _list(value):
    return value if isinstance(value, list) else []


def _dict(value):
    return value if isinstance(value, dict) else None


def parseReport(text):
    """The JSON report, normalised.

    Raises ValueError when the text is not a JSON object or names another format (a report of a
    newer major version would be misread). Every section may be absent:
    returns a dict with proximalSite (dict or None), measurements (list of dicts), warnings (list
    of str), recommendation (dict or None), families (list of dicts, each with a list of checks),
    fitCheck (dict or None), hostileNeck (dict or None: the neck's assessment against the
    hostile-neck rules, read as {"hostile": bool, "determinate": bool, "summary": str, "checks":
    [{"name", "status", "text", ...}]}, every field optional), deployment (dict or None: the ordered
    configuration, Logic/IO/DeploymentToJson.h; null when no family has a main body),
    simulatedFamily (the family of the simulated graft, device.simulated, or None) and notSimulated
    (why no graft was simulated, device.notSimulated, or None).
    """
    try:
        data = json.loads(text)
    except ValueError as error:
        raise ValueError("The planning report is not valid JSON (%s); the CLI run did not finish writing it." % error)
    if not isinstance(data, dict):
        raise ValueError("The planning report is a JSON %s, expected an object." % type(data).__name__)
    reportFormat = data.get("format")
    if reportFormat != REPORT_FORMAT:
        raise ValueError(
            "The planning report has format %r, expected %r; the CLI and this module come from "
            "different versions of the extension." % (reportFormat, REPORT_FORMAT)
        )
    device = _dict(data.get("device")) or {}
    families = []
    for family in _list(device.get("families")):
        if isinstance(family, dict):
            checks = [c for c in _list(family.get("checks")) if isinstance(c, dict)]
            name = family.get("family", family.get("name", "?"))
            families.append({"family": str(name), "checks": checks, "entry": family})
    return {
        "proximalSite": _dict(data.get("proximalSite")),
        "measurements": [m for m in _list(data.get("measurements")) if isinstance(m, dict)],
        "warnings": [str(w) for w in _list(data.get("warnings"))],
        "recommendation": _normalRecommendation(_dict(device.get("recommendation")), families),
        "families": families,
        "fitCheck": _dict(data.get("fitCheck")),
        "hostileNeck": _dict(data.get("hostileNeck")),
        "deployment": _dict(data.get("deployment")),
        "simulatedFamily": device.get("simulated") if isinstance(device.get("simulated"), str) else None,
        "notSimulated": device.get("notSimulated") if isinstance(device.get("notSimulated"), str) else None,
    }


def withReportVerdicts(values, report):
    """The return values with hostileNeck as the report's assessment decides it, where it can.

    The return value is false both for a neck that passes every rule and for one with an undecided
    rule; the report's hostileNeck section tells them apart: hostile true gives True, hostile false
    gives False when determinate is true and None ("not determined") when it is false. Without the
    section (or without those two booleans) the values are returned unchanged (``DECIDED_FROM``
    already applied). Returns a new dict.
    """
    decided = dict(values)
    section = report.get("hostileNeck") or {}
    hostile, determinate = section.get("hostile"), section.get("determinate")
    if isinstance(hostile, bool) and isinstance(determinate, bool):
        decided["hostileNeck"] = True if hostile else (False if determinate else None)
    return decided


def _normalRecommendation(recommendation, families):
    """The recommendation with status and the three diameters always present.

    Two shapes are read: the contract's (status, family, *DiameterMm, reasons) and the selection's
    own (family or null, withinIfu, summary, reasons, with the sizes in the family's entry under
    mainBody/rightLimb/leftLimb.diameterMm). A family outside its IFU gets status "outsideIfu".
    """
    if recommendation is None:
        return None
    normal = dict(recommendation)
    family = recommendation.get("family")
    if "status" not in normal:
        if not family:
            normal["status"] = "noDeviceWithinIfu"
        else:
            normal["status"] = "recommended" if recommendation.get("withinIfu", True) else "outsideIfu"
    entry = next((f["entry"] for f in families if family and f["family"] == family), {})
    for key, part in (("mainBodyDiameterMm", "mainBody"), ("rightLimbDiameterMm", "rightLimb"),
                      ("leftLimbDiameterMm", "leftLimb")):
        if key not in normal:
            size = _dict(entry.get(part)) or {}
            normal[key] = size.get("diameterMm")
    normal["reasons"] = [str(r) for r in _list(recommendation.get("reasons"))]
    return normal


def _size(value):
    """A catalogue size as the order list writes it: "25", "14.5" (0.1 mm at most), "?" when missing."""
    number = _toFloat(value)
    if number is None:
        return "?"
    text = clinicalNumber(number, "mm")
    return text[:-2] if text.endswith(".0") else text


def _mm(value):
    """A length or diameter in mm at 0.1 mm ("28.0 mm"), "not measured" when missing."""
    return formatValue(_toFloat(value), "mm")


def _words(name):
    """An identifier in words: "coveredOstia" -> "covered ostia" (for fields the panel does not know)."""
    return "".join(" " + c.lower() if c.isupper() else c for c in str(name)).strip()


def _family(report, name):
    """The parsed family entry (``parseReport``'s families) named ``name``, or None."""
    return next((f for f in report.get("families", []) if name and f["family"] == name), None)


def _requirement(family, checkName):
    """(text, minimum) of a family's check ("right iliac seal length": ("≥ 15 mm", 15.0)), or (None, None)."""
    check = next((c for c in (family or {}).get("checks", []) if c.get("name") == checkName), None)
    if check is None:
        return None, None
    return check.get("requirement"), _toFloat(check.get("min"))


#: The fit check's proximal seal minimum when the report does not give it (fitCheck.minimumProximalSealMm,
#: written since issue 30): the CLI's FitCheckParams.minimumProximalSealMm, Logic/Device/FitCheck.h.
MINIMUM_PROXIMAL_SEAL_MM = 10.0


def _sealLine(label, length, needsText, minimum, estimated):
    """("ok"/"fail"/"text", "<label> on healthy wall 25.8 mm (needs ≥ 10 mm), estimated (lumen)")."""
    value = _toFloat(length)
    text = "%s on healthy wall %s" % (label, _mm(value))
    if needsText:
        text += " (needs %s)" % needsText
    if estimated:
        text += ", estimated (lumen): the outer wall not traced under part of it"
    kind = "text" if value is None or minimum is None else ("ok" if value >= minimum else "fail")
    return kind, text


#: Fit-check fields that fitCheckLines writes as sentences; the others are listed in words.
_FIT_CHECK_KNOWN = frozenset((
    "passed", "limbsChecked", "proximalSealLengthMm", "proximalSealEnd", "shortestAppositionLengthMm",
    "proximalCalcifiedPercent", "rightIliacSealLengthMm", "leftIliacSealLengthMm", "proximalOversizingPercent",
    "rightLimbOversizingPercent", "leftLimbOversizingPercent", "migrationRisk", "coveredOstia", "ostia",
    "findings", "sealDefinition", "sealEstimatedOnLumen", "minimumProximalSealMm", "minimumIliacSealMm",
    "minimumAppositionLengthMm", "shortestAppositionSide", "shortestAppositionEnd", "proximalSealUncertaintyMm",
    "proximalSealUncertainty",
))


def fitCheckLines(fitCheck, family=None):
    """The report's fit check of the simulated graft as (kind, sentence) lines, at clinical precision.

    fitCheck: the report's fitCheck object (every field optional). family: the parsed family entry of
    the simulated graft (``parseReport``'s families), whose "right/left iliac seal length" checks give
    the iliac seal requirement's words. The minimums are the report's (minimumProximalSealMm,
    minimumIliacSealMm); without them the proximal one is MINIMUM_PROXIMAL_SEAL_MM and the iliac one
    the family's check's, else none is shown. E.g. ("ok", "proximal seal on healthy wall 25.8 mm (needs ≥ 10 mm); the
    seal ends where the aorta widens …"). Fields the panel does not know follow in words.
    """
    lines = []
    passed = fitCheck.get("passed")
    if isinstance(passed, bool):
        lines.append(("ok", "The simulated graft passes the fit check.") if passed
                     else ("fail", "The simulated graft does not pass the fit check."))
    checked = _dict(fitCheck.get("limbsChecked")) or {}
    for side in ("right", "left"):
        if checked.get(side) is False:
            lines.append(("indeterminate", "The %s limb was not sized (the scan ends above its landing zone): its "
                                           "seal, oversizing and internal iliac are not checked." % side))
    onLumen = _dict(fitCheck.get("sealEstimatedOnLumen")) or {}
    proximalMinimum = _toFloat(fitCheck.get("minimumProximalSealMm"))
    proximalMinimum = MINIMUM_PROXIMAL_SEAL_MM if proximalMinimum is None else proximalMinimum
    if "proximalSealLengthMm" in fitCheck:
        kind, text = _sealLine("proximal seal", fitCheck["proximalSealLengthMm"],
                               "≥ %s mm" % _size(proximalMinimum), proximalMinimum,
                               onLumen.get("proximal") is True)
        uncertainty = _toFloat(fitCheck.get("proximalSealUncertaintyMm"))
        if uncertainty is not None:
            text += "; uncertainty %s" % _mm(uncertainty)
            seal = _toFloat(fitCheck["proximalSealLengthMm"])
            if kind == "ok" and seal is not None and seal < proximalMinimum + uncertainty:
                kind = "indeterminate"  # the fit check's "cannot be excluded"
            if fitCheck.get("proximalSealUncertainty"):
                text += " (%s)" % fitCheck["proximalSealUncertainty"]
        if fitCheck.get("proximalSealEnd"):
            text += "; the seal ends where %s" % fitCheck["proximalSealEnd"]
        lines.append((kind, text))
    appositionMinimum = _toFloat(fitCheck.get("minimumAppositionLengthMm"))
    apposition = _toFloat(fitCheck.get("shortestAppositionLengthMm"))
    if "shortestAppositionLengthMm" in fitCheck:
        text = "shortest apposition length %s" % _mm(apposition)
        if appositionMinimum is not None:
            text += " (needs ≥ %s mm)" % _size(appositionMinimum)
        text += ", the shortest sealed length of the graft's columns from its proximal edge"
        if fitCheck.get("shortestAppositionSide"):
            text += ", on the patient's %s side" % fitCheck["shortestAppositionSide"]
        if fitCheck.get("shortestAppositionEnd"):
            text += "; it ends where %s" % fitCheck["shortestAppositionEnd"]
        kind = "text" if apposition is None or appositionMinimum is None else (
            "ok" if apposition >= appositionMinimum else "fail")
        lines.append((kind, text))
    if "proximalCalcifiedPercent" in fitCheck:
        lines.append(("text", "calcified share of the proximal seal zone %s"
                      % formatValue(_toFloat(fitCheck["proximalCalcifiedPercent"]), "%")))
    for side in ("right", "left"):
        key = side + "IliacSealLengthMm"
        if key in fitCheck and checked.get(side) is not False:
            needsText, minimum = _requirement(family, side + " iliac seal length")
            reported = _toFloat(fitCheck.get("minimumIliacSealMm"))
            if reported is not None:
                needsText, minimum = "≥ %s mm" % _size(reported), reported
            lines.append(_sealLine(side + " iliac seal", fitCheck[key], needsText, minimum, onLumen.get(side) is True))
    for key, label in (("proximalOversizingPercent", "main body oversizing at the proximal edge"),
                       ("rightLimbOversizingPercent", "right limb oversizing in the landing zone"),
                       ("leftLimbOversizingPercent", "left limb oversizing in the landing zone")):
        if key in fitCheck:
            lines.append(("text", "%s %s" % (label, formatValue(_toFloat(fitCheck[key]), "%"))))
    risk = fitCheck.get("migrationRisk")
    if isinstance(risk, bool):
        proximal = _toFloat(fitCheck.get("proximalSealLengthMm"))
        if not risk:
            lines.append(("text", "migration risk: no"))
        elif (apposition is not None and appositionMinimum is not None and apposition < appositionMinimum
              and not (proximal is not None and proximal < proximalMinimum)):
            lines.append(("fail", "migration risk: the shortest apposition length is shorter than %s"
                          % _mm(appositionMinimum)))
        else:
            lines.append(("fail", "migration risk: the proximal seal is shorter than %s" % _mm(proximalMinimum)))
    if "coveredOstia" in fitCheck:
        covered = _list(fitCheck["coveredOstia"])
        # Issue 46 item 1: an ostium not covered as read, but within its edge's uncertainty of the graft.
        mayBe = [o for o in _list(fitCheck.get("ostia")) if isinstance(o, dict) and o.get("mayBeCovered") is True]
        if not covered and mayBe:
            lines.append(("indeterminate", "no ostium covered as read; "
                          + "; ".join("the %s ostium may be covered (its edge is read within %s)"
                                      % (_words(o.get("branch", "?")), _mm(_toFloat(o.get("edgeUncertaintyMm"))))
                                      for o in mayBe)))
        elif not covered:
            lines.append(("ok", "no ostium covered"))
        for ostium in covered:
            text = (ostium.get("text") or _words(ostium.get("name", "?"))) if isinstance(ostium, dict) else (
                "covers the %s ostium" % _words(ostium))
            lines.append(("fail", text))
    for finding in _list(fitCheck.get("findings")):
        lines.append(("fail", str(finding)))
    if fitCheck.get("sealDefinition"):
        lines.append(("text", "Sealed means %s." % fitCheck["sealDefinition"]))
    for key, value in fitCheck.items():
        if key not in _FIT_CHECK_KNOWN:
            lines.extend(_genericLines(key, value))
    return lines


#: Unit suffixes of the report's field names, and the unit each is shown in (``_genericLines``).
_FIELD_UNITS = (("Mm", "mm"), ("Percent", "%"), ("Deg", "deg"), ("Ml", "mL"))


def _genericLines(key, value, prefix=""):
    """A field the panel does not know, in words: "gap to wall: 2.3 mm" for gapToWallMm (a number at
    the clinical precision of its name's unit suffix, else 0.1; a count as it is), "yes"/"no", lists
    one line each."""
    key = str(key)
    suffix, unit = next(((suffix, unit) for suffix, unit in _FIELD_UNITS if key.endswith(suffix)), ("", None))
    label = prefix + _words(key[: len(key) - len(suffix)])
    if isinstance(value, list):
        lines = []
        for item in value:
            if isinstance(item, dict):
                text = item.get("text") or ", ".join("%s %s" % (_words(k), v) for k, v in sorted(item.items()))
                lines.append(("fail" if item.get("status") == "fail" else "text", "%s: %s" % (label, text)))
            else:
                lines.append(("text", "%s: %s" % (label, item)))
        return lines
    if isinstance(value, dict):
        return [line for inner, innerValue in value.items() for line in _genericLines(inner, innerValue, label + " ")]
    if isinstance(value, bool):
        return [("text", "%s: %s" % (label, "yes" if value else "no"))]
    if isinstance(value, int) and not unit:
        return [("text", "%s: %d" % (label, value))]  # a count
    if isinstance(value, (int, float)):
        return [("text", "%s: %s" % (label, formatValue(float(value), unit) if unit else clinicalNumber(value, None)))]
    return [("text", "%s: %s" % (label, "not measured" if value is None else value))]


def _estimatedText(entry, levelsKey="estimatedLevels"):
    """" — estimated (lumen) at (a), (b)" where an entry (recommendation, family, deployment) is
    estimated on the lumen; "" otherwise."""
    if (entry or {}).get("estimated") != "lumen":
        return ""
    levels = [str(level) for level in _list(entry.get(levelsKey))]
    return " — estimated (lumen)" + (" at " + ", ".join(levels) if levels else "")


def recommendationLines(report):
    """The recommendation as (kind, text) lines; kind is heading, ok, fail, indeterminate,
    warning or text. A section missing from the report adds no line."""
    lines = []
    recommendation = report.get("recommendation")
    if recommendation is not None:
        status, ifuStatus = recommendation.get("status"), recommendation.get("ifuStatus")
        estimated = _estimatedText(recommendation)
        if status == "recommended":
            kind = {"fail": "fail", "indeterminate": "indeterminate"}.get(ifuStatus, "ok")
            lines.append(
                (
                    kind,
                    "Recommended: %s, main body %s mm, right limb %s mm, left limb %s mm%s"
                    % (
                        recommendation.get("family", "?"),
                        _size(recommendation.get("mainBodyDiameterMm")),
                        _size(recommendation.get("rightLimbDiameterMm")),
                        _size(recommendation.get("leftLimbDiameterMm")),
                        estimated,
                    ),
                )
            )
        elif status == "noDeviceWithinIfu":
            lines.append(("fail", "No device of the catalogue is within its instructions for use."))
        elif status == "outsideIfu":
            lines.append(("fail", "%s is outside its instructions for use." % recommendation.get("family")))
        else:
            lines.append(("indeterminate", "Device recommendation: unknown status %r." % status))
        if ifuStatus in IFU_STATUS_SENTENCES and not (status != "recommended" and ifuStatus == "fail"):
            sentence = IFU_STATUS_SENTENCES[ifuStatus]
            lines.append((_IFU_KINDS[ifuStatus], sentence[0].upper() + sentence[1:] + "."))
        if estimated:
            lines.append(("indeterminate",
                          "Estimated (lumen): sized on the lumen where the outer wall was not traced."))
        if recommendation.get("summary"):
            lines.append(("text", str(recommendation["summary"])))
        for reason in recommendation["reasons"]:
            lines.append(("text", reason))
    site = report.get("proximalSite")
    if site is not None:
        source = site.get("source")
        where = PROXIMAL_SITE_SOURCES.get(source, "source %r" % source)
        kind = "warning" if source in ("top", "notFound") else "text"
        lines.append((kind, "Proximal implantation site from %s." % where))
    for family in report.get("families", []):
        counts = collections.Counter(c.get("status") for c in family["checks"])
        entry = family["entry"]
        status = IFU_STATUS_WORDS.get(entry.get("ifuStatus"))
        qualifiers = ", ".join(q for q in (status, _estimatedText(entry)[3:]) if q)
        lines.append(
            (
                "heading",
                "%s%s: %d pass, %d fail, %d indeterminate"
                % (family["family"], " (%s)" % qualifiers if qualifiers else "", counts["pass"], counts["fail"],
                   counts["indeterminate"]),
            )
        )
        for check in family["checks"]:
            status = check.get("status")
            if status in ("fail", "indeterminate"):
                text = check.get("text") or check.get("criterion", "?")
                lines.append((status, text))
        configuration = _dict(entry.get("configuration"))
        if configuration is not None and configuration.get("configured") is False:
            reason = configuration.get("unknownReason") or "no reason given"
            lines.append(("indeterminate", "Not configured: %s." % reason))
        elif configuration is not None and configuration.get("orderList"):
            lines.append(("text", "Order list: %s" % configuration["orderList"]))
    neck = report.get("hostileNeck")
    if neck:
        lines.append(("heading", "Hostile-neck rules"))
        if neck.get("summary"):
            decided = withReportVerdicts({"hostileNeck": None}, report)["hostileNeck"]
            kind = {True: "fail", False: "ok"}.get(decided, "indeterminate")
            lines.append((kind, str(neck["summary"])))
        for check in _list(neck.get("checks")):
            if isinstance(check, dict) and check.get("status") in ("fail", "indeterminate"):
                lines.append((check["status"], str(check.get("text") or check.get("name", "?"))))
    if report.get("notSimulated"):
        lines.append(("fail", "No stent graft was simulated: %s." % report["notSimulated"]))
    fitCheck = report.get("fitCheck")
    if fitCheck:
        simulated = report.get("simulatedFamily") or (report.get("deployment") or {}).get("family")
        lines.append(("heading", "Fit check of the simulated graft" + (" (%s)" % simulated if simulated else "")))
        lines.extend(fitCheckLines(fitCheck, _family(report, simulated)))
    for warning in report.get("warnings", []):
        lines.append(("warning", "Warning: " + warning))
    return lines


_HTML_COLOURS = {"ok": "#1a7f37", "fail": "#cf222e", "indeterminate": "#9a6700", "warning": "#9a6700"}


def linesHtml(lines):
    """(kind, text) lines as rich text for a QLabel: headings bold, verdicts coloured, text indented;
    every text escaped. "" for no line."""
    parts = []
    for kind, text in lines:
        escaped = html.escape(text)
        if kind == "heading":
            parts.append("<b>%s</b>" % escaped)
        elif kind in _HTML_COLOURS:
            parts.append('<span style="color:%s">%s</span>' % (_HTML_COLOURS[kind], escaped))
        else:
            parts.append("&nbsp;&nbsp;" + escaped)
    return "<br>".join(parts)


def recommendationHtml(report):
    """The recommendation as rich text for a QLabel (every text escaped)."""
    return linesHtml(recommendationLines(report)) or "The report holds no device recommendation."


def measurementSummaryLines(values, measurementRows=()):
    """One "label, wall: value unit (estimated)" line per return value, in RETURN_VALUES order (the
    wall only on diameters, the flag only where the measurements table marks the value)."""
    lines = []
    for label, value, wall, estimated in resultsTableRows(values, measurementRows):
        lines.append("%s%s: %s%s" % (label, ", " + wall if wall else "", value, " (estimated)" if estimated else ""))
    return lines
