// The vessel wall through the whole plan (issue 12, "What must show"): outer-wall (a)–(f), Dmax
// and the thrombus values against the wall phantom's analytic truth on fine and thick slices, no
// leak into the neighbours that touch the vessel without a fat plane, outer = lumen + 2 × wall
// where there is no thrombus, sizing on the wall the IFU names, and the hostile-neck verdict.
#include <algorithm>
#include <map>
#include <cmath>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "Phantom/AorticPhantom.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "PipelineSupport.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

/// The issue's anatomy with a wall: a 25 mm outer neck, a 1.5 mm wall, an anterior crescent of
/// sac thrombus 15 mm at its thickest, a 4 mm crescent of neck thrombus reaching from the sac
/// 20 mm up the neck (into the 15 mm below the site), a 120° calcified arc in the neck (against
/// the lumen) and 90° in the sac (at the outer wall under the thrombus, where sac calcium lies),
/// in periaortic fat. Common iliacs 14 mm: with the 1.5 mm wall the phantom's internal iliacs
/// of 12 mm ones have a lumen of under 4 mm, which the thinning may prune (noticed, issue 13's
/// class, not this one's).
PhantomParams ThrombusPhantom()
{
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.sacCalcificationSide = PhantomSide::Anterior;
  p.wallThicknessMm = 1.5;
  p.thrombusMaxThicknessMm = 15.0;
  p.neckThrombusThicknessMm = 4.0;
  p.neckThrombusLengthMm = 20.0;
  p.neckCalcificationArcDeg = 120.0;
  p.sacCalcificationArcDeg = 90.0;
  p.tissueHu = -100.0;
  return p;
}

struct Grid
{
  const char* name;
  std::array<double, 3> spacingMm;
  double noiseHu;
  /// The issue's bar for outer (a)–(f) and Dmax: 1.0 mm on 0.8 × 0.8 × 1.0 mm voxels, 1.5 mm on
  /// 2.5 mm slices (the half-maximum edge is blurred along z where the wall is oblique to the
  /// slices).
  double outerMm;
  /// The lumen values' present bars (MeasureAnatomyTest): 1.0 mm fine, 1.5 mm on thick slices.
  double lumenMm;
};

void PrintTo(const Grid& grid, std::ostream* os)
{
  *os << grid.name;
}

class WallPlan : public ::testing::TestWithParam<Grid>
{
};

TEST_P(WallPlan, OuterDiametersThrombusAndArcs_AgainstTheTruth)
{
  PhantomParams p = ThrombusPhantom();
  p.spacingMm = GetParam().spacingMm;
  p.noiseSigmaHu = GetParam().noiseHu;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, testing::ShippedPlanParams());
  ASSERT_TRUE(plan.Reached(PlanStage::Measurements));
  const Measurements& m = plan.measurements;
  const PhantomSizing& truth = phantom.truth.sizing;
  testing::ExpectOuterDiametersNear(m, truth, GetParam().outerMm);
  testing::ExpectDiametersNear(m, truth, GetParam().lumenMm);
  // The thrombus makes the difference the issue is about: the lumen's Dmax is ~15 mm short.
  EXPECT_GT(m.Value("maxAneurysmDiameter") - m.Value("maxAneurysmLumenDiameter"), 10.0);
  // Thrombus volume within 10 % (issue 12): a 0.1 mm radial bias of either edge is ~2.5 % of it.
  EXPECT_NEAR(m.Value("thrombusVolume"), truth.thrombusVolumeMl, 0.10 * truth.thrombusVolumeMl);
  // Arcs within 10 percentage points, the thickest thrombus within 2 mm (issue 12).
  EXPECT_NEAR(m.Value("neckThrombusArc"), truth.neckThrombusArcPercent, 10.0);
  EXPECT_NEAR(m.Value("neckCalcificationArc"), truth.neckCalcificationArcPercent, 10.0);
  EXPECT_NEAR(m.Value("maxThrombusThickness"), truth.maxThrombusThicknessMm, 2.0);
  // The planted neck thrombus and calcium are there to be found: the truth is not zero.
  EXPECT_GT(truth.neckThrombusArcPercent, 20.0);
  EXPECT_GT(truth.neckCalcificationArcPercent, 20.0);
  // The sac lies inside the outer wall: more than the lumen plus the thrombus.
  EXPECT_GT(m.Value("sacVolume"), m.Value("thrombusVolume"));
  // Every table row of a diameter says which wall it measures.
  for (const Measurement& row : m.values)
    if (row.unit == "mm" && row.name.find("Diameter") != std::string::npos)
    {
      EXPECT_EQ(row.wall, row.name.find("Lumen") != std::string::npos || row.name.find("Access") != std::string::npos
                            ? "lumen"
                            : "outer")
        << row.name;
    }
}

