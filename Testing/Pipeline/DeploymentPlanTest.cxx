// The ordered configuration and the deployed graft through the whole pipeline (issues 29 and 30),
// on phantoms whose landmarks are known: where the limbs land against the true internal iliac
// ostium, the covered lengths against the components, the simulated graft's edges and lengths
// against where it was deployed, and the seal on healthy wall against the phantom's own healthy
// neck.
#include <algorithm>
#include <array>
#include <iostream>
#include <limits>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Centerlines/ProximalSite.h"
#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"
#include "PipelineSupport.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "Stent/WallDistanceField.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

/// Sums of catalogue figures are exact to rounding.
constexpr double ExactMm = 1e-9;
/// The simulated graft's positions and lengths: the issue's bar.
constexpr double DeployedMm = 1.0;

RepairPlan Plan(const AorticPhantom& phantom, const PlanParams& params = testing::ShippedPlanParams())
{
  return PlanRepair(phantom.ct, phantom.truth.seedLps, PlanRequest{}, params);
}

/// The shipped parameters with the Endurant II forced. The wall phantom's 22.0 mm outer (a) lies
/// 0.13 mm below the point where the recommendation turns from the Endurant II 25 mm (13.6 %
/// oversizing) to the Excluder Conformable 26 mm (18.2 %) around the 15 % target, well within the
/// outer wall's measurement error (+0.1 to +0.3 mm on this phantom): the tests of how a graft
/// deploys and seals pin the family they were written for rather than follow that coin.
PlanParams EndurantParams()
{
  PlanParams params = testing::ShippedPlanParams();
  params.selection.forcedDevice = "Endurant II";
  return params;
}

/// A wall in fat and 14 mm common iliacs (external iliacs wide enough for every family's access).
PhantomParams WallPhantom()
{
  PhantomParams p = testing::WithWallInFat(PhantomParams{});
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  return p;
}

Point3 TruthLandmark(const AorticPhantom& phantom, const std::string& name)
{
  for (const PhantomLandmark& l : phantom.truth.landmarks)
    if (l.name == name)
      return l.lps;
  throw std::runtime_error("no truth landmark " + name);
}

/// The centroid of the fitted ring k of `segment`, and its position along `side`'s path from the
/// deployment target, read back off the surface (projected onto the centerline), not off the layout.
double RingPathMm(const RepairPlan& plan, int segment, int k, int side, Point3* centroid = nullptr)
{
  const GraftLayout& g = plan.graft.layout;
  Point3 sum = Point3::Zero();
  int count = 0;
  for (int j = 0; j < g.mesh.verticesPerRing; ++j)
  {
    const int i = g.mesh.Id(segment, k, j);
    (void)side; // the whole ring: its centroid lies on its plane's centre line, not off it in a bend
    sum += plan.graft.fit.V.row(i).transpose();
    ++count;
  }
  const Point3 c = sum / count;
  if (centroid)
    *centroid = c;
  if (segment == TrunkSegment)
    return ProjectOntoCenterline(plan.centerlines.aorta, c) - g.targetAbscissaMm;
  const Centerline& iliac = side == 0 ? plan.centerlines.rightIliac : plan.centerlines.leftIliac;
  return g.PathOfIliac(side, ProjectOntoCenterline(iliac, c));
}

/// The simulated graft's own axis on `side`, read off the fitted surface here: the centres of the
/// trunk's rings from the first, then of the side's leg's, joined by straight segments — per ring
/// (segment, k), its length along that polyline from the first ring, mm.
std::map<std::pair<int, int>, double> AxisLengths(const RepairPlan& plan, int side)
{
  const GraftLayout& g = plan.graft.layout;
  std::map<std::pair<int, int>, double> lengths;
  Point3 previous = Point3::Zero();
  double length = 0.0;
  for (const int seg : { int(TrunkSegment), 1 + side })
    for (int k = 0; k < g.mesh.RingsIn(seg); ++k)
    {
      Point3 centre;
      RingPathMm(plan, seg, k, side, &centre);
      if (!lengths.empty())
        length += (centre - previous).norm();
      lengths[{ seg, k }] = length;
      previous = centre;
    }
  return lengths;
}

/// The simulated extent [from, to] of component `index` on `side`'s path: the rings where any of
/// its vertices on that side carry it (as the outer component or as the one inserted). With
/// `alongAxis`, as lengths along the graft's own axis from its proximal edge (AxisLengths).
std::pair<double, double> SimulatedExtent(const RepairPlan& plan,
                                          int index,
                                          int side,
                                          const std::map<std::pair<int, int>, double>* alongAxis = nullptr)
{
  const GraftLayout& g = plan.graft.layout;
  double from = 1e9, to = -1e9;
  for (int seg = 0; seg < 3; ++seg)
  {
    if (seg != TrunkSegment && seg != 1 + side)
      continue;
    for (int k = 0; k < g.mesh.RingsIn(seg); ++k)
    {
      bool carries = false;
      for (int j = 0; j < g.mesh.verticesPerRing; ++j)
      {
        const int i = g.mesh.Id(seg, k, j);
        carries = carries || (g.side[i] == side && (g.component[i] == index || g.innerComponent[i] == index));
      }
      if (!carries)
        continue;
      const double path = alongAxis ? alongAxis->at({ seg, k }) : RingPathMm(plan, seg, k, side);
      from = std::min(from, path);
      to = std::max(to, path);
    }
  }
  return { from, to };
}

