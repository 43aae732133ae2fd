"""The panel's Re-plan (issue 45 item 3), without Slicer.

After a run the landmarks the CLI found or was given are an editable markups node. The surgeon drags
one (or edits the lumen segment in Segment Editor) and presses Re-plan: the run starts from the
edited landmarks and, unless the lumen was edited, from the lumen the last run produced, so the
region growing is not repeated. The panel then shows what changed, old → new.

- ``landmarksFromMarkups`` (the CLI's ``--outputLandmarks`` file, Slicer markups JSON) and
  ``landmarksFromControlPoints`` (the markups node's points) read the four landmarks that are CLI
  inputs (``EDITABLE_LANDMARKS``) with whether each was given; ``landmarksToText`` and
  ``landmarksFromText`` keep the last run's landmarks in the parameter node.
- ``movedLandmarks``: which of them the surgeon moved (``MOVE_TOLERANCE_MM``).
- ``lumenFingerprint`` and ``lumenEdited``: whether the lumen segment differs from the one the last
  run produced.
- ``replanParameters``: the re-plan's CLI parameters from the previous run's.
- ``resultsSnapshot``, ``changeLines`` and ``replanHtml``: what a run showed, at clinical precision
  and in words (Results.py's labels and formats, OrderList.py's components), and the lines that
  differ between two runs.

Frames: landmarks are held in LPS millimetres, the CLI's frame and its landmarks file's. The CLI's
point inputs are RAS (``coordinateSystem="ras"`` in the XML: the markups node's own coordinates), so
a landmark becomes RAS once, in ``replanParameters``, where it becomes a CLI parameter (``lpsToRas``).
"""

import collections
import hashlib
import json
import math

from . import OrderList, Results

#: The landmarks the surgeon can move, in the landmarks file's labels, which are also the CLI's point
#: parameters (--lowestRenalOstium, --aorticBifurcation, --rightInternalIliacOrigin,
#: --leftInternalIliacOrigin). The file's other points (renal, coeliac, mesenteric ostia, iliac
#: bifurcations) are informational: no CLI input takes them.
EDITABLE_LANDMARKS = ("lowestRenalOstium", "aorticBifurcation", "rightInternalIliacOrigin", "leftInternalIliacOrigin")

#: The landmarks in words, for the panel.
LANDMARK_WORDS = {
    "lowestRenalOstium": "lowest renal ostium (proximal site)",
    "aorticBifurcation": "aortic bifurcation",
    "rightInternalIliacOrigin": "right internal iliac origin",
    "leftInternalIliacOrigin": "left internal iliac origin",
}

#: How far a landmark must move to count as moved, in mm. Well below a CT voxel (0.6-1 mm in plane,
#: 1-3 mm between slices): a point left where it was reads back within 0.001 mm (the landmarks file
#: keeps 0.0001 mm, Slicer sends six significant digits), while a click that only selects a point can
#: nudge it by a fraction of a screen pixel. A smaller deliberate move would shift the centerline
#: point the CLI projects it onto by less than one centerline step (1 mm by default), so taking it
#: as given would change nothing but the landmark's source.
MOVE_TOLERANCE_MM = 0.5

#: The description the CLI starts a landmark's control point with when the user gave it ("Given by
#: the user."); a found one starts with "Found".
GIVEN_PREFIX = "Given"

#: The label map the CLI writes (outputLabelMap) holds the lumen as 1 and the background as 0, so the
#: re-plan takes every non-zero voxel: lumenLabels empty. A previous run's lumenLabels (e.g. the
#: values of a TotalSegmentator map) would name labels this map does not have.
REPLAN_LUMEN_LABELS = ""

Landmark = collections.namedtuple("Landmark", "lps given")
Landmark.__doc__ = """One editable landmark: lps, its (L, P, S) position in mm; given, whether the
user gave it (the CLI's description starts with "Given") rather than the plan finding it."""


def lpsToRas(point):
    """(x, y, z) LPS -> (-x, -y, z) RAS, in mm (the same flip turns RAS back into LPS)."""
    x, y, z = (float(c) for c in point)
    return (-x, -y, z)


rasToLps = lpsToRas


def _point(value, what):
    """Three finite floats from a position, or ValueError naming ``what``."""
    try:
        point = tuple(float(c) for c in value)
    except (TypeError, ValueError):
        point = ()
    if len(point) != 3 or not all(math.isfinite(c) for c in point):
        raise ValueError("The position of %s is %r, expected three finite numbers in mm." % (what, value))
    return point


