// Measurement accuracy, the classes issue 32's sweep found, through the whole plan on the
// phantom's analytic truth: the narrower of two unequal common iliacs (its internal iliac, blurred
// below the window, was lost and the landing zone read the external iliac), the Y of a narrow
// iliac with a wall below a wide distal aorta (refused by the radius ratio), and (b) on a short
// neck angled into the sac (read on a bend where no plane is the cross-section).
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Phantom/AorticPhantom.h"
#include "Pipeline/PlanRepair.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

RepairPlan Measured(const AorticPhantom& phantom, const PlanParams& params = testing::ShippedPlanParams())
{
  PlanRequest request;
  request.through = PlanStage::Measurements;
  return PlanRepair(phantom.ct, phantom.truth.seedLps, request, params);
}

bool Warned(const RepairPlan& plan, const std::string& start)
{
  return std::any_of(plan.warnings.begin(), plan.warnings.end(),
                     [&](const std::string& w) { return w.rfind(start, 0) == 0; });
}

/// The sweep's slope allowance (sweep_random_anatomy.py): the largest change of the truth aorta's
/// diameter within ±1 mm of the level `belowMm` below the proximal site along its axis, mm; the
/// lumen's, or with `outer` the outer wall's (a phantom with a wall).
double ShoulderAllowanceMm(const PhantomTruth& truth, double belowMm, bool outer = false)
{
  const PhantomVessel& aorta = truth.vessels.front();
  const Eigen::VectorXd& radius = outer && aorta.outerRadiusMm.size() > 0 ? aorta.outerRadiusMm : aorta.radiusMm;
  const auto site = std::find_if(truth.landmarks.begin(), truth.landmarks.end(),
                                 [](const PhantomLandmark& l) { return l.name == "proximalImplantationSite"; });
  std::vector<double> s(static_cast<std::size_t>(aorta.axis.rows()), 0.0);
  Eigen::Index nearest = 0;
  for (Eigen::Index i = 0; i < aorta.axis.rows(); ++i)
  {
    if (i > 0)
      s[std::size_t(i)] = s[std::size_t(i - 1)] + (aorta.axis.row(i) - aorta.axis.row(i - 1)).norm();
    if ((aorta.axis.row(i).transpose() - site->lps).norm() < (aorta.axis.row(nearest).transpose() - site->lps).norm())
      nearest = i;
  }
  const double level = s[std::size_t(nearest)] + belowMm;
  double here = 0.0, best = 1e9;
  for (Eigen::Index i = 0; i < aorta.axis.rows(); ++i)
    if (std::abs(s[std::size_t(i)] - level) < best)
    {
      best = std::abs(s[std::size_t(i)] - level);
      here = 2.0 * radius[i];
    }
  double allowance = 0.0;
  for (Eigen::Index i = 0; i < aorta.axis.rows(); ++i)
    if (std::abs(s[std::size_t(i)] - level) <= 1.0 + 1e-9)
      allowance = std::max(allowance, std::abs(2.0 * radius[i] - here));
  return allowance;
}

/// Unequal common iliacs (outer diameters, mm), a wall in fat with sac thrombus, and the slices.
struct UnequalIliacs
{
  const char* name;
  double rightMm, leftMm, wallMm, sliceMm, distalNeckMm;
};

void PrintTo(const UnequalIliacs& c, std::ostream* os)
{
  *os << c.name;
}

class NarrowerIliac : public ::testing::TestWithParam<UnequalIliacs>
{
};

TEST_P(NarrowerIliac, WithinToleranceLumenAndOuter)
{
  const UnequalIliacs& c = GetParam();
  PhantomParams p;
  p.rightIliacDiameterMm = c.rightMm;
  p.leftIliacDiameterMm = c.leftMm;
  p.wallThicknessMm = c.wallMm;
  p.tissueHu = -100.0;
  p.thrombusMaxThicknessMm = 12.0;
  p.distalNeckDiameterMm = c.distalNeckMm;
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Measured(phantom);
  ASSERT_TRUE(plan.Reached(PlanStage::Measurements));
  const PhantomSizing& truth = phantom.truth.sizing;
  // The issue's tolerances: lumen 1.0 mm, outer 1.5 mm on slices up to 1.25 mm; 1.5 / 2.0 mm on
  // thicker ones (a voxel's partial volume along the slice).
  const bool thin = c.sliceMm <= 1.25;
  const double lumenMm = thin ? 1.0 : 1.5, outerMm = thin ? 1.5 : 2.0;
  const Measurements& m = plan.measurements;
  EXPECT_NEAR(m.Value("rightIliacLumenDiameter"), truth.rightIliacDiameter, lumenMm);
  EXPECT_NEAR(m.Value("leftIliacLumenDiameter"), truth.leftIliacDiameter, lumenMm);
  EXPECT_NEAR(m.Value("rightIliacDiameter"), truth.outerRightIliacDiameter, outerMm);
  EXPECT_NEAR(m.Value("leftIliacDiameter"), truth.outerLeftIliacDiameter, outerMm);
  // The cause: the narrower iliac's internal iliac was not found, so its leg ended 60 mm down,
  // in the external iliac. Both are found now, and no warning says otherwise.
  EXPECT_FALSE(Warned(plan, "No right internal iliac artery was found"));
  EXPECT_FALSE(Warned(plan, "No left internal iliac artery was found"));
}