INSTANTIATE_TEST_SUITE_P(VesselWall,
                         WallPlan,
                         ::testing::Values(Grid{ "Fine", { 0.8, 0.8, 1.0 }, 20.0, 1.0, 1.0 },
                                           Grid{ "ThickSlices", { 0.7, 0.7, 2.5 }, 30.0, 1.5, 1.5 }),
                         [](const auto& info) { return std::string(info.param.name); });

/// The plan through the measurements, with the wall label map the neighbour checks count on.
RepairPlan MeasuredWithWallLabels(const AorticPhantom& phantom)
{
  PlanRequest request;
  request.through = PlanStage::Measurements;
  request.wallLabelMap = true;
  return PlanRepair(phantom.ct, phantom.truth.seedLps, request, testing::ShippedPlanParams());
}

/// Voxels of `label` in the truth that the wall label map puts inside the outer wall (≥ 1).
double FractionInside(const LabelImage& wallLabels, const LabelImage& truth, PhantomLabel label, long& count)
{
  const std::size_t n = truth.GetLargestPossibleRegion().GetNumberOfPixels();
  const unsigned char* w = wallLabels.GetBufferPointer();
  const unsigned char* t = truth.GetBufferPointer();
  long inside = 0;
  count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (t[i] == label)
    {
      ++count;
      inside += w[i] != 0;
    }
  return count ? double(inside) / double(count) : 0.0;
}

TEST(VesselWall, NeighboursWithoutAFatPlane_FewerThanTwoPercentInsideAndNoNumberMadeUp)
{
  // Psoas, an unenhanced IVC, the duodenum and the left renal vein, each pressed against the
  // vessel over at least a fifth of its circumference (AorticWall.h; AorticWallPhantomTest).
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.wallThicknessMm = 1.5;
  p.tissueHu = -100.0;
  p.includePsoas = p.includeIvc = p.includeDuodenum = p.includeLeftRenalVein = true;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = MeasuredWithWallLabels(phantom);
  ASSERT_TRUE(plan.wallLabels);
  // Issue 12's bar, < 2 %, for each. (The enhancing left renal vein had 3.9 % inside: the lumen's
  // boundary refinement reached through the blurred wall into it; its reach is now 1.6 mm on
  // every axis, GrowLumenRegion.h.)
  for (const PhantomLabel label : { PsoasLabel, IvcLabel, DuodenumLabel, RenalVeinLabel })
  {
    long count = 0;
    const double inside = FractionInside(*plan.wallLabels, *phantom.labels, label, count);
    EXPECT_GT(count, 1000) << label; // the neighbour is in the phantom
    EXPECT_LT(inside, 0.02) << "label " << int(label) << ": " << 100.0 * inside << " % of " << count;
  }
  // Where they hide most of the circumference the wall is not drawn: every outer value is either
  // within the 1 mm bar of the truth or not measured — never a made-up number.
  const PhantomSizing& truth = phantom.truth.sizing;
  const std::pair<const char*, double> outer[] = { { "proximalNeckDiameter", truth.outerProximalNeckDiameter },
                                                   { "neckDiameter15mm", truth.outerNeckDiameter15mm },
                                                   { "maxAneurysmDiameter", truth.outerMaxAneurysmDiameter },
                                                   { "distalNeckMinDiameter", truth.outerDistalNeckMinDiameter },
                                                   { "rightIliacDiameter", truth.outerRightIliacDiameter },
                                                   { "leftIliacDiameter", truth.outerLeftIliacDiameter } };
  for (const auto& [name, expected] : outer)
  {
    const double value = plan.measurements.Value(name);
    EXPECT_TRUE(std::isnan(value) || std::abs(value - expected) <= 1.0) << name << " " << value << " vs " << expected;
    if (std::isnan(value))
    {
      EXPECT_TRUE(std::any_of(plan.warnings.begin(), plan.warnings.end(),
                              [&](const std::string& w)
                              { return w.rfind(name, 0) == 0 && w.find("not measured") != std::string::npos; }))
        << name;
    }
  }
}

