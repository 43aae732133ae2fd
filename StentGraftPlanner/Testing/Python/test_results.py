#!/usr/bin/python3
"""StentGraftPlannerLib.Results: return values, the diameter profile and the JSON report.

The sample files in Data/ follow the report contract (format StentGraftPlanner.report/1) and the
profile table's columns; the defective ones check that a missing or malformed section is skipped.
"""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import Results  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Data")


def read(name):
    with open(os.path.join(DATA, name)) as f:
        return f.read()


class ReturnValuesTest(unittest.TestCase):
    def test_NumbersStringsAndGaps(self):
        given = {"proximalNeckDiameter": "22.25", "neckAngleAlpha": "-1", "neckAngleBeta": " 35 ",
                 "recommendedDevice": "Endurant II:25", "rightIliacDiameter": "", "leftIliacDiameter": "abc",
                 "neckConicity": "inf"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual(values["proximalNeckDiameter"], 22.25)
        self.assertIsNone(values["neckAngleAlpha"])  # -1: not measured
        self.assertEqual(values["neckAngleBeta"], 35.0)
        self.assertEqual(values["recommendedDevice"], "Endurant II:25")
        for name in ("rightIliacDiameter", "leftIliacDiameter", "neckConicity", "maxAneurysmDiameter"):
            self.assertIsNone(values[name], name)
        self.assertEqual(set(values), {item.name for item in Results.RETURN_VALUES})

    def test_EverythingNotMeasured_IsNoneExceptTheDeviceVerdict(self):
        # Issue 14 item 6: what the CLI writes when a run measures nothing (PlanValues.h).
        given = {item.name: ("-1" if item.kind == "float" else "none") for item in Results.RETURN_VALUES}
        values = Results.readReturnValues(given.get)
        self.assertEqual(values["recommendedDevice"], Results.NO_DEVICE)  # "none" is a verdict here
        for item in Results.RETURN_VALUES:
            if item.name != "recommendedDevice":
                self.assertIsNone(values[item.name], item.name)
        lines = Results.measurementSummaryLines(values)
        self.assertIn("(e) right iliac diameter: not measured", lines)
        self.assertFalse([line for line in lines if "-1" in line], lines)

    def test_NotMeasured_CoversEveryNonNegativeQuantity(self):
        for item in Results.RETURN_VALUES:
            if item.kind == "float" and item.unit in ("mm", "deg", ""):  # diameters, lengths, angles, ratios
                self.assertIn(item.name, Results.NOT_MEASURED_NAMES, item.name)
        self.assertNotIn("neckConicity", Results.NOT_MEASURED_NAMES)

    def test_MinusOnePercentConicity_IsAValueWhenBothDiametersAreMeasured(self):
        given = {"proximalNeckDiameter": "25", "neckDiameter15mm": "24.75", "neckConicity": "-1"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual(values["neckConicity"], -1.0)  # the neck narrows 1 % downward

    def test_Conicity_IsNotMeasuredWithoutEitherDiameter(self):
        for missing in ("proximalNeckDiameter", "neckDiameter15mm"):
            given = {"proximalNeckDiameter": "25", "neckDiameter15mm": "24.75", "neckConicity": "-1", missing: "-1"}
            values = Results.readReturnValues(lambda name: given.get(name, ""))
            self.assertIsNone(values["neckConicity"], missing)

    def test_NegativeValueOfAMeasurableQuantity_IsKept(self):
        values = Results.readReturnValues(lambda name: "-2.5")
        self.assertEqual(values["neckConicity"], -2.5)  # a neck narrowing downward
        self.assertEqual(values["rightIliacDiameter"], -2.5)  # not the CLI's -1: shown, not hidden

    def test_FormatValue(self):
        self.assertEqual(Results.formatValue(22.25, "mm"), "22.2 mm")
        self.assertEqual(Results.formatValue(None, "mm"), "not measured")
        self.assertEqual(Results.formatValue(1.234, ""), "1.23")
        lines = Results.measurementSummaryLines({"proximalNeckDiameter": 22.0})
        self.assertEqual(lines[0], "(a) proximal neck diameter: 22.0 mm")
        self.assertEqual(len(lines), len(Results.RETURN_VALUES))


class ProfileTest(unittest.TestCase):
    def test_SampleTable_SplitsSortsAndSkipsUnreadableRows(self):
        series = Results.profileSeries(Results.readCsvRows(read("diameter-profile.csv")))
        self.assertEqual(list(series), ["aorta", "rightIliac", "leftIliac", "superiorMesenteric"])
        self.assertEqual(series["aorta"]["abscissaMm"], [0.0, 1.0])  # sorted along the vessel
        self.assertEqual(series["aorta"]["meanDiameterMm"], [22.0, 22.1])
        self.assertEqual(series["rightIliac"]["abscissaMm"], [0.0, 1.0])  # the NaN-mean row is dropped
        self.assertNotEqual(series["rightIliac"]["minDiameterMm"][1], series["rightIliac"]["minDiameterMm"][1])  # NaN gap
        self.assertEqual(series["leftIliac"]["meanDiameterMm"], [10.2, 10.1])

    def test_EmptyAndMissingVessels_GiveNoSeries(self):
        self.assertEqual(Results.profileSeries([]), {})
        rows = [{"vessel": "", "abscissaMm": "0", "meanDiameterMm": "3"}, {"abscissaMm": "0", "meanDiameterMm": "3"}]
        self.assertEqual(Results.profileSeries(rows), {})

    def test_NumericCells_AreAcceptedAsWellAsText(self):
        series = Results.profileSeries([{"vessel": "aorta", "abscissaMm": 2, "meanDiameterMm": 20.5}])
        self.assertEqual(series["aorta"]["meanDiameterMm"], [20.5])


class ReportTest(unittest.TestCase):
    def test_FullReport_AllSections(self):
        report = Results.parseReport(read("report-full.json"))
        self.assertEqual(report["proximalSite"]["source"], "renal")
        self.assertEqual(len(report["measurements"]), 2)
        self.assertEqual(report["warnings"], ["Active contour hit the iteration limit (3000)."])
        self.assertEqual(report["recommendation"]["family"], "Endurant II")
        self.assertEqual([f["family"] for f in report["families"]], ["Endurant II", "Zenith Flex"])
        self.assertEqual(report["fitCheck"]["proximalSealLengthMm"], 18.5)

    def test_MinimalReport_HasEmptySections(self):
        report = Results.parseReport(read("report-minimal.json"))
        self.assertEqual(report, {"proximalSite": None, "measurements": [], "warnings": [], "recommendation": None,
                                  "families": [], "fitCheck": None})
        self.assertEqual(Results.recommendationLines(report), [])
        self.assertEqual(Results.recommendationHtml(report), "The report holds no device recommendation.")

    def test_MalformedSections_AreSkipped(self):
        report = Results.parseReport(read("report-no-device.json"))
        self.assertEqual(report["warnings"], [])
        self.assertEqual(report["families"], [])
        self.assertEqual(report["recommendation"]["status"], "noDeviceWithinIfu")

    def test_WrongFormatOrNotJson_RaiseValueError(self):
        for text, pattern in (('{"format": "StentGraftPlanner.report/2"}', "report/2"), ("[1, 2]", "list"),
                              ("{", "not valid JSON"), ("{}", "None")):
            with self.assertRaisesRegex(ValueError, pattern, msg=text):
                Results.parseReport(text)


class RecommendationTextTest(unittest.TestCase):
    def test_FullReport_Lines(self):
        lines = Results.recommendationLines(Results.parseReport(read("report-full.json")))
        self.assertEqual(lines[0], ("ok", "Recommended: Endurant II, main body 25 mm, right limb 16 mm, left limb 13 mm"))
        self.assertIn(("text", "oversizing 12 % within 10-20 %"), lines)
        self.assertIn(("text", "Proximal implantation site from the lowest renal artery found on the centerlines."), lines)
        self.assertIn(("heading", "Endurant II: 1 pass, 0 fail, 1 indeterminate"), lines)
        self.assertIn(("indeterminate", "suprarenal angle alpha not measurable"), lines)
        self.assertIn(("fail", "neck length 12 mm, needs >= 15 mm: -3 mm"), lines)
        self.assertNotIn(("pass", "neck length 25 mm, needs >= 10 mm: +15 mm"), lines)  # passes are counted only
        self.assertIn(("fail", "ostiaCovered: right renal ostium covered <by> 2 mm"), lines)
        self.assertIn(("text", "migrationRisk: no"), lines)
        self.assertEqual(lines[-1], ("warning", "Warning: Active contour hit the iteration limit (3000)."))

    def test_NoDevice_AndSiteFromTop_AreFlagged(self):
        lines = Results.recommendationLines(Results.parseReport(read("report-no-device.json")))
        self.assertEqual(lines[0][0], "fail")
        self.assertIn("No device", lines[0][1])
        self.assertIn(("text", "neck length 9 mm below every family's minimum"), lines)
        self.assertEqual([kind for kind, text in lines if "top of the aortic centerline" in text], ["warning"])

    def test_SelectionShape_IsReadLikeTheContractShape(self):
        report = Results.parseReport(read("report-selection-shape.json"))
        recommendation = report["recommendation"]
        self.assertEqual(recommendation["status"], "recommended")
        self.assertEqual((recommendation["mainBodyDiameterMm"], recommendation["rightLimbDiameterMm"],
                          recommendation["leftLimbDiameterMm"]), (26, 14.5, 12))
        lines = Results.recommendationLines(report)
        self.assertEqual(lines[0], ("ok", "Recommended: Excluder (C3), main body 26 mm, right limb 14.5 mm, left limb 12 mm"))
        self.assertIn(("text", "Excluder (C3) 26 mm: 15 % oversizing"), lines)
        self.assertIn(("heading", "Zenith Flex: 0 pass, 1 fail, 0 indeterminate"), lines)
        self.assertIn(("fail", "neck length 12 mm, needs >= 15 mm: -3 mm"), lines)

    def test_SelectionShape_NoFamilyOrOutsideIfu(self):
        none = Results.parseReport('{"format": "StentGraftPlanner.report/1", "device": {"recommendation": {"family": null, "withinIfu": false}}}')
        self.assertEqual(none["recommendation"]["status"], "noDeviceWithinIfu")
        self.assertIsNone(none["recommendation"]["mainBodyDiameterMm"])
        forced = Results.parseReport('{"format": "StentGraftPlanner.report/1", "device": {"recommendation": {"family": "A", "withinIfu": false}}}')
        self.assertEqual(Results.recommendationLines(forced)[0], ("fail", "A is outside its instructions for use."))

    def test_UnknownStatus_IsShownNotHidden(self):
        report = Results.parseReport('{"format": "StentGraftPlanner.report/1", "device": {"recommendation": {"status": "x"}}}')
        self.assertEqual(Results.recommendationLines(report), [("indeterminate", "Device recommendation: unknown status 'x'.")])

    def test_Html_EscapesTextAndColoursStatus(self):
        text = Results.recommendationHtml(Results.parseReport(read("report-full.json")))
        self.assertIn("covered &lt;by&gt; 2 mm", text)
        self.assertNotIn("<by>", text)
        self.assertIn('<span style="color:#1a7f37">Recommended: Endurant II', text)
        self.assertIn("<b>Zenith Flex: 0 pass, 1 fail, 0 indeterminate</b>", text)


if __name__ == "__main__":
    unittest.main()
