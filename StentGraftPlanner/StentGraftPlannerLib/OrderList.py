"""The order list of a StentGraftSimulation run, as the panel shows it (issue 29).

From the JSON report's ``deployment`` (Logic/IO/DeploymentToJson.h; parsed by
``Results.parseReport``): ``orderListLines`` — the family, the side the main body goes up and why,
its IFU status, one line per component to order (role, name, diameters × length, catalogue code,
where it lies from the proximal edge), the overlaps against their windows, each side's covered
length and planned seal, the findings with their options, the notes and the alternatives; or why
the configuration is not known — ``anatomyLines``, the lengths along the centerlines it was chosen
from, and ``orderListHtml``, both side by side as rich text for a QLabel. Lines are (kind, text)
pairs with the kinds of ``Results.recommendationLines``.

Units: millimetres, shown at 0.1 mm (catalogue sizes as the catalogue writes them: "25", "14.5").
"""

import math

from .Results import (
    IFU_STATUS_SENTENCES,
    _IFU_KINDS,
    _dict,
    _estimatedText,
    _family,
    _list,
    _mm,
    _size,
    _toFloat,
    _words,
    clinicalNumber,
    linesHtml,
)


#: The components' roles in words (the report's deployment.components[].role).
ROLE_WORDS = {
    "mainBody": "main body",
    "ipsilateralLimb": "ipsilateral limb",
    "contralateralLimb": "contralateral limb",
    "iliacExtension": "iliac extension",
    "aorticCuff": "aortic cuff",
}

#: The side of a vessel a component's distal edge lies in.
_VESSEL_SIDES = {"rightIliac": "right", "leftIliac": "left"}

#: The proximal implantation site's source in a few words (the order list's landmark).
_SITE_WORDS = {"renal": "the lowest renal ostium", "landmark": "the lowest renal ostium",
               "top": "the top of the aortic centerline"}


def _siteWords(report):
    return _SITE_WORDS.get((report.get("proximalSite") or {}).get("source"), "the proximal implantation site")


def _proximalEdgeText(report, deployment):
    """Where the main body's proximal edge is deployed: "at the lower edge of the lowest renal ostium",
    "5.0 mm below the lower edge of …", or "" when the report does not give both positions."""
    target = _toFloat((_dict(deployment.get("anatomy")) or {}).get("deploymentTargetAbscissaMm"))
    site = _toFloat((report.get("proximalSite") or {}).get("abscissaMm"))
    if target is None or site is None:
        return ""
    where = _siteWords(report)
    edge = "the lower edge of " + where if "ostium" in where else where
    offset = target - site
    if abs(offset) < 0.05:
        return "at " + edge
    return "%s %s %s" % (_mm(abs(offset)), "below" if offset > 0 else "above", edge)


def componentSide(component):
    """"right" or "left" for a component in an iliac (a limb, an iliac extension), else None."""
    if component.get("role") in ("mainBody", "aorticCuff"):
        return None
    return _VESSEL_SIDES.get(component.get("vessel"))


def componentProductText(component):
    """What is ordered, as the catalogue sizes it: "Excluder contralateral leg 14.5 × 100 mm (PLC141000)";
    a tapered one "26-14.5 × 120 mm"; "code not public" where the catalogue gives no code."""
    diameter, distal = _toFloat(component.get("diameterMm")), _toFloat(component.get("distalDiameterMm"))
    diameters = _size(diameter if diameter is not None else distal)
    if diameter is not None and distal is not None and distal != diameter:
        diameters += "-" + _size(distal)
    code = component.get("catalogueCode") or "code not public"
    return "%s %s × %s mm (%s)" % (component.get("name", "?"), diameters, _size(component.get("lengthMm")), code)