/// One neighbour pressed against the vessel without a fat plane (AorticWall.h: psoas 160° of the
/// infrarenal aorta, IVC 80° all along, duodenum 100° across the neck, left renal vein 90° above the
/// site), sac thrombus 12 mm.
class OneNeighbour : public ::testing::TestWithParam<PhantomLabel>
{
};

TEST_P(OneNeighbour, EveryOuterValueMeasuredWithinTheBarAndTheNeighbourOutside)
{
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.wallThicknessMm = 1.5;
  p.thrombusMaxThicknessMm = 12.0;
  p.tissueHu = -100.0;
  p.includePsoas = GetParam() == PsoasLabel;
  p.includeIvc = GetParam() == IvcLabel;
  p.includeDuodenum = GetParam() == DuodenumLabel;
  p.includeLeftRenalVein = GetParam() == RenalVeinLabel;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = MeasuredWithWallLabels(phantom);
  ASSERT_TRUE(plan.wallLabels);
  long count = 0;
  const double inside = FractionInside(*plan.wallLabels, *phantom.labels, GetParam(), count);
  EXPECT_GT(count, 1000);
  EXPECT_LT(inside, 0.02) << 100.0 * inside << " % of " << count; // issue 12's bar
  // With one neighbour at least half the circumference shows its wall everywhere: every value is
  // measured (before, the psoas alone left the neck and the sac below the thrombus untraced —
  // the first circle, fitted to every candidate, leaned toward it and the wall's own candidates
  // were dropped for good — and the duodenum alone read (b) 27.1 mm for 25, with 2.7 % of it
  // inside), within the fine grid's 1 mm bar.
  testing::ExpectOuterDiametersNear(plan.measurements, phantom.truth.sizing, 1.0);
  EXPECT_NEAR(plan.measurements.Value("thrombusVolume"), phantom.truth.sizing.thrombusVolumeMl,
              0.10 * phantom.truth.sizing.thrombusVolumeMl); // issue 12's bar
}

INSTANTIATE_TEST_SUITE_P(VesselWall,
                         OneNeighbour,
                         ::testing::Values(PsoasLabel, IvcLabel, DuodenumLabel, RenalVeinLabel),
                         [](const auto& info)
                         {
                           switch (info.param)
                           {
                             case PsoasLabel:
                               return std::string("Psoas");
                             case IvcLabel:
                               return std::string("Ivc");
                             case DuodenumLabel:
                               return std::string("Duodenum");
                             default:
                               return std::string("LeftRenalVein");
                           }
                         });

/// Issue 31, item 5: an elliptical sac (axes 66 × 55 mm, ratio 1.2, the major axis transverse)
/// with the IVC against a quarter of its circumference on the right — over one end of the major
/// axis — on fine voxels and on 2.5 mm slices.
class EllipticalSacBehindTheIvc : public ::testing::TestWithParam<Grid>
{
};

TEST_P(EllipticalSacBehindTheIvc, DmaxWithinOneAndAHalfMillimetresAndMarkedEstimated)
{
  const Grid& grid = GetParam();
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.wallThicknessMm = 1.5;
  p.thrombusMaxThicknessMm = 12.0;
  p.tissueHu = -100.0;
  p.sacAxisRatio = 1.2;
  p.sacMajorAxis = PhantomSide::Left;
  p.includeIvc = true;
  p.ivcArcDeg = 90.0;
  p.spacingMm = grid.spacingMm;
  p.noiseSigmaHu = grid.noiseHu;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = MeasuredWithWallLabels(phantom);
  const PhantomSizing& truth = phantom.truth.sizing;
  // 1.5 mm: the issue's bar for Dmax with a quarter of the outer wall invisible (the circle that
  // completed the hidden arc read 59.2 mm for 66.1 on fine voxels).
  const Measurement* dmax = plan.measurements.Find("maxAneurysmDiameter");
  ASSERT_NE(dmax, nullptr);
  EXPECT_NEAR(dmax->value, truth.outerMaxAneurysmDiameter, 1.5);
  // Its caliper's right end lies behind the IVC, on the fitted ellipse: estimated, and the plan says so.
  EXPECT_TRUE(dmax->estimated);
  EXPECT_TRUE(std::any_of(plan.warnings.begin(), plan.warnings.end(),
                          [](const std::string& w)
                          { return w.rfind("maxAneurysmDiameter is estimated: one end of its caliper", 0) == 0; }));
  // The rest of the outer values within the grid's bar (the neck is round).
  for (const auto& [name, expected] :
       { std::pair<const char*, double>{ "proximalNeckDiameter", truth.outerProximalNeckDiameter },
         { "neckDiameter15mm", truth.outerNeckDiameter15mm } })
    EXPECT_NEAR(plan.measurements.Value(name), expected, grid.outerMm) << name;
  // The thrombus fills the ellipse's ends around the round lumen: issue 12's 10 % bar.
  EXPECT_NEAR(plan.measurements.Value("thrombusVolume"), truth.thrombusVolumeMl, 0.10 * truth.thrombusVolumeMl);
}