def landmarksFromControlPoints(points):
    """The editable landmarks of a list of control points.

    points: (label, description, ras) for each control point whose position is defined, as the
        markups node holds them (its own coordinates, RAS mm).
    Returns label -> Landmark (LPS) for the labels of EDITABLE_LANDMARKS; the first point of a label
    counts (the CLI writes each once). Other labels are ignored. ValueError for an unreadable position.
    """
    landmarks = {}
    for label, description, ras in points:
        if label in EDITABLE_LANDMARKS and label not in landmarks:
            given = str(description or "").startswith(GIVEN_PREFIX)
            landmarks[label] = Landmark(rasToLps(_point(ras, label)), given)
    return landmarks


def landmarksFromMarkups(markups):
    """The editable landmarks of a Slicer markups JSON document (the CLI's --outputLandmarks file).

    markups: its text or the parsed dict. Positions are read in the markup's coordinateSystem ("LPS",
    the CLI's and Slicer's default since 5.0, or "RAS"; absent: LPS) and returned in LPS. Control
    points whose positionStatus is not "defined" are skipped. Returns label -> Landmark; ValueError
    when the document is not markups JSON or a coordinate system is unknown.
    """
    data = json.loads(markups) if isinstance(markups, str) else markups
    if not isinstance(data, dict) or not isinstance(data.get("markups"), list):
        raise ValueError("The landmarks are not a Slicer markups JSON document (no 'markups' list).")
    points = []
    for markup in data["markups"]:
        if not isinstance(markup, dict):
            continue
        system = str(markup.get("coordinateSystem") or "LPS").upper()
        if system not in ("LPS", "RAS"):
            raise ValueError("The landmarks' coordinate system is %r, expected LPS or RAS."
                             % markup.get("coordinateSystem"))
        for point in markup.get("controlPoints") or []:
            if not isinstance(point, dict) or point.get("positionStatus", "defined") != "defined":
                continue
            label = point.get("label")
            position = _point(point.get("position"), label)
            points.append((label, point.get("description"), position if system == "RAS" else lpsToRas(position)))
    return landmarksFromControlPoints(points)


def landmarksToText(landmarks):
    """Landmarks as a parameter-node string (JSON: label -> {"lps": [x, y, z], "given": bool})."""
    return json.dumps({label: {"lps": list(mark.lps), "given": bool(mark.given)}
                       for label, mark in landmarks.items()}, sort_keys=True)


def landmarksFromText(text):
    """Landmarks back from ``landmarksToText``; {} for an empty text, ValueError for an unreadable one."""
    if not text:
        return {}
    try:
        data = json.loads(text)
        return {label: Landmark(_point(entry["lps"], label), bool(entry["given"])) for label, entry in data.items()
                if label in EDITABLE_LANDMARKS}
    except (AttributeError, KeyError, TypeError, ValueError) as error:
        raise ValueError("The landmarks of the last run, stored in the scene, cannot be read (%s); press Apply "
                         "for a new run." % error)


def distanceMm(a, b):
    """Distance between two points, in mm."""
    return math.dist(a, b)


def movedLandmarks(previous, edited, toleranceMm=MOVE_TOLERANCE_MM):
    """The labels of the landmarks the surgeon moved, in EDITABLE_LANDMARKS order.

    previous, edited: label -> Landmark, after the last run and now. A landmark counts as moved when
    it lies more than toleranceMm from where the last run put it, or is new (placed where the last
    run had none). One deleted from the list is not moved: what the last run was given stays given,
    and one it found is found again. ValueError for a negative or non-finite tolerance.
    """
    if not (math.isfinite(toleranceMm) and toleranceMm >= 0):
        raise ValueError("The landmark tolerance %r mm must be a finite number of 0 or more." % toleranceMm)
    moved = []
    for label in EDITABLE_LANDMARKS:
        now = edited.get(label)
        before = previous.get(label)
        if now is not None and (before is None or distanceMm(now.lps, before.lps) > toleranceMm):
            moved.append(label)
    return moved


def lumenFingerprint(shape, data):
    """A digest of a lumen mask: its shape (array dimensions) and its voxels (bytes). Two masks with the
    same fingerprint hold the same voxels."""
    digest = hashlib.sha256(repr(tuple(int(n) for n in shape)).encode("ascii"))
    digest.update(data)
    return digest.hexdigest()


