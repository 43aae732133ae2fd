"""Reading what the StentGraftSimulation CLI returns, and formatting the device recommendation.

Three things come back from a run besides the nodes Slicer loads itself:

- return parameters (``--returnparameterfile``; read in Slicer with
  ``cliNode.GetParameterAsString(name)``): ``readReturnValues``;
- the diameter profile table (columns vessel, abscissaMm, meanDiameterMm, minDiameterMm,
  maxDiameterMm, areaDiameterMm; one row per centerline sample of aorta, rightIliac and leftIliac):
  ``profileSeries`` splits it into one series per vessel for the plot;
- the JSON report (``"format": "StentGraftPlanner.report/1"``): ``parseReport`` normalises it,
  treating every missing section as "not shown" rather than an error, and
  ``recommendationLines``/``recommendationHtml`` turn it into the panel's text.

Units: millimetres, degrees and percent, as the CLI writes them. Coordinates in the report are
LPS (the CLI's frame); nothing here converts them.
"""

import collections
import csv
import html
import io
import json
import math

REPORT_FORMAT = "StentGraftPlanner.report/1"

ReturnValue = collections.namedtuple("ReturnValue", "name kind unit label missing")
ReturnValue.__doc__ = """One return parameter of the CLI that the panel reads.

name: the XML <name>.
kind: "float" or "str".
unit: "mm", "deg", "%" or "" (a ratio), for display.
label: the panel's text.
missing: the text the CLI writes when it does not have the value, where that text cannot be a
    real value (then it is read as None); None where it can, and is read as the value.
"""

#: The CLI writes every return value of the XML; one it does not have (not measured, a stage not
#: run) as -1 for a number, "none" for a text (Logic/Pipeline/PlanValues.h).
NOT_MEASURED = "-1"
NO_VALUE = "none"


def _number(name, unit, label, missing=NOT_MEASURED):
    """A number that cannot be negative (diameter, length, angle, tortuosity, device size): its -1
    is always "not measured". A signed one passes missing=None."""
    return ReturnValue(name, "float", unit, label, missing)


def _text(name, label, missing=NO_VALUE):
    return ReturnValue(name, "str", "", label, missing)


#: The CLI's return parameters this module reads, in display order. Which ones read -1 (or
#: "none") as missing follows the XML's descriptions; check_cli_contract.py derives it from there.
RETURN_VALUES = (
    _number("proximalNeckDiameter", "mm", "(a) proximal neck diameter"),
    _number("neckDiameter15mm", "mm", "(b) neck diameter 15 mm below"),
    _number("maxAneurysmDiameter", "mm", "(c) maximum aneurysm diameter"),
    _number("distalNeckMinDiameter", "mm", "(d) distal neck minimum diameter"),
    _number("rightIliacDiameter", "mm", "(e) right iliac diameter"),
    _number("leftIliacDiameter", "mm", "(f) left iliac diameter"),
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
    _number("rightAccessMinDiameter", "mm", "right access minimum diameter"),
    _number("leftAccessMinDiameter", "mm", "left access minimum diameter"),
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


def readReturnValues(getParameterAsString):
    """The return values of a finished run.

    getParameterAsString: a function name -> str (``cliNode.GetParameterAsString`` in Slicer).
    Returns name -> float, str or None. None where the text is empty or unreadable, where the CLI
    wrote its "not measured" text (-1, none) for a value that cannot take it (``ReturnValue.missing``),
    and for a computed value one of whose operands is None (``COMPUTED_FROM``).
    """
    values = {}
    for item in RETURN_VALUES:
        text = (getParameterAsString(item.name) or "").strip()
        if item.kind == "str":
            values[item.name] = None if not text or text == item.missing else text
            continue
        value = _toFloat(text)
        if value is not None and item.missing is not None and value == float(item.missing):
            value = None
        values[item.name] = value
    for name, operands in COMPUTED_FROM.items():
        if any(values[operand] is None for operand in operands):
            values[name] = None
    return values


def formatValue(value, unit):
    """"23.4 mm", "12 deg", "1.05", or "not measured" for None."""
    if value is None:
        return "not measured"
    if isinstance(value, str):
        return value
    text = "%.1f" % value
    return "%s %s" % (text, unit) if unit else "%.2f" % value


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
    of str), recommendation (dict or None), families (list of dicts, each with a list of checks)
    and fitCheck (dict or None).
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
    }


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


def measurementSummaryLines(values):
    """One "label: value unit" line per return value, in RETURN_VALUES order."""
    return ["%s: %s" % (item.label, formatValue(values.get(item.name), item.unit)) for item in RETURN_VALUES]
