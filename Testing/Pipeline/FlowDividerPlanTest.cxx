// Issue 46 item 7: the aortic bifurcation on bifurcations that are not symmetric Y's. The plan
// reports both landmarks — B where the axes meet (VesselOrigins.h) and the flow divider where the
// lumen divides (FlowDivider.h) — and the configuration measures each limb's iliac seal from the
// flow divider. The truth is the phantom's: B at the origin where its axes meet, the flow divider
// found on its tubes' own signed distances (PhantomSizing::proximalSiteToFlowDividerLength).
// Anatomies: a symmetric Y, iliacs leaving at 15° and 40°, a wide distal aorta (30 mm), and a
// bifurcation at the floor of the sac (no distal neck, the sac narrowing to 30 mm at B); walls in
// fat on 1.0 mm slices with 18 HU noise and 2.5 mm slices with 30 HU (issue 46's independent
// phantoms).
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"
#include "Pipeline/PlanRepair.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

struct BifurcationCase
{
  const char* name;
  double rightDeg, leftDeg;  ///< each common iliac's angle from the midline
  double distalDiameterMm;   ///< the distal aorta's outer diameter
  double distalNeckLengthMm; ///< the sac's bottom above B
  double sliceMm;
  /// A steep funnel: the sac's diameter and length, and its thrombus (0: the default sac, none).
  double sacMm = 0.0, sacLengthMm = 0.0, thrombusMm = 0.0;
  bool concentric = false;
};

void PrintTo(const BifurcationCase& c, std::ostream* os)
{
  *os << c.name << ", " << c.sliceMm << " mm slices";
}

class FlowDividerPlan : public ::testing::TestWithParam<BifurcationCase>
{
};

TEST_P(FlowDividerPlan, BothLandmarksAndTheSealFromTheDivider)
{
  const BifurcationCase c = GetParam();
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  p.noiseSigmaHu = c.sliceMm > 2.0 ? 30.0 : 18.0;
  p.rightCommonIliacAngleDeg = c.rightDeg;
  p.leftCommonIliacAngleDeg = c.leftDeg;
  p.distalNeckDiameterMm = c.distalDiameterMm;
  p.distalNeckLengthMm = c.distalNeckLengthMm;
  if (c.sacMm > 0.0)
  {
    p.maxAneurysmDiameterMm = c.sacMm;
    p.aneurysmLengthMm = c.sacLengthMm;
    p.thrombusMaxThicknessMm = c.thrombusMm;
    p.thrombusConcentric = c.concentric;
    p.thrombusSide = PhantomSide::Right;
  }
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PhantomSizing& t = phantom.truth.sizing;
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, testing::ShippedPlanParams());
  ASSERT_TRUE(plan.Reached(PlanStage::Device));
  const Measurements& m = plan.measurements;
  ASSERT_TRUE(m.flowDivider.found) << m.flowDivider.reason;
  const Point3 dividerTruth = testing::TruthLandmark(phantom.truth, "flowDivider");
  // Heights: the phantom's aorta is vertical below the sac, B at z = 0.
  const double dividerError = m.flowDivider.lps.z() - dividerTruth.z();
  const double bError = m.bifurcationLps.z();
  const double siteError = m.Value("proximalSiteToFlowDividerLength") - t.proximalSiteToFlowDividerLength;
  const double rightError = m.Value("rightIliacLengthFromFlowDivider") - t.rightIliacLengthFromFlowDivider;
  const double leftError = m.Value("leftIliacLengthFromFlowDivider") - t.leftIliacLengthFromFlowDivider;
  std::cout << "[ divider  ] " << c.name << ", " << c.sliceMm << " mm slices: flow divider " << -dividerTruth.z()
            << " mm below B, read " << dividerError << " mm off in height (" << m.flowDivider.lps.x() - dividerTruth.x()
            << " mm sideways); B read " << bError << " mm off; site to divider " << siteError
            << ", right iliac from it " << rightError << ", left " << leftError << " mm\n";
  // The divider's height: the mask decides at voxel centres, so its apex lies within half a slice
  // plus the blur's and noise's shift of the lumen's edge (about 0.5 mm on these walls).
  const double halfSlice = 0.5 * c.sliceMm;
  EXPECT_NEAR(dividerError, 0.0, halfSlice + 0.5);
  // B where the axes meet, on the same anatomies (LandmarksPlanTest's bar for the site-to-B
  // length: 2 mm) — on a 30 mm distal aorta on 2.5 mm slices too, where the iliac chords that
  // started in the lumen both iliacs share read it 2.7 mm high (VesselOrigins.h; 0.5 mm now).
  EXPECT_NEAR(bError, 0.0, 2.0);
  // Down a steep funnel (no distal neck, a 75 mm sac over 80 mm: the lumen narrows by 0.6–0.9 mm of
  // diameter per mm into B), B's height error is (d)'s: within 1 mm there. (On issue 46's sweep
  // draws B read 2.3 mm high on 1.25 mm slices and 3.8 mm on 3 mm slices before the funnel's rules,
  // VesselOrigins.h; these four read within 0.9 mm with or without them — where a funnel's skeleton
  // junction falls decides, so the rules' own test is cli.FunnelBifurcation on those draws. Here the
  // outer (d)'s extrapolation to B's level is what fails without it: 20.4 and 19.4 for 18 and 17.)
  if (c.sacMm > 0.0)
  {
    EXPECT_NEAR(bError, 0.0, 1.0);
  }
  // The lengths from it add the site's (up to 1.3 mm on slices of 2 mm or finer: MeasureAnatomy.h;
  // 1.5 mm on 2.5 mm slices: issue 46 item 1's bar) and the internal iliac origin's errors (1.5 mm:
  // the measured iliac lengths' bar in test_measurements_cli.py).
  EXPECT_NEAR(siteError, 0.0, halfSlice + 0.5 + (c.sliceMm > 2.0 ? 1.5 : 1.3));
  EXPECT_NEAR(rightError, 0.0, halfSlice + 0.5 + 1.5);
  EXPECT_NEAR(leftError, 0.0, halfSlice + 0.5 + 1.5);
  // (d), lumen and outer, at the sweep's bars (sweep_random_anatomy.py: 1.0 / 1.5 mm on slices up
  // to 1.25 mm, 1.5 / 2.0 mm on thicker ones) — on every case, "InTheSac" too: there the sac
  // narrows straight into B, its narrowest level is B itself and the fitted trunk's last ring reads
  // the funnel (32-37 mm for 27 mm lumen before DistalAorta.h read on down to B).
  const bool thin = c.sliceMm <= 1.25;
  EXPECT_NEAR(m.Value("distalNeckMinLumenDiameter"), t.distalNeckMinDiameter, thin ? 1.0 : 1.5);
  EXPECT_NEAR(m.Value("distalNeckMinDiameter"), t.outerDistalNeckMinDiameter, thin ? 1.5 : 2.0);
  std::cout << "[ (d)      ] lumen " << m.Value("distalNeckMinLumenDiameter") << " for " << t.distalNeckMinDiameter
            << ", outer " << m.Value("distalNeckMinDiameter") << " for " << t.outerDistalNeckMinDiameter << " mm\n";
  // Every configuration measures each limb's seal from the divider, below B on each side's path
  // (its projection on the iliacs lies 4.6–9.4 mm below B on these anatomies: r / tan θ less
  // the read's error).
  const double target = plan.deploymentTargetAbscissaMm;
  int configured = 0;
  for (const FamilyEvaluation& family : plan.selection.families)
  {
    const DeviceConfiguration& config = family.configuration;
    if (!config.configured)
      continue;
    ++configured;
    for (int side = 0; side < 2; ++side)
    {
      SCOPED_TRACE(family.family + (side == 0 ? ", right" : ", left"));
      // From the divider's lowest position within its uncertainty (half the slice here).
      const double divider = m.bifurcationAbscissaMm - target + m.iliacStartBeyondBifurcationMm[side] +
                             m.flowDivider.iliacAbscissaMm[side] + 0.5 * c.sliceMm;
      EXPECT_NEAR(config.sealFromMm[side], divider, 1e-9);
      EXPECT_GT(config.sealFromMm[side], m.bifurcationAbscissaMm - target + 3.0);
      EXPECT_NEAR(config.sealLengthMm[side], config.coveredLengthMm[side] - config.sealFromMm[side], 1e-9);
      EXPECT_GE(config.landingLowMm[side], config.sealFromMm[side] + 10.0 - 1e-9); // every family: a 10-15 mm seal
    }
  }
  EXPECT_GE(configured, 1);
}

