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
/// diameter within ±1 mm of the level `belowMm` below the proximal site along its axis, mm.
double ShoulderAllowanceMm(const PhantomTruth& truth, double belowMm)
{
  const PhantomVessel& aorta = truth.vessels.front();
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
      here = 2.0 * aorta.radiusMm[i];
    }
  double allowance = 0.0;
  for (Eigen::Index i = 0; i < aorta.axis.rows(); ++i)
    if (std::abs(s[std::size_t(i)] - level) <= 1.0 + 1e-9)
      allowance = std::max(allowance, std::abs(2.0 * aorta.radiusMm[i] - here));
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

/// A short neck angled into the sac: its length (mm), β (degrees) and the slices (mm).
struct AngledNeck
{
  const char* name;
  double lengthMm, betaDeg, sliceMm;
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
    return;
  }
  // Measured: within the issue's tolerance (1.0 mm; 1.5 mm on thicker slices) plus the slope
  // allowance — the truth's diameter change within ±1 mm of the level (the sac's shoulder).
  const double tolerance = (c.sliceMm <= 1.25 ? 1.0 : 1.5) + ShoulderAllowanceMm(phantom.truth, 15.0);
  EXPECT_NEAR(b, phantom.truth.sizing.neckDiameter15mm, tolerance);
}

INSTANTIATE_TEST_SUITE_P(Issue32,
                         ShortAngledNeck,
                         // Necks 12–16 mm at β 30–60°, 1.25 and 3 mm slices.
                         ::testing::Values(AngledNeck{ "Neck12_Beta47_Fine", 12.2, 46.5, 1.25 },
                                           AngledNeck{ "Neck14_Beta55_Fine", 14.0, 55.0, 1.0 },
                                           AngledNeck{ "Neck16_Beta37_Thick", 15.8, 37.0, 3.0 },
                                           AngledNeck{ "Neck13_Beta60_Thick", 13.0, 60.0, 2.0 },
                                           AngledNeck{ "Neck15_Beta30_Fine", 15.0, 30.0, 1.25 }),
                         [](const auto& info) { return std::string(info.param.name); });

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