INSTANTIATE_TEST_SUITE_P(Issue32,
                         NarrowerIliac,
                         // Ratios 1.3–2.0, diameters 8–18 mm, either side narrower, 1.25 and 3 mm slices. The last: an
                         // 8 mm iliac with a 1.6 mm wall (a 4.8 mm lumen) below a 25 mm distal aorta, whose Y the
                         // radius ratio refused (0.22 by the truth, less on 3 mm slices).
                         ::testing::Values(UnequalIliacs{ "Ratio2_Right8_Fine", 8.0, 16.0, 1.5, 1.25, 15.0 },
                                           UnequalIliacs{ "Ratio1p8_Right9p3_Fine", 9.3, 17.0, 1.5, 1.25, 15.0 },
                                           UnequalIliacs{ "Ratio1p4_Left12p5_Thick", 17.5, 12.5, 1.5, 3.0, 15.0 },
                                           UnequalIliacs{ "Ratio1p3_Left10_Thick", 13.0, 10.0, 1.5, 3.0, 15.0 },
                                           UnequalIliacs{ "Ratio1p5_Left8_WideDistalAorta_Thick", 12.0, 8.0, 1.6, 3.0,
                                                          25.0 }),
                         [](const auto& info) { return std::string(info.param.name); });

/// A short neck angled into the sac: its length (mm), β (degrees) and the slices (mm); optionally
/// a wall in fat (mm) with sac thrombus (mm at its thickest, concentric or eccentric).
struct AngledNeck
{
  const char* name;
  double lengthMm, betaDeg, sliceMm;
  double wallMm = 0.0, thrombusMm = 0.0;
  bool concentric = false;
};

void PrintTo(const AngledNeck& c, std::ostream* os)
{
  *os << c.name;
}

class ShortAngledNeck : public ::testing::TestWithParam<AngledNeck>
{
};

TEST_P(ShortAngledNeck, BWithinToleranceOrNotMeasuredWithTheReason)
{
  const AngledNeck& c = GetParam();
  PhantomParams p;
  p.neckDiameterMm = 24.0;
  p.neckLengthMm = c.lengthMm;
  p.neckAngleDeg = c.betaDeg;
  p.maxAneurysmDiameterMm = 60.0;
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  if (c.wallMm > 0.0)
  {
    p.wallThicknessMm = c.wallMm;
    p.tissueHu = -100.0;
    p.thrombusMaxThicknessMm = c.thrombusMm;
    p.thrombusConcentric = c.concentric;
  }
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Measured(phantom);
  ASSERT_TRUE(plan.Reached(PlanStage::Measurements));
  const Measurements& m = plan.measurements;
  const double b = m.Value("neckLumenDiameter15mm");
  if (std::isnan(b))
  {
    // Not measured: the plan says why, and the conicity built on it is left out too.
    EXPECT_TRUE(Warned(plan, "(b) is not measured: 15 mm below the proximal site the lumen's diameter changes by"));
    EXPECT_TRUE(std::isnan(m.Value("neckConicity")));
    EXPECT_TRUE(std::isnan(m.reverseTaperMm[1])); // the outer (b) less (a): it reached the neck rules
    return;
  }
  // Measured: within the issue's tolerance (1.0 mm; 1.5 mm on thicker slices) plus the slope
  // allowance — the truth's diameter change within ±1 mm of the level (the sac's shoulder).
  // Near the phantom's kink the truth is the narrowest section of its own solid through the level
  // (KinkSection.h); the plan reads (b) in the lumen's narrowest plane where the centerline's plane
  // cuts it obliquely (MeasureAnatomy's ObliqueExcessMm).
  const bool thin = c.sliceMm <= 1.25;
  const double tolerance = (thin ? 1.0 : 1.5) + ShoulderAllowanceMm(phantom.truth, 15.0);
  EXPECT_NEAR(b, phantom.truth.sizing.neckDiameter15mm, tolerance);
  // The outer (b), where the wall in fat shows it: outer 1.5 mm (2.0 mm on thicker slices) plus the
  // outer wall's own slope (under concentric thrombus far steeper than the lumen's).
  if (c.wallMm > 0.0)
  {
    const double outer = m.Value("neckDiameter15mm");
    ASSERT_FALSE(std::isnan(outer));
    EXPECT_NEAR(outer, phantom.truth.sizing.outerNeckDiameter15mm,
                (thin ? 1.5 : 2.0) + ShoulderAllowanceMm(phantom.truth, 15.0, true));
  }
}

