#!/usr/bin/python3
"""StentGraftPlannerLib.Results: the order list of the report's deployment, beside the anatomy (issue 29).

The reports in Data/ are real StentGraftSimulation outputs on SyntheticAorticPhantom phantoms, trimmed
(evidence texts, most families and checks, the ostia left out):
- report-deployment.json: outer wall traced, right common iliac 10 mm: configured, a finding
  (commonIliacTooShort) with its option, a note, three alternatives, ifuStatus fail;
- report-lumen.json: no outer wall (no fat around the vessel): sized on the lumen, estimated
  (lumen), ifuStatus indeterminate;
- report-not-configured.json: --ipsilateralSide left --deploymentOffsetMm 5, the left internal iliac
  not found: configured false with its unknownReason.
"""
import copy
import json
import os
import re
import sys
import unittest
import xml.etree.ElementTree as ET

MODULE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, MODULE_DIR)
from StentGraftPlannerLib import OrderList, Results  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "Data")


def report(name):
    with open(os.path.join(DATA, name)) as f:
        return Results.parseReport(f.read())


def withDeployment(change):
    """report-deployment.json with ``change(deployment)`` applied to a copy of its deployment."""
    parsed = report("report-deployment.json")
    parsed["deployment"] = copy.deepcopy(parsed["deployment"])
    change(parsed["deployment"])
    return parsed


