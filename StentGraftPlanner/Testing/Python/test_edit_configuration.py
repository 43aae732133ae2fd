#!/usr/bin/python3
"""StentGraftPlannerLib.EditConfiguration and OrderList.differenceLines: the panel's editable order list
(issue 47 item 3), on the shipped catalogue and a configuration the CLI writes (--outputConfiguration on
the demo phantom: Excluder Conformable, main body from the left, two limbs with their overlaps).
"""
import copy
import json
import os
import sys
import unittest

MODULE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, MODULE_DIR)
from StentGraftPlannerLib import EditConfiguration, OrderList, Settings  # noqa: E402

CATALOG_PATH = os.path.join(MODULE_DIR, "..", "Resources", "devices.json")

#: What --outputConfiguration wrote for the demo phantom (scripts/demo.sh).
DEMO = {
    "format": "StentGraftPlanner configuration",
    "formatVersion": 1,
    "description": "Recommended configuration for phantom.nrrd",
    "family": "Excluder Conformable",
    "mainBodySide": "left",
    "components": [
        {"role": "mainBody", "code": "CXT261412", "proximalEdgeBelowLowestRenalMm": 0.5},
        {"role": "limb", "side": "left", "code": "PLC161000", "overlapMm": 41.87294142250906},
        {"role": "limb", "side": "right", "code": "PLC161200", "overlapMm": 30.0},
    ],
}


def catalog():
    with open(CATALOG_PATH) as f:
        return json.load(f)


class EditConfigurationTest(unittest.TestCase):
    def test_rows_name_each_component_in_words_with_its_entry(self):
        self.assertEqual(EditConfiguration.rows(DEMO), [
            ("main body", "mainBody", {"code": "CXT261412"}),
            ("left limb", "limb", {"code": "PLC161000"}),
            ("right limb", "limb", {"code": "PLC161200"}),
        ])

    def test_catalogue_entries_are_the_family_s_of_that_role_with_their_sizes(self):
        entries = EditConfiguration.catalogueEntries(catalog(), "excluder conformable", "limb")
        codes = [entry.get("code") for entry, _ in entries]
        self.assertIn({"code": "PLC161400"}, [entry for entry, _ in entries])
        self.assertEqual(len(codes), len(set(codes)))
        text = dict((entry["code"], words) for entry, words in entries)["PLC161400"]
        self.assertEqual(text, "16 × 135 mm (PLC161400)")  # the leg's proximal diameter is not public
        self.assertEqual(EditConfiguration.catalogueEntries(catalog(), "Endurant III", "limb"), [])
        # A code-less entry is named by its sizes (the Excluder C3's main bodies).
        bodies = EditConfiguration.catalogueEntries(catalog(), "Excluder (C3)", "mainBody")
        self.assertEqual(bodies[0][0], {"diameterMm": 23, "distalDiameterMm": 12, "lengthMm": 120})
        self.assertEqual(bodies[0][1], "23–12 × 120 mm")

    def test_a_changed_entry_keeps_its_overlap_and_nothing_else_changes(self):
        chosen = [None, None, {"code": "PLC161400"}]
        edited, edits = EditConfiguration.editedConfiguration(DEMO, chosen, "left")
        self.assertEqual(edited["components"][2], {"role": "limb", "side": "right", "code": "PLC161400",
                                                   "overlapMm": 30.0})
        self.assertEqual(edited["components"][:2], DEMO["components"][:2])
        self.assertEqual(edits, ["right limb: PLC161400"])
        self.assertEqual(DEMO["components"][2]["code"], "PLC161200", "the document given is not changed")
        # The same entry chosen again is no edit.
        same, edits = EditConfiguration.editedConfiguration(DEMO, [{"code": "CXT261412"}, None, None], "left")
        self.assertEqual(same["components"], DEMO["components"])
        self.assertEqual(edits, [])

    def test_the_other_side_drops_the_limbs_positions_and_keeps_the_main_body_s(self):
        edited, edits = EditConfiguration.editedConfiguration(DEMO, [None] * 3, "right")
        self.assertEqual(edited["mainBodySide"], "right")
        self.assertEqual(edited["components"][0]["proximalEdgeBelowLowestRenalMm"], 0.5)
        for component in edited["components"][1:]:
            self.assertNotIn("overlapMm", component)
        self.assertEqual(edits, ["main body from the right (the limbs placed again)"])

    def test_a_size_chosen_for_a_code_replaces_the_code(self):
        document = copy.deepcopy(DEMO)
        edited, _ = EditConfiguration.editedConfiguration(
            document, [{"diameterMm": 26, "distalDiameterMm": 14.5, "lengthMm": 120}, None, None], "left")
        self.assertNotIn("code", edited["components"][0])
        self.assertEqual(edited["components"][0]["lengthMm"], 120)

    def test_bad_choices_are_refused(self):
        with self.assertRaises(ValueError):
            EditConfiguration.editedConfiguration(DEMO, [None], "left")
        with self.assertRaises(ValueError):
            EditConfiguration.editedConfiguration(DEMO, [None] * 3, "middle")

    def test_the_simulation_runs_with_the_file_and_no_forced_device(self):
        parameters = {"device": "Endurant II:28", "outputReport": "/tmp/r.json"}
        result = EditConfiguration.simulationParameters(parameters, "/tmp/edited.json")
        self.assertEqual(result["configuration"], "/tmp/edited.json")
        self.assertEqual(result["device"], "auto")
        self.assertEqual(parameters["device"], "Endurant II:28", "the run's own parameters are not changed")

    def test_each_run_asks_for_the_configuration_beside_its_report(self):
        self.assertEqual(Settings.configurationPath("/tmp/StentGraftPlanner-abc.json"),
                         "/tmp/StentGraftPlanner-abc-configuration.json")


class DifferenceLinesTest(unittest.TestCase):
    def test_the_plan_s_own_configuration_has_no_difference_lines(self):
        self.assertEqual(OrderList.differenceLines({"given": False, "differences": None}), [])

    def test_a_given_configuration_says_how_it_differs_with_each_consequence(self):
        deployment = {"given": True, "differences": {"recommendedOrderList": "A; B", "items": [
            {"what": "right limb", "change": "20 mm longer", "consequence": "it covers",
             "text": "right limb 20 mm longer: it covers"}]}}
        self.assertEqual(OrderList.differenceLines(deployment), [
            ("warning", "Differs from the plan's recommendation (A; B):"),
            ("text", "right limb 20 mm longer: it covers."),
        ])
        deployment["differences"]["items"] = []
        self.assertEqual(OrderList.differenceLines(deployment),
                         [("pass", "The same as the plan's recommendation (A; B).")])


if __name__ == "__main__":
    unittest.main()
