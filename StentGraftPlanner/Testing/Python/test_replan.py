#!/usr/bin/python3
"""StentGraftPlannerLib.Replan: the panel's Re-plan (issue 45 item 3) without Slicer.

The landmarks are read from documents shaped as the CLI's --outputLandmarks file (Slicer markups JSON,
LPS), the change list from Data/report-deployment.json and return values written here; every expected
value is worked out by hand from the planted ones (an LPS point and its RAS negation, a length shown
at 0.1 mm), not taken from a previous run.

Run: /usr/bin/python3 -m unittest discover -s StentGraftPlanner/Testing/Python -p "test_replan.py"
"""
import copy
import json
import os
import re
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import Replan, Results  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Data")

#: LPS positions of the four editable landmarks and two informational ones, as the CLI writes them.
POSITIONS = {
    "lowestRenalOstium": (-0.2728, -0.2041, 125.2718),
    "aorticBifurcation": (-0.0275, -0.0180, -0.2894),
    "rightInternalIliacOrigin": (-23.4114, 0.0234, -50.6694),
    "leftInternalIliacOrigin": (23.4001, 0.7143, -50.5610),
    "rightRenalOstium": (-1.0, 0.5, 129.9901),
    "coeliacOstium": (0.0, -1.5, 162.9901),
}


def markups(positions=POSITIONS, given=(), system="LPS", extra=()):
    """A markups JSON document as the CLI writes it: one fiducial markup, one control point per label."""
    points = []
    for index, (label, position) in enumerate(positions.items()):
        description = ("Given by the user." if label in given else "Found: where the axes meet.") \
            if label in Replan.EDITABLE_LANDMARKS else "leaves the aorta from its right side"
        points.append({"id": str(index + 1), "label": label, "description": description,
                       "position": list(position), "selected": True, "locked": True, "positionStatus": "defined"})
    points.extend(extra)
    return {"markups": [{"type": "Fiducial", "coordinateSystem": system, "controlPoints": points}]}


def moved(positions, label, deltaLps):
    """positions with one label's point moved by deltaLps (mm, LPS)."""
    result = dict(positions)
    result[label] = tuple(c + d for c, d in zip(positions[label], deltaLps))
    return result


def landmarks(positions=POSITIONS, given=()):
    return Replan.landmarksFromMarkups(markups(positions, given))


class FrameTest(unittest.TestCase):
    def test_LpsToRas_NegatesLeftAndPosteriorOnly(self):
        self.assertEqual(Replan.lpsToRas((12.5, -40.0, 88.0)), (-12.5, 40.0, 88.0))
        self.assertEqual(Replan.rasToLps(Replan.lpsToRas((1.0, 2.0, 3.0))), (1.0, 2.0, 3.0))