class OrderListTest(unittest.TestCase):
    def test_ConfiguredDeployment_ListsComponentsOverlapsSidesFindingsNotesAndAlternatives(self):
        lines = OrderList.orderListLines(report("report-deployment.json"))
        self.assertEqual(lines[:9], [
            ("heading", "Order list: Endurant II, main body from the right: the wider access vessel (right 6.9 mm, "
                        "left 6.8 mm)"),
            ("fail", "Endurant II — outside its instructions for use: a criterion failed on measured values."),
            ("text", "main body: Endurant IIs main body 25-14 × 103 mm (ESBF2514C103E), proximal edge at the lower edge "
                     "of the lowest renal ostium, flow divider 50.0 mm and contralateral gate end 84.0 mm below it "
                     "(42.9 mm above the aortic bifurcation), ipsilateral leg to 103.0 mm"),
            ("text", "right ipsilateral limb: Endurant limb 16 × 82 mm (ETLW1616C082E), from 51.9 mm to 133.9 mm below "
                     "the proximal edge"),
            ("text", "left contralateral limb: Endurant limb 16 × 124 mm (ETLW1616C124E), from 53.9 mm to 177.9 mm "
                     "below the proximal edge"),
            ("ok", "overlap, right ipsilateral limb in the main body's ipsilateral leg: 51.1 mm (needs 30.0–53.0 mm)"),
            ("ok", "overlap, left contralateral limb in the gate: 30.1 mm (needs 30.0–34.0 mm)"),
            ("text", "right side: covered 133.9 mm from the proximal edge; planned seal in the common iliac 7.0 mm, "
                     "distal edge 0.0 mm above the internal iliac ostium"),
            ("text", "left side: covered 177.9 mm from the proximal edge; planned seal in the common iliac 51.0 mm, "
                     "distal edge 0.0 mm above the internal iliac ostium"),
        ])
        finding = lines.index(("fail", "Finding: right common iliac too short for Endurant II's minimum iliac seal: "
                                       "7.0 mm from the aortic bifurcation to the internal iliac ostium (2.4 mm above "
                                       "the internal iliac origin), needs ≥ 15 mm; the right limb lands 0.0 mm above the "
                                       "internal iliac ostium with a 7.0 mm seal."))
        self.assertEqual(lines[finding + 1], ("text", "Option: an iliac extension into the right external iliac artery "
                                                      "that covers the internal iliac (embolise it first), or an iliac "
                                                      "branch device."))  # each finding with its option
        self.assertEqual([kind for kind, text in lines if text.startswith("Note: Narrow distal aorta")], ["warning"])
        alternatives = [text for kind, text in lines if text.startswith("Alternative: ")]
        self.assertEqual(len(alternatives), 3)
        self.assertEqual(alternatives[2], "Alternative: the right limb would be 20 mm if (e) were 16.0 mm (measured "
                                          "14.5 mm, uncertainty ±1.5 mm on the outer wall).")
        self.assertLess(finding, lines.index(("text", alternatives[0])))

    def test_EveryNumber_IsAtClinicalPrecision(self):
        # The report holds 51.09975085266856 and the like; a person reads 0.1 mm.
        for name in ("report-deployment.json", "report-lumen.json", "report-not-configured.json"):
            parsed = report(name)
            for kind, text in OrderList.orderListLines(parsed) + OrderList.anatomyLines(parsed):
                for number in re.findall(r"\d+\.(\d+)", text):
                    self.assertEqual(len(number), 1, (name, text))

    def test_CodeNotPublic_OneDiameter_AndAnExtensionsSide(self):
        def change(deployment):
            limb = deployment["components"][1]
            limb.update(catalogueCode=None, distalDiameterMm=16.0)
            deployment["components"].append({"role": "iliacExtension", "name": "Endurant iliac extension",
                                              "catalogueCode": None, "diameterMm": 16, "distalDiameterMm": 13,
                                              "lengthMm": 82, "vessel": "rightIliac", "fromTargetMm": [120, 202]})
        lines = [text for kind, text in OrderList.orderListLines(withDeployment(change))]
        self.assertIn("right ipsilateral limb: Endurant limb 16 × 82 mm (code not public), from 51.9 mm to 133.9 mm "
                      "below the proximal edge", lines)
        self.assertIn("right iliac extension: Endurant iliac extension 16-13 × 82 mm (code not public), from 120.0 mm "
                      "to 202.0 mm below the proximal edge", lines)

    def test_OverlapOutsideItsWindow_IsAFailure_AndAnOpenWindowSaysAtLeast(self):
        def change(deployment):
            deployment["overlaps"][0].update(overlapMm=25.04, maxMm=None)
            deployment["overlaps"][1].update(overlapMm=35.0, minMm=30, maxMm=30)
        lines = OrderList.orderListLines(withDeployment(change))
        self.assertIn(("fail", "overlap, right ipsilateral limb in the main body's ipsilateral leg: 25.0 mm "
                               "(needs ≥ 30.0 mm)"), lines)
        self.assertIn(("fail", "overlap, left contralateral limb in the gate: 35.0 mm (needs 30.0 mm)"), lines)

    def test_DistalEdgePastTheInternalIliac_SaysItCoversIt(self):
        lines = OrderList.orderListLines(withDeployment(
            lambda d: d["landingZones"]["left"].update(marginToInternalIliacMm=-3.26)))
        self.assertIn(("text", "left side: covered 177.9 mm from the proximal edge; planned seal in the common iliac "
                               "51.0 mm, distal edge 3.3 mm past the internal iliac ostium (covers it)"), lines)

    def test_HoldRanges_InWordsAtClinicalPrecision_AndANegativeOneAsNone(self):
        # Issue 47: how far a limb may land from its plan (report deployment.components[].holdsMm).
        def change(deployment):
            deployment["components"][2]["holdsMm"] = {"above": 5.0, "below": 4.96, "aboveLimit": "seal",
                                                      "belowLimit": "covers"}
            deployment["components"][1]["holdsMm"] = {"above": 12.349, "below": -0.74, "aboveLimit": "stop",
                                                      "belowLimit": "overlap"}
        lines = [text for kind, text in OrderList.orderListLines(withDeployment(change))]
        self.assertIn("left contralateral limb: Endurant limb 16 × 124 mm (ETLW1616C124E), from 53.9 mm to 177.9 mm "
                      "below the proximal edge; holds if it lands up to 5.0 mm higher (then the left iliac seal falls "
                      "under the minimum) or 5.0 mm lower (then it covers the left internal iliac ostium)", lines)
        self.assertIn("right ipsilateral limb: Endurant limb 16 × 82 mm (ETLW1616C082E), from 51.9 mm to 133.9 mm "
                      "below the proximal edge; holds if it lands up to 12.3 mm higher (then it is as deep as it goes "
                      "in what it is inserted into: it cannot land higher) or none (0.7 mm short) lower (then an overlap "
                      "falls under the minimum)", lines)
        # The main body and a report without ranges: nothing added.
        self.assertEqual(OrderList.holdsText({"role": "mainBody", "holdsMm": None}), "")
        self.assertEqual(OrderList.holdsText({"role": "contralateralLimb"}), "")

    def test_DeploymentTolerance_EachComponentsRange_FindingsAndNotes(self):
        # Issue 47: the simulated ranges (report deployment.tolerance), after the sides' lines.
        tolerance = {
            "assessed": True, "toleranceMm": 5.0, "searchMm": 10.0, "resolutionMm": 0.5, "simulations": 8,
            "components": [
                {"component": 0, "name": "main body", "finding": None,
                 "text": "holds from 0.0 mm above to at least 10.0 mm below its planned position"},
                {"component": 2, "name": "left contralateral limb",
                 "finding": "the left contralateral limb holds only 0.0 mm below (…)",
                 "text": "holds from 0.0 mm (as far as it goes) above to 0.0 mm below its planned position"}],
            "findings": ["the left contralateral limb holds only 0.0 mm below (lower: type III endoleak risk) its "
                         "planned position: less than the 5.0 mm deployment tolerance"],
            "notes": ["The main body's proximal edge is placed at the lowest renal ostium on purpose."]}
        lines = OrderList.orderListLines(withDeployment(lambda d: d.update(tolerance=tolerance)))
        first = lines.index(("text", "Deployment tolerance: each component moved up to 10.0 mm up and down its vessel "
                                     "(the others where planned); it should hold 5.0 mm either way"))
        self.assertTrue(lines[first - 1][1].startswith("left side: covered"))
        self.assertEqual(lines[first + 1], ("ok", "main body: holds from 0.0 mm above to at least 10.0 mm below its "
                                                  "planned position"))
        self.assertEqual(lines[first + 2][0], "fail")
        self.assertEqual(lines[first + 3], ("fail", "Finding (deployment tolerance): the left contralateral limb holds "
                                                    "only 0.0 mm below (lower: type III endoleak risk) its planned "
                                                    "position: less than the 5.0 mm deployment tolerance."))
        self.assertEqual(lines[first + 4], ("warning", "Note: The main body's proximal edge is placed at the lowest "
                                                       "renal ostium on purpose."))
        notAssessed = OrderList.orderListLines(withDeployment(lambda d: d.update(tolerance={
            "assessed": False, "notAssessedReason": "the graft does not pass at its planned position (x)"})))
        self.assertIn(("indeterminate", "Deployment tolerance not assessed: the graft does not pass at its planned "
                                        "position (x)."), notAssessed)
        # An older report (no tolerance): no line.
        self.assertFalse(any("tolerance" in text for kind, text in OrderList.orderListLines(
            report("report-deployment.json"))))

    def test_DeploymentOffset_PlacesTheProximalEdgeBelowOrAbove(self):
        def moved(offset):
            site = 79.91357586890256  # the report's proximalSite.abscissaMm
            parsed = withDeployment(lambda d: d["anatomy"].update(deploymentTargetAbscissaMm=site + offset))
            return OrderList.orderListLines(parsed)[2][1]
        self.assertIn("proximal edge 5.0 mm below the lower edge of the lowest renal ostium,", moved(5.0))
        self.assertIn("proximal edge 12.5 mm above the lower edge of the lowest renal ostium,", moved(-12.5))
        self.assertIn("proximal edge at the lower edge of the lowest renal ostium,", moved(0.01))

    def test_LumenOnly_IsMarkedEstimatedAndIndeterminate(self):
        lines = OrderList.orderListLines(report("report-lumen.json"))
        self.assertEqual(lines[0], ("heading", "Order list: Endurant II, main body from the right: the wider access vessel "
                                               "(right 9.6 mm, left 9.6 mm) — estimated (lumen) at (a), (b), (e), (f)"))
        self.assertEqual(lines[1], ("indeterminate", "Endurant II — instructions for use not determined: no criterion "
                                                     "failed, but one could not be checked (a value not measured, within "
                                                     "its uncertainty, or sized on the lumen)."))
        components = [text for kind, text in lines if kind == "text" and ": Endurant" in text]
        self.assertEqual(len(components), 3)  # still a full order list

    def test_NotConfigured_SaysWhyAndListsNoComponent(self):
        lines = OrderList.orderListLines(report("report-not-configured.json"))
        self.assertEqual(lines, [
            ("heading", "Order list: Zenith Flex, main body from the left, as chosen in the plan's settings "
                                "(main body side)"),
            ("indeterminate", "Not configured: the left internal iliac origin was not found, so the landing zone's "
                              "lower end is not known."),
        ])

    def test_NoDeployment_ShowsTheReturnValueOrNothing(self):
        minimal = Results.parseReport('{"format": "StentGraftPlanner.report/1", "deployment": null}')
        self.assertEqual(OrderList.orderListLines(minimal), [])
        self.assertEqual(OrderList.orderListLines(minimal, {"orderList": None}), [])
        self.assertEqual(OrderList.orderListLines(minimal, {"orderList": "not configured: no landmark"}),
                         [("heading", "Order list"), ("text", "not configured: no landmark")])