def _componentLine(component, deployment, report):
    """One ordered component: role, name, diameters × length, catalogue code, and where it lies."""
    role = component.get("role")
    words = ROLE_WORDS.get(role, _words(role or "component"))
    side = componentSide(component)
    text = "%s%s: %s" % (side + " " if side else "", words, componentProductText(component))
    ends = _list(component.get("fromTargetMm"))
    proximal, distalEnd = (_toFloat(ends[0]), _toFloat(ends[1])) if len(ends) == 2 else (None, None)
    if role == "mainBody":
        edge = _proximalEdgeText(report, deployment)
        parts = ["proximal edge " + edge] if edge else []
        if deployment.get("flowDividerMm") is not None and deployment.get("gateEndMm") is not None:
            parts.append("flow divider %s and contralateral gate end %s below it (%s above the aortic bifurcation)"
                         % (_mm(deployment["flowDividerMm"]), _mm(deployment["gateEndMm"]),
                            _mm(deployment.get("gateClearanceMm"))))
        if distalEnd is not None:
            parts.append("ipsilateral leg to %s" % _mm(distalEnd))
        return text + (", " + ", ".join(parts) if parts else "")
    if proximal is not None and distalEnd is not None:
        text += ", from %s to %s below the proximal edge" % (_mm(proximal), _mm(distalEnd))
    holds = holdsText(component)
    return text + ("; " + holds if holds else "")


#: What ends a component's hold range (the report's deployment.components[].holdsMm limits), above
#: and below: a failure, or a stop (it cannot go further that way).
_HOLD_LIMITS = {
    "covers": ("it covers the {side} internal iliac ostium",) * 2,
    "seal": ("the {side} iliac seal falls under the minimum",) * 2,
    "overlap": ("an overlap falls under the minimum",) * 2,
    "stop": ("it is as deep as it goes in what it is inserted into: it cannot land higher",
             "what is inserted into it is as deep as it goes: it cannot land lower"),
}


def holdsText(component):
    """How far a limb or extension may land from its plan (issue 47): "holds if it lands up to 5.0 mm
    higher (then the left iliac seal falls under the minimum) or 5.0 mm lower (then it covers the left
    internal iliac ostium)"; "" where the report gives no range (the main body, an older report)."""
    holds = _dict(component.get("holdsMm"))
    if not holds:
        return ""
    above, below = _toFloat(holds.get("above")), _toFloat(holds.get("below"))
    if above is None or below is None:
        return ""
    side = componentSide(component) or ""

    def limit(key, above):
        words = _HOLD_LIMITS.get(key, (_words(key or "a constraint"),) * 2)[0 if above else 1]
        return words.format(side=side).replace("  ", " ")

    def rangeText(mm):
        return _mm(mm) if mm >= 0 else "none (%s short)" % _mm(-mm)

    return "holds if it lands up to %s higher (then %s) or %s lower (then %s)" % (
        rangeText(above), limit(holds.get("aboveLimit"), True), rangeText(below), limit(holds.get("belowLimit"), False))


def _overlapLine(overlap):
    """("ok"/"fail", "overlap, <junction>: 31.0 mm (needs 30–34 mm)")."""
    length, low, high = (_toFloat(overlap.get(k)) for k in ("overlapMm", "minMm", "maxMm"))
    if low is None:
        needs = ""
    elif high is None:
        needs = " (needs ≥ %s)" % _mm(low)
    elif high - low < 0.05:
        needs = " (needs %s)" % _mm(low)
    else:
        needs = " (needs %s–%s)" % (clinicalNumber(low, "mm"), _mm(high))
    top = high if high is not None else math.inf
    within = length is not None and low is not None and low - 0.05 < length < top + 0.05  # 0.1 mm: as shown
    kind = "text" if length is None or low is None else ("ok" if within else "fail")
    return kind, "overlap, %s: %s%s" % (overlap.get("junction", "?"), _mm(length), needs)


def _sideLine(deployment, side):
    """"right side: covered 177.4 mm from the proximal edge; planned seal in the common iliac 52.0 mm,
    distal edge 0.0 mm above the internal iliac ostium" (None when the side's numbers are missing)."""
    covered = _toFloat(deployment.get(side + "CoveredLengthMm"))
    zone = _dict((_dict(deployment.get("landingZones")) or {}).get(side)) or {}
    seal, margin = _toFloat(zone.get("sealMm")), _toFloat(zone.get("marginToInternalIliacMm"))
    if covered is None:
        return None
    text = "%s side: covered %s from the proximal edge" % (side, _mm(covered))
    if seal is not None:
        text += "; planned seal in the common iliac %s" % _mm(seal)
    if margin is not None:
        text += (", distal edge %s above the internal iliac ostium" % _mm(margin) if margin >= 0
                 else ", distal edge %s past the internal iliac ostium (covers it)" % _mm(-margin))
    return text


