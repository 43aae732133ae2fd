// Issue 47: the plan that still holds when the deployment misses, through the whole pipeline on
// straight phantoms whose answers can be worked out by hand — the main body over a neck whose
// healthy length L is known holds down to L − the minimum seal − its uncertainty; a limb whose
// distal edge lies d above its internal iliac ostium, or whose overlap o lies over the minimum m,
// holds down to the nearer of d and o − m; and the demo phantom's limbs no longer end at the
// internal iliac ostium where the landing zone has room for a margin.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>

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

/// The search's resolution (DeploymentTolerance::resolutionMm) and the fit check's own rounding of
/// an ostium's edge (ostiumOverlapToleranceMm): how closely a simulated range meets a range worked
/// out from the plan's own figures.
constexpr double SearchMm = 1.0;

RepairPlan Plan(const AorticPhantom& phantom, const PlanParams& params)
{
  return PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, params);
}

/// A wall in fat, 14 mm common iliacs of `commonIliacMm` (internal iliacs far below a 25 mm neck's
/// graft), the Endurant II (its 30–34 mm overlap window in the gate: a range worked out by hand).
PhantomParams StraightPhantom(double commonIliacMm = 55.0)
{
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.rightCommonIliacLengthMm = p.leftCommonIliacLengthMm = commonIliacMm;
  return p;
}

/// The shipped parameters with the tolerance on (ShippedPlanParams leaves it off under the
/// sanitizers).
PlanParams TolerancePlanParams()
{
  PlanParams params = testing::ShippedPlanParams();
  params.assessDeploymentTolerance = true;
  return params;
}

PlanParams EndurantParams()
{
  PlanParams params = TolerancePlanParams();
  params.selection.forcedDevice = "Endurant II";
  return params;
}

const ComponentHold& HoldOf(const RepairPlan& plan, OrderRole role, int side = -1)
{
  const DeviceConfiguration& c = *plan.Configuration();
  for (const ComponentHold& h : plan.deploymentTolerance.components)
    if (c.components[h.component].role == role && (side < 0 || c.components[h.component].side == side))
      return h;
  throw std::runtime_error("no such component in the tolerance");
}

void Print(const RepairPlan& plan)
{
  for (const ComponentHold& h : plan.deploymentTolerance.components)
    std::cout << "[ holds    ] " << h.name << ": " << h.Text(plan.deploymentTolerance.searchMm) << "\n";
}

// A 25 mm neck whose thrombus begins 16 mm below the site: the main body may land as far down as
// leaves the minimum seal and its uncertainty on healthy wall, L − 10 − 2 mm, within the ring
// spacing the seal's end is read on; beyond it the fit check's type Ia finding says why, and the
// range (under the 5 mm tolerance) is the tolerance's finding. Up, its edge is at the lowest renal
// on purpose: a note, not a finding. (Not 20 mm: the crescent is then 6.3 mm tall with 3 mm tapers,
// and the rings read over it — the seal 25.5 mm — issue 46 item 2's phantom class.)
TEST(Issue47, NeckThrombusSixteenMillimetresBelowTheSite_MainBodyHoldsDownToTheHealthyNeckLessTheSeal)
{
  PhantomParams p = StraightPhantom(60.0);
  p.neckLengthMm = 25.0;
  p.neckThrombusThicknessMm = 6.0;
  p.neckThrombusLengthMm = p.neckLengthMm - 16.0 + 1.3; // 2 mm thick over a quarter from 16 mm down (AorticWall.h)
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_TRUE(plan.HasGraft());
  ASSERT_TRUE(plan.deploymentTolerance.assessed) << plan.deploymentTolerance.notAssessedReason;
  Print(plan);
  const ComponentHold& body = HoldOf(plan, OrderRole::MainBody);
  const double healthy = phantom.truth.sizing.healthyNeckLength;
  const double expected = healthy - FitCheckParams{}.minimumProximalSealMm - plan.fitCheck.proximalSealUncertaintyMm;
  std::cout << "[ neck     ] planned proximal seal " << plan.fitCheck.proximalSealLengthMm
            << " mm, shortest apposition " << plan.fitCheck.shortestAppositionLengthMm << " mm ("
            << plan.fitCheck.shortestAppositionSide << ": " << plan.fitCheck.shortestAppositionEnd << ")\n";
  std::cout << "[ neck     ] healthy neck (truth) " << healthy << " mm: main body holds " << body.belowMm
            << " mm below; by hand " << expected << " mm\n";
  EXPECT_NEAR(body.belowMm, expected, StentMeshParams{}.ringSpacingMm);
  EXPECT_NE(body.belowFails.find("type Ia"), std::string::npos) << body.belowFails;
  EXPECT_TRUE(body.aboveAtAorticOstium) << body.aboveFails;
  EXPECT_LE(body.aboveMm, plan.deploymentMarginMm + FitCheckParams{}.ostiumOverlapToleranceMm + 0.5);
  // Narrower than the 5 mm tolerance: a finding of the tolerance naming the main body.
  const bool named = std::any_of(plan.deploymentTolerance.findings.begin(), plan.deploymentTolerance.findings.end(),
                                 [](const std::string& f) { return f.find("main body") != std::string::npos; });
  EXPECT_EQ(named, body.belowMm < DeploymentToleranceMm) << body.belowMm << " mm";
}