class ReadLandmarksTest(unittest.TestCase):
    def test_CliFile_GivesTheFourEditableLandmarksInLps(self):
        read = Replan.landmarksFromMarkups(json.dumps(markups(given=("rightInternalIliacOrigin",))))
        self.assertEqual(set(read), set(Replan.EDITABLE_LANDMARKS))  # the renal and coeliac ostia are not inputs
        for label in Replan.EDITABLE_LANDMARKS:
            self.assertEqual(read[label].lps, POSITIONS[label], label)  # LPS, as in the file
            self.assertEqual(read[label].given, label == "rightInternalIliacOrigin", label)

    def test_RasDocument_IsTurnedIntoLps(self):
        ras = {label: Replan.lpsToRas(p) for label, p in POSITIONS.items()}
        read = Replan.landmarksFromMarkups(markups(ras, system="RAS"))
        self.assertEqual(read["rightInternalIliacOrigin"].lps, POSITIONS["rightInternalIliacOrigin"])

    def test_UndefinedPointsAndUnknownLabels_AreSkipped(self):
        extra = [{"label": "leftInternalIliacOrigin", "description": "Given", "position": [9, 9, 9]},  # a duplicate
                 {"label": "aorticBifurcation", "positionStatus": "undefined", "position": [0, 0, 0]}]
        positions = {k: v for k, v in POSITIONS.items() if k != "aorticBifurcation"}
        read = Replan.landmarksFromMarkups(markups(positions, extra=extra))
        self.assertNotIn("aorticBifurcation", read)
        self.assertEqual(read["leftInternalIliacOrigin"], Replan.Landmark(POSITIONS["leftInternalIliacOrigin"], False))

    def test_ControlPointsOfTheNode_AreRasAndBecomeLps(self):
        read = Replan.landmarksFromControlPoints([
            ("aorticBifurcation", "Given by the user.", (1.0, 2.0, 3.0)),
            ("rightRenalOstium", "Found", (5.0, 5.0, 5.0)),
            ("leftInternalIliacOrigin", "", (-4.0, 6.0, -50.0)),
        ])
        self.assertEqual(read, {"aorticBifurcation": Replan.Landmark((-1.0, -2.0, 3.0), True),
                                "leftInternalIliacOrigin": Replan.Landmark((4.0, -6.0, -50.0), False)})

    def test_BadDocuments_AreValueErrorsThatSayWhat(self):
        with self.assertRaisesRegex(ValueError, "markups"):
            Replan.landmarksFromMarkups({"controlPoints": []})
        with self.assertRaisesRegex(ValueError, "coordinate system is 'IJK'"):
            Replan.landmarksFromMarkups(markups(system="IJK"))
        bad = markups({"aorticBifurcation": (1.0, float("nan"), 2.0)})
        with self.assertRaisesRegex(ValueError, "aorticBifurcation"):
            Replan.landmarksFromMarkups(bad)

    def test_TextInTheParameterNode_RoundTrips(self):
        read = landmarks(given=("aorticBifurcation",))
        self.assertEqual(Replan.landmarksFromText(Replan.landmarksToText(read)), read)
        self.assertEqual(Replan.landmarksFromText(""), {})
        with self.assertRaisesRegex(ValueError, "press Apply"):
            Replan.landmarksFromText("{not json")
        with self.assertRaisesRegex(ValueError, "press Apply"):
            Replan.landmarksFromText('{"aorticBifurcation": {"lps": [1, 2]}}')


class MovedLandmarksTest(unittest.TestCase):
    def test_OnlyAMoveBeyondTheToleranceCounts(self):
        before = landmarks()
        label = "rightInternalIliacOrigin"
        tolerance = Replan.MOVE_TOLERANCE_MM
        self.assertEqual(tolerance, 0.5)
        for delta, expected in (((0.0, 0.0, 0.0), []), ((0.0, 0.0, -0.4), []),  # a nudge while selecting
                                ((0.3, 0.3, 0.3), [label]),  # 0.52 mm: beyond 0.5, though no axis is
                                ((0.0, 0.0, -8.0), [label])):
            after = landmarks(moved(POSITIONS, label, delta))
            self.assertEqual(Replan.movedLandmarks(before, after), expected, delta)

    def test_ResultsComeInTheCliOrder_NewOnesCountDeletedOnesDoNot(self):
        before = landmarks({k: v for k, v in POSITIONS.items() if k != "leftInternalIliacOrigin"})
        after = landmarks(moved(POSITIONS, "aorticBifurcation", (0.0, 0.0, 5.0)))
        self.assertEqual(Replan.movedLandmarks(before, after), ["aorticBifurcation", "leftInternalIliacOrigin"])
        del after["aorticBifurcation"]
        self.assertEqual(Replan.movedLandmarks(before, after), ["leftInternalIliacOrigin"])

    def test_BadTolerance_IsAValueError(self):
        for tolerance in (-0.1, float("nan")):
            with self.assertRaisesRegex(ValueError, "tolerance"):
                Replan.movedLandmarks({}, {}, tolerance)