def orderListLines(report, values=None):
    """The order list of the report's deployment as (kind, text) lines (kinds as recommendationLines).

    A heading (the family, the side the main body goes up and why, its IFU status, "estimated
    (lumen)" where the sizes are), one line per component (its role in words, name, diameters ×
    length and catalogue code, or "code not public"; where it lies from the proximal edge), the
    overlaps against their windows, the covered length of each side, each finding with its option,
    the notes and the alternatives. When the configuration was not made, one line says why
    (unknownReason). Without a deployment (no family has a main body, or an older report) the
    return value orderList of ``values`` is shown when there is one; else no line.
    """
    deployment = report.get("deployment")
    if not deployment:
        text = (values or {}).get("orderList")
        return [("heading", "Order list"), ("text", text)] if text else []
    familyName = deployment.get("family") or "?"
    family = _family(report, familyName)
    entry = (family or {}).get("entry", {})
    status = entry.get("ifuStatus")
    heading = ("Order list (your configuration): %s" if deployment.get("given") else "Order list: %s") % familyName
    if deployment.get("ipsilateralReason"):
        heading += ", main body from the %s" % deployment["ipsilateralReason"]
    heading += _estimatedText({"estimated": deployment.get("estimated") or entry.get("estimated"),
                               "estimatedLevels": entry.get("estimatedLevels")})
    lines = [("heading", heading)]
    if status in IFU_STATUS_SENTENCES:
        lines.append((_IFU_KINDS[status], "%s — %s." % (familyName, IFU_STATUS_SENTENCES[status])))
    if deployment.get("configured") is False:
        lines.append(("indeterminate", "Not configured: %s." % (deployment.get("unknownReason") or "no reason given")))
        return lines
    for component in _list(deployment.get("components")):
        if isinstance(component, dict):
            lines.append(("text", _componentLine(component, deployment, report)))
    lines += differenceLines(deployment)
    for overlap in _list(deployment.get("overlaps")):
        if isinstance(overlap, dict):
            lines.append(_overlapLine(overlap))
    for side in ("right", "left"):
        text = _sideLine(deployment, side)
        if text:
            lines.append(("text", text))
    lines += toleranceLines(deployment)
    for finding in _list(deployment.get("findings")):
        if isinstance(finding, dict):
            lines.append(("fail", "Finding: %s." % finding.get("text", "?")))
            if finding.get("option"):
                lines.append(("text", "Option: %s." % finding["option"]))
    for note in _list(deployment.get("notes")):
        lines.append(("warning", "Note: %s" % note))
    for alternative in _list(deployment.get("alternatives")):
        if isinstance(alternative, dict):
            lines.append(("text", "Alternative: %s." % alternative.get("text", "?")))
    return lines


def differenceLines(deployment):
    """A configuration the surgeon gave (issue 47; the report's deployment.differences): a line saying it
    is the same as the plan's recommendation, or how it differs, then one line per difference with its
    consequence ("right limb 20 mm longer (…): the right side covers …"); [] for the plan's own."""
    differences = _dict(deployment.get("differences"))
    if not deployment.get("given") or differences is None:
        return []
    recommended = differences.get("recommendedOrderList") or "none"
    items = [d for d in _list(differences.get("items")) if isinstance(d, dict)]
    if not items:
        return [("pass", "The same as the plan's recommendation (%s)." % recommended)]
    lines = [("warning", "Differs from the plan's recommendation (%s):" % recommended)]
    for item in items:
        lines.append(("text", "%s." % item.get("text", "?")))
    return lines


