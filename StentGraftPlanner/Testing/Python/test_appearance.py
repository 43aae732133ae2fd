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

    def test_SurfacesInsideTheLumen_StayVisible(self):
        # The lumen must be translucent, or the centerlines and the stents inside it are hidden.
        self.assertLess(Appearance.LOOKS["outputLabelMap"].opacity, 0.5)
        self.assertLess(Appearance.LOOKS["outputStentModel"].opacity, Appearance.LOOKS["outputSimulatedStentModel"].opacity)

    def test_VesselColours_AreDistinctAndStable(self):
        colours = [Appearance.vesselColor(v) for v in ("aorta", "rightIliac", "leftIliac")]
        self.assertEqual(len(set(colours)), 3)
        self.assertEqual(Appearance.vesselColor("other", 0), Appearance.vesselColor("other", 3))
        self.assertNotIn(Appearance.vesselColor("other", 1), colours)
        self.assertEqual(Appearance.vesselTitle("rightIliac"), "Right iliac")
        self.assertEqual(Appearance.vesselTitle("coeliac"), "coeliac")


if __name__ == "__main__":
    unittest.main()