/// Issue 30's three checks on a deployed graft, with issue 46 item 5's fabric that does not
/// shorten: the proximal edge at the target; every component as long as the catalogue says and
/// where the configuration puts it, both along the graft's own axis (AxisLengths: the fabric); every
/// distal edge as far along that axis as the fabric ordered reaches (the components less their
/// overlaps), and on the centerline where the plan says it lies (covered length + the shift).
void ExpectDeployedAsPlanned(const RepairPlan& plan)
{
  ASSERT_TRUE(plan.HasGraft());
  const GraftLayout& g = plan.graft.layout;
  ASSERT_TRUE(g.configured);
  const DeviceConfiguration& c = *plan.Configuration();
  ASSERT_EQ(g.components.size(), c.components.size());
  double edge = 0.0, length = 0.0, distal = 0.0; // the largest deviations, printed for the record
  for (int side = 0; side < 2; ++side)
  {
    const double at = RingPathMm(plan, TrunkSegment, 0, side);
    EXPECT_NEAR(at, 0.0, DeployedMm) << "proximal edge, side " << side;
    edge = std::max(edge, std::abs(at));
  }
  const std::array<std::map<std::pair<int, int>, double>, 2> axis{ AxisLengths(plan, 0), AxisLengths(plan, 1) };
  for (int index = 0; index < int(c.components.size()); ++index)
  {
    const ConfiguredComponent& part = c.components[std::size_t(index)];
    SCOPED_TRACE(part.OrderText());
    const int side = part.role == OrderRole::MainBody ? c.ipsilateralSide : part.side;
    const auto [from, to] = SimulatedExtent(plan, index, side, &axis[std::size_t(side)]);
    EXPECT_NEAR(to - from, part.item.lengthMm, DeployedMm) << "simulated length along the graft's axis";
    EXPECT_NEAR(from, part.proximalMm, DeployedMm) << "along the graft's axis";
    length = std::max({ length, std::abs(to - from - part.item.lengthMm), std::abs(from - part.proximalMm) });
  }
  for (int side = 0; side < 2; ++side)
  {
    const std::size_t s = std::size_t(side);
    const int last = g.mesh.RingsIn(1 + side) - 1;
    const double along = axis[s].at({ 1 + side, last });
    EXPECT_NEAR(along, c.coveredLengthMm[s], DeployedMm) << "distal edge along the graft's axis, side " << side;
    EXPECT_NEAR(plan.graftAxisLengthMm[s], along, 1e-9) << "the plan's axis is the surface's";
    const double at = RingPathMm(plan, 1 + side, last, side);
    EXPECT_NEAR(at, c.coveredLengthMm[s] + plan.distalEdgeShiftMm[s], DeployedMm)
      << "distal edge on the centerline, side " << side;
    distal = std::max({ distal, std::abs(along - c.coveredLengthMm[s]),
                        std::abs(at - c.coveredLengthMm[s] - plan.distalEdgeShiftMm[s]) });
  }
  std::cout << "[ deployed ] largest deviation from the plan: proximal edge " << edge << " mm, component ends "
            << length << " mm, distal edges " << distal << " mm; distal edges shifted " << plan.distalEdgeShiftMm[0]
            << " (right), " << plan.distalEdgeShiftMm[1] << " (left) mm down the centerline" << std::endl;
}

class ConfiguredPhantom : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

// Issue 29: common iliacs of 20, 35 and 55 mm (with a 120 mm aorta) and aortas of 90, 120 and
// 160 mm from the lowest renal to the bifurcation (with 55 mm common iliacs). Every limb's distal
// edge lies above the true internal iliac ostium and below it by no more than the family's length
// step; the overlaps are within the family's range; the covered lengths are the components'
// lengths minus the overlaps, exactly. And issue 30: deployed as planned.
TEST_P(ConfiguredPhantom, LimbsLandAboveTheTrueInternalIliacOstium)
{
  const auto [cia, aorta] = GetParam();
  PhantomParams p = WallPhantom();
  p.rightCommonIliacLengthMm = p.leftCommonIliacLengthMm = cia;
  // The site → bifurcation length is neck + sac + 20 mm of distal neck (AorticPhantom.h).
  p.neckLengthMm = aorta >= 120.0 ? 25.0 : 20.0;
  p.aneurysmLengthMm = aorta - 20.0 - p.neckLengthMm;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  ASSERT_NEAR(phantom.truth.sizing.proximalSiteToBifurcationLength, aorta, 1e-9);
  const RepairPlan plan = Plan(phantom);
  const DeviceConfiguration* c = plan.Configuration();
  ASSERT_NE(c, nullptr) << plan.selection.summary;
  ASSERT_TRUE(c->configured) << c->unknownReason;
  // A 20 mm common iliac holds 4.5–5.1 mm below the flow divider (it lies 10.6 mm below B on
  // these 12 mm iliacs at 25°; 2 mm of mouth and the ostium's radius above the origin): too short
  // for Endurant's 15 mm seal on both sides, and said so — the seal is measured from where the
  // iliac lumens part, not from B. The others: no finding.
  if (cia <= 20.0)
  {
    ASSERT_EQ(c->findings.size(), 2u);
    for (const ConfigurationFinding& f : c->findings)
      EXPECT_EQ(f.constraint, "commonIliacTooShort") << f.text;
  }
  else
    EXPECT_TRUE(c->findings.empty()) << c->findings.front().text;
  const PlanParams shipped = testing::ShippedPlanParams(); // the family below points into it
  const DeviceFamily& family = *FindDeviceFamily(shipped.catalog, c->family);
  const Point3 B = TruthLandmark(phantom, "aorticBifurcation");
  for (int side = 0; side < 2; ++side)
  {
    SCOPED_TRACE(side == 0 ? "right" : "left");
    // The true limit: the internal iliac ostium's radius above its origin, and not past its edge.
    const PhantomSizing& truth = phantom.truth.sizing;
    const double origin = side == 0 ? truth.rightIliacLength : truth.leftIliacLength;
    const double radius = side == 0 ? truth.rightInternalIliacRadius : truth.leftInternalIliacRadius;
    const double ostium = side == 0 ? truth.rightInternalIliacOstium : truth.leftInternalIliacOstium;
    const double limit = std::min(origin - radius, ostium);
    // Where the simulated graft's distal edge lies along the true common iliac's axis from B.
    Point3 edge;
    RingPathMm(plan, 1 + side, plan.graft.layout.mesh.RingsIn(1 + side) - 1, side, &edge);
    const Eigen::Vector3d axis =
      (TruthLandmark(phantom, side == 0 ? "rightIliacBifurcation" : "leftIliacBifurcation") - B).normalized();
    const double along = (edge - B).dot(axis);
    // 1.5 mm: the internal iliac origin is located within 1 mm (MeasureAnatomyTest's bar) and its
    // radius, the ostium's half width, within 0.5 mm.
    constexpr double originMm = 1.5;
    EXPECT_LE(along, limit + originMm) << "covers the internal iliac ostium";
    // The family's length step: the largest gap between its limb lengths of the landing diameter.
    const ConfiguredComponent* last = nullptr;
    for (const ConfiguredComponent& part : c->components)
      if (part.role != OrderRole::MainBody && part.side == side)
        last = &part;
    ASSERT_NE(last, nullptr);
    std::vector<double> lengths;
    for (const CatalogueComponent* limb : family.ComponentsOf(ComponentRole::Limb))
      if (limb->distalDiameterMm == last->item.distalDiameterMm)
        lengths.push_back(limb->lengthMm);
    std::sort(lengths.begin(), lengths.end());
    double step = 0.0;
    for (std::size_t i = 1; i < lengths.size(); ++i)
      step = std::max(step, lengths[i] - lengths[i - 1]);
    EXPECT_GE(along, limit - step - originMm) << "more than the length step above the ostium";
    // Covered = the components' lengths minus the overlaps, exactly.
    double sum = side == c->ipsilateralSide ? c->components.front().item.lengthMm : c->gateEndMm;
    for (const ConfiguredComponent& part : c->components)
      if (part.role != OrderRole::MainBody && part.side == side)
        sum += part.item.lengthMm;
    for (const ComponentOverlap& o : c->overlaps)
      if (o.side == side)
      {
        sum -= o.overlapMm;
        EXPECT_GE(o.overlapMm, family.junctions.overlapMm.min - ExactMm) << o.junction;
        EXPECT_LE(o.overlapMm, o.maxMm + ExactMm) << o.junction;
      }
    EXPECT_NEAR(c->coveredLengthMm[std::size_t(side)], sum, ExactMm);
  }
  ExpectDeployedAsPlanned(plan);
  // The simulated seal in a 20 mm common iliac: the first few mm below the bifurcation lie where
  // the two iliac lumens merge, wider than a limb, so the sealed length is below Endurant's 15 mm:
  // a type Ib finding, beside the configuration's short common iliacs — the only kinds.
  for (const std::string& f : plan.fitCheck.findings)
    EXPECT_TRUE(cia <= 20.0 &&
                (f.find("type Ib") != std::string::npos || f.find("common iliac too short") != std::string::npos))
      << f;
}

