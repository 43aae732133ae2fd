#!/usr/bin/python3
"""StentGraftPlannerLib.Appearance: every look is a valid colour and opacity, the plot's vessel
colours are distinct so the three series can be told apart, and the simulated graft is coloured by
component in the visual report's colours."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import Appearance, OrderList, Settings  # noqa: E402


class AppearanceTest(unittest.TestCase):
    def test_Looks_AreInRangeAndBelongToOutputs(self):
        outputs = {r.name for r in Settings.OUTPUT_ROLES}
        for role, look in Appearance.LOOKS.items():
            self.assertIn(role, outputs)
            self.assertEqual(len(look.color), 3)
            self.assertTrue(all(0.0 <= c <= 1.0 for c in look.color), role)
            self.assertTrue(0.0 < look.opacity <= 1.0, role)
            if look.scalars:
                low, high = look.scalarRange
                self.assertLess(low, high)

    def test_EveryShownOutput_HasALook(self):
        # The module shows each model output with LOOKS[role] and each segment's label map likewise;
        # a new output without a look would fail there, inside Slicer only.
        for role in Settings.OUTPUT_ROLES:
            if role.nodeClass in ("vtkMRMLModelNode", "vtkMRMLLabelMapVolumeNode", "vtkMRMLMarkupsFiducialNode"):
                self.assertIn(role.name, Appearance.LOOKS, role.name)
        segmented = {role for name, role in Appearance.SEGMENTS}
        for role in Settings.OUTPUT_ROLES:
            if role.nodeClass == "vtkMRMLLabelMapVolumeNode":
                self.assertIn(role.name, segmented, role.name)  # shown as a segment, not on the label layer

    def test_SurfacesInsideTheLumen_StayVisible(self):
        # The lumen must be translucent, or the centerlines and the stents inside it are hidden.
        self.assertLess(Appearance.LOOKS["outputLabelMap"].opacity, 0.5)
        self.assertLess(Appearance.LOOKS["outputStentModel"].opacity, Appearance.LOOKS["outputSimulatedStentModel"].opacity)

    def test_OuterWall_IsASecondTranslucentSegmentAroundTheLumen(self):
        # Issue 12 item 6: the panel shows the outer wall as a second, translucent segment.
        self.assertEqual(Appearance.SEGMENTS, (("Lumen", "outputLabelMap"), ("Outer wall", "outputWallLabelMap")))
        outputs = {r.name: r for r in Settings.OUTPUT_ROLES}
        for name, role in Appearance.SEGMENTS:
            self.assertEqual(outputs[role].nodeClass, "vtkMRMLLabelMapVolumeNode", name)
            self.assertIn(role, Appearance.LOOKS)
        lumen, outer = Appearance.LOOKS["outputLabelMap"], Appearance.LOOKS["outputWallLabelMap"]
        self.assertLess(outer.opacity, 0.5)  # the lumen, centerlines and stents inside stay visible
        self.assertGreaterEqual(outer.opacity, 0.15)  # and the wall itself can still be seen
        self.assertNotEqual(outer.color, lumen.color)
        self.assertEqual(outer.sliceFillOpacity, 0.0)  # an outline in the slices: the CT and the lumen stay readable
        self.assertIsNone(lumen.sliceFillOpacity)  # the lumen keeps Slicer's filled look
        self.assertTrue(lumen.visible and outer.visible)

    def test_OuterWallModel_IsColouredByThrombusAndHidden(self):
        look = Appearance.LOOKS["outputOuterWallModel"]
        self.assertEqual(look.scalars, "ThrombusThicknessMm")  # the CLI's point data (XML outputOuterWallModel)
        self.assertEqual(look.scalarRange[0], 0.0)  # no thrombus at the bottom of the map
        self.assertGreaterEqual(look.scalarRange[1], 15.0)  # a thick sac thrombus still within the map
        self.assertFalse(look.visible)  # the segment shows the outer wall; one translucent shell at a time
        self.assertLess(look.opacity, 0.5)
        for role in ("outputCenterlines", "outputStentModel", "outputSimulatedStentModel", "outputLandmarks"):
            self.assertTrue(Appearance.LOOKS[role].visible, role)

    def test_SimulatedGraft_IsColouredByComponentRole(self):
        # Issue 30: each component its own colour, by the CLI's ComponentRole point data (codes 0-4).
        look = Appearance.LOOKS["outputSimulatedStentModel"]
        self.assertEqual(look.scalars, "ComponentRole")
        self.assertEqual(look.scalarRange, (0.0, 4.0))
        self.assertEqual(look.colorTable, Appearance.COMPONENT_COLOR_TABLE)
        for role in Appearance.LOOKS:
            if role != "outputSimulatedStentModel":
                self.assertIsNone(Appearance.LOOKS[role].colorTable, role)  # the others keep the rainbow map

    def test_ComponentColours_AreTheReportsInRoleCodeOrder(self):
        # The visual report's colours (Logic/Views/SceneMeshes.cxx), entry i = ComponentRole code i.
        self.assertEqual(Appearance.componentColorTable(), [
            (0, "main body", (0.15, 0.35, 0.85, 1.0)),
            (1, "ipsilateral limb", (0.1, 0.65, 0.25, 1.0)),
            (2, "contralateral limb", (0.95, 0.55, 0.05, 1.0)),
            (3, "iliac extension", (0.55, 0.25, 0.75, 1.0)),
            (4, "aortic cuff", (0.0, 0.6, 0.6, 1.0)),
        ])
        self.assertEqual(len({role.color for role in Appearance.COMPONENT_ROLES}), 5)  # told apart

    def test_ComponentRoles_MatchTheOrderListsWords(self):
        # The report's role codes, and the words the order list uses for them.
        self.assertEqual([role.code for role in Appearance.COMPONENT_ROLES], list(OrderList.ROLE_WORDS))
        self.assertEqual([role.name for role in Appearance.COMPONENT_ROLES], list(OrderList.ROLE_WORDS.values()))

    def test_ComponentRoleCodes_MapToTheirOwnColourEntry(self):
        # Slicer's lookup over the scalar range: entry = floor((code - low) / (high - low) * n), clamped to
        # n - 1 (vtkLookupTable); every integer code must land on its own entry.
        low, high = Appearance.LOOKS["outputSimulatedStentModel"].scalarRange
        entries = len(Appearance.componentColorTable())
        for code in range(entries):
            self.assertEqual(min(int((code - low) / (high - low) * entries), entries - 1), code)

    def test_VesselColours_AreDistinctAndStable(self):
        colours = [Appearance.vesselColor(v) for v in ("aorta", "rightIliac", "leftIliac")]
        self.assertEqual(len(set(colours)), 3)
        self.assertEqual(Appearance.vesselColor("other", 0), Appearance.vesselColor("other", 3))
        self.assertNotIn(Appearance.vesselColor("other", 1), colours)
        self.assertEqual(Appearance.vesselTitle("rightIliac"), "Right iliac")
        self.assertEqual(Appearance.vesselTitle("coeliac"), "coeliac")


if __name__ == "__main__":
    unittest.main()
