"""Reading what the StentGraftSimulation CLI returns, and formatting the device recommendation.

Four things come back from a run besides the nodes Slicer loads itself:

- return parameters (``--returnparameterfile``; read in Slicer with
  ``cliNode.GetParameterAsString(name)``): ``readReturnValues``;
- the measurements table (columns name, value, unit, definition, vessel, abscissaMm, the ring's
  min/max/area diameters, wall and estimated): ``estimatedNames`` reads which outer-wall diameters
  sit at a level less than 60 % supported, and ``resultsTableRows`` makes the panel's table of every
  return value with its wall (outer wall or lumen), "not measured" and the estimated flag;
- the diameter profile table (columns vessel, abscissaMm, meanDiameterMm, minDiameterMm,
  maxDiameterMm, areaDiameterMm; one row per centerline sample of aorta, rightIliac and leftIliac):
  ``profileSeries`` splits it into one series per vessel for the plot;
- the JSON report (``"format": "StentGraftPlanner.report/1"``): ``parseReport`` normalises it,
  treating every missing section as "not shown" rather than an error; ``withReportVerdicts`` lets
  its hostile-neck assessment tell a passed neck from an undecided one (the return value is false
  for both); ``recommendationLines``/``recommendationHtml`` turn it into the panel's text.

Units: millimetres, degrees, percent and millilitres, as the CLI writes them. Coordinates in the report are
LPS (the CLI's frame); nothing here converts them.
"""

import collections
import csv
import html
import io
import json
import math

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

PROFILE_COLUMNS = ("abscissaMm", "meanDiameterMm", "minDiameterMm", "maxDiameterMm", "areaDiameterMm")
PROFILE_VESSELS = ("aorta", "rightIliac", "leftIliac")