class AnatomyTest(unittest.TestCase):
    def test_FromTheReport_AlongTheCenterlinesFromTheProximalEdge(self):
        self.assertEqual(OrderList.anatomyLines(report("report-deployment.json")), [
            ("heading", "Anatomy, from the proximal edge (at the lower edge of the lowest renal ostium)"),
            ("text", "→ aortic bifurcation 126.9 mm"),
            ("text", "→ right internal iliac origin 136.3 mm (common iliac 9.4 mm)"),
            ("text", "→ left internal iliac origin 180.4 mm (common iliac 53.5 mm)"),
        ])

    def test_FlowDivider_BelowTheBifurcation(self):
        def change(deployment):
            deployment["anatomy"]["targetToFlowDividerMm"] = 137.26
        lines = OrderList.anatomyLines(withDeployment(change))
        self.assertEqual(lines[1:3], [
            ("text", "→ aortic bifurcation 126.9 mm"),
            ("text", "→ flow divider 137.3 mm (where the lumen divides; the limbs' seal is measured from it)"),
        ])
        self.assertEqual(len(lines), 5)
        self.assertNotIn("flow divider", str(OrderList.anatomyLines(report("report-deployment.json"))))

    def test_InternalIliacNotFound_IsNotMeasured(self):
        lines = OrderList.anatomyLines(report("report-not-configured.json"))
        self.assertEqual(lines[0], ("heading", "Anatomy, from the proximal edge (5.0 mm below the lower edge of the "
                                               "lowest renal ostium)"))
        self.assertEqual(lines[2:], [("text", "→ right internal iliac origin 145.8 mm (common iliac 24.5 mm)"),
                                     ("text", "→ left internal iliac origin not measured")])

    def test_WithoutADeployment_FromTheReturnValues(self):
        parsed = Results.parseReport('{"format": "StentGraftPlanner.report/1", "proximalSite": {"source": "renal"}}')
        values = {"proximalSiteToBifurcationLength": 125.4276665, "rightIliacLength": 54.52840335,
                  "leftIliacLength": None}
        self.assertEqual(OrderList.anatomyLines(parsed, values), [
            ("heading", "Anatomy, from the lowest renal ostium"),
            ("text", "→ aortic bifurcation 125.4 mm"),
            ("text", "aortic bifurcation → right internal iliac origin 54.5 mm (180.0 mm from the proximal site)"),
            ("text", "aortic bifurcation → left internal iliac origin not measured"),
        ])
        self.assertEqual(OrderList.anatomyLines(parsed, {}), [])
        self.assertEqual(OrderList.anatomyLines(parsed), [])