def toleranceLines(deployment):
    """The simulated deployment tolerance (issue 47; the report's deployment.tolerance): a heading line,
    one line per component ("main body: holds from 0.0 mm above to at least 10.0 mm below its planned
    position (…)"; "ok" where it holds the tolerance either way, "fail" where it does not), each
    finding, each note; one line saying why when it was not assessed; none for an older report."""
    tolerance = _dict(deployment.get("tolerance"))
    if not tolerance:
        return []
    if not tolerance.get("assessed"):
        reason = tolerance.get("notAssessedReason")
        return [("indeterminate", "Deployment tolerance not assessed: %s." % reason)] if reason else []
    lines = [("text", "Deployment tolerance: each component moved up to %s up and down its vessel (the others where "
                      "planned); it should hold %s either way"
              % (_mm(_toFloat(tolerance.get("searchMm"))), _mm(_toFloat(tolerance.get("toleranceMm")))))]
    for hold in _list(tolerance.get("components")):
        if isinstance(hold, dict):
            lines.append(("fail" if hold.get("finding") else "ok",
                          "%s: %s" % (hold.get("name", "?"), hold.get("text", "?"))))
    for finding in _list(tolerance.get("findings")):
        lines.append(("fail", "Finding (deployment tolerance): %s." % finding))
    for note in _list(tolerance.get("notes")):
        lines.append(("warning", "Note: %s" % note))
    return lines


def anatomyLines(report, values=None):
    """The anatomy's lengths the order list was chosen from, along the centerlines, as (kind, text).

    From the report's deployment.anatomy, measured from the main body's proximal edge: to the aortic
    bifurcation, to the flow divider where it was found, and to each internal iliac origin (the common
    iliac between B and it). Without it, from
    the return values proximalSiteToBifurcationLength, rightIliacLength and leftIliacLength (from the
    proximal site). No line when neither is there.
    """
    anatomy = _dict((report.get("deployment") or {}).get("anatomy")) or {}
    toBifurcation = _toFloat(anatomy.get("targetToBifurcationMm"))
    lines = []
    if toBifurcation is not None:
        edge = _proximalEdgeText(report, report["deployment"])
        lines.append(("heading", "Anatomy, from the proximal edge" + (" (%s)" % edge if edge else "")))
        lines.append(("text", "→ aortic bifurcation %s" % _mm(toBifurcation)))
        toDivider = _toFloat(anatomy.get("targetToFlowDividerMm"))
        if toDivider is not None:
            lines.append(("text", "→ flow divider %s (where the lumen divides; the limbs' seal is measured from it)"
                          % _mm(toDivider)))
        for side in ("right", "left"):
            toIliac = _toFloat(anatomy.get("targetTo%sInternalIliacMm" % side.capitalize()))
            common = " (common iliac %s)" % _mm(toIliac - toBifurcation) if toIliac is not None else ""
            lines.append(("text", "→ %s internal iliac origin %s%s" % (side, _mm(toIliac), common)))
        return lines
    values = values or {}
    names = ("proximalSiteToBifurcationLength", "rightIliacLength", "leftIliacLength")
    if all(values.get(name) is None for name in names):
        return []
    toBifurcation = values.get("proximalSiteToBifurcationLength")
    lines.append(("heading", "Anatomy, from %s" % _siteWords(report)))
    lines.append(("text", "→ aortic bifurcation %s" % _mm(toBifurcation)))
    for side in ("right", "left"):
        iliac = values.get(side + "IliacLength")
        total = ""
        if iliac is not None and toBifurcation is not None:
            total = " (%s from the proximal site)" % _mm(toBifurcation + iliac)
        lines.append(("text", "aortic bifurcation → %s internal iliac origin %s%s" % (side, _mm(iliac), total)))
    return lines


def orderListHtml(report, values=None):
    """The order list (``orderListLines``) beside the anatomy's lengths (``anatomyLines``), as a two-column
    rich-text table for the panel's first label; one column when only one of them has lines, "" when
    neither has."""
    columns = [linesHtml(lines) for lines in (orderListLines(report, values), anatomyLines(report, values)) if lines]
    if not columns:
        return ""
    cells = "".join('<td valign="top" style="padding-right:12px">%s</td>' % column for column in columns)
    return "<table><tr>%s</tr></table>" % cells