class ReplanParametersTest(unittest.TestCase):
    PREVIOUS = {"inputVolume": "/cases/ct.nrrd", "seed": [0.0, 0.0, 60.0], "lowerHu": "200", "lumenLabels": "52,65,66",
                "outputLabelMap": "/run1/lumen.nrrd", "outputLandmarks": "/run1/landmarks.mrk.json"}

    def test_MovedLandmark_IsTheCliInputInRas(self):
        before = landmarks()
        after = landmarks(moved(POSITIONS, "rightInternalIliacOrigin", (1.0, -2.0, -8.0)))
        replan = Replan.replanParameters(self.PREVIOUS, before, after)
        # LPS (-23.4114, 0.0234, -50.6694) + (1, -2, -8) = (-22.4114, -1.9766, -58.6694); RAS negates L and P.
        expected = [22.4114, 1.9766, -58.6694]
        for got, want in zip(replan.parameters["rightInternalIliacOrigin"], expected):
            self.assertAlmostEqual(got, want, places=9)
        self.assertEqual(replan.moved, ["rightInternalIliacOrigin"])
        for label in ("lowestRenalOstium", "aorticBifurcation", "leftInternalIliacOrigin"):
            self.assertNotIn(label, replan.parameters)  # found and unmoved: the CLI finds it again

    def test_PreviousParameters_AreKeptAndNotChanged(self):
        kept = copy.deepcopy(self.PREVIOUS)
        replan = Replan.replanParameters(self.PREVIOUS, landmarks(), landmarks())
        self.assertEqual(self.PREVIOUS, kept)
        for name in ("inputVolume", "seed", "lowerHu", "outputLandmarks"):
            self.assertEqual(replan.parameters[name], self.PREVIOUS[name], name)

    def test_PreviousLumen_IsPassedAndItsLabelsCleared(self):
        replan = Replan.replanParameters(self.PREVIOUS, landmarks(), landmarks())
        self.assertEqual(replan.parameters["inputLumenSegmentation"], "/run1/lumen.nrrd")  # the run's outputLabelMap
        # The CLI's map is 1 = lumen: the previous run's 52,65,66 would find no voxel in it.
        self.assertEqual(replan.parameters["lumenLabels"], "")
        self.assertFalse(replan.lumenEdited)
        replan = Replan.replanParameters(self.PREVIOUS, landmarks(), landmarks(), previousLumen="copy of the lumen")
        self.assertEqual(replan.parameters["inputLumenSegmentation"], "copy of the lumen")

    def test_EditedLumen_WinsOverThePreviousOne(self):
        replan = Replan.replanParameters(self.PREVIOUS, landmarks(), landmarks(), previousLumen="previous",
                                         editedLumen="edited")
        self.assertEqual((replan.parameters["inputLumenSegmentation"], replan.lumenEdited), ("edited", True))

    def test_NoLumen_IsAValueError(self):
        previous = {k: v for k, v in self.PREVIOUS.items() if k != "outputLabelMap"}
        with self.assertRaisesRegex(ValueError, "lumen"):
            Replan.replanParameters(previous, landmarks(), landmarks())

    def test_GivenBefore_StaysGiven_AsTheUsersOwnPointOrAsTheLandmark(self):
        before = landmarks(given=("lowestRenalOstium", "aorticBifurcation"))
        previous = dict(self.PREVIOUS, lowestRenalOstium="the user's point list")
        replan = Replan.replanParameters(previous, before, before)
        self.assertEqual(replan.parameters["lowestRenalOstium"], "the user's point list")  # exactly what was given
        self.assertEqual(replan.parameters["aorticBifurcation"], list(Replan.lpsToRas(POSITIONS["aorticBifurcation"])))
        self.assertEqual(replan.givenAgain, ["lowestRenalOstium", "aorticBifurcation"])
        self.assertEqual(replan.moved, [])

    def test_MovedGivenLandmark_ReplacesTheUsersPoint(self):
        before = landmarks(given=("lowestRenalOstium",))
        after = landmarks(moved(POSITIONS, "lowestRenalOstium", (0.0, 0.0, -6.0)), given=("lowestRenalOstium",))
        replan = Replan.replanParameters(dict(self.PREVIOUS, lowestRenalOstium="old list"), before, after)
        self.assertEqual(replan.parameters["lowestRenalOstium"][2], POSITIONS["lowestRenalOstium"][2] - 6.0)
        self.assertEqual((replan.moved, replan.givenAgain), (["lowestRenalOstium"], []))

    def test_PointInput_MakesEachPointsValue(self):
        calls = []

        def pointInput(label, ras):
            calls.append((label, tuple(round(c, 6) for c in ras)))
            return "node of " + label

        before = landmarks(given=("leftInternalIliacOrigin",))
        after = landmarks(moved(POSITIONS, "aorticBifurcation", (0.0, 0.0, 5.0)), given=("leftInternalIliacOrigin",))
        replan = Replan.replanParameters(self.PREVIOUS, before, after, pointInput=pointInput)
        self.assertEqual(calls, [("aorticBifurcation", (0.0275, 0.018, 4.7106)),
                                 ("leftInternalIliacOrigin", (-23.4001, -0.7143, -50.561))])
        self.assertEqual(replan.parameters["aorticBifurcation"], "node of aorticBifurcation")