/// Each limb that lands holds down to the nearer of its distal edge's distance to its internal
/// iliac ostium (as the plan's fit check reads the ostium: the ostium's tolerance beyond it) and
/// its overlap over the family's minimum, within 1 mm (or at least the search's end, when both lie
/// beyond it); the configuration predicted the overlap's room exactly. Returns how many limbs were
/// checked, and how many of them an ostium ended.
std::pair<int, int> ExpectLimbsHoldToTheirOstiumOrOverlap(const RepairPlan& plan)
{
  const DeviceConfiguration& c = *plan.Configuration();
  const double end = plan.deploymentTolerance.searchMm;
  int checked = 0, byOstium = 0;
  for (const ComponentHold& h : plan.deploymentTolerance.components)
  {
    const ConfiguredComponent& part = c.components[h.component];
    if (part.role == OrderRole::MainBody || part.distalMm < c.coveredLengthMm[std::size_t(part.side)] - 1e-9)
      continue;
    SCOPED_TRACE(h.name);
    const std::string ostium = part.side == 0 ? "rightInternalIliac" : "leftInternalIliac";
    const auto o = std::find_if(plan.fitCheck.ostia.begin(), plan.fitCheck.ostia.end(),
                                [&](const OstiumCoverage& x) { return x.branch == ostium; });
    EXPECT_NE(o, plan.fitCheck.ostia.end());
    if (o == plan.fitCheck.ostia.end())
      continue;
    const double d = -o->overlapMm + FitCheckParams{}.ostiumOverlapToleranceMm;
    double overlapRoom = 1e9;
    for (const ComponentOverlap& j : c.overlaps)
      if (std::size_t(j.inner) == h.component)
        overlapRoom = j.overlapMm - j.minMm;
    const double expected = std::min(d, overlapRoom);
    std::cout << "[ limb     ] " << h.name << ": " << d << " mm to the ostium, overlap " << overlapRoom
              << " mm over the minimum; holds " << h.belowMm << " mm below\n";
    ++checked;
    if (overlapRoom < d)
    {
      EXPECT_NEAR(part.holdsBelowMm, overlapRoom, 1e-9);
    }
    if (expected >= end)
    {
      EXPECT_EQ(h.belowMm, end);
      EXPECT_TRUE(h.belowFails.empty()) << h.belowFails;
      continue;
    }
    byOstium += d < overlapRoom ? 1 : 0;
    EXPECT_NEAR(h.belowMm, expected, SearchMm);
    EXPECT_NE(h.belowFails.find(d < overlapRoom ? "internal iliac ostium" : "type III"), std::string::npos)
      << h.belowFails;
  }
  return { checked, byOstium };
}