def lumenEdited(fingerprintAfterRun, fingerprintNow):
    """Whether the lumen segment was edited since the last run.

    fingerprintAfterRun: ``lumenFingerprint`` of the segment the last run produced ("" when not
        recorded, e.g. a scene saved by an older version: then the segment as it is now is taken, which
        is the run's own lumen when nobody edited it).
    fingerprintNow: of the segment now; "" when it is gone, a ValueError: nothing to plan on.
    """
    if not fingerprintNow:
        raise ValueError("The lumen segment of the last run is gone (deleted from the segmentation), so there is "
                         "no lumen to re-plan on; undo the deletion, or press Apply to segment the lumen again.")
    return not fingerprintAfterRun or fingerprintAfterRun != fingerprintNow


ReplanInputs = collections.namedtuple("ReplanInputs", "parameters moved givenAgain lumenEdited")
ReplanInputs.__doc__ = """A re-plan's CLI parameters and what they were made from.

parameters: the dictionary for the CLI (as Settings.buildCliParameters makes it).
moved: labels of the landmarks the surgeon moved, now given to the CLI at their new positions.
givenAgain: labels of the landmarks the last run was given and that are given again, unmoved.
lumenEdited: whether the lumen passed is the surgeon's edited one (else the last run's).
"""


def _rasList(label, ras):
    return list(ras)


def replanParameters(previousParameters, previousLandmarks, editedLandmarks, previousLumen=None, editedLumen=None,
                     pointInput=_rasList, toleranceMm=MOVE_TOLERANCE_MM):
    """The CLI parameters of a re-plan.

    previousParameters: the previous run's parameter dictionary (settings, inputs, outputs); not changed.
    previousLandmarks, editedLandmarks: label -> Landmark (LPS) after the last run and now.
    previousLumen: the lumen label map the last run wrote (its node or path); None: the previous
        run's outputLabelMap.
    editedLumen: the label map of the lumen as the surgeon edited it, or None when it was not edited.
    pointInput: (label, ras) -> the value of a point parameter: a markups node holding that one point
        in Slicer; by default [R, A, S], which Testing/CLI/sem_rules.py passes as Slicer does.
    toleranceMm: as for movedLandmarks.

    Returns ReplanInputs. In the parameters:
    - each moved landmark is given at its new position, in RAS (it replaces a point the previous run
      was given for it);
    - each landmark the previous run was given and the surgeon did not move stays given: the previous
      parameter when there was one (the user's own point), else the landmark's position (a point given
      by an earlier re-plan);
    - a landmark the previous run found and nobody moved is not passed: the CLI finds it again, on
      the same lumen, in the same place;
    - inputLumenSegmentation is the edited lumen, else the previous one, so the region growing is not
      repeated; lumenLabels is emptied (REPLAN_LUMEN_LABELS).
    ValueError when there is no lumen to pass.
    """
    lumen = editedLumen if editedLumen is not None else (
        previousLumen if previousLumen is not None else previousParameters.get("outputLabelMap"))
    if lumen is None:
        raise ValueError("The last run's lumen label map is not available, so the re-plan has no lumen to start "
                         "from; press Apply for a new run.")
    parameters = dict(previousParameters)
    moved = movedLandmarks(previousLandmarks, editedLandmarks, toleranceMm)
    givenAgain = []
    for label in EDITABLE_LANDMARKS:
        before = previousLandmarks.get(label)
        if label in moved:
            parameters[label] = pointInput(label, lpsToRas(editedLandmarks[label].lps))
        elif before is not None and before.given:
            givenAgain.append(label)
            if parameters.get(label) is None:
                parameters[label] = pointInput(label, lpsToRas(before.lps))
    parameters["inputLumenSegmentation"] = lumen
    parameters["lumenLabels"] = REPLAN_LUMEN_LABELS
    return ReplanInputs(parameters, moved, givenAgain, editedLumen is not None)


#: Return values the change list leaves out: the order list's text is shown component by component.
_SNAPSHOT_SKIPPED = frozenset(("orderList",))

#: The fit check's seal lengths (the report's fitCheck), shown as the fit check's lines name them.
_SEAL_ENTRIES = (
    ("proximalSealLengthMm", "Proximal seal on healthy wall"),
    ("rightIliacSealLengthMm", "Right iliac seal on healthy wall"),
    ("leftIliacSealLengthMm", "Left iliac seal on healthy wall"),
)