class LumenEditedTest(unittest.TestCase):
    def test_Fingerprint_SeesOneVoxelAndTheShape(self):
        mask = bytes(1000)
        edited = bytes(999) + b"\x01"
        base = Replan.lumenFingerprint((10, 10, 10), mask)
        self.assertEqual(base, Replan.lumenFingerprint((10, 10, 10), bytes(1000)))
        self.assertNotEqual(base, Replan.lumenFingerprint((10, 10, 10), edited))
        self.assertNotEqual(base, Replan.lumenFingerprint((20, 5, 10), mask))  # same bytes, another grid

    def test_Edited_ComparesWithTheRunsLumen(self):
        self.assertFalse(Replan.lumenEdited("abc", "abc"))
        self.assertTrue(Replan.lumenEdited("abc", "abd"))
        self.assertTrue(Replan.lumenEdited("", "abc"))  # not recorded: the segment as it is now
        with self.assertRaisesRegex(ValueError, "gone"):
            Replan.lumenEdited("abc", "")


def report(change=None):
    with open(os.path.join(DATA, "report-deployment.json")) as f:
        data = json.load(f)
    if change:
        change(data)
    return Results.parseReport(json.dumps(data))


#: Return values of a run, as the CLI writes them (every other one: not measured).
VALUES = {"proximalNeckDiameter": "22.14", "proximalNeckLumenDiameter": "20.5", "proximalNeckLength": "27.0",
          "proximalSiteToBifurcationLength": "126.05", "rightIliacLength": "55.74", "leftIliacLength": "55.73",
          "rightIliacDiameter": "-1", "rightLimbLength": "82", "recommendedDevice": "Endurant II",
          "ipsilateralSideUsed": "right", "orderList": "a long text"}


def values(**changed):
    given = dict(VALUES, **changed)
    return Results.readReturnValues(lambda name: given.get(name, "-1"))


