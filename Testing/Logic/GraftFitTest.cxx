// Device selection on measured phantoms and the simulated graft's fit check (issue 6), through
// the pipeline the CLI runs: segmentation → centerlines → measure-mode fit → measurements →
// selection → simulate-mode fit with the device's nominal radii → fit check.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Device/DeployGraft.h"
#include "Device/FitCheck.h"
#include "Device/SelectDevice.h"
#include "IO/ReadDeviceCatalog.h"
#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"
#include "PipelineSupport.h"

namespace sgp
{
namespace
{

using testing::MeasuredPlan;

const CriterionCheck& Check(const FamilyEvaluation& family, const std::string& name)
{
  for (const CriterionCheck& c : family.checks)
    if (c.name == name)
      return c;
  throw std::runtime_error("no check " + name + " for " + family.family);
}

/// The simulate-mode fit of `plan`'s mesh with nominal diameters (trunk, right, left; NaN: a leg not
/// sized, carried at 12 mm) and its check: the chosen diameters on the measured landing zones
/// (LayOutOnMeasureMesh), as the pipeline simulates a family whose lengths are not configured.
FitCheck Simulate(const MeasuredPlan& plan, const std::array<double, 3>& diameters)
{
  const GraftLayout layout = LayOutOnMeasureMesh(plan.mesh, plan.measurements, "Test", diameters, { 12.0, 12.0 });
  const DeployedGraft graft = DeployGraft(layout, plan.wall, ActiveContourParams::Simulate({ 24.0, 14.0, 14.0 }));
  EXPECT_TRUE(graft.fit.converged);
  FitCheckContext context;
  context.limbSized = { std::isfinite(diameters[1]), std::isfinite(diameters[2]) };
  return CheckGraftFit(graft, plan.measurements, plan.tree, &plan.vesselWall, context);
}

/// Mean of a per-vertex value over the trunk's first `rings` rings (the proximal neck).
double NeckMean(const StentMesh& mesh, const Eigen::VectorXd& values, int rings)
{
  double sum = 0.0;
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < mesh.verticesPerRing; ++j)
      sum += values[mesh.Id(TrunkSegment, k, j)];
  return sum / (rings * mesh.verticesPerRing);
}

/// The phantom with a wall in fat (sizing is on the outer wall, which needs one to be seen).
MeasuredPlan PlanFor(const PhantomParams& p, AorticPhantom& phantom)
{
  phantom = GenerateAorticPhantom(testing::WithWallInFat(p));
  return testing::MeasureFromCt(*phantom.ct, phantom.truth.seedLps);
}

class KnownNeck : public ::testing::TestWithParam<double>
{
};

TEST_P(KnownNeck, MainBodyIsTheSizeNearestFifteenPercentWithinTenToTwenty)
{
  PhantomParams p;
  p.neckDiameterMm = GetParam();
  AorticPhantom phantom;
  const MeasuredPlan plan = PlanFor(p, phantom);
  const double a = plan.measurements.Value("proximalNeckDiameter");
  ASSERT_NEAR(a, GetParam(), 1.0); // issue 5's bar: the selection sees the neck it should
  const DeviceCatalog catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  const DeviceSelection selection = SelectDevice(SizingFromMeasurements(plan.measurements), catalog);
  ASSERT_EQ(selection.families.size(), catalog.families.size());
  for (std::size_t f = 0; f < catalog.families.size(); ++f)
  {
    SCOPED_TRACE(catalog.families[f].name);
    // Brute force over the catalogue: the size inside 10–20 % nearest 15 %.
    double best = std::nan(""), bestDistance = 1e9;
    for (const DeviceSize& size : catalog.families[f].mainBodies.sizes)
    {
      const double over = 100.0 * (size.diameterMm / a - 1.0);
      if (over >= 10.0 && over <= 20.0 && std::abs(over - 15.0) < bestDistance)
      {
        best = size.diameterMm;
        bestDistance = std::abs(over - 15.0);
      }
    }
    const SizeChoice& chosen = selection.families[f].mainBody;
    if (std::isnan(best))
      EXPECT_FALSE(chosen.Chosen()) << chosen.diameterMm;
    else
    {
      EXPECT_EQ(chosen.diameterMm, best);
      EXPECT_GE(chosen.oversizingPercent, 10.0);
      EXPECT_LE(chosen.oversizingPercent, 20.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(GraftFit, KnownNeck, ::testing::Values(22.0, 27.0));

TEST(GraftFit, NineMillimetreNeck_NeverPassesTheNeckLengthCriteria)
{
  // A 7.4 mm shoulder: by the 10 % rule the neck is 9.0 mm long (AorticPhantom.h), 1 mm short of
  // Endurant II's ≥ 10 mm (β = 0 ≤ 60°) and 6 mm short of the ≥ 15 mm devices. Measured through
  // the whole pipeline, not substituted.
  PhantomParams p;
  p.neckLengthMm = 7.4;
  AorticPhantom phantom;
  const MeasuredPlan plan = PlanFor(p, phantom);
  ASSERT_NEAR(phantom.truth.sizing.proximalNeckLength, 9.0, 0.1); // the shoulder's rise: 1.6 mm
  const double neck = plan.measurements.Value("proximalNeckLength");
  EXPECT_NEAR(neck, 9.0, NeckLengthUncertaintyMm); // the measurement's stated accuracy
  const DeviceCatalog catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  const DeviceSelection measured = SelectDevice(SizingFromMeasurements(plan.measurements), catalog);
  for (const FamilyEvaluation& family : measured.families)
  {
    SCOPED_TRACE(family.family);
    const CriterionCheck& c = Check(family, "neck length");
    EXPECT_NEAR(c.margin, neck - c.min, 1e-9) << c.text;
    // Never a pass: short by more than the uncertainty fails; within it, indeterminate.
    EXPECT_EQ(c.status, neck - c.min < -NeckLengthUncertaintyMm ? CheckStatus::Fail : CheckStatus::Indeterminate)
      << c.text;
    if (c.min >= 15.0)
    {
      EXPECT_EQ(c.status, CheckStatus::Fail) << c.text; // 6 mm short: beyond any measurement error
    }
  }
  EXPECT_LT(measured.recommended, 0) << measured.summary; // no device within IFU
}

TEST(GraftFit, NeckOneMillimetreOverTheLimit_IndeterminateNotPass)
{
  // A 9.4 mm shoulder: an 11.0 mm neck, 1 mm over Endurant II's ≥ 10 mm — inside the measurement's
  // uncertainty, so the check says it cannot tell rather than "pass".
  PhantomParams p;
  p.neckLengthMm = 9.4;
  AorticPhantom phantom;
  const MeasuredPlan plan = PlanFor(p, phantom);
  ASSERT_NEAR(phantom.truth.sizing.proximalNeckLength, 11.0, 0.1);
  const DeviceSelection measured =
    SelectDevice(SizingFromMeasurements(plan.measurements), ReadDeviceCatalog(SGP_DEVICES_JSON));
  for (const FamilyEvaluation& family : measured.families)
    if (family.family == "Endurant II")
    {
      const CriterionCheck& c = Check(family, "neck length");
      ASSERT_LE(std::abs(c.margin), NeckLengthUncertaintyMm) << c.text; // measured within 1 ± 2 mm of 10
      EXPECT_EQ(c.status, CheckStatus::Indeterminate) << c.text;
      EXPECT_NE(c.text.find("uncertainty"), std::string::npos) << c.text;
    }
}

class DefaultPhantomGraft : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    phantom = new AorticPhantom(GenerateAorticPhantom(PhantomParams{}));
    plan = new MeasuredPlan(testing::MeasureFromCt(*phantom->ct, phantom->truth.seedLps));
  }
  static void TearDownTestSuite()
  {
    delete plan;
    delete phantom;
  }
  static AorticPhantom* phantom;
  static MeasuredPlan* plan;
};
AorticPhantom* DefaultPhantomGraft::phantom = nullptr;
MeasuredPlan* DefaultPhantomGraft::plan = nullptr;

TEST_F(DefaultPhantomGraft, CorrectlySized_OnTheWallInTheNeckAndSealing)
{
  // 25 mm main body on the 22 mm neck (+14 %), 14 mm limbs on 12 mm iliacs (+17 %).
  const FitCheck c = Simulate(*plan, { 25.0, 14.0, 14.0 });
  // The first three rings (8 mm of neck) press on the wall: the gap is the wall force's
  // softening at most (Huber δ = 1 mm; in practice a few tenths).
  EXPECT_LT(NeckMean(plan->mesh, c.appositionMm, 3), 0.3);
  // The graft seals over the whole 25 mm neck (ring spacing ≤ 4 mm quantizes the length).
  EXPECT_GE(c.proximalSealLengthMm, phantom->truth.sizing.proximalNeckLength - 4.0);
  EXPECT_GE(c.rightIliacSealLengthMm, 10.0);
  EXPECT_GE(c.leftIliacSealLengthMm, 10.0);
  // Over the measured (a), exactly (only rounding: both are one division of the same doubles):
  // the lumen's, as this phantom has no fat to show an outer wall (lumen-only, like issue 6's).
  EXPECT_TRUE(plan->vesselWall.Empty());
  EXPECT_EQ(c.oversizingWall, "lumen");
  EXPECT_NEAR(c.proximalOversizingPercent, 100.0 * (25.0 / plan->measurements.Value("proximalNeckLumenDiameter") - 1.0),
              1e-9);
  EXPECT_FALSE(c.migrationRisk);
  EXPECT_EQ(c.CoveredOstia(), "none");
  EXPECT_TRUE(c.Passed()) << c.findings.front();
}

TEST_F(DefaultPhantomGraft, Undersized_GapInTheNeckAndMigrationRisk)
{
  // An 18 mm main body in a 22 mm neck stops at its radius: a 2 mm gap all round.
  const FitCheck c = Simulate(*plan, { 18.0, 14.0, 14.0 });
  // (22 − 18)/2 = 2 mm; above 1.5 mm: the ring opens to within 2 % of R, and the segmented wall
  // lies within half a voxel (0.4 mm) of the analytic one.
  EXPECT_GT(NeckMean(plan->mesh, c.appositionMm, 3), 1.5);
  EXPECT_LT(c.proximalSealLengthMm, 10.0);
  EXPECT_TRUE(c.migrationRisk);
  EXPECT_LT(c.proximalOversizingPercent, 0.0);
  EXPECT_FALSE(c.Passed());
}

TEST_F(DefaultPhantomGraft, GraftAboveTheLowestRenal_CoversItsOstium)
{
  // The plan's graft starts at the lower edge of the lowest (right) renal ostium: nothing covered.
  const FitCheck atSite = Simulate(*plan, { 25.0, 14.0, 14.0 });
  EXPECT_EQ(atSite.CoveredOstia(), "none");
  // Started 10 mm higher, its top reaches over the whole right renal ostium (6 mm across).
  MeasuredPlan higher = *plan;
  StentMeshParams meshParams;
  meshParams.proximalAbscissaMm = plan->site.abscissaMm - 10.0;
  testing::FitAndMeasure(higher, meshParams);
  const FitCheck above = Simulate(higher, { 25.0, 14.0, 14.0 });
  bool rightRenalCovered = false;
  for (const OstiumCoverage& o : above.ostia)
    if (o.branch == "rightRenal")
      rightRenalCovered = o.covered;
  EXPECT_TRUE(rightRenalCovered) << above.CoveredOstia();
  EXPECT_FALSE(above.Passed());
}

TEST_F(DefaultPhantomGraft, LimbsNotSized_TheProximalPartChecked)
{
  // A partial plan: the limbs are not sized (NaN), the legs simulated at the iliac lumen's own
  // 12 mm only to carry the connection element. The proximal part is the whole check's: the same
  // top ring, oversizing over the same (a) (exactly: one division of the same doubles), the seal
  // zone within one ring (3.9 mm: the legs' radii change the trunk's fit near the junction only)
  // and the same aortic ostia; nothing distal is reported or found.
  const double none = std::numeric_limits<double>::quiet_NaN();
  const FitCheck whole = Simulate(*plan, { 25.0, 14.0, 14.0 });
  for (const double mainBody : { 25.0, 18.0 })
  {
    SCOPED_TRACE(mainBody);
    const FitCheck c = Simulate(*plan, { mainBody, none, none });
    const FitCheck full = mainBody == 25.0 ? whole : Simulate(*plan, { mainBody, 14.0, 14.0 });
    EXPECT_FALSE(c.Complete());
    EXPECT_FALSE(c.Passed()); // a partial check cannot pass
    EXPECT_NEAR(c.proximalOversizingPercent, full.proximalOversizingPercent, 1e-9);
    EXPECT_NEAR(c.proximalSealLengthMm, full.proximalSealLengthMm, 3.9);
    EXPECT_EQ(c.migrationRisk, full.migrationRisk);
    for (const double distal : { c.rightIliacSealLengthMm, c.leftIliacSealLengthMm, c.rightLimbOversizingPercent,
                                 c.leftLimbOversizingPercent })
      EXPECT_TRUE(std::isnan(distal)) << distal;
    std::vector<std::string> aortic, checked;
    for (const OstiumCoverage& o : full.ostia)
      if (o.parent == "aorta")
        aortic.push_back(o.branch + (o.covered ? " covered" : ""));
    for (const OstiumCoverage& o : c.ostia)
      checked.push_back(o.branch + (o.covered ? " covered" : ""));
    EXPECT_EQ(checked, aortic); // the internal iliacs are not checked
    for (const std::string& f : c.findings)
      EXPECT_EQ(f.find("limb"), std::string::npos) << f;
    for (const std::string& f : c.findings)
      EXPECT_EQ(f.find("iliac seal"), std::string::npos) << f;
    // The 18 mm main body's proximal findings are found without the limbs (migration risk).
    EXPECT_EQ(c.findings.empty(), mainBody == 25.0) << (c.findings.empty() ? "" : c.findings.front());
  }
}

/// The correctly sized graft (25 mm main body, 14 mm limbs) deployed in the default phantom.
DeployedGraft DeployCorrectlySized(const MeasuredPlan& plan)
{
  const GraftLayout layout =
    LayOutOnMeasureMesh(plan.mesh, plan.measurements, "Test", { 25.0, 14.0, 14.0 }, { 12.0, 12.0 });
  return DeployGraft(layout, plan.wall, ActiveContourParams::Simulate({ 24.0, 14.0, 14.0 }));
}

/// The centre of the deployed trunk's ring k (the mean of its vertices), LPS mm.
Point3 TrunkRingCentre(const DeployedGraft& graft, int k)
{
  return RingCentroid(graft.layout.mesh, graft.fit.V, TrunkSegment, k);
}

/// The trunk's column whose top vertex points most nearly along `direction` (LPS) from the top ring's centre.
int ColumnToward(const DeployedGraft& graft, const Eigen::Vector3d& direction)
{
  const StentMesh& mesh = graft.layout.mesh;
  const Point3 centre = TrunkRingCentre(graft, 0);
  int best = 0;
  double bestCos = -2.0;
  for (int j = 0; j < mesh.verticesPerRing; ++j)
  {
    const Eigen::Vector3d d = (graft.fit.V.row(mesh.Id(TrunkSegment, 0, j)).transpose() - centre).normalized();
    if (d.dot(direction) > bestCos)
    {
      bestCos = d.dot(direction);
      best = j;
    }
  }
  return best;
}

std::string FindingWith(const FitCheck& c, const std::string& words)
{
  for (const std::string& f : c.findings)
    if (f.find(words) != std::string::npos)
      return f;
  return "";
}

// Issue 46 item 4: a fit check passed with a shortest apposition length of 0.0 mm. One column of
// the correctly sized graft is planted 3 mm off the wall from its third ring down: 15 of its 16
// vertices still touch, so every ring seals (≥ 90 %) and the proximal seal is unchanged, but that
// column apposes only from the edge to the second ring — the shortest apposition length, exactly
// (its sealed share drops from 1 to 0 between the second and third ring: it ends at the second).
TEST_F(DefaultPhantomGraft, OneColumnOffTheWall_ShortAppositionIsAFindingThatNamesItsSideAndTheGap)
{
  DeployedGraft graft = DeployCorrectlySized(*plan);
  const FitCheck before = CheckGraftFit(graft, plan->measurements, plan->tree, &plan->vesselWall, FitCheckContext{});
  ASSERT_TRUE(before.Passed()) << before.findings.front();
  ASSERT_GE(before.shortestAppositionLengthMm, 10.0);
  const StentMesh& mesh = graft.layout.mesh;
  const int column = ColumnToward(graft, Eigen::Vector3d::UnitX()); // the patient's left (LPS +x)
  for (int k = 2; k < mesh.RingsIn(TrunkSegment); ++k)
    graft.fit.wallDistanceMm[mesh.Id(TrunkSegment, k, column)] = -3.0;
  const FitCheck c = CheckGraftFit(graft, plan->measurements, plan->tree, &plan->vesselWall, FitCheckContext{});
  const std::vector<double>& s = mesh.ringAbscissaMm[TrunkSegment];
  EXPECT_NEAR(c.shortestAppositionLengthMm, s[1] - s[0], 1e-9);
  // The rings still seal where they did: the planted column only takes one vertex in 16 off the
  // share of the ring in the sac where the seal ends, which moves its interpolated end by a
  // fraction of a millimetre (0.24 mm here), and the seal is no finding.
  EXPECT_NEAR(c.proximalSealLengthMm, before.proximalSealLengthMm, 0.5);
  EXPECT_GE(c.proximalSealLengthMm, 10.0 + c.proximalSealUncertaintyMm);
  EXPECT_EQ(c.shortestAppositionSide, "left");
  EXPECT_EQ(c.shortestAppositionEnd, "it is not in contact with the wall (gap 3.0 mm)");
  EXPECT_TRUE(c.migrationRisk);
  EXPECT_FALSE(c.Passed());
  const std::string finding = FindingWith(c, "shortest apposition length");
  EXPECT_NE(finding.find("type Ia endoleak and migration risk"), std::string::npos) << finding;
  EXPECT_NE(finding.find("needs ≥ 10 mm"), std::string::npos) << finding;
  EXPECT_NE(finding.find("on the patient's left side"), std::string::npos) << finding;
  EXPECT_NE(finding.find("gap 3.0 mm"), std::string::npos) << finding;
}

// The same class on thrombus: a traced wall whose planes carry a narrow arc (5 of 64 rays, 8 %:
// under the 10 % that would end the ring's seal) of 4 mm thrombus under the graft's posterior
// column, from its third ring down. The rings seal; that column does not, and the finding says why.
TEST_F(DefaultPhantomGraft, OneColumnOnANarrowArcOfThrombus_ShortAppositionIsAFindingThatSaysThrombus)
{
  const DeployedGraft graft = DeployCorrectlySized(*plan);
  const StentMesh& mesh = graft.layout.mesh;
  const std::vector<double>& s = mesh.ringAbscissaMm[TrunkSegment];
  const int rings = mesh.RingsIn(TrunkSegment);
  const int column = ColumnToward(graft, Eigen::Vector3d::UnitY()); // posterior (LPS +y)
  const double neck = plan->measurements.Value("proximalNeckLumenDiameter");
  ASSERT_TRUE(std::isfinite(neck));
  const auto wallWith = [&](double thrombusMm)
  {
    VesselWall wall;
    for (double at = s.front(); at <= s.back(); at += wall.stepMm)
    {
      int k = 0;
      while (k + 2 < rings && s[std::size_t(k + 1)] < at)
        ++k;
      const double f = std::clamp((at - s[std::size_t(k)]) / (s[std::size_t(k + 1)] - s[std::size_t(k)]), 0.0, 1.0);
      OuterWallPlane plane;
      plane.abscissaMm = at;
      plane.centreLps = (1.0 - f) * TrunkRingCentre(graft, k) + f * TrunkRingCentre(graft, k + 1);
      const Eigen::Vector3d axis = (TrunkRingCentre(graft, k + 1) - TrunkRingCentre(graft, k)).normalized();
      // Ray 0 points at the column's vertex of the nearer ring, so the arc is centred under it.
      const int nearer = f < 0.5 ? k : k + 1;
      Eigen::Vector3d u = graft.fit.V.row(mesh.Id(TrunkSegment, nearer, column)).transpose() - plane.centreLps;
      u = (u - u.dot(axis) * axis).normalized();
      plane.uLps = u;
      plane.vLps = axis.cross(u);
      plane.thrombusMm = Eigen::VectorXd::Zero(64);
      if (at >= s[2] - 0.5)
        for (int ray : { 62, 63, 0, 1, 2 }) // within 11.25° of ray 0
          plane.thrombusMm[ray] = thrombusMm;
      plane.calcified.assign(64, false);
      plane.minCaliperMm = plane.areaDiameterMm = neck;
      plane.supportedFraction = 1.0;
      wall.vessels[TrunkSegment].planes.push_back(plane);
    }
    return wall;
  };
  const VesselWall healthy = wallWith(0.0), thrombus = wallWith(4.0);
  const FitCheck before = CheckGraftFit(graft, plan->measurements, plan->tree, &healthy, FitCheckContext{});
  ASSERT_TRUE(before.Passed()) << before.findings.front();
  const FitCheck c = CheckGraftFit(graft, plan->measurements, plan->tree, &thrombus, FitCheckContext{});
  EXPECT_NEAR(c.shortestAppositionLengthMm, s[1] - s[0], 1e-9);
  // The rings still seal where they did: the planted column only takes one vertex in 16 off the
  // share of the ring in the sac where the seal ends, which moves its interpolated end by a
  // fraction of a millimetre (0.24 mm here), and the seal is no finding.
  EXPECT_NEAR(c.proximalSealLengthMm, before.proximalSealLengthMm, 0.5);
  EXPECT_GE(c.proximalSealLengthMm, 10.0 + c.proximalSealUncertaintyMm);
  EXPECT_EQ(c.shortestAppositionSide, "posterior");
  EXPECT_EQ(c.shortestAppositionEnd, "it lies on thrombus 4.0 mm thick (over 2 mm)");
  EXPECT_FALSE(c.Passed());
  EXPECT_NE(FindingWith(c, "shortest apposition length").find("on the patient's posterior side"), std::string::npos);
}

TEST_F(DefaultPhantomGraft, MismatchedMeasurements_InputError)
{
  // A fitted surface of another mesh than the layout's.
  DeployedGraft graft;
  graft.layout = LayOutOnMeasureMesh(plan->mesh, plan->measurements, "Test", { 25.0, 14.0, 14.0 }, { 12.0, 12.0 });
  StentMeshParams meshParams;
  meshParams.ringSpacingMm = 2.0;
  const StentMesh other = BuildStentMesh(plan->tree, meshParams);
  graft.fit.V = other.V;
  graft.fit.wallDistanceMm = Eigen::VectorXd::Zero(other.V.rows());
  EXPECT_THROW(CheckGraftFit(graft, plan->measurements, plan->tree, &plan->vesselWall, FitCheckContext{}), InputError);
}

} // namespace
} // namespace sgp

namespace sgp
{
namespace
{

// Issue 46 item 5: the fabric's positions on the centerline, from a graft's axis (analytic axes).
TEST(FabricLength, PathAt_LinearBetweenRingsMmForMmBeyondTheEnds)
{
  GraftAxis axis;
  axis.lengthMm = { 0.0, 10.0, 18.0 }; // the second stretch: 8 mm of graft over 10 mm of centerline
  axis.pathMm = { 0.0, 10.0, 20.0 };
  EXPECT_DOUBLE_EQ(axis.LengthMm(), 18.0);
  EXPECT_DOUBLE_EQ(axis.PathAt(5.0), 5.0);
  EXPECT_DOUBLE_EQ(axis.PathAt(14.0), 15.0);
  EXPECT_DOUBLE_EQ(axis.PathAt(18.0), 20.0);
  EXPECT_DOUBLE_EQ(axis.PathAt(25.0), 27.0);
  EXPECT_DOUBLE_EQ(axis.PathAt(-2.0), -2.0);
}

TEST(FabricLength, PlacedAlongTheGraft_EveryPositionWhereItsFabricReaches)
{
  DeviceConfiguration c;
  c.configured = true;
  c.ipsilateralSide = 0;
  const auto component = [](OrderRole role, int side, double from, double to)
  {
    ConfiguredComponent part;
    part.role = role;
    part.side = side;
    part.proximalMm = from;
    part.distalMm = to;
    part.item.lengthMm = to - from;
    return part;
  };
  c.components = { component(OrderRole::MainBody, 0, 0.0, 100.0), component(OrderRole::IpsilateralLimb, 0, 70.0, 170.0),
                   component(OrderRole::ContralateralLimb, 1, 60.0, 180.0) };
  c.flowDividerMm = 50.0;
  c.gateEndMm = 85.0;
  c.coveredLengthMm = { 170.0, 180.0 };
  // Both axes: along the centerline to 40 mm, then 40 mm of graft over 50 mm of centerline (the
  // sac, cut straight), then mm for mm.
  GraftAxis axis;
  axis.lengthMm = { 0.0, 40.0, 80.0, 200.0 };
  axis.pathMm = { 0.0, 40.0, 90.0, 210.0 };
  const DeviceConfiguration placed = PlacedAlongTheGraft(c, { axis, axis });
  const auto expected = [](double fabric) {
    return fabric <= 40.0 ? fabric : fabric <= 80.0 ? 40.0 + (fabric - 40.0) * 1.25 : 90.0 + (fabric - 80.0);
  };
  constexpr double exact = 1e-12; // sums and products of the figures above
  for (std::size_t k = 0; k < c.components.size(); ++k)
  {
    EXPECT_NEAR(placed.components[k].proximalMm, expected(c.components[k].proximalMm), exact) << k;
    EXPECT_NEAR(placed.components[k].distalMm, expected(c.components[k].distalMm), exact) << k;
    EXPECT_DOUBLE_EQ(placed.components[k].item.lengthMm, c.components[k].item.lengthMm) << "the catalogue's";
  }
  EXPECT_NEAR(placed.flowDividerMm, 52.5, exact);
  EXPECT_NEAR(placed.gateEndMm, 95.0, exact);
  EXPECT_NEAR(placed.coveredLengthMm[0], 180.0, exact);
  EXPECT_NEAR(placed.coveredLengthMm[1], 190.0, exact);
  // An axis that follows the centerline moves nothing.
  GraftAxis straight;
  straight.lengthMm = straight.pathMm = { 0.0, 100.0, 200.0 };
  const DeviceConfiguration same = PlacedAlongTheGraft(c, { straight, straight });
  for (std::size_t k = 0; k < c.components.size(); ++k)
    EXPECT_NEAR(same.components[k].distalMm, c.components[k].distalMm, exact) << k;
  EXPECT_NEAR(same.coveredLengthMm[1], c.coveredLengthMm[1], exact);
}

} // namespace
} // namespace sgp