#: A component's place in the graft, in words, by its role (limbs named by side, not by role, so that
#: a limb that stays on its side but changes role still compares with itself).
_COMPONENT_PLACES = {"mainBody": "main body", "ipsilateralLimb": "limb", "contralateralLimb": "limb",
                     "iliacExtension": "iliac extension", "aorticCuff": "aortic cuff"}

#: What the change list shows for a component one of the two runs does not have.
NO_COMPONENT = "none"


def _capitalized(text):
    return text[:1].upper() + text[1:]


def _componentEntries(report):
    entries, counts = [], collections.Counter()
    for component in Results._list((report.get("deployment") or {}).get("components")):
        if not isinstance(component, dict):
            continue
        role = component.get("role")
        place = _COMPONENT_PLACES.get(role, Results._words(role or "component"))
        side = OrderList.componentSide(component)
        label = _capitalized((side + " " if side else "") + place)
        counts[label] += 1
        if counts[label] > 1:
            label += " %d" % counts[label]
        entries.append(("component:" + label, label, OrderList.componentProductText(component)))
    return entries


def resultsSnapshot(values, report):
    """What a run showed, as [key, label, text] entries at clinical precision and in words.

    values: the return values (Results.readReturnValues, withReportVerdicts); report: the parsed
    report (Results.parseReport). The entries: every return value the panel's table shows
    (Results.RETURN_VALUES, the order list's text aside), labelled as there (a diameter with its wall)
    and formatted as there (Results.formatReturnValue); the fit check's three seal lengths; each
    component of the order list (OrderList.componentProductText) under its place ("Right limb").
    JSON-serialisable, so the parameter node can keep it (``json.dumps``).
    """
    entries = []
    for item in Results.RETURN_VALUES:
        if item.name in _SNAPSHOT_SKIPPED:
            continue
        label = item.label + (", " + Results.WALL_TEXT[item.wall] if item.wall else "")
        entries.append([item.name, _capitalized(label), Results.formatReturnValue(item, values.get(item.name))])
    fitCheck = report.get("fitCheck") or {}
    for key, label in _SEAL_ENTRIES:
        entries.append(["fitCheck:" + key, label, Results._mm(fitCheck.get(key))])
    entries.extend([key, label, text] for key, label, text in _componentEntries(report))
    return entries


def changeLines(before, after):
    """The entries of two snapshots (``resultsSnapshot``) that differ, as "Label: old → new" lines.

    Entries are compared as shown, so a value equal at clinical precision is no change. In the order of
    ``after``, then the components only ``before`` has; a component one run does not have reads
    NO_COMPONENT.
    """
    old = {entry[0]: entry for entry in before}
    new = {entry[0]: entry for entry in after}
    lines = []
    for key, label, text in after:
        previous = old[key][2] if key in old else NO_COMPONENT
        if previous != text:
            lines.append("%s: %s → %s" % (label, previous, text))
    for key, label, text in before:
        if key not in new:
            lines.append("%s: %s → %s" % (label, text, NO_COMPONENT))
    return lines


def snapshotFromText(text):
    """A snapshot kept in the parameter node (``json.dumps`` of resultsSnapshot); None for an empty or
    unreadable text (no change list can be made then)."""
    try:
        entries = json.loads(text) if text else None
    except ValueError:
        return None
    if not isinstance(entries, list) or not all(isinstance(e, list) and len(e) == 3 for e in entries):
        return None
    return entries


def replanLines(replan, changes):
    """The panel's account of a re-plan as (kind, text) lines (kinds as Results.recommendationLines):
    what it started from (the landmarks moved and given again, the lumen), then each change."""
    lines = [("heading", "Re-plan: what changed since the last run")]
    for label in replan.moved:
        lines.append(("text", "%s: moved by you, given to the plan" % _capitalized(LANDMARK_WORDS[label])))
    for label in replan.givenAgain:
        lines.append(("text", "%s: your point of the last run, given again" % _capitalized(LANDMARK_WORDS[label])))
    lines.append(("text", "Lumen: as you edited it" if replan.lumenEdited
                  else "Lumen: the last run's (region growing not repeated)"))
    if changes is None:
        lines.append(("indeterminate", "The last run's results are not kept in this scene, so the changes "
                                       "cannot be listed."))
    elif not changes:
        lines.append(("ok", "Nothing changed at clinical precision."))
    lines.extend(("text", line) for line in changes or [])
    return lines


def replanHtml(replan, changes):
    """``replanLines`` as rich text for a QLabel (every text escaped)."""
    return Results.linesHtml(replanLines(replan, changes))