class OrderListHtmlTest(unittest.TestCase):
    def test_OrderListBesideTheAnatomy_InTwoCells(self):
        text = OrderList.orderListHtml(report("report-deployment.json"))
        self.assertTrue(text.startswith("<table><tr><td"), text[:40])
        self.assertEqual(text.count("<td"), 2)
        orderList, anatomy = text.index("<b>Order list: Endurant II"), text.index("<b>Anatomy, from the proximal edge")
        self.assertLess(orderList, anatomy)  # the order list first, the anatomy beside it
        self.assertLess(text.index("</td>"), anatomy)
        self.assertIn("the main body&#x27;s ipsilateral leg", text)  # escaped
        self.assertIn('<span style="color:#cf222e">Finding: right common iliac too short', text)

    def test_OnlyOneSide_OneCell_NothingNoTable(self):
        parsed = Results.parseReport('{"format": "StentGraftPlanner.report/1"}')
        self.assertEqual(OrderList.orderListHtml(parsed), "")
        text = OrderList.orderListHtml(parsed, {"proximalSiteToBifurcationLength": 100.0})
        self.assertEqual(text.count("<td"), 1)
        self.assertIn("→ aortic bifurcation 100.0 mm", text)

    def test_OrderList_IsTheFirstResultInThePanel(self):
        # Issue 29: the order list first among the results, before the recommendation and the IFU details.
        with open(os.path.join(MODULE_DIR, "Resources", "UI", "StentGraftPlanner.ui")) as f:
            root = ET.fromstring(f.read())
        results = next(w for w in root.iter("widget") if w.get("name") == "resultsCollapsibleButton")
        names = [w.get("name") for w in results.iter("widget")][1:]
        # Issue 47: the order list made editable comes right below it, then the recommendation.
        self.assertEqual(names[:2], ["orderListLabel", "editConfigurationGroupBox"])
        group = next(w for w in results.iter("widget") if w.get("name") == "editConfigurationGroupBox")
        inside = len(list(group.iter("widget")))
        self.assertEqual(names[1 + inside], "recommendationLabel")


class ReportSectionsTest(unittest.TestCase):
    def test_Deployment_AndTheSimulatedFamily_AreRead(self):
        parsed = report("report-deployment.json")
        self.assertEqual(parsed["simulatedFamily"], "Endurant II")
        self.assertEqual(parsed["deployment"]["components"][0]["catalogueCode"], "ESBF2514C103E")
        self.assertIsNone(report("report-not-configured.json")["simulatedFamily"])  # device.simulated null
        broken = Results.parseReport(json.dumps({"format": "StentGraftPlanner.report/1", "deployment": [1],
                                                 "device": {"simulated": 3}}))
        self.assertEqual((broken["deployment"], broken["simulatedFamily"]), (None, None))


if __name__ == "__main__":
    unittest.main()