PROXIMAL_SITE_SOURCES = {
    "landmark": "the lowest-renal landmark you placed",
    "renal": "the lowest renal artery found on the centerlines",
    "top": "the top of the aortic centerline: no renal artery was found, so place the lowest-renal "
    "landmark and run again for a true proximal neck",
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


def readReturnValues(getParameterAsString):
    """The return values of a finished run.

    getParameterAsString: a function name -> str (``cliNode.GetParameterAsString`` in Slicer).
    Returns name -> float, str, bool or None. None where the text is empty or unreadable, where the
    CLI wrote its "not measured" text (-1, none) for a value that cannot take it
    (``ReturnValue.missing``), for a computed value one of whose operands is None
    (``COMPUTED_FROM``), and for a false verdict one of whose quantities is None (``DECIDED_FROM``).
    """
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


def formatValue(value, unit):
    """"23.4 mm", "12 deg", "1.05", "Yes"/"No" for a verdict, or "not measured" for None."""
    if value is None:
        return "not measured"
    if isinstance(value, bool):
        return "Yes" if value else "No"
    if isinstance(value, str):
        return value
    text = "%.1f" % value
    return "%s %s" % (text, unit) if unit else "%.2f" % value


def formatReturnValue(item, value):
    """``formatValue``, but "not determined" for a verdict (a bool) that is None."""
    if item.kind == "bool" and value is None:
        return "not determined"
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
    fitCheck (dict or None) and hostileNeck (dict or None: the neck's assessment against the
    hostile-neck rules, read as {"hostile": bool, "determinate": bool, "summary": str, "checks":
    [{"name", "status", "text", ...}]}, every field optional).
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


def _mm(value):
    number = _toFloat(value)
    return "?" if number is None else ("%g" % number)


def _fitCheckLines(fitCheck, prefix="", depth=0):
    """Generic lines for the fit-check section (its fields are the CLI's to extend)."""
    lines = []
    for key, value in fitCheck.items():
        label = prefix + str(key)
        if isinstance(value, dict) and depth < 2:
            lines.extend(_fitCheckLines(value, label + " ", depth + 1))
        elif isinstance(value, list):
            for item in value:
                if isinstance(item, dict):
                    text = item.get("text") or ", ".join("%s %s" % kv for kv in sorted(item.items()))
                    kind = "fail" if item.get("status") == "fail" else "text"
                    lines.append((kind, "%s: %s" % (label, text)))
                else:
                    lines.append(("text", "%s: %s" % (label, item)))
        elif isinstance(value, bool):
            lines.append(("text", "%s: %s" % (label, "yes" if value else "no")))
        elif isinstance(value, float):
            lines.append(("text", "%s: %.1f" % (label, value)))
        else:
            lines.append(("text", "%s: %s" % (label, value)))
    return lines


def recommendationLines(report):
    """The recommendation as (kind, text) lines; kind is heading, ok, fail, indeterminate,
    warning or text. A section missing from the report adds no line."""
    lines = []
    recommendation = report.get("recommendation")
    if recommendation is not None:
        status = recommendation.get("status")
        if status == "recommended":
            lines.append(
                (
                    "ok",
                    "Recommended: %s, main body %s mm, right limb %s mm, left limb %s mm"
                    % (
                        recommendation.get("family", "?"),
                        _mm(recommendation.get("mainBodyDiameterMm")),
                        _mm(recommendation.get("rightLimbDiameterMm")),
                        _mm(recommendation.get("leftLimbDiameterMm")),
                    ),
                )
            )
        elif status == "noDeviceWithinIfu":
            lines.append(("fail", "No device of the catalogue is within its instructions for use."))
        elif status == "outsideIfu":
            lines.append(("fail", "%s is outside its instructions for use." % recommendation.get("family")))
        else:
            lines.append(("indeterminate", "Device recommendation: unknown status %r." % status))
        if recommendation.get("summary"):
            lines.append(("text", str(recommendation["summary"])))
        for reason in recommendation["reasons"]:
            lines.append(("text", reason))
    site = report.get("proximalSite")
    if site is not None:
        source = site.get("source")
        where = PROXIMAL_SITE_SOURCES.get(source, "source %r" % source)
        kind = "warning" if source == "top" else "text"
        lines.append((kind, "Proximal implantation site from %s." % where))
    for family in report.get("families", []):
        counts = collections.Counter(c.get("status") for c in family["checks"])
        lines.append(
            (
                "heading",
                "%s: %d pass, %d fail, %d indeterminate"
                % (family["family"], counts["pass"], counts["fail"], counts["indeterminate"]),
            )
        )
        for check in family["checks"]:
            status = check.get("status")
            if status in ("fail", "indeterminate"):
                text = check.get("text") or check.get("criterion", "?")
                lines.append((status, text))
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
    fitCheck = report.get("fitCheck")
    if fitCheck:
        lines.append(("heading", "Fit check of the simulated graft"))
        lines.extend(_fitCheckLines(fitCheck))
    for warning in report.get("warnings", []):
        lines.append(("warning", "Warning: " + warning))
    return lines


_HTML_COLOURS = {"ok": "#1a7f37", "fail": "#cf222e", "indeterminate": "#9a6700", "warning": "#9a6700"}


def recommendationHtml(report):
    """The recommendation as rich text for a QLabel (every text escaped)."""
    parts = []
    for kind, text in recommendationLines(report):
        escaped = html.escape(text)
        if kind == "heading":
            parts.append("<b>%s</b>" % escaped)
        elif kind in _HTML_COLOURS:
            parts.append('<span style="color:%s">%s</span>' % (_HTML_COLOURS[kind], escaped))
        else:
            parts.append("&nbsp;&nbsp;" + escaped)
    return "<br>".join(parts) if parts else "The report holds no device recommendation."


def measurementSummaryLines(values, measurementRows=()):
    """One "label, wall: value unit (estimated)" line per return value, in RETURN_VALUES order (the
    wall only on diameters, the flag only where the measurements table marks the value)."""
    lines = []
    for label, value, wall, estimated in resultsTableRows(values, measurementRows):
        lines.append("%s%s: %s%s" % (label, ", " + wall if wall else "", value, " (estimated)" if estimated else ""))
    return lines