INSTANTIATE_TEST_SUITE_P(Issue31,
                         EllipticalSacBehindTheIvc,
                         ::testing::Values(Grid{ "Fine", { 0.8, 0.8, 1.0 }, 20.0, 1.0, 1.0 },
                                           Grid{ "ThickSlices", { 0.7, 0.7, 2.5 }, 30.0, 1.5, 1.5 }),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(VesselWall, WallWithoutThrombus_OuterIsLumenPlusTwoWalls)
{
  // A 2 mm wall all along, no thrombus: at every sizing level the outer diameter is the lumen's
  // plus 4 mm, within 0.5 mm (issue 12).
  PhantomParams p;
  p.wallThicknessMm = 2.0;
  p.tissueHu = -100.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanRequest request;
  request.through = PlanStage::Measurements;
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, request, testing::ShippedPlanParams());
  const Measurements& m = plan.measurements;
  for (const char* name : { "proximalNeckDiameter", "neckDiameter15mm", "maxAneurysmDiameter", "distalNeckMinDiameter",
                            "rightIliacDiameter", "leftIliacDiameter" })
  {
    const std::string lumen = std::string(name).replace(std::string(name).find("Diameter"), 8, "LumenDiameter");
    // The outer values are the traced contours' area-equivalent diameters, except (c), the largest
    // maximum caliper, whose maximum over the contour's noise reads up to half a millimetre over
    // the truth (55.47 and 55.51 for 55.0 mm, by the lumen's edge level): for (c) its contour's
    // area-equivalent diameter (55.10 mm) is compared, like the other levels.
    const Measurement* outer = m.Find(name);
    ASSERT_NE(outer, nullptr) << name;
    const double outerMm = std::string(name) == "maxAneurysmDiameter" ? outer->areaMm : outer->value;
    EXPECT_NEAR(outerMm - m.Value(lumen), 2 * p.wallThicknessMm, 0.5) << name;
  }
  EXPECT_NEAR(plan.vesselWall.wallThicknessMm, p.wallThicknessMm, 0.3); // measured above the neck
  EXPECT_TRUE(plan.vesselWall.wallThicknessEstimated);
  EXPECT_LT(m.Value("thrombusVolume"), 2.0); // no thrombus: what is left is edge noise, mL
  EXPECT_LT(m.Value("neckThrombusArc"), 10.0);
}