INSTANTIATE_TEST_SUITE_P(
  Issue32,
  ShortAngledNeck,
  // Necks 12–16 mm at β 30–60°, 1.25 and 3 mm slices.
  ::testing::Values(AngledNeck{ "Neck12_Beta47_Fine", 12.2, 46.5, 1.25 },
                    AngledNeck{ "Neck14_Beta55_Fine", 14.0, 55.0, 1.0 },
                    AngledNeck{ "Neck16_Beta37_Thick", 15.8, 37.0, 3.0 },
                    AngledNeck{ "Neck13_Beta60_Thick", 13.0, 60.0, 2.0 },
                    AngledNeck{ "Neck15_Beta30_Fine", 15.0, 30.0, 1.25 },
                    // With a wall in fat and sac thrombus: the level just past the
                    // kink, where the centerline's plane cut the lumen 1.4–1.7 mm
                    // wide on issue 32's sweep (seed 61).
                    AngledNeck{ "Neck14_Beta47_WallEccentric_Fine", 14.4, 47.0, 1.25, 1.6, 15.0, false },
                    AngledNeck{ "Neck13_Beta53_WallConcentric_Thick", 13.2, 53.0, 2.5, 1.8, 14.0, true },
                    AngledNeck{ "Neck15_Beta39_WallConcentric_Thick", 14.6, 39.0, 3.0, 1.4, 10.0, true }),
  [](const auto& info) { return std::string(info.param.name); });

TEST(Issue32, BJustBelowAKinkedNeckWithAWallIsNotReadWide)
{
  // (b) within 1.2 mm below the neck's kink (necks 13.8 and 14.3 mm at β 40–52°), a 1.7 mm wall in
  // fat and eccentric sac thrombus, 1.25 mm slices: the smoothed centerline there runs up to 16° off
  // the axis, and the ring's plane ⊥ it cut the lumen wide — +0.95 to +1.70 mm on these six, mean
  // +1.30 mm, before (b) was read in the lumen's narrowest plane (MeasureAnatomy's
  // ObliqueExcessMm); after, −0.36 to +0.46 mm, mean −0.05 mm. Each within the issue's tolerance
  // (lumen 1.0, outer 1.5 mm) plus the slope allowance, and the six lumen errors' mean within
  // 0.5 mm: a common offset of half the tolerance is a bias of the method, not noise.
  double sum = 0.0;
  int count = 0;
  for (double lengthMm : { 13.8, 14.3 })
    for (double betaDeg : { 40.0, 46.0, 52.0 })
    {
      PhantomParams p;
      p.neckDiameterMm = 25.4;
      p.neckLengthMm = lengthMm;
      p.neckAngleDeg = betaDeg;
      p.maxAneurysmDiameterMm = 63.3;
      p.aneurysmLengthMm = 93.9;
      p.distalNeckDiameterMm = 19.0;
      p.rightIliacDiameterMm = 8.8;
      p.leftIliacDiameterMm = 12.8;
      p.wallThicknessMm = 1.7;
      p.tissueHu = -115.0;
      p.thrombusMaxThicknessMm = 15.4;
      p.thrombusSide = PhantomSide::Left;
      p.spacingMm = { 0.8, 0.8, 1.25 };
      const AorticPhantom phantom = GenerateAorticPhantom(p);
      const RepairPlan plan = Measured(phantom);
      ASSERT_TRUE(plan.Reached(PlanStage::Measurements));
      const Measurements& m = plan.measurements;
      const PhantomSizing& truth = phantom.truth.sizing;
      const double b = m.Value("neckLumenDiameter15mm"), outer = m.Value("neckDiameter15mm");
      ASSERT_FALSE(std::isnan(b)) << lengthMm << " mm at " << betaDeg << "°";
      EXPECT_NEAR(b, truth.neckDiameter15mm, 1.0 + ShoulderAllowanceMm(phantom.truth, 15.0))
        << lengthMm << " mm at " << betaDeg << "°";
      EXPECT_NEAR(outer, truth.outerNeckDiameter15mm, 1.5 + ShoulderAllowanceMm(phantom.truth, 15.0, true))
        << lengthMm << " mm at " << betaDeg << "°";
      sum += b - truth.neckDiameter15mm;
      ++count;
    }
  EXPECT_NEAR(sum / count, 0.0, 0.5);
}

TEST(Issue32, BOnALongAngledNeckIsMeasured)
{
  // The bend rule leaves (b) out only where its level lies on the bend: on a 35 mm neck angled
  // 50° the level 15 mm below the site is on the straight neck, and (b) is measured there.
  PhantomParams p;
  p.neckLengthMm = 35.0;
  p.neckAngleDeg = 50.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Measured(phantom);
  ASSERT_TRUE(plan.Reached(PlanStage::Measurements));
  EXPECT_NEAR(plan.measurements.Value("neckLumenDiameter15mm"), phantom.truth.sizing.neckDiameter15mm, 1.0);
  EXPECT_FALSE(Warned(plan, "(b) is not measured"));
}

} // namespace
} // namespace sgp
