// Issue 46 item 3: the sac behind its neighbours. Where the IVC and the psoas (and the duodenum,
// across the neck) touch the aorta without a fat plane, the outer wall is traced where it shows and
// completed behind them; Dmax and the thrombus volume must stay within the vessel-wall bars against
// the phantom's analytic truth: round and near-round sacs, the IVC over 72-120° of the
// circumference and both psoas, on 1 mm and 2.5 mm slices with the noise of the issue's
// independent phantoms (elliptical sacs behind the IVC: VesselWallPlanTest's Issue31 series).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

struct NeighbourCase
{
  const char* name;
  double axisRatio; ///< PhantomParams::sacAxisRatio (1: round; the major axis transverse)
  double ivcArcDeg; ///< 0: no IVC
  bool psoas;
  bool duodenum;
  double sliceMm;
};

void PrintTo(const NeighbourCase& c, std::ostream* os)
{
  *os << c.name << ", IVC over " << c.ivcArcDeg << "°, " << c.sliceMm << " mm slices";
}

class SacBehindNeighbours : public ::testing::TestWithParam<NeighbourCase>
{
};

TEST_P(SacBehindNeighbours, DmaxAndThrombusVolumeWithinTheirBars)
{
  const NeighbourCase c = GetParam();
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.neckDiameterMm = 25.0;
  p.maxAneurysmDiameterMm = 62.0;
  p.thrombusMaxThicknessMm = 15.0; // an eccentric crescent (anterior)
  p.neckThrombusThicknessMm = 4.0;
  p.neckThrombusLengthMm = 15.0;
  p.sacAxisRatio = c.axisRatio;
  p.includeIvc = c.ivcArcDeg > 0.0;
  p.ivcArcDeg = p.includeIvc ? c.ivcArcDeg : p.ivcArcDeg;
  p.includePsoas = c.psoas;
  p.includeDuodenum = c.duodenum;
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  p.noiseSigmaHu = c.sliceMm > 2.0 ? 30.0 : 18.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanRequest request;
  request.through = PlanStage::Measurements;
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, request, testing::ShippedPlanParams());
  const PhantomSizing& truth = phantom.truth.sizing;
  const Measurement* dmax = plan.measurements.Find("maxAneurysmDiameter");
  ASSERT_NE(dmax, nullptr);
  const double volume = plan.measurements.Value("thrombusVolume");
  std::cout << "[ sac      ] " << c.name << ", IVC " << c.ivcArcDeg << "°, " << c.sliceMm << " mm slices: Dmax "
            << dmax->value << " for " << truth.outerMaxAneurysmDiameter << " mm"
            << (dmax->estimated ? " (estimated)" : "") << "; thrombus " << volume << " for " << truth.thrombusVolumeMl
            << " mL (" << 100.0 * (volume / truth.thrombusVolumeMl - 1.0) << " %)\n";
  // Issue 12's bars: Dmax 1.0 mm on 1 mm slices, 1.5 mm on 2.5 mm ones; the thrombus volume 10 %.
  // Where the neighbours hide the outer wall over more of the aorta than a gap the plan bridges
  // (the duodenum across the neck with the IVC and both psoas: 4 % of the circumference shows), a
  // value is not measured, and the plan says which and why: a number not made up.
  const auto notMeasuredAndSaid = [&](const std::string& name)
  {
    return std::any_of(plan.warnings.begin(), plan.warnings.end(),
                       [&](const std::string& w)
                       { return w.find(name) != std::string::npos && w.find("not measured") != std::string::npos; });
  };
  if (std::isnan(dmax->value))
  {
    EXPECT_TRUE(c.duodenum) << "Dmax not measured where the neck shows";
    EXPECT_TRUE(notMeasuredAndSaid("maxAneurysmDiameter"));
  }
  else
  {
    EXPECT_NEAR(dmax->value, truth.outerMaxAneurysmDiameter, c.sliceMm > 2.0 ? 1.5 : 1.0);
  }
  if (std::isnan(volume))
  {
    EXPECT_TRUE(c.duodenum) << "thrombus volume not measured where the neck shows";
    EXPECT_TRUE(notMeasuredAndSaid("thrombusVolume"));
  }
  else
  {
    EXPECT_NEAR(volume, truth.thrombusVolumeMl, 0.10 * truth.thrombusVolumeMl);
  }
}

// The IVC and both psoas together on 1 mm slices read the thrombus volume +10.2 and +12.0 % until
// the second pass's axis ran through the contours' area centroids and on straight across the sac's
// shoulders (OuterWallAxis). Not in the series, open (docs/limitations.md): an elliptical sac
// (ratio 1.2) behind the IVC and both psoas (Dmax 62.1 mm for 74.5: two thirds hidden, the circle
// completes the plane).
INSTANTIATE_TEST_SUITE_P(Issue46,
                         SacBehindNeighbours,
                         ::testing::Values(NeighbourCase{ "Round", 1.0, 0.0, false, false, 1.0 },
                                           NeighbourCase{ "Round", 1.0, 90.0, false, false, 1.0 },
                                           NeighbourCase{ "Round", 1.0, 0.0, true, false, 1.0 },
                                           NeighbourCase{ "Round", 1.0, 72.0, true, false, 2.5 },
                                           NeighbourCase{ "Round", 1.0, 120.0, true, true, 2.5 },
                                           NeighbourCase{ "NearRound", 1.05, 90.0, true, true, 1.0 },
                                           NeighbourCase{ "NearRound", 1.05, 90.0, true, false, 2.5 },
                                           NeighbourCase{ "Round", 1.0, 90.0, true, false, 1.0 },
                                           NeighbourCase{ "Round", 1.0, 120.0, true, false, 1.0 }),
                         [](const auto& info)
                         {
                           return std::string(info.param.name) + "_Ivc" + std::to_string(int(info.param.ivcArcDeg)) +
                                  "deg" + (info.param.psoas ? "_Psoas" : "") +
                                  (info.param.duodenum ? "_Duodenum" : "") + "_Slices" +
                                  std::to_string(int(10.0 * info.param.sliceMm)) + "tenthsMm";
                         });

} // namespace
} // namespace sgp