class ChangeLinesTest(unittest.TestCase):
    def changes(self, beforeValues, afterValues, afterReport=None):
        before = Replan.resultsSnapshot(beforeValues, report())
        after = Replan.resultsSnapshot(afterValues, afterReport or report())
        return Replan.changeLines(before, after)

    def test_SameRun_ChangesNothing(self):
        self.assertEqual(self.changes(values(), values()), [])

    def test_MovedValues_AreNamedInWordsAtClinicalPrecision(self):
        lines = self.changes(values(), values(rightIliacLength="63.84", proximalNeckDiameter="23.0"))
        self.assertEqual(lines, ["(a) proximal neck diameter, outer wall: 22.1 mm → 23.0 mm",
                                 "Right iliac length: 55.7 mm → 63.8 mm"])
        for line in lines:  # words, not identifiers
            self.assertIsNone(re.search(r"\b[a-z]+[A-Z][A-Za-z]*\b", line), line)

    def test_EqualAtDisplayPrecision_IsNoChange(self):
        # 55.74 and 55.71 both show as 55.7 mm; 22.14 and 22.06 both as 22.1 mm.
        self.assertEqual(self.changes(values(), values(rightIliacLength="55.71", proximalNeckDiameter="22.06")), [])

    def test_NotMeasuredAndVerdicts_AreWords(self):
        lines = self.changes(values(), values(rightIliacDiameter="14.04", rightLimbLength="0",
                                              ipsilateralSideUsed="left"))
        self.assertIn("(e) right iliac diameter, outer wall: not measured → 14.0 mm", lines)
        self.assertIn("Right limb length: 82.0 mm → no limb: the main body's ipsilateral leg lands on the right",
                      lines)
        self.assertIn("Main body introduced from: right → left", lines)
        self.assertFalse([line for line in lines if line.startswith("Order list")], lines)  # shown as components

    def test_Components_ThatChangeAppearOrGoAreNamedByPlace(self):
        def longerRightLimb(data):
            right = data["deployment"]["components"][1]
            right.update(lengthMm=124.0, catalogueCode="ETLW1616C124E")
            data["deployment"]["components"].append(
                {"role": "iliacExtension", "vessel": "rightIliac", "name": "Endurant limb", "diameterMm": 16.0,
                 "distalDiameterMm": 16.0, "lengthMm": 82.0, "catalogueCode": "ETLW1616C082E"})
            del data["deployment"]["components"][2]  # the left limb

        lines = self.changes(values(), values(), report(longerRightLimb))
        self.assertEqual(lines, [
            "Right limb: Endurant limb 16 × 82 mm (ETLW1616C082E) → Endurant limb 16 × 124 mm (ETLW1616C124E)",
            "Right iliac extension: none → Endurant limb 16 × 82 mm (ETLW1616C082E)",
            "Left limb: Endurant limb 16 × 124 mm (ETLW1616C124E) → none",
        ])

    def test_FitCheckSeal_IsAValue(self):
        def longerSeal(data):
            data["fitCheck"]["rightIliacSealLengthMm"] = 11.26

        self.assertEqual(self.changes(values(), values(), report(longerSeal)),
                         ["Right iliac seal on healthy wall: 3.2 mm → 11.3 mm"])

    def test_SnapshotKeptAsText_ComparesTheSame(self):
        before = Replan.snapshotFromText(json.dumps(Replan.resultsSnapshot(values(), report())))
        after = Replan.resultsSnapshot(values(leftIliacLength="60.0"), report())
        self.assertEqual(Replan.changeLines(before, after), ["Left iliac length: 55.7 mm → 60.0 mm"])
        for text in ("", "{", '{"a": 1}', "[[1, 2]]"):
            self.assertIsNone(Replan.snapshotFromText(text), text)


class ReplanLinesTest(unittest.TestCase):
    def test_SaysWhatTheReplanStartedFromAndWhatChanged(self):
        replan = Replan.ReplanInputs({}, ["rightInternalIliacOrigin"], ["aorticBifurcation"], False)
        lines = Replan.replanLines(replan, ["Right iliac length: 55.7 mm → 63.8 mm"])
        texts = [text for kind, text in lines]
        self.assertEqual(texts, ["Re-plan: what changed since the last run",
                                 "Right internal iliac origin: moved by you, given to the plan",
                                 "Aortic bifurcation: your point of the last run, given again",
                                 "Lumen: the last run's (region growing not repeated)",
                                 "Right iliac length: 55.7 mm → 63.8 mm"])
        edited = replan._replace(lumenEdited=True, moved=[], givenAgain=[])
        self.assertIn(("ok", "Nothing changed at clinical precision."), Replan.replanLines(edited, []))
        self.assertIn(("text", "Lumen: as you edited it"), Replan.replanLines(edited, []))
        self.assertEqual(Replan.replanLines(edited, None)[-1][0], "indeterminate")
        self.assertIn("55.7 mm → 63.8 mm", Replan.replanHtml(replan, ["a <b> → c"] + texts[-1:]))
        self.assertIn("a &lt;b&gt; → c", Replan.replanHtml(replan, ["a <b> → c"]))


if __name__ == "__main__":
    unittest.main()
