// Issue 46: no passed fit check where a limb covers an internal iliac ostium. The fit check judges a
// limb's distal edge against the ostium's upstream edge as FindBranchOstium reads it; a limb past
// the true edge by more than FitCheckParams::ostiumOverlapToleranceMm must read as covering it, so
// the edge as read may lie above (upstream of) the true one, hardly below it. The truth is the
// phantom's mouth as drawn (PhantomSizing::rightInternalIliacOstium: where the internal iliac's
// surface first shows beside the common and external iliacs), on slices of 0.8-3 mm, internal
// iliacs leaving laterally or from the back, straight and kinked common iliacs.
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "Centerlines/Centerlines.h"
#include "Centerlines/ProximalSite.h"
#include "Phantom/AorticPhantom.h"
#include "Phantom/PhantomAnatomy.h"
#include "PhantomTestSupport.h"
#include "Pipeline/PlanRepair.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

struct MouthCase
{
  double sliceMm;
  bool posterior; ///< PhantomParams::posteriorInternalIliac
  double kinkDeg; ///< PhantomParams::commonIliacKinkDeg
  const char* name;
};

void PrintTo(const MouthCase& c, std::ostream* os)
{
  *os << c.name << ", " << c.sliceMm << " mm slices";
}

class InternalIliacMouth : public ::testing::TestWithParam<MouthCase>
{
};

TEST_P(InternalIliacMouth, EdgeReadAtOrAboveTheMouth)
{
  const MouthCase c = GetParam();
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  p.noiseSigmaHu = c.sliceMm > 2.0 ? 30.0 : 18.0; // issue 46's independent phantoms' noise
  p.posteriorInternalIliac = c.posterior;
  p.commonIliacKinkDeg = c.kinkDeg;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, testing::ShippedPlanParams());
  const Point3 B = testing::TruthLandmark(phantom.truth, "aorticBifurcation");
  for (int side = 0; side < 2; ++side)
  {
    SCOPED_TRACE(side == 0 ? "right" : "left");
    const std::string name = side == 0 ? "rightInternalIliac" : "leftInternalIliac";
    const Centerline& iliac = side == 0 ? plan.centerlines.rightIliac : plan.centerlines.leftIliac;
    const Centerline* branch = plan.centerlines.FindVessel(name);
    ASSERT_NE(branch, nullptr);
    const BranchOstium ostium = FindBranchOstium(iliac, *branch);
    ASSERT_TRUE(ostium.found);
    // Along the common iliac's last axis piece (the truth's: AorticPhantom.h), from its end.
    const double lateral = side == 0 ? -1.0 : 1.0, angle = p.rightCommonIliacAngleDeg * std::acos(-1.0) / 180.0;
    const Point3 end =
      testing::TruthLandmark(phantom.truth, side == 0 ? "rightIliacBifurcation" : "leftIliacBifurcation");
    const Point3 first = Point3(lateral * std::sin(angle), 0.0, -std::cos(angle));
    const Point3 kink = c.kinkDeg > 0.0 ? Point3(B + phantom::kinkFromBifurcationMm * first) : B;
    const Eigen::Vector3d axis = (end - kink).normalized();
    const PhantomSizing& truth = phantom.truth.sizing;
    const double length = side == 0 ? truth.rightIliacLength : truth.leftIliacLength;
    const double mouth = side == 0 ? truth.rightInternalIliacOstium : truth.leftInternalIliacOstium;
    const double read = length + (PositionAt(iliac, ostium.upperAbscissaMm) - end).dot(axis);
    std::cout << "[ mouth    ] " << c.name << ", " << c.sliceMm << " mm slices, " << name << ": upstream edge read "
              << read - mouth << " mm from the mouth as drawn (" << mouth - length << " mm past the division)\n";
    // Not below it by more than 0.1 mm: a limb past the mouth by more than the fit check's 0.5 mm
    // tolerance and this then reads as covering it. Measured: −1.6…+0.1 mm (+0.08 and +0.05 on
    // 3 mm slices, where the inscribed radius the edge is read from is cut to the slices).
    EXPECT_LE(read, mouth + 0.1);
    // And not far above it: the configuration keeps its limbs above the edge as read, so each
    // millimetre read high is a millimetre of iliac seal given away (measured at most 1.6 mm).
    EXPECT_GE(read, mouth - 2.0);
    // The fit check reads the same edge.
    for (const OstiumCoverage& o : plan.fitCheck.ostia)
      if (o.branch == name)
      {
        EXPECT_DOUBLE_EQ(o.upperAbscissaMm, ostium.upperAbscissaMm);
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Issue46,
                         InternalIliacMouth,
                         ::testing::Values(MouthCase{ 0.8, false, 0.0, "Lateral" },
                                           MouthCase{ 1.0, false, 0.0, "Lateral" },
                                           MouthCase{ 2.5, false, 0.0, "Lateral" },
                                           MouthCase{ 3.0, false, 0.0, "Lateral" },
                                           MouthCase{ 1.0, true, 0.0, "Posterior" },
                                           MouthCase{ 2.5, true, 0.0, "Posterior" },
                                           MouthCase{ 1.0, false, 30.0, "LateralKinked" },
                                           MouthCase{ 3.0, true, 30.0, "PosteriorKinked" }),
                         [](const auto& info) {
                           return std::string(info.param.name) + "_Slices" +
                                  std::to_string(int(10.0 * info.param.sliceMm)) + "tenthsMm";
                         });

} // namespace
} // namespace sgp