// Issue 46 items 6 and 9: with no internal iliac in view (e)/(f) are read at a level no branch
// chose — an estimate, marked so: the right internal iliac is not drawn, the left is; only the right
// values are marked estimated, their definitions and a warning name the level, and the return file
// lists them in estimatedValues. The level is 5 mm above where the common iliac narrows into its
// external iliac (IliacNarrowingAbscissa): at the default 60 mm leg the zone lay on the external
// iliac, and (e) read 10.4 for 14.7 mm on issue 46's sweep; here it reads the common iliac.
TEST(VesselWall, NoInternalIliacInView_LandingZoneReadAtTheDefaultIsAnEstimate)
{
  PhantomParams p;
  p.wallThicknessMm = 2.0;
  p.tissueHu = -100.0;
  p.rightInternalIliac = false;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanRequest request;
  request.through = PlanStage::Measurements;
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, request, testing::ShippedPlanParams());
  const Measurements& m = plan.measurements;
  ASSERT_FALSE(std::isfinite(m.internalIliacAbscissaMm[0])); // the right one is not in view
  ASSERT_TRUE(std::isfinite(m.internalIliacAbscissaMm[1]));
  for (const char* name : { "rightIliacLumenDiameter", "rightIliacDiameter" })
  {
    const Measurement* value = m.Find(name);
    ASSERT_NE(value, nullptr) << name;
    ASSERT_TRUE(std::isfinite(value->value)) << name;
    EXPECT_TRUE(value->estimated) << name;
    EXPECT_NE(value->definition.find("estimated: read at a landing zone above where the right iliac narrows into its "
                                     "external iliac"),
              std::string::npos)
      << value->definition;
    EXPECT_NE(value->definition.find("as no right internal iliac origin was found"), std::string::npos)
      << value->definition;
  }
  // On the common iliac: within the sweep's bars of its truth (1.0 mm lumen, 1.5 mm outer, on
  // these 0.8 × 0.8 × 1 mm voxels).
  EXPECT_NEAR(m.Value("rightIliacLumenDiameter"), phantom.truth.sizing.rightIliacDiameter, 1.0);
  EXPECT_NEAR(m.Value("rightIliacDiameter"), phantom.truth.sizing.outerRightIliacDiameter, 1.5);
  for (const char* name : { "leftIliacLumenDiameter", "leftIliacDiameter" })
  {
    ASSERT_NE(m.Find(name), nullptr) << name;
    EXPECT_FALSE(m.Find(name)->estimated) << name;
  }
  int warnings = 0;
  for (const std::string& w : m.warnings)
    warnings += w.find("rightIliacLumenDiameter") == 0 &&
                    w.find("are estimated: read at a landing zone above") != std::string::npos
                  ? 1
                  : 0;
  EXPECT_EQ(warnings, 1);
  std::string estimated;
  for (const PlanValue& v : PlanReturnValues(plan))
    if (v.name == "estimatedValues")
      estimated = "," + v.text + ",";
  EXPECT_NE(estimated.find(",rightIliacDiameter,"), std::string::npos) << estimated;
  EXPECT_NE(estimated.find(",rightIliacLumenDiameter,"), std::string::npos) << estimated;
  EXPECT_EQ(estimated.find(",leftIliac"), std::string::npos) << estimated;
}

TEST(VesselWall, OuterNeck25Lumen22_MainBodyOversizedOnTheOuterWall)
{
  // 25 mm outer neck, 1.5 mm wall: a 22 mm lumen. The IFU's 10–20 % is over the outer wall.
  // (Common iliacs 14 mm, so that the external iliacs admit a sheath: PlanRepairTest.)
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  p.wallThicknessMm = 1.5;
  p.tissueHu = -100.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const PlanParams params = testing::ShippedPlanParams();
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, params);
  ASSERT_GE(plan.selection.recommended, 0) << plan.selection.summary;
  const FamilyEvaluation& chosen = plan.selection.families[plan.selection.recommended];
  const double over = 100.0 * (chosen.mainBody.diameterMm / 25.0 - 1.0);
  EXPECT_GE(over, 10.0) << chosen.family << " " << chosen.mainBody.diameterMm;
  EXPECT_LE(over, 20.0) << chosen.family << " " << chosen.mainBody.diameterMm;
  // The same plan sized on the lumen (every family's reference switched): another main body.
  DeviceCatalog lumenCatalog = params.catalog;
  for (DeviceFamily& family : lumenCatalog.families)
    family.diameterReference = DiameterReference::Lumen;
  const DeviceSelection onLumen = SelectDevice(SizingFromMeasurements(plan.measurements), lumenCatalog);
  ASSERT_GE(onLumen.recommended, 0) << onLumen.summary;
  const FamilyEvaluation& lumenChoice = onLumen.families[onLumen.recommended];
  EXPECT_TRUE(lumenChoice.family != chosen.family || lumenChoice.mainBody.diameterMm != chosen.mainBody.diameterMm)
    << lumenChoice.family << " " << lumenChoice.mainBody.diameterMm;
  // On the lumen it would be oversized by less than 10 % over the outer wall: undersized.
  EXPECT_LT(lumenChoice.mainBody.diameterMm, chosen.mainBody.diameterMm);
  // The table states the wall of the sizes and of the fit check's oversizing.
  for (const Measurement& row : plan.rows)
    if (row.name == "mainBodyDiameter" || row.name == "proximalOversizing")
    {
      EXPECT_EQ(row.wall, "outer") << row.name;
    }
  EXPECT_EQ(plan.fitCheck.oversizingWall, "outer");
}