INSTANTIATE_TEST_SUITE_P(
  Issue46,
  FlowDividerPlan,
  ::testing::Values(BifurcationCase{ "SymmetricY", 25.0, 25.0, 18.0, 20.0, 1.0 },
                    BifurcationCase{ "SymmetricY", 25.0, 25.0, 18.0, 20.0, 2.5 },
                    BifurcationCase{ "UnequalAngles", 15.0, 40.0, 18.0, 20.0, 1.0 },
                    BifurcationCase{ "UnequalAngles", 15.0, 40.0, 18.0, 20.0, 2.5 },
                    BifurcationCase{ "WideDistalAorta", 25.0, 25.0, 30.0, 20.0, 1.0 },
                    BifurcationCase{ "WideDistalAorta", 25.0, 25.0, 30.0, 20.0, 2.5 },
                    BifurcationCase{ "InTheSac", 25.0, 25.0, 30.0, 0.0, 1.0 },
                    BifurcationCase{ "InTheSac", 25.0, 25.0, 30.0, 0.0, 2.5 },
                    // Issue 46's sweep: a 75 mm sac funnelling into an 18 mm
                    // bifurcation, with a crescent of thrombus on the right and a
                    // concentric one, on 1.25 and 3 mm slices.
                    BifurcationCase{ "FunnelEccentric", 30.0, 35.0, 18.0, 0.0, 1.25, 75.0, 80.0, 16.0, false },
                    BifurcationCase{ "FunnelEccentric", 30.0, 35.0, 18.0, 0.0, 3.0, 75.0, 80.0, 16.0, false },
                    BifurcationCase{ "FunnelConcentric", 38.0, 40.0, 17.0, 0.0, 1.25, 75.0, 80.0, 20.0, true },
                    BifurcationCase{ "FunnelConcentric", 38.0, 40.0, 17.0, 0.0, 3.0, 75.0, 80.0, 20.0, true }),
  [](const auto& info)
  { return std::string(info.param.name) + "_Slices" + std::to_string(int(10.0 * info.param.sliceMm)) + "tenthsMm"; });

} // namespace
} // namespace sgp
