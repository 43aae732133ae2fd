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
        verdicts = ("recommendedDevice", "ipsilateralSideUsed", "orderList")  # "none": no main body (the XML)
        for name in verdicts[1:]:
            self.assertEqual(values[name], "none", name)
        for item in Results.RETURN_VALUES:
            if item.name not in verdicts:
                self.assertIsNone(values[item.name], item.name)
        lines = Results.measurementSummaryLines(values)
        self.assertIn("(e) right iliac diameter, outer wall: not measured", lines)
        self.assertIn("(e) right iliac diameter, lumen: not measured", lines)
        self.assertIn("thrombus volume, proximal site to bifurcation: not measured", lines)
        self.assertIn("hostile neck: not determined", lines)
        self.assertIn("main body length: not measured", lines)
        self.assertIn("main body introduced from: no main body", lines)
        self.assertIn("order list: no main body", lines)
        self.assertIn("recommended device: none within its instructions for use", lines)
        self.assertIn("instructions for use (IFU): not given", lines)  # "none" is not a status
        self.assertFalse([line for line in lines if "-1" in line or line.endswith(": none")], lines)

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

    def test_NotMeasuredList_DecidesWhichValuesAreMissing(self):
        # The CLI names what it does not have (PlanValues.h): its -1 of a signed value is a number
        # when not named, even without the diameters it is computed from; a named one is missing.
        given = {"neckConicity": "-1", "rightIliacDiameter": "-1", "hostileNeck": "false",
                 "recommendedDevice": "none", "notMeasured": "rightIliacDiameter,hostileNeck"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual(values["neckConicity"], -1.0)
        self.assertIsNone(values["rightIliacDiameter"])
        self.assertIsNone(values["hostileNeck"])  # a false verdict the CLI did not decide
        self.assertEqual(values["recommendedDevice"], "none")  # a result: no family within its IFU
        self.assertIsNone(values["proximalNeckDiameter"])  # not written at all
        given["notMeasured"] = "none"
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual(values["rightIliacDiameter"], -1.0)  # the list says measured: a value
        self.assertIs(values["hostileNeck"], False)

    def test_NegativeValueOfAMeasurableQuantity_IsKept(self):
        values = Results.readReturnValues(lambda name: "-2.5")
        self.assertEqual(values["neckConicity"], -2.5)  # a neck narrowing downward
        self.assertEqual(values["rightIliacDiameter"], -2.5)  # not the CLI's -1: shown, not hidden

    def test_FormatValue(self):
        self.assertEqual(Results.formatValue(22.25, "mm"), "22.2 mm")
        self.assertEqual(Results.formatValue(None, "mm"), "not measured")
        self.assertEqual(Results.formatValue(1.234, ""), "1.23")
        self.assertEqual(Results.formatValue(1.006, "ratio"), "1.01")
        self.assertEqual(Results.formatValue(61.54, "mL"), "61.5 mL")
        self.assertEqual(Results.formatValue(34.56, "deg"), "34.6°")  # a symbol, not "deg"
        self.assertEqual(Results.formatValue(13.5001, "%"), "14 %")  # whole percent
        self.assertEqual(Results.formatValue(-0.13, "%"), "0 %")  # no "-0 %"
        self.assertEqual(Results.formatValue(-2.6, "%"), "-3 %")
        self.assertEqual(Results.formatValue(-0.04, "mm"), "0.0 mm")
        self.assertEqual(Results.formatValue(True, ""), "Yes")
        self.assertEqual(Results.formatValue(False, ""), "No")
        lines = Results.measurementSummaryLines({"proximalNeckDiameter": 25.0, "proximalNeckLumenDiameter": 22.0})
        self.assertEqual(lines[:2], ["(a) proximal neck diameter, outer wall: 25.0 mm",
                                     "(a) proximal neck diameter, lumen: 22.0 mm"])
        self.assertEqual(len(lines), len(Results.RETURN_VALUES))


class AutomaticSeedTest(unittest.TestCase):
    # Issue 16 item 1: the panel places the seed the CLI found, and only that one.
    def test_AutomaticSeed_IsReadAsRas(self):
        values = {"seedSource": "automatic", "seedUsed": "0.35,-5.15,72.24013729"}
        self.assertEqual(Results.automaticSeed(values.get), (0.35, -5.15, 72.24013729))

    def test_UserSeedOrUnreadable_IsNone(self):
        self.assertIsNone(Results.automaticSeed({"seedSource": "user", "seedUsed": "1,2,3"}.get))
        for text in ("", "1,2", "a,b,c", "nan,1,2"):
            self.assertIsNone(Results.automaticSeed({"seedSource": "automatic", "seedUsed": text}.get), text)


class WallTest(unittest.TestCase):
    """Issue 12 items 3 and 6: (a)-(f) outer wall to outer wall under their old names, the lumen values
    beside them, each labelled with its wall; the thrombus values; -1 read as not measured."""

    def test_EachLevel_HasAnOuterAndALumenDiameter_InThatOrder(self):
        byName = {item.name: item for item in Results.RETURN_VALUES}
        names = [item.name for item in Results.RETURN_VALUES]
        self.assertEqual(len(Results.DIAMETER_PAIRS), 6)
        for outer, lumen, label in Results.DIAMETER_PAIRS:
            self.assertEqual((byName[outer].wall, byName[lumen].wall), (Results.OUTER_WALL, Results.LUMEN))
            self.assertEqual(byName[outer].label, byName[lumen].label)  # one level, told apart by the wall
            self.assertEqual(names.index(lumen), names.index(outer) + 1)
            self.assertIn("Lumen", lumen)
        self.assertEqual(byName["rightAccessMinDiameter"].wall, Results.LUMEN)  # inscribed lumen diameter
        for name in ("proximalNeckLength", "thrombusVolume", "neckThrombusArc", "hostileNeck", "mainBodyDiameter"):
            self.assertEqual(byName[name].wall, "", name)  # not a diameter of a wall

    def test_OuterAndLumenValues_AreReadUnderTheirNames(self):
        given = {"proximalNeckDiameter": "25.1", "proximalNeckLumenDiameter": "22.05", "maxAneurysmDiameter": "62",
                 "maxAneurysmLumenDiameter": "34.5"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual((values["proximalNeckDiameter"], values["proximalNeckLumenDiameter"]), (25.1, 22.05))
        self.assertEqual((values["maxAneurysmDiameter"], values["maxAneurysmLumenDiameter"]), (62.0, 34.5))

    def test_NewValues_MinusOneIsNotMeasured(self):
        names = ("thrombusVolume", "sacVolume", "maxThrombusThickness", "neckThrombusArc", "neckCalcificationArc") + tuple(
            name for pair in Results.DIAMETER_PAIRS for name in pair[:2])
        values = Results.readReturnValues(lambda name: "-1")
        for name in names:
            self.assertIn(name, Results.NOT_MEASURED_NAMES, name)
            self.assertIsNone(values[name], name)
        rows = {row[0] + row[2]: row[1] for row in Results.resultsTableRows(values)}
        self.assertEqual(rows["thrombus volume, proximal site to bifurcation"], "not measured")
        self.assertEqual(rows["(c) maximum aneurysm diameterouter wall"], "not measured")
        self.assertEqual(rows["(c) maximum aneurysm diameterlumen"], "not measured")

    def test_NewValues_AreShownWithTheirUnits(self):
        given = {"thrombusVolume": "61.54", "sacVolume": "140", "maxThrombusThickness": "14.2", "neckThrombusArc": "0",
                 "neckCalcificationArc": "37.5"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual(values["neckThrombusArc"], 0.0)  # no thrombus thicker than 2 mm: a value, not a gap
        shown = {row[0]: row[1] for row in Results.resultsTableRows(values)}
        self.assertEqual(shown["thrombus volume, proximal site to bifurcation"], "61.5 mL")
        self.assertEqual(shown["sac volume inside the outer wall"], "140.0 mL")
        self.assertEqual(shown["maximum thrombus thickness"], "14.2 mm")
        self.assertEqual(shown["neck thrombus arc (thicker than 2 mm)"], "0 %")  # 1 %: clinical precision
        self.assertEqual(shown["neck calcification arc"], "38 %")


class HostileNeckTest(unittest.TestCase):
    """hostileNeck is an XML <boolean>: Yes, No, or not determined where the CLI's false may stand for
    an undecided rule (a quantity the rules need was not measured) or it wrote nothing readable."""

    MEASURED = {"proximalNeckLength": "24", "proximalNeckDiameter": "25", "neckDiameter15mm": "26",
                "neckAngleBeta": "35", "neckAngleAlpha": "20", "neckThrombusArc": "10", "neckCalcificationArc": "5"}

    def shown(self, **given):
        texts = dict(self.MEASURED, **given)
        values = Results.readReturnValues(lambda name: texts.get(name, ""))
        row = [row for row in Results.resultsTableRows(values) if row[0] == "hostile neck"]
        self.assertEqual(len(row), 1)
        return values["hostileNeck"], row[0][1]

    def test_TrueAndFalse_AreYesAndNo(self):
        self.assertEqual(self.shown(hostileNeck="true"), (True, "Yes"))
        self.assertEqual(self.shown(hostileNeck="false"), (False, "No"))
        self.assertEqual(self.shown(hostileNeck=" TRUE "), (True, "Yes"))

    def test_EmptyOrUnreadable_IsNotDetermined(self):
        for text in ("", "maybe", "-1", "none"):
            self.assertEqual(self.shown(hostileNeck=text), (None, "not determined"), text)

    def test_FalseWithAQuantityNotMeasured_IsNotDetermined(self):
        # The XML: false "when a rule could not be decided"; alpha is -1 when the scan starts too low.
        for quantity in Results.DECIDED_FROM["hostileNeck"]:
            self.assertEqual(self.shown(hostileNeck="false", **{quantity: "-1"}), (None, "not determined"), quantity)

    def test_TrueWithAQuantityNotMeasured_StaysYes(self):
        # One failed rule makes the neck hostile, whatever the undecided ones would give.
        self.assertEqual(self.shown(hostileNeck="true", neckAngleAlpha="-1", neckThrombusArc="-1"), (True, "Yes"))

    def test_ReportAssessment_TellsNoFromNotDetermined(self):
        # The CLI writes false for an undecided rule even when every quantity was measured (a neck
        # length within its uncertainty of the threshold); the report's assessment says which.
        values = Results.readReturnValues(lambda name: dict(self.MEASURED, hostileNeck="false").get(name, ""))
        self.assertIs(values["hostileNeck"], False)
        for section, expected in (({"hostile": False, "determinate": False}, None),
                                  ({"hostile": False, "determinate": True}, False),
                                  ({"hostile": True, "determinate": False}, True),
                                  ({"summary": "no booleans"}, False), (None, False)):
            report = {"hostileNeck": section}
            decided = Results.withReportVerdicts(values, report)
            self.assertIs(decided["hostileNeck"], expected, section)
            self.assertIs(values["hostileNeck"], False)  # a new dict: the read values stay as read
        undecided = Results.withReportVerdicts(values, {"hostileNeck": {"hostile": False, "determinate": False}})
        self.assertIn(("hostile neck", "not determined", "", ""), Results.resultsTableRows(undecided))

    def test_ReportAssessment_ListsFailedAndUndecidedRules(self):
        report = Results.parseReport(
            '{"format": "StentGraftPlanner.report/1", "hostileNeck": {"hostile": true, "determinate": false, '
            '"summary": "hostile neck: fails short-neck (1 of 3 rules of \'default\'); indeterminate: alpha", "checks": ['
            '{"name": "short-neck", "status": "fail", "text": "neck length 12.0 mm, needs >= 15 mm: -3.0 mm"}, '
            '{"name": "alpha", "status": "indeterminate", "text": "neck angle alpha not measured"}, '
            '{"name": "wide-neck", "status": "pass", "text": "neck diameter 25.0 mm, needs <= 28 mm: +3.0 mm"}]}}')
        lines = Results.recommendationLines(report)
        self.assertEqual(lines, [
            ("heading", "Hostile-neck rules"),
            ("fail", "hostile neck: fails short-neck (1 of 3 rules of 'default'); indeterminate: alpha"),
            ("fail", "neck length 12.0 mm, needs >= 15 mm: -3.0 mm"),
            ("indeterminate", "neck angle alpha not measured"),
        ])  # passes are counted in the summary only, as the families' checks
        for section, kind in (({"hostile": False, "determinate": True}, "ok"),
                              ({"hostile": False, "determinate": False}, "indeterminate"), ({}, "indeterminate")):
            lines = Results.recommendationLines({"hostileNeck": dict(section, summary="s")})
            self.assertEqual(lines, [("heading", "Hostile-neck rules"), (kind, "s")], section)

    def test_HostileNeck_IsNotAWallValue(self):
        rows = Results.resultsTableRows({"hostileNeck": False})
        self.assertEqual([row for row in rows if row[0] == "hostile neck"], [("hostile neck", "No", "", "")])


class ResultsTableTest(unittest.TestCase):
    """The panel's table: every return value with its wall, and the estimated flag of the CLI's
    measurements table (column estimated: true where an outer diameter sits at a level less than
    60 % supported)."""

    def rows(self):
        return Results.readCsvRows(read("measurements-wall.csv"))

    def test_EstimatedNames_FromTheCsv(self):
        # neckDiameter15mm: true; maxAneurysmDiameter: TRUE (any case); its lumen row "true" too (the
        # CLI's to mark); rightIliacDiameter: true though not measured; false and empty are not.
        self.assertEqual(Results.estimatedNames(self.rows()),
                         {"neckDiameter15mm", "maxAneurysmDiameter", "maxAneurysmLumenDiameter", "rightIliacDiameter"})

    def test_UnknownName_MarksNothing(self):
        rows = [{"name": "noSuchValue", "wall": "outer", "estimated": "true"},
                {"name": "leftIliacDiameter", "wall": "outer", "estimated": "yes"},
                {"name": "", "estimated": "true"}, {"estimated": "true"}]
        self.assertEqual(Results.estimatedNames(rows), {"leftIliacDiameter"})
        self.assertEqual(Results.tableWalls(rows), {"leftIliacDiameter": "outer"})

    def test_TheTablesWall_IsShownWhereItGivesOne(self):
        # The neck length is measured on the outer wall where it was traced, on the lumen where not:
        # only the CLI's row says which. Empty or unknown texts keep the module's own label.
        rows = self.rows() + [{"name": "neckConicity", "wall": "Lumen"}, {"name": "neckAngleBeta", "wall": "both"}]
        self.assertNotIn("proximalNeckLength", Results.tableWalls(rows))  # the sample's row leaves it empty
        rows.append({"name": "proximalNeckLength", "wall": "outer"})
        walls = Results.tableWalls(rows)
        self.assertEqual((walls["proximalNeckLength"], walls["neckConicity"]), ("outer", "lumen"))
        self.assertNotIn("neckAngleBeta", walls)
        self.assertEqual(walls["maxAneurysmLumenDiameter"], "lumen")
        shown = {row[0]: row[2] for row in Results.resultsTableRows({}, rows)}
        self.assertEqual(shown["proximal neck length"], "outer wall")
        self.assertEqual(shown["neck conicity"], "lumen")
        self.assertEqual(shown["infrarenal neck angle beta"], "")
        self.assertEqual(shown["thrombus volume, proximal site to bifurcation"], "")  # the sample's row: no wall

    def test_TableWithoutTheNewColumns_MarksNothing(self):
        # A measurements table of a CLI from before issue 12.
        rows = [{"name": "proximalNeckDiameter", "value": "22.3", "unit": "mm"}]
        self.assertEqual(Results.estimatedNames(rows), set())
        self.assertEqual(Results.estimatedNames([]), set())

    def test_Rows_LabelWallValueAndEstimated(self):
        given = {"proximalNeckDiameter": "25.1", "proximalNeckLumenDiameter": "22.04", "neckDiameter15mm": "26.4",
                 "neckLumenDiameter15mm": "20.2", "maxAneurysmDiameter": "62", "maxAneurysmLumenDiameter": "34.5",
                 "rightIliacDiameter": "-1", "thrombusVolume": "61.5", "hostileNeck": "true"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        rows = Results.resultsTableRows(values, self.rows())
        self.assertEqual(len(rows), len(Results.RETURN_VALUES))
        self.assertTrue(all(len(row) == len(Results.RESULTS_COLUMNS) for row in rows))
        self.assertEqual(rows[:6], [
            ("(a) proximal neck diameter", "25.1 mm", "outer wall", ""),
            ("(a) proximal neck diameter", "22.0 mm", "lumen", ""),
            ("(b) neck diameter 15 mm below", "26.4 mm", "outer wall", "yes"),
            ("(b) neck diameter 15 mm below", "20.2 mm", "lumen", ""),
            ("(c) maximum aneurysm diameter", "62.0 mm", "outer wall", "yes"),
            ("(c) maximum aneurysm diameter", "34.5 mm", "lumen", "yes"),
        ])
        byLabelAndWall = {(row[0], row[2]): row for row in rows}
        # Not measured: no estimated flag on a value that is not there.
        self.assertEqual(byLabelAndWall[("(e) right iliac diameter", "outer wall")][1:], ("not measured", "outer wall", ""))
        self.assertEqual(byLabelAndWall[("thrombus volume, proximal site to bifurcation", "")][1:], ("61.5 mL", "", ""))
        self.assertEqual(byLabelAndWall[("hostile neck", "")][1], "Yes")

    def test_SummaryLines_CarryWallAndEstimated(self):
        values = Results.readReturnValues(lambda name: {"neckDiameter15mm": "26.4"}.get(name, ""))
        lines = Results.measurementSummaryLines(values, self.rows())
        self.assertIn("(b) neck diameter 15 mm below, outer wall: 26.4 mm (estimated)", lines)
        self.assertIn("(b) neck diameter 15 mm below, lumen: not measured", lines)


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
                                  "families": [], "fitCheck": None, "hostileNeck": None, "deployment": None,
                                  "simulatedFamily": None, "notSimulated": None})
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
        # A field the panel does not know is listed in words; the known ones as sentences.
        self.assertIn(("fail", "ostia covered: right renal ostium covered <by> 2 mm"), lines)
        self.assertIn(("ok", "proximal seal on healthy wall 18.5 mm (needs ≥ 10 mm)"), lines)
        self.assertIn(("text", "migration risk: no"), lines)
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



class DeploymentReturnValuesTest(unittest.TestCase):
    """Issue 29's return values: the ordered lengths, the side, the order list and ifuStatus."""

    def test_NewValues_AreReadAndShownInWords(self):
        given = {"mainBodyLength": "145", "rightLimbLength": "0", "leftLimbLength": "124",
                 "ipsilateralSideUsed": "right",
                 "orderList": "Endurant II bifurcated main body 25-16 × 145 mm (ETBF2516C145E)",
                 "ifuStatus": "indeterminate"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        self.assertEqual((values["mainBodyLength"], values["rightLimbLength"], values["leftLimbLength"]),
                         (145.0, 0.0, 124.0))
        self.assertEqual(values["ipsilateralSideUsed"], "right")
        shown = {row[0]: row[1] for row in Results.resultsTableRows(values)}
        self.assertEqual(shown["main body length"], "145.0 mm")
        self.assertEqual(shown["right limb length"], "no limb: the main body's ipsilateral leg lands on the right")
        self.assertEqual(shown["left limb length"], "124.0 mm")
        self.assertEqual(shown["main body introduced from"], "right")
        self.assertEqual(shown["order list"], "Endurant II bifurcated main body 25-16 × 145 mm (ETBF2516C145E)")
        self.assertEqual(shown["instructions for use (IFU)"],
                         "IFU not determined: no criterion failed, but one could not be checked")

    def test_NotConfigured_MinusOneIsNotMeasured_AndEachIfuStatusHasWords(self):
        given = {"mainBodyLength": "-1", "rightLimbLength": "-1", "leftLimbLength": "-1", "ipsilateralSideUsed": "left",
                 "orderList": "not configured: the left internal iliac origin was not found", "ifuStatus": "fail"}
        values = Results.readReturnValues(lambda name: given.get(name, ""))
        for name in ("mainBodyLength", "rightLimbLength", "leftLimbLength"):
            self.assertIsNone(values[name], name)
        shown = {row[0]: row[1] for row in Results.resultsTableRows(values)}
        self.assertEqual(shown["right limb length"], "not measured")
        self.assertEqual(shown["order list"], "not configured: the left internal iliac origin was not found")
        self.assertEqual(shown["instructions for use (IFU)"], "outside IFU: a criterion failed on measured values")
        byName = {item.name: item for item in Results.RETURN_VALUES}
        self.assertEqual(Results.formatReturnValue(byName["ifuStatus"], "pass"),
                         "within IFU: every criterion met on measured values")
        self.assertEqual(Results.formatReturnValue(byName["ifuStatus"], "odd"), "odd")  # unknown: shown, not hidden


class ClinicalPrecisionTest(unittest.TestCase):
    """Issue 30: the panel shows what the CLI's table shows (its shown column, ValueText.h): real rows of
    three runs (outer wall, lumen only with estimated values, a landmark not found)."""

    def rows(self):
        return Results.readCsvRows(read("measurements-shown.csv"))

    def test_FormatValue_EqualsTheTablesShownColumn(self):
        rows = self.rows()
        self.assertEqual({row["unit"] for row in rows}, {"mm", "deg", "%", "ratio", "mL"})  # every unit is covered
        for row in rows:
            shown = row["shown"]
            estimated = shown.endswith(" (estimated)")
            self.assertEqual(estimated, row["estimated"] == "true", row["name"])
            value = float(row["value"]) if row["value"] else None
            self.assertEqual(Results.formatValue(value, row["unit"]), shown.replace(" (estimated)", ""), row["name"])

    def test_PanelTable_ShowsTheSameTextAndFlagsTheEstimates(self):
        rows = self.rows()
        values = Results.readReturnValues(lambda name: next((r["value"] for r in rows if r["name"] == name), ""))
        byName = {item.name: item for item in Results.RETURN_VALUES}
        table = {(row[0], row[2]): row for row in Results.resultsTableRows(values, rows)}
        checked = set()
        for row in rows:
            if row["name"] in Results.COMPUTED_FROM or row["name"] not in byName:
                continue  # conicity's operand (b) is not a sample row; the fit check's rows are the report's
            item = byName[row["name"]]
            checked.add(row["name"])
            shown = row["shown"].replace(" (estimated)", "")
            panel = [r for (label, wall), r in table.items() if label == item.label and r[1] == shown]
            self.assertTrue(panel, (row["name"], shown))
            if row["estimated"] == "true":
                self.assertEqual(panel[0][3], "yes", row["name"])
        self.assertGreaterEqual(len(checked), 9)
        self.assertIn("mainBodyDiameter", checked)  # an estimated one


class IfuStatusTest(unittest.TestCase):
    """withinIfu is false both for a failed and for an unchecked criterion: the recommendation says which,
    and "estimated (lumen)" wherever the sizes are estimates."""

    def test_LumenOnly_RecommendationIsIndeterminateAndEstimated(self):
        lines = Results.recommendationLines(Results.parseReport(read("report-lumen.json")))
        self.assertEqual(lines[:3], [
            ("indeterminate",
             "Recommended: Endurant II, main body 25 mm, right limb 16 mm, left limb 16 mm — estimated (lumen)"),
            ("indeterminate", "Instructions for use not determined: no criterion failed, but one could not be checked "
                              "(a value not measured, within its uncertainty, or sized on the lumen)."),
            ("indeterminate", "Estimated (lumen): sized on the lumen where the outer wall was not traced."),
        ])
        self.assertIn(("heading", "Endurant II (IFU not determined, estimated (lumen) at (a), (b), (e), (f)): "
                                  "2 pass, 0 fail, 2 indeterminate"), lines)
        self.assertIn(("text", "Order list: Endurant II bifurcated main body 25-16 × 145 mm (ETBF2516C145E); Endurant "
                               "limb 16 × 82 mm (ETLW1616C082E); Endurant limb 16 × 124 mm (ETLW1616C124E)"), lines)

    def test_Pass_IsOk_AndNoDeviceDoesNotRepeatTheFailure(self):
        passed = Results.parseReport('{"format": "StentGraftPlanner.report/1", "device": {"recommendation": '
                                     '{"family": "A", "withinIfu": true, "ifuStatus": "pass", "estimated": null}, '
                                     '"families": [{"name": "A", "mainBody": {"diameterMm": 25.04}}]}}')
        self.assertEqual(Results.recommendationLines(passed)[:2], [
            ("ok", "Recommended: A, main body 25 mm, right limb ? mm, left limb ? mm"),
            ("ok", "Within its instructions for use: every criterion met on measured values.")])
        lines = Results.recommendationLines(Results.parseReport(read("report-deployment.json")))
        self.assertEqual(lines[0], ("fail", "No device of the catalogue is within its instructions for use."))
        self.assertFalse([text for kind, text in lines if "a criterion failed on measured values" in text])
        self.assertIn(("heading", "Endurant II (outside IFU): 1 pass, 1 fail, 0 indeterminate"), lines)

    def test_NotConfiguredFamily_SaysWhy(self):
        lines = Results.recommendationLines(Results.parseReport(read("report-not-configured.json")))
        self.assertIn(("indeterminate", "Not configured: the left internal iliac origin was not found, so the landing "
                                        "zone's lower end is not known."), lines)


class FitCheckTest(unittest.TestCase):
    """The fit check as sentences at clinical precision, each seal against its minimum."""

    def test_RealFitCheck_Sentences(self):
        parsed = Results.parseReport(read("report-deployment.json"))
        lines = Results.recommendationLines(parsed)
        start = lines.index(("heading", "Fit check of the simulated graft (Endurant II)"))
        self.assertEqual(lines[start + 1:start + 12], [
            ("fail", "The simulated graft does not pass the fit check."),
            ("ok", "proximal seal on healthy wall 28.0 mm (needs ≥ 10 mm); the seal ends where the aorta widens beyond "
                   "110 % of (a) under 100 % of the ring (the aneurysm)"),
            ("text", "shortest apposition length 26.9 mm, the shortest sealed length of the graft's columns from its "
                     "proximal edge"),  # a report before issue 46 item 4: no minimum, no side
            ("text", "calcified share of the proximal seal zone 0 %"),
            ("fail", "right iliac seal on healthy wall 3.2 mm (needs ≥ 15 mm)"),  # the family's minimum, not 10 mm
            ("ok", "left iliac seal on healthy wall 47.3 mm (needs ≥ 15 mm)"),
            ("text", "main body oversizing at the proximal edge 13 %"),
            ("text", "right limb oversizing in the landing zone 14 %"),
            ("text", "left limb oversizing in the landing zone 14 %"),
            ("text", "migration risk: no"),
            ("ok", "no ostium covered"),
        ])
        self.assertEqual(lines[start + 12][0], "fail")
        self.assertTrue(lines[start + 12][1].startswith("type Ib endoleak risk: right iliac seal 3.2 mm"))
        self.assertFalse([text for kind, text in lines[start:] if "Mm" in text or "ostia:" in text])  # words only

    def test_ShortApposition_FailsWithItsSideAndCause(self):
        # Issue 46 item 4: the rings seal (28 mm) but one column apposes over 4 mm only.
        fitCheck = {"proximalSealLengthMm": 28.0, "minimumProximalSealMm": 10, "shortestAppositionLengthMm": 4.04,
                    "minimumAppositionLengthMm": 10, "shortestAppositionSide": "left posterior",
                    "shortestAppositionEnd": "it lies on thrombus 3.2 mm thick (over 2 mm)", "migrationRisk": True}
        lines = Results.fitCheckLines(fitCheck)
        self.assertIn(("fail", "shortest apposition length 4.0 mm (needs ≥ 10 mm), the shortest sealed length of the "
                               "graft's columns from its proximal edge, on the patient's left posterior side; it "
                               "ends where it lies on thrombus 3.2 mm thick (over 2 mm)"), lines)
        self.assertIn(("fail", "migration risk: the shortest apposition length is shorter than 10.0 mm"), lines)
        fitCheck["shortestAppositionLengthMm"] = 12.0
        fitCheck["migrationRisk"] = False
        lines = Results.fitCheckLines(fitCheck)
        self.assertEqual([kind for kind, text in lines if text.startswith("shortest apposition")], ["ok"])
        self.assertFalse([text for kind, text in lines if "Mm" in text])  # no field listed as a name

    def test_SealWithinItsUncertainty_Indeterminate(self):
        # Issue 46 item 2: 13.0 mm on 2.5 mm slices, uncertain by 5.0 mm: the risk cannot be excluded.
        fitCheck = {"proximalSealLengthMm": 13.0, "minimumProximalSealMm": 10, "proximalSealUncertaintyMm": 5.0,
                    "proximalSealUncertainty": "the site's and the seal end's 2.5 mm each, the scan's sampling "
                                               "interval along the aorta"}
        self.assertEqual(Results.fitCheckLines(fitCheck), [
            ("indeterminate", "proximal seal on healthy wall 13.0 mm (needs ≥ 10 mm); uncertainty 5.0 mm (the site's "
                              "and the seal end's 2.5 mm each, the scan's sampling interval along the aorta)")])
        fitCheck["proximalSealLengthMm"] = 15.5
        self.assertEqual(Results.fitCheckLines(fitCheck)[0][0], "ok")

    def test_OstiumWithinItsEdgesUncertainty_Indeterminate(self):
        # Issue 46 item 1: the graft at the renal's lower edge as read, which may lie 1.25 mm lower.
        fitCheck = {"coveredOstia": [], "ostia": [
            {"branch": "rightRenal", "covered": False, "mayBeCovered": True, "edgeUncertaintyMm": 1.25},
            {"branch": "leftRenal", "covered": False, "mayBeCovered": False, "edgeUncertaintyMm": 1.25}]}
        self.assertEqual(Results.fitCheckLines(fitCheck), [
            ("indeterminate", "no ostium covered as read; the right renal ostium may be covered (its edge is read "
                              "within 1.2 mm)")])
        fitCheck["ostia"][0]["mayBeCovered"] = False
        self.assertEqual(Results.fitCheckLines(fitCheck), [("ok", "no ostium covered")])

    def test_EstimatedSeals_PartialPlanAndRisks(self):
        fitCheck = {"proximalSealLengthMm": 9.25, "sealEstimatedOnLumen": {"proximal": True, "right": False},
                    "limbsChecked": {"right": True, "left": False}, "rightIliacSealLengthMm": 20.0,
                    "leftIliacSealLengthMm": None, "migrationRisk": True, "coveredOstia": ["rightRenal"],
                    "oversizingWall": "outer"}
        lines = Results.fitCheckLines(fitCheck)
        self.assertEqual(lines, [
            ("indeterminate", "The left limb was not sized (the scan ends above its landing zone): its seal, "
                              "oversizing and internal iliac are not checked."),
            ("fail", "proximal seal on healthy wall 9.2 mm (needs ≥ 10 mm), estimated (lumen): the outer wall not "
                     "traced under part of it"),
            ("text", "right iliac seal on healthy wall 20.0 mm"),  # no family: no minimum to compare with
            ("fail", "migration risk: the proximal seal is shorter than 10.0 mm"),
            ("fail", "covers the right renal ostium"),
            ("text", "oversizing wall: outer"),  # a field the panel does not know, in words
        ])

    def test_ReportedMinimums_JudgeTheSeals(self):
        # The report's minimums (issue 30: FitCheck's, the family's iliac one) win over the fallbacks.
        fitCheck = {"proximalSealLengthMm": 12.0, "minimumProximalSealMm": 15.0, "rightIliacSealLengthMm": 12.0,
                    "minimumIliacSealMm": 10.0, "migrationRisk": True}
        lines = Results.fitCheckLines(fitCheck)
        self.assertEqual(lines, [
            ("fail", "proximal seal on healthy wall 12.0 mm (needs ≥ 15 mm)"),
            ("ok", "right iliac seal on healthy wall 12.0 mm (needs ≥ 10 mm)"),
            ("fail", "migration risk: the proximal seal is shorter than 15.0 mm"),
        ])

    def test_UnknownFields_InWordsAtTheirUnitsPrecision(self):
        lines = Results.fitCheckLines({"gapToWallMm": 2.345, "coveredSharePercent": 12.6, "tiltDeg": 3.04,
                                       "ringCount": 12, "limbGaps": {"rightMm": None, "leftMm": 0.96}})
        self.assertEqual(lines, [("text", "gap to wall: 2.3 mm"), ("text", "covered share: 13 %"),
                                 ("text", "tilt: 3.0°"), ("text", "ring count: 12"),
                                 ("text", "limb gaps right: not measured"), ("text", "limb gaps left: 1.0 mm")])

    def test_ClinicalNumber_RoundsToTheUnitsPrecisionWithoutMinusZero(self):
        self.assertEqual([Results.clinicalNumber(v, u) for v, u in ((22.06, "mm"), (14.5, "%"), (1.005001, "ratio"),
                                                                     (-0.4, "%"), (-0.04, "deg"), (7.25, None))],
                         ["22.1", "14", "1.01", "0", "0.0", "7.2"])


if __name__ == "__main__":
    unittest.main()