// On a straight phantom with the Endurant II: the contralateral limb in its gate (a 30–34 mm
// window, placed 34 deep) holds down to o − m = 4 mm; the ipsilateral one to its ostium or beyond
// the search.
TEST(Issue47, StraightPhantom_EachLimbHoldsDownToItsOstiumOrItsOverlap)
{
  const AorticPhantom phantom = GenerateAorticPhantom(StraightPhantom());
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_TRUE(plan.HasGraft());
  ASSERT_TRUE(plan.deploymentTolerance.assessed) << plan.deploymentTolerance.notAssessedReason;
  Print(plan);
  EXPECT_EQ(ExpectLimbsHoldToTheirOstiumOrOverlap(plan).first, 2);
  const ComponentHold& contra = HoldOf(plan, OrderRole::ContralateralLimb);
  EXPECT_NEAR(contra.belowMm, 4.0, SearchMm);
  EXPECT_TRUE(contra.aboveStops); // as deep in the gate as it goes
}

// The issue's failure on scripts/demo.sh's phantom: without a margin (tolerance 0) a limb ended
// 0.0 mm above its internal iliac ostium; with the default each side keeps the margin its landing
// zone allows (the tolerance, or half the zone where it is shorter); the return value says whether
// the plan holds within the tolerance.
TEST(Issue47, DemoPhantom_NoLimbEndsAtTheInternalIliacOstium)
{
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.includeBone = p.includeKidneys = true;
  p.thrombusMaxThicknessMm = 12.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanParams exactParams = testing::ShippedPlanParams();
  exactParams.selection.deploymentToleranceMm = 0.0;
  exactParams.assessDeploymentTolerance = false;
  const RepairPlan exact = Plan(phantom, exactParams);
  const RepairPlan plan = Plan(phantom, TolerancePlanParams());
  ASSERT_TRUE(exact.Configuration() && exact.Configuration()->configured);
  ASSERT_TRUE(plan.Configuration() && plan.Configuration()->configured);
  const DeviceConfiguration& before = *exact.Configuration();
  const DeviceConfiguration& after = *plan.Configuration();
  EXPECT_LT(std::min(before.marginToInternalIliacMm[0], before.marginToInternalIliacMm[1]), 0.5)
    << "the issue's case: without a margin a limb ends at the ostium";
  Print(plan);
  for (int side = 0; side < 2; ++side)
  {
    SCOPED_TRACE(side == 0 ? "right" : "left");
    const double zone = after.landingHighMm[side] - after.landingLowMm[side];
    // Both zones here are about 30 mm long: a limb length that keeps the seal and the margin exists.
    const double wanted = std::min(DeploymentToleranceMm, 0.5 * zone);
    EXPECT_GE(after.marginToInternalIliacMm[side], wanted - 0.1)
      << "above the ostium in a " << zone << " mm landing zone";
    EXPECT_GE(after.sealLengthMm[side],
              after.landingLowMm[side] - after.sealFromMm[side] - 1e-9); // still the minimum seal
  }
  ASSERT_TRUE(plan.deploymentTolerance.assessed) << plan.deploymentTolerance.notAssessedReason;
  // The left limb ends above its ostium with a margin: its range ends there (the Excluder's
  // contralateral leg at its minimum overlap: 0 mm).
  const auto [checked, byOstium] = ExpectLimbsHoldToTheirOstiumOrOverlap(plan);
  EXPECT_EQ(checked, 2);
  EXPECT_GE(byOstium, 1);
  bool found = false;
  for (const PlanValue& v : PlanReturnValues(plan))
    if (v.name == "deploymentToleranceHeld")
    {
      found = true;
      EXPECT_EQ(v.text, plan.deploymentTolerance.findings.empty() ? "true" : "false");
    }
  EXPECT_TRUE(found);
  EXPECT_TRUE(exact.deploymentTolerance.components.empty()); // not assessed when asked not to
}

} // namespace
} // namespace sgp
