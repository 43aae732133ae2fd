#!/usr/bin/python3
"""StentGraftPlannerLib.Appearance: every look is a valid colour and opacity, and the plot's vessel
colours are distinct so the three series can be told apart."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from StentGraftPlannerLib import Appearance, Settings  # noqa: E402


class AppearanceTest(unittest.TestCase):
    def test_Looks_AreInRangeAndBelongToOutputs(self):
        outputs = {r.name for r in Settings.OUTPUT_ROLES}
        for role, look in Appearance.LOOKS.items():
            self.assertIn(role, outputs)
            self.assertEqual(len(look.color), 3)
            self.assertTrue(all(0.0 <= c <= 1.0 for c in look.color), role)
            self.assertTrue(0.0 < look.opacity <= 1.0, role)
            if look.scalars:
                low, high = look.scalarRangeMm
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
        self.assertEqual(look.scalarRangeMm[0], 0.0)  # no thrombus at the bottom of the map
        self.assertGreaterEqual(look.scalarRangeMm[1], 15.0)  # a thick sac thrombus still within the map
        self.assertFalse(look.visible)  # the segment shows the outer wall; one translucent shell at a time
        self.assertLess(look.opacity, 0.5)
        for role in ("outputCenterlines", "outputStentModel", "outputSimulatedStentModel", "outputLandmarks"):
            self.assertTrue(Appearance.LOOKS[role].visible, role)

    def test_VesselColours_AreDistinctAndStable(self):
        colours = [Appearance.vesselColor(v) for v in ("aorta", "rightIliac", "leftIliac")]
        self.assertEqual(len(set(colours)), 3)
        self.assertEqual(Appearance.vesselColor("other", 0), Appearance.vesselColor("other", 3))
        self.assertNotIn(Appearance.vesselColor("other", 1), colours)
        self.assertEqual(Appearance.vesselTitle("rightIliac"), "Right iliac")
        self.assertEqual(Appearance.vesselTitle("coeliac"), "coeliac")


if __name__ == "__main__":
    unittest.main()