TEST(VesselWall, CalcifiedNeck_HostileByItsRuleOnly)
{
  // A 270° calcified arc over the neck (75 % of the circumference, rule: ≥ 50 %); otherwise a
  // favourable neck (25 mm long, 22 mm, straight).
  PhantomParams p;
  p.wallThicknessMm = 1.5;
  p.tissueHu = -100.0;
  p.neckCalcificationArcDeg = 270.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanRequest request;
  request.through = PlanStage::Measurements;
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, request, testing::ShippedPlanParams());
  EXPECT_NEAR(plan.measurements.Value("neckCalcificationArc"), phantom.truth.sizing.neckCalcificationArcPercent, 10.0);
  EXPECT_TRUE(plan.neck.hostile) << plan.neck.summary;
  for (const CriterionCheck& c : plan.neck.checks)
    EXPECT_EQ(c.status, c.name == "neck-calcification" ? CheckStatus::Fail : CheckStatus::Pass) << c.text;
  for (const PlanValue& v : PlanReturnValues(plan))
    if (v.name == "hostileNeck")
    {
      EXPECT_TRUE(v.measured);
      EXPECT_EQ(v.text, "true");
    }
}

class NoFatAroundTheVessel : public ::testing::TestWithParam<double>
{
};

TEST_P(NoFatAroundTheVessel, OuterValuesNotMeasured_DeviceSizedOnTheLumenAsAnEstimate)
{
  // Soft tissue (40 HU) all round, with no wall (the lumen-only phantom) or a 1.5 mm wall: no
  // outer wall can be seen, so none is made up — the outer values are not measured, and a warning
  // says so. Issue 29 item 4: the device is sized on the lumen, labelled estimated (lumen), and
  // the IFU result is indeterminate — never "no device within IFU" from values not measured.
  PhantomParams p;
  p.wallThicknessMm = GetParam();
  // 14 mm iliacs: external iliacs of 10.5 mm, whose lumen passes every family's access check, so
  // that nothing fails on a measured value.
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, testing::ShippedPlanParams());
  EXPECT_TRUE(plan.vesselWall.Empty());
  EXPECT_TRUE(std::isnan(plan.measurements.Value("proximalNeckDiameter")));
  EXPECT_TRUE(std::isfinite(plan.measurements.Value("proximalNeckLumenDiameter")));
  const auto warned = [&](const std::string& part)
  {
    return std::any_of(plan.warnings.begin(), plan.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(warned("No outer wall was found"));
  EXPECT_TRUE(warned("The outer wall was not traced at (a), (b), (e), (f): the device is sized on the lumen"));
  ASSERT_GE(plan.selection.recommended, 0) << plan.selection.summary;
  EXPECT_NE(plan.selection.summary.find("estimated (lumen)"), std::string::npos) << plan.selection.summary;
  EXPECT_EQ(plan.selection.summary.find("no device within IFU"), std::string::npos);
  EXPECT_EQ(plan.selection.ifuStatus, CheckStatus::Indeterminate);
  const FamilyEvaluation& family = plan.selection.families[std::size_t(plan.selection.recommended)];
  EXPECT_TRUE(family.EstimatedOnLumen());
  // Sized on the lumen's (a): the main body's oversizing is over the lumen.
  EXPECT_NEAR(family.mainBody.oversizingPercent,
              OversizingPercent(family.mainBody.diameterMm, plan.measurements.Value("proximalNeckLumenDiameter")),
              1e-9);
  std::map<std::string, PlanValue> values;
  for (const PlanValue& v : PlanReturnValues(plan))
    values[v.name] = v;
  EXPECT_EQ(values["ifuStatus"].text, "indeterminate");
  EXPECT_EQ(values["withinIfu"].text, "false");
  EXPECT_NE(values["recommendedDevice"].text, "none");
  EXPECT_FALSE(values["proximalNeckDiameter"].measured);
  EXPECT_FALSE(values["thrombusVolume"].measured);
  // Every row the estimate feeds says so.
  for (const Measurement& row : plan.rows)
    if (row.name == "mainBodyDiameter" || row.name == "rightLimbDiameter" || row.name == "leftLimbDiameter" ||
        row.name == "mainBodyLength")
    {
      EXPECT_NE(row.definition.find("estimated (lumen)"), std::string::npos) << row.name << ": " << row.definition;
    }
}

INSTANTIATE_TEST_SUITE_P(VesselWall,
                         NoFatAroundTheVessel,
                         ::testing::Values(0.0, 1.5),
                         [](const auto& info) { return info.param > 0.0 ? "WallInSoftTissue" : "LumenOnly"; });

} // namespace
} // namespace sgp