INSTANTIATE_TEST_SUITE_P(Deployment,
                         ConfiguredPhantom,
                         ::testing::Values(std::tuple{ 20.0, 120.0 },
                                           std::tuple{ 35.0, 120.0 },
                                           std::tuple{ 55.0, 120.0 },
                                           std::tuple{ 55.0, 90.0 },
                                           std::tuple{ 55.0, 160.0 }),
                         [](const auto& info)
                         {
                           return "Cia" + std::to_string(int(std::get<0>(info.param))) + "_Aorta" +
                                  std::to_string(int(std::get<1>(info.param)));
                         });

/// One phantom of issue 30's list: the neck angle, the slice thickness, neck thrombus or not.
struct NeckCase
{
  const char* name;
  double betaDeg;
  double sliceMm;
  double neckThrombusMm;
};

/// Printed by its name in test listings (not as the struct's bytes).
void PrintTo(const NeckCase& c, std::ostream* os)
{
  *os << c.name;
}

class DeployedGraftPhantom : public ::testing::TestWithParam<NeckCase>
{
};

TEST_P(DeployedGraftPhantom, EdgeAtTheTargetLengthsAsCatalogued)
{
  PhantomParams p = WallPhantom();
  p.neckAngleDeg = GetParam().betaDeg;
  p.spacingMm = { 0.8, 0.8, GetParam().sliceMm };
  p.neckThrombusThicknessMm = GetParam().neckThrombusMm;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_NE(plan.Configuration(), nullptr) << plan.selection.summary;
  ASSERT_TRUE(plan.Configuration()->configured) << plan.Configuration()->unknownReason;
  ExpectDeployedAsPlanned(plan);
  // The target is the proximal site and its margin, read off the aortic centerline where the
  // trunk's first ring's plane lies (not off the layout). The margin: the site's uncertainty less
  // the 0.5 mm an ostium's edge tolerates (FitCheck.h), the uncertainty that of the renal's walls
  // read on the CT (ProximalSite.h EdgeUncertainty).
  EXPECT_NEAR(plan.graft.layout.targetAbscissaMm, plan.measurements.site.abscissaMm + plan.deploymentMarginMm, ExactMm);
  EXPECT_NEAR(plan.deploymentMarginMm, plan.measurements.site.edgeUncertaintyMm - 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(plan.measurements.site.edgeUncertaintyMm, std::max(1.0, 0.5 * GetParam().sliceMm));
}

INSTANTIATE_TEST_SUITE_P(Deployment,
                         DeployedGraftPhantom,
                         ::testing::Values(NeckCase{ "StraightThinSlices", 0.0, 0.8, 0.0 },
                                           NeckCase{ "Beta30", 30.0, 1.0, 0.0 },
                                           NeckCase{ "Beta60", 60.0, 1.0, 0.0 },
                                           NeckCase{ "ThickSlices", 0.0, 2.5, 0.0 },
                                           NeckCase{ "NeckThrombus", 0.0, 1.0, 4.0 }),
                         [](const auto& info) { return std::string(info.param.name); });

/// Issue 46 item 5: a sac of `sacMm` with a crescent of thrombus a quarter of it thick (the lumen
/// off-centre, anterior), a neck angled `betaDeg`.
struct SacCase
{
  double sacMm;
  double betaDeg;
};

void PrintTo(const SacCase& c, std::ostream* os)
{
  *os << c.sacMm << " mm sac, neck " << c.betaDeg << "°";
}

class GraftThroughTheSac : public ::testing::TestWithParam<SacCase>
{
};

// The fitted graft runs straighter than the lumen's centerline through an off-centre lumen and
// round an angled neck: its own axis, not the centerline, must be as long as its fabric (the
// issue's bar: 2 mm; ExpectDeployedAsPlanned holds it to DeployedMm), its distal edges lie where
// that fabric ends (on the centerline: the covered length plus the shift the plan reports), and
// the internal iliac ostia are judged where they lie.
TEST_P(GraftThroughTheSac, AxisAsLongAsItsFabricAndEdgesWhereItEnds)
{
  const SacCase c = GetParam();
  PhantomParams p = WallPhantom();
  p.maxAneurysmDiameterMm = c.sacMm;
  p.neckAngleDeg = c.betaDeg;
  p.thrombusMaxThicknessMm = 0.25 * c.sacMm;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_NE(plan.Configuration(), nullptr) << plan.selection.summary;
  ASSERT_TRUE(plan.Configuration()->configured) << plan.Configuration()->unknownReason;
  const DeviceConfiguration& configuration = *plan.Configuration();
  for (int side = 0; side < 2; ++side)
  {
    const std::size_t s = std::size_t(side);
    std::cout << "[ fabric   ] " << (side == 0 ? "right" : "left") << ": fabric " << plan.graftFabricLengthMm[s]
              << " mm, the graft's axis " << plan.graftAxisLengthMm[s] << " mm over " << plan.graftPathLengthMm[s]
              << " mm of centerline: distal edge " << plan.distalEdgeShiftMm[s] << " mm further down\n";
    EXPECT_DOUBLE_EQ(plan.graftFabricLengthMm[s], configuration.coveredLengthMm[s]);
    EXPECT_NEAR(plan.distalEdgeShiftMm[s], plan.graftPathLengthMm[s] - configuration.coveredLengthMm[s], 1e-9);
    // The fitted graft never runs longer than the centerline it is laid on (it straightens, it
    // does not wind), so its distal edge lies at or below where the centerline length puts it.
    EXPECT_GE(plan.distalEdgeShiftMm[s], -DeployedMm);
  }
  ExpectDeployedAsPlanned(plan);
  // The internal iliac ostia, judged where the graft ends: the fit check's overlap is that of the
  // leg's last ring as fitted (read back off the surface) with the ostium as read; and against the
  // truth's upstream edge of the ostium (its mouth as drawn, along the true common iliac's axis from
  // B), an edge past it by more than the fit check's 0.5 mm tolerance and the edge's reading (at
  // most 0.1 mm below it: Issue46/InternalIliacMouth) cannot pass.
  const Point3 B = TruthLandmark(phantom, "aorticBifurcation");
  for (int side = 0; side < 2; ++side)
  {
    SCOPED_TRACE(side == 0 ? "right" : "left");
    const PhantomSizing& truth = phantom.truth.sizing;
    const double ostium = side == 0 ? truth.rightInternalIliacOstium : truth.leftInternalIliacOstium;
    const Centerline& iliac = side == 0 ? plan.centerlines.rightIliac : plan.centerlines.leftIliac;
    const int last = plan.graft.layout.mesh.RingsIn(1 + side) - 1;
    Point3 edge;
    RingPathMm(plan, 1 + side, last, side, &edge);
    const double edgeOnIliac = ProjectOntoCenterline(iliac, edge);
    const Eigen::Vector3d axis =
      (TruthLandmark(phantom, side == 0 ? "rightIliacBifurcation" : "leftIliacBifurcation") - B).normalized();
    const double past = (edge - B).dot(axis) - ostium;
    const std::string name = side == 0 ? "rightInternalIliac" : "leftInternalIliac";
    const auto o = std::find_if(plan.fitCheck.ostia.begin(), plan.fitCheck.ostia.end(),
                                [&](const OstiumCoverage& x) { return x.branch == name; });
    ASSERT_NE(o, plan.fitCheck.ostia.end());
    const double read = (PositionAt(iliac, o->upperAbscissaMm) - B).dot(axis) - ostium;
    std::cout << "[ fabric   ] " << name << ": the distal edge " << -past
              << " mm above the truth's upstream edge of the ostium; the fit check's edge " << read
              << " mm below the truth's, the graft " << -o->overlapMm << " mm above it\n";
    // 0.1 mm: the last ring's centre projected back onto the iliac against its plane's abscissa.
    EXPECT_NEAR(o->overlapMm, edgeOnIliac - o->upperAbscissaMm, 0.1);
    constexpr double edgeReadingMm = 0.1;
    if (past > FitCheckParams{}.ostiumOverlapToleranceMm + edgeReadingMm)
    {
      EXPECT_FALSE(plan.fitCheck.Passed()) << "the edge covers the ostium";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
  Issue46,
  GraftThroughTheSac,
  ::testing::Values(SacCase{ 40.0, 0.0 }, SacCase{ 60.0, 30.0 }, SacCase{ 80.0, 0.0 }, SacCase{ 80.0, 60.0 }),
  [](const auto& info)
  {
    return "Sac" + std::to_string(int(info.param.sacMm)) + "mm_Neck" + std::to_string(int(info.param.betaDeg)) + "deg";
  });

/// A 25 mm neck whose crescent of thrombus, 6 mm thick, reaches up the neck so that it lies at
/// least 2 mm thick under a quarter of the circumference from `belowMm` under the site (its top
/// tapers over 3 mm: AorticWall.h); no thrombus when belowMm ≤ 0. Its lumen drawn level by level,
/// as the truth's discs (PhantomParams::neckLumenPerLevel: drawn as a tube round its centre curve
/// the onset lay 2.6 mm lower than the truth, and every seal read 3.0-3.1 mm long).
PhantomParams NeckThrombusBelowTheSite(double belowMm)
{
  PhantomParams p = WallPhantom();
  p.neckLengthMm = 25.0;
  p.neckLumenPerLevel = true;
  if (belowMm > 0.0)
  {
    p.neckThrombusThicknessMm = 6.0;
    p.neckThrombusLengthMm = p.neckLengthMm - belowMm + 1.3; // the taper's first 1.3 mm stay under 2 mm over a quarter
  }
  return p;
}

/// The phantom of issue 30's seal test: the thrombus 9 mm below the site, or none.
PhantomParams NeckThrombusNineMillimetresBelowTheSite(bool thrombus)
{
  return NeckThrombusBelowTheSite(thrombus ? 9.0 : 0.0);
}

/// Prints the measured seal beside the truth it is judged against (for the notes; the
/// assertions follow it).
void PrintSeal(const RepairPlan& plan, double truthMm, const char* truthName)
{
  std::cout << "[ seal     ] proximal seal " << plan.fitCheck.proximalSealLengthMm << " mm; " << truthName << " "
            << truthMm << " mm\n";
}

TEST(Deployment, NeckThrombusNineMillimetresBelowTheSite_SealNineMillimetresTypeIa)
{
  const AorticPhantom phantom = GenerateAorticPhantom(NeckThrombusNineMillimetresBelowTheSite(true));
  // The phantom is what the issue describes (its truth, computed on the analytic thrombus).
  ASSERT_NEAR(phantom.truth.sizing.neckThrombusBelowSite, 9.0, 0.2);
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_TRUE(plan.HasGraft());
  PrintSeal(plan, phantom.truth.sizing.healthyNeckLength, "healthy neck (truth)");
  const double spacing = StentMeshParams{}.ringSpacingMm;
  // Within the ring spacing of 9 mm (the seal ends between a ring that seals and one that does not).
  EXPECT_NEAR(plan.fitCheck.proximalSealLengthMm, 9.0, spacing);
  // And within half a spacing (plus the site's 1 mm) of the healthy neck the truth gives: the seal
  // counts only healthy wall, not the thrombus-lined neck below.
  EXPECT_NEAR(plan.fitCheck.proximalSealLengthMm, phantom.truth.sizing.healthyNeckLength, 0.5 * spacing + 1.0);
  // Below the 10 mm minimum, or within the seal's uncertainty above it, where the risk is flagged
  // as one that cannot be excluded (FitCheckParams::sealUncertaintyMm).
  EXPECT_LT(plan.fitCheck.proximalSealLengthMm, 10.0 + FitCheckParams{}.sealUncertaintyMm);
  EXPECT_TRUE(plan.fitCheck.migrationRisk);
  EXPECT_TRUE(std::any_of(plan.fitCheck.findings.begin(), plan.fitCheck.findings.end(),
                          [](const std::string& f) {
                            return f.find("type Ia") != std::string::npos && f.find("thrombus") != std::string::npos;
                          }))
    << (plan.fitCheck.findings.empty() ? "no finding" : plan.fitCheck.findings.front());
  EXPECT_FALSE(plan.fitCheck.Passed());
  // Every vertex the fit check calls sealing lies on healthy wall.
  for (Eigen::Index i = 0; i < plan.fitCheck.sealing.size(); ++i)
    if (plan.fitCheck.sealing[i])
    {
      ASSERT_NE(plan.fitCheck.healthyWall[i], 0) << "vertex " << i;
    }
}

/// Issue 46 item 2: neck thrombus whose onset lies `belowMm` under the site, on slices `sliceMm`
/// thick (0.8 mm in-plane): on thick slices the onset is blurred over a slice, and a seal read 13 mm
/// on 2.5 mm slices passed where the healthy neck was 9.3 mm.
struct NeckThrombusOnSlices
{
  double belowMm;
  double sliceMm;
};

std::ostream& operator<<(std::ostream& out, const NeckThrombusOnSlices& c)
{
  return out << c.belowMm << " mm below the site, " << c.sliceMm << " mm slices";
}

class NeckThrombusSeries : public ::testing::TestWithParam<NeckThrombusOnSlices>
{
};

TEST_P(NeckThrombusSeries, NoPassUnderTheMinimumAndTheUncertaintyFollowsTheSlice)
{
  const NeckThrombusOnSlices c = GetParam();
  PhantomParams p = NeckThrombusBelowTheSite(c.belowMm);
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  p.noiseSigmaHu = c.sliceMm > 2.0 ? 30.0 : 18.0; // the issue's independent phantoms' noise
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_TRUE(plan.HasGraft());
  const double truth = phantom.truth.sizing.healthyNeckLength;
  const FitCheck& fit = plan.fitCheck;
  std::cout << "[ seal     ] " << c << ": proximal seal " << fit.proximalSealLengthMm << " ± "
            << fit.proximalSealUncertaintyMm << " mm; healthy neck (truth) " << truth << " mm; "
            << (fit.Passed() ? "passed" : "failed") << "\n";
  // The seal's uncertainty grows with the slice: twice the sampling interval along the aorta, at
  // least the 2 mm of 1 mm slices. The centerline at the site runs up to 20° off the z axis here
  // (the renal ostia pull it), so the interval lies between 0.94 × the slice and the slice.
  EXPECT_LE(fit.proximalSealUncertaintyMm, std::max(2.0, 2.0 * c.sliceMm) + 1e-9);
  EXPECT_GE(fit.proximalSealUncertaintyMm, std::max(2.0, 2.0 * 0.94 * c.sliceMm));
  // The reading within its stated uncertainty of the truth, and on slices of 1 mm or less within
  // 1 mm (the issue's bar: the onset placed no better than the 1 mm wall planes). Read from the
  // graft's proximal edge, which lies at the site as read (its margin and the renal edge's
  // uncertainty below it): −0.5…+0.7 mm on the thin slices here, −3.6…+1.3 mm on 2.5-3 mm slices.
  // (The seal's end at the first wall plane past the unhealthy share's limit, not interpolated to
  // the crossing: +0.6 mm on average, +1.6 at the onsets 11 and 12 mm below on 1 mm slices.)
  // (The phantom's lumen drawn as a tube round its centre curve read 3.0-3.1 mm long on every
  // slice: PhantomParams::neckLumenPerLevel.)
  EXPECT_NEAR(fit.proximalSealLengthMm, truth, fit.proximalSealUncertaintyMm);
  if (c.sliceMm <= 1.0 + 1e-9)
  {
    EXPECT_NEAR(fit.proximalSealLengthMm, truth, 1.0);
  }
  // The safety the issue asks for: no passed fit check on a healthy neck under the 10 mm minimum.
  if (truth < 10.0)
  {
    EXPECT_FALSE(fit.Passed());
    EXPECT_TRUE(fit.migrationRisk);
  }
}

INSTANTIATE_TEST_SUITE_P(Issue46,
                         NeckThrombusSeries,
                         ::testing::Values(NeckThrombusOnSlices{ 6.0, 0.8 },
                                           NeckThrombusOnSlices{ 6.0, 2.5 },
                                           NeckThrombusOnSlices{ 9.0, 1.0 },
                                           NeckThrombusOnSlices{ 9.0, 2.5 },
                                           NeckThrombusOnSlices{ 9.0, 3.0 },
                                           NeckThrombusOnSlices{ 12.0, 1.0 },
                                           NeckThrombusOnSlices{ 12.0, 3.0 },
                                           NeckThrombusOnSlices{ 14.0, 0.8 },
                                           NeckThrombusOnSlices{ 14.0, 2.5 },
                                           NeckThrombusOnSlices{ 11.0, 1.0 },
                                           NeckThrombusOnSlices{ 13.0, 1.0 }),
                         [](const ::testing::TestParamInfo<NeckThrombusOnSlices>& info)
                         {
                           return "Below" + std::to_string(int(info.param.belowMm)) + "mm_Slices" +
                                  std::to_string(int(info.param.sliceMm * 10.0)) + "tenthsMm";
                         });

/// Issue 46 item 1: the graft's fabric against an 8 mm lowest renal on 1, 2.5 and 3 mm slices, at
/// the plan's own target (the lower edge as read and its margin), at the edge as read (offset
/// −margin), and 1.5 mm above it.
struct RenalCoverageCase
{
  double sliceMm;
  double aboveTargetMm; ///< NaN: at the edge as read (−margin); else −offset from the target
  const char* name;
};

void PrintTo(const RenalCoverageCase& c, std::ostream* os)
{
  *os << c.name << ", " << c.sliceMm << " mm slices";
}

class RenalCoverageSeries : public ::testing::TestWithParam<RenalCoverageCase>
{
};

// Where the truth's graft covers the renal ostium (beyond the 0.5 mm an edge tolerates), the fit
// check does not pass and names the renal; where the edge as read could lie on the ostium (the
// graft within its uncertainty of it), the fit check says so; at the plan's own target neither.
TEST_P(RenalCoverageSeries, NoPassWhereTheGraftCoversTheRenalAndSaysWhereItMay)
{
  const RenalCoverageCase c = GetParam();
  PhantomParams p = WallPhantom();
  p.renalRadiusMm = 4.0;
  p.spacingMm = { 0.8, 0.8, c.sliceMm };
  p.noiseSigmaHu = c.sliceMm > 2.0 ? 30.0 : 18.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  PlanParams params = EndurantParams();
  double margin = 0.0; // the plan's (SiteMarginMm); at the edge as read, from a first plan
  if (std::isnan(c.aboveTargetMm))
    margin = Plan(phantom, params).deploymentMarginMm;
  params.deploymentOffsetMm = std::isnan(c.aboveTargetMm) ? -margin : -c.aboveTargetMm;
  const RepairPlan plan = Plan(phantom, params);
  ASSERT_TRUE(plan.HasGraft());
  ASSERT_EQ(plan.measurements.site.renal, "rightRenal");
  if (std::isnan(c.aboveTargetMm))
  {
    EXPECT_DOUBLE_EQ(plan.deploymentMarginMm, margin);
  }
  margin = plan.deploymentMarginMm;
  EXPECT_GE(margin, std::max(1.0, 0.5 * c.sliceMm) - 0.5); // the site's uncertainty less 0.5 mm
  const FitCheck& fit = plan.fitCheck;
  const OstiumCoverage* renal = nullptr;
  for (const OstiumCoverage& o : fit.ostia)
    if (o.branch == "rightRenal")
      renal = &o;
  ASSERT_NE(renal, nullptr);
  const double truthEdge =
    ProjectOntoCenterline(plan.centerlines.aorta, TruthLandmark(phantom, "proximalImplantationSite"));
  const double truthOverlap = truthEdge - plan.graft.layout.targetAbscissaMm; // of the graft with the ostium
  std::cout << "[ renal    ] " << c.name << ", " << c.sliceMm << " mm slices: graft edge " << -renal->overlapMm
            << " mm below the edge as read, " << -truthOverlap << " mm below the truth's; "
            << (renal->covered        ? "covered"
                : renal->mayBeCovered ? "may be covered"
                                      : "not covered")
            << "; " << (fit.Passed() ? "passed" : "failed") << "\n";
  const bool named = testing::AnyWarningContains(fit.findings, "right renal ostium");
  if (truthOverlap > FitCheckParams{}.ostiumOverlapToleranceMm)
  {
    EXPECT_FALSE(fit.Passed());
    EXPECT_TRUE(renal->covered || renal->mayBeCovered);
    EXPECT_TRUE(named);
  }
  if (std::isnan(c.aboveTargetMm) || c.aboveTargetMm > margin) // at or above the edge as read
  {
    EXPECT_TRUE(renal->covered || renal->mayBeCovered);
    EXPECT_TRUE(named);
  }
  if (c.aboveTargetMm == 0.0) // the plan's own target: the ostium not covered, wherever its edge lies
  {
    EXPECT_FALSE(renal->covered || renal->mayBeCovered);
    EXPECT_FALSE(named);
    EXPECT_LE(truthOverlap, FitCheckParams{}.ostiumOverlapToleranceMm); // the edge at the ostium's edge
  }
}

INSTANTIATE_TEST_SUITE_P(
  Issue46,
  RenalCoverageSeries,
  ::testing::Values(RenalCoverageCase{ 1.0, 0.0, "AtTheTarget" },
                    RenalCoverageCase{ 2.5, 0.0, "AtTheTarget" },
                    RenalCoverageCase{ 3.0, 0.0, "AtTheTarget" },
                    RenalCoverageCase{ 1.0, std::numeric_limits<double>::quiet_NaN(), "AtTheEdgeAsRead" },
                    RenalCoverageCase{ 2.5, std::numeric_limits<double>::quiet_NaN(), "AtTheEdgeAsRead" },
                    RenalCoverageCase{ 3.0, std::numeric_limits<double>::quiet_NaN(), "AtTheEdgeAsRead" },
                    RenalCoverageCase{ 1.0, 2.5, "TwoAndAHalfAboveTheTarget" },
                    RenalCoverageCase{ 2.5, 2.5, "TwoAndAHalfAboveTheTarget" }),
  [](const auto& info)
  { return std::string(info.param.name) + "_Slices" + std::to_string(int(10.0 * info.param.sliceMm)) + "tenthsMm"; });

TEST(Deployment, SameNeckWithoutThrombus_SealIsTheNeckLength)
{
  const AorticPhantom phantom = GenerateAorticPhantom(NeckThrombusNineMillimetresBelowTheSite(false));
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_TRUE(plan.HasGraft());
  PrintSeal(plan, phantom.truth.sizing.proximalNeckLength, "neck length (truth)");
  // 2 mm: the issue's bar (the neck's end is where the outer wall widens past 110 % of (a), which
  // the seal stops at too; the rings quantize it by half a spacing, the site by 1 mm). The seal
  // runs from the fabric's edge, the site's margin below the site (issue 46 item 1).
  EXPECT_NEAR(plan.fitCheck.proximalSealLengthMm, phantom.truth.sizing.proximalNeckLength - plan.deploymentMarginMm,
              2.0);
  EXPECT_FALSE(plan.fitCheck.migrationRisk);
}

TEST(Deployment, DemoPhantom_SealNoLongerThanItsNeck)
{
  // scripts/demo.sh's phantom: a clean neck over a sac lined with thrombus. The old fit check
  // counted contact with the sac's thrombus as seal (39.7 mm on a 27.3 mm neck).
  PhantomParams p = WallPhantom();
  p.includeBone = p.includeKidneys = true;
  p.thrombusMaxThicknessMm = 12.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const RepairPlan plan = Plan(phantom);
  ASSERT_TRUE(plan.HasGraft());
  PrintSeal(plan, phantom.truth.sizing.proximalNeckLength, "neck length (truth)");
  EXPECT_LE(plan.fitCheck.proximalSealLengthMm,
            phantom.truth.sizing.proximalNeckLength + StentMeshParams{}.ringSpacingMm);
  EXPECT_GE(plan.fitCheck.proximalSealLengthMm, phantom.truth.sizing.proximalNeckLength - 2.0);
}

TEST(Deployment, LimbOneCatalogueLengthTooLong_CoversTheInternalIliacAndSaysSo)
{
  const AorticPhantom phantom = GenerateAorticPhantom(WallPhantom());
  const PlanParams params = testing::ShippedPlanParams();
  const RepairPlan plan = Plan(phantom, params);
  ASSERT_TRUE(plan.HasGraft());
  DeviceConfiguration c = *plan.Configuration();
  ASSERT_TRUE(c.configured);
  // The contralateral limb one catalogue length longer (the next longer limb of its diameter).
  const int contra = 1 - c.ipsilateralSide;
  auto limb = std::find_if(c.components.begin(), c.components.end(),
                           [&](const ConfiguredComponent& x) { return x.role == OrderRole::ContralateralLimb; });
  ASSERT_NE(limb, c.components.end());
  const DeviceFamily& family = *FindDeviceFamily(params.catalog, c.family);
  const CatalogueComponent* longer = nullptr;
  for (const CatalogueComponent* candidate : family.ComponentsOf(ComponentRole::Limb))
    if (candidate->distalDiameterMm == limb->item.distalDiameterMm && candidate->lengthMm > limb->item.lengthMm &&
        (!longer || candidate->lengthMm < longer->lengthMm))
      longer = candidate;
  ASSERT_NE(longer, nullptr);
  limb->item = *longer;
  limb->distalMm = limb->proximalMm + longer->lengthMm;
  c.coveredLengthMm[std::size_t(contra)] = limb->distalMm;
  GraftLayout layout =
    LayOutGraft(plan.centerlines, plan.measurements, c, plan.deploymentTargetAbscissaMm, params.mesh);
  const WallDistanceField wall =
    WallDistanceField::FromLumen(*plan.lumen.mask, 5.0, StentReach(layout.mesh, plan.centerlines));
  const DeployedGraft graft = DeployGraft(std::move(layout), wall, params.graft);
  FitCheckContext context;
  context.minimumOverlapMm = family.junctions.overlapMm.min;
  const FitCheck check = CheckGraftFit(graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  const std::string branch = contra == 0 ? "rightInternalIliac" : "leftInternalIliac";
  EXPECT_NE(check.CoveredOstia().find(branch), std::string::npos) << check.CoveredOstia();
  EXPECT_TRUE(std::any_of(check.findings.begin(), check.findings.end(),
                          [&](const std::string& f)
                          {
                            return f.find(std::string("the ") + (contra == 0 ? "right" : "left") +
                                          " internal iliac ostium is covered") != std::string::npos;
                          }));
  EXPECT_FALSE(check.Passed());
  // The plan's own limb covers nothing.
  EXPECT_EQ(plan.fitCheck.CoveredOstia(), "none");
}

/// Issue 29's failing constraints through the pipeline: the finding with its numbers and option,
/// and a fit check that does not pass.
void ExpectConstraintNamed(const RepairPlan& plan,
                           const std::vector<std::string>& constraints,
                           const std::string& option)
{
  const DeviceConfiguration* c = plan.Configuration();
  ASSERT_NE(c, nullptr) << plan.selection.summary;
  ASSERT_TRUE(c->configured) << c->unknownReason;
  const auto found = std::find_if(c->findings.begin(), c->findings.end(),
                                  [&](const ConfigurationFinding& f)
                                  { return std::count(constraints.begin(), constraints.end(), f.constraint) > 0; });
  ASSERT_NE(found, c->findings.end()) << (c->findings.empty() ? "no finding" : c->findings.front().text);
  EXPECT_NE(found->option.find(option), std::string::npos) << found->option;
  ASSERT_TRUE(plan.HasGraft());
  EXPECT_FALSE(plan.fitCheck.Passed());
  EXPECT_TRUE(std::any_of(plan.fitCheck.findings.begin(), plan.fitCheck.findings.end(),
                          [&](const std::string& f) { return f.find(found->text) != std::string::npos; }));
  std::map<std::string, std::string> values;
  for (const PlanValue& v : PlanReturnValues(plan))
    values[v.name] = v.text;
  EXPECT_EQ(values["fitCheckPassed"], "false");
}

TEST(Deployment, TwelveMillimetreCommonIliac_ShortSealNamedWithTheExternalIliacOption)
{
  PhantomParams p = WallPhantom();
  p.leftCommonIliacLengthMm = 12.0;
  const RepairPlan plan = Plan(GenerateAorticPhantom(p));
  // Too short for the family's minimum seal (Endurant, 15 mm), or — a family that seals in 10 mm
  // (Excluder), whose shortest leg reaches past the ostium — the internal iliac covered; either
  // way the option is the external iliac, covering the internal iliac.
  ExpectConstraintNamed(plan, { "commonIliacTooShort", "internalIliacCovered" }, "external iliac");
}

TEST(Deployment, TwentySixMillimetreCommonIliac_WiderThanTheWidestLimbNamedWithTheBellBottomOption)
{
  // An ectatic right common iliac under a distal aorta wide enough to lead into it.
  PhantomParams p = WallPhantom();
  p.rightIliacDiameterMm = 26.0;
  p.distalNeckDiameterMm = 30.0;
  const RepairPlan plan = Plan(GenerateAorticPhantom(p));
  ExpectConstraintNamed(plan, { "iliacTooWide" }, "bell-bottom");
}

TEST(Deployment, SixteenMillimetreDistalAortaWithFourteenMillimetreLimbs_LimbCompression)
{
  PhantomParams p = testing::WithWallInFat(PhantomParams{}); // 12 mm iliacs: 14.5 mm limbs
  p.distalNeckDiameterMm = 16.0;
  const RepairPlan plan = Plan(GenerateAorticPhantom(p));
  ExpectConstraintNamed(plan, { "limbCompression" }, "aorto-uni-iliac");
}

} // namespace
} // namespace sgp

namespace sgp
{
namespace
{

// The overlap of a limb in the gate is read on the fabric the graft was deployed with
// (GraftLayout::fabricMm), not on the centerline positions it was placed at: the contralateral
// limb's top moved down its fabric to leave 2 mm less than the family's minimum overlap raises the
// type III finding, its centerline positions untouched.
TEST(Deployment, OverlapShortOnTheFabric_TypeIIIFinding)
{
  const AorticPhantom phantom = GenerateAorticPhantom(WallPhantom());
  const RepairPlan plan = Plan(phantom, EndurantParams());
  ASSERT_NE(plan.Configuration(), nullptr) << plan.selection.summary;
  ASSERT_TRUE(plan.Configuration()->configured) << plan.Configuration()->unknownReason;
  const auto typeIII = [](const FitCheck& fit)
  {
    return std::any_of(fit.findings.begin(), fit.findings.end(),
                       [](const std::string& f) { return f.find("type III") != std::string::npos; });
  };
  EXPECT_FALSE(typeIII(plan.fitCheck));
  const DeviceConfiguration& c = *plan.Configuration();
  const PlanParams shipped = testing::ShippedPlanParams(); // the family below points into it
  const DeviceFamily& family = *FindDeviceFamily(shipped.catalog, c.family);
  DeployedGraft graft = plan.graft;
  std::size_t limb = 0;
  while (limb < c.components.size() && c.components[limb].role != OrderRole::ContralateralLimb)
    ++limb;
  ASSERT_LT(limb, c.components.size());
  const double shortOverlap = family.junctions.overlapMm.min - 2.0;
  graft.layout.fabricMm[limb][0] = graft.layout.fabricGateEndMm - shortOverlap;
  FitCheckContext context;
  context.family = c.family;
  context.minimumIliacSealMm = family.ifu.iliacSealLengthMm.min;
  context.minimumOverlapMm = family.junctions.overlapMm.min;
  const FitCheck fit = CheckGraftFit(graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  EXPECT_TRUE(typeIII(fit)) << (fit.findings.empty() ? "no finding" : fit.findings.front());
  EXPECT_FALSE(fit.Passed());
}

} // namespace
} // namespace sgp
