// Measurements (a)–(f), lengths and angles against the phantom's analytic truth (issue 5).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Measurement/MeasureAnatomy.h"
#include "PhantomTestSupport.h"
#include "PipelineSupport.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

using testing::MeasuredPlan;
using testing::MeasureFromCt;

/// The bars. Diameters (issue 5): 1.0 mm on 0.8 × 0.8 × 1.0 mm voxels, 1.5 mm on 0.7 × 0.7 ×
/// 2.0 mm (the fitted ring lies on the segmented wall, which is within half a voxel of the
/// analytic wall on each side; 2 mm slices blur the wall where it is oblique to them). Landmarks
/// where the axes meet (the aortic bifurcation, the internal iliac origins): 1 mm — the chords
/// follow the smoothed centerlines, which lie within 0.2 mm of the axes; measured 0.1–0.7 mm.
/// Lengths, each at its real accuracy on these phantoms (measured − truth):
///  - neck length: NeckLengthUncertaintyMm (2 mm; measured −1.7…+0.9 mm, its cause in
///    MeasureAnatomy.h), the same band device selection calls indeterminate;
///  - site to bifurcation: 1.5 mm (measured −0.3…+1.1 mm: the detected site lies up to 1.3 mm
///    from the truth's, B within 0.7 mm) — taking B at the skeleton's junction reads 2.8 mm long;
///  - bifurcation to each internal iliac origin: 1.5 mm (measured −0.9…+0.3 mm; B's error and
///    the origin's add up).
/// β: 5° (the published repeatability of 3-D centerline angles is ≈ 6°).
constexpr double fineDiameterMm = 1.0;
constexpr double coarseDiameterMm = 1.5;
constexpr double landmarkMm = 1.0;
constexpr double neckLengthMm = NeckLengthUncertaintyMm;
constexpr double siteToBifurcationMm = 1.5;
constexpr double iliacLengthMm = 1.5;
constexpr double angleDeg = 5.0;

Point3 TruthLandmark(const AorticPhantom& phantom, const std::string& name)
{
  for (const PhantomLandmark& l : phantom.truth.landmarks)
    if (l.name == name)
      return l.lps;
  throw std::runtime_error("no truth landmark " + name);
}

void ExpectSizing(const Measurements& m, const AorticPhantom& phantom, double diameterMm)
{
  const PhantomSizing& truth = phantom.truth.sizing;
  testing::ExpectDiametersNear(m, truth, diameterMm);
  EXPECT_NEAR(m.Value("proximalNeckLength"), truth.proximalNeckLength, neckLengthMm);
  EXPECT_NEAR(m.Value("proximalSiteToBifurcationLength"), truth.proximalSiteToBifurcationLength, siteToBifurcationMm);
  EXPECT_NEAR(m.Value("rightIliacLength"), truth.rightIliacLength, iliacLengthMm);
  EXPECT_NEAR(m.Value("leftIliacLength"), truth.leftIliacLength, iliacLengthMm);
  EXPECT_NEAR(m.Value("neckAngleBeta"), truth.neckAngleBetaDeg, angleDeg);
  EXPECT_LT((m.bifurcationLps - TruthLandmark(phantom, "aorticBifurcation")).norm(), landmarkMm);
  EXPECT_LT((m.internalIliacOriginLps[0] - TruthLandmark(phantom, "rightIliacBifurcation")).norm(), landmarkMm);
  EXPECT_LT((m.internalIliacOriginLps[1] - TruthLandmark(phantom, "leftIliacBifurcation")).norm(), landmarkMm);
}

/// The phantom iliac's tortuosity: common (55 mm) plus external iliac (70 mm) over the chord from
/// the bifurcation to the external iliac's end, from the truth axes.
double TruthTortuosity(const AorticPhantom& phantom, const std::string& side)
{
  double length = 0.0;
  Point3 end = Point3::Zero();
  for (const PhantomVessel& v : phantom.truth.vessels)
    if (v.name == side + "Iliac" || v.name == side + "ExternalIliac")
    {
      for (Eigen::Index i = 1; i < v.axis.rows(); ++i)
        length += (v.axis.row(i) - v.axis.row(i - 1)).norm();
      if (v.name == side + "ExternalIliac")
        end = v.axis.row(v.axis.rows() - 1).transpose();
    }
  return length / end.norm(); // the bifurcation is the origin
}

/// The default phantom (0.8 × 0.8 × 1.0 mm, noise 20 HU), measured once for the suite.
class NoisyPhantomMeasurements : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    phantom = new AorticPhantom(GenerateAorticPhantom(PhantomParams{}));
    plan = new MeasuredPlan(MeasureFromCt(*phantom->ct, phantom->truth.seedLps));
  }
  static void TearDownTestSuite()
  {
    delete plan;
    delete phantom;
  }
  static AorticPhantom* phantom;
  static MeasuredPlan* plan;
};
AorticPhantom* NoisyPhantomMeasurements::phantom = nullptr;
MeasuredPlan* NoisyPhantomMeasurements::plan = nullptr;

TEST_F(NoisyPhantomMeasurements, DiametersLengthsAndBetaAgainstTruth)
{
  ASSERT_TRUE(plan->fit.converged);
  ExpectSizing(plan->measurements, *phantom, fineDiameterMm);
}

TEST_F(NoisyPhantomMeasurements, ShapeValues_StraightNeckAndIliacs)
{
  const Measurements& m = plan->measurements;
  // The phantom's suprarenal aorta continues the neck's axis: α = 0 (same 5° bar as β).
  EXPECT_NEAR(m.Value("neckAngleAlpha"), 0.0, angleDeg);
  // The first 15 mm of the neck are a cylinder: conicity 0; (b) and (a) each within 1 mm of
  // 22 mm gives at most ±2/22 = ±9 %, the rings actually agree far better — 3 %.
  EXPECT_NEAR(m.Value("neckConicity"), 0.0, 3.0);
  // Tortuosity from the truth axes; the centerline stops about an inscribed radius before the
  // external iliac's end (4.5 mm of 125), which changes the ratio by < 0.01.
  EXPECT_NEAR(m.Value("rightIliacTortuosity"), TruthTortuosity(*phantom, "right"), 0.01);
  EXPECT_NEAR(m.Value("leftIliacTortuosity"), TruthTortuosity(*phantom, "left"), 0.01);
  // Access: the external iliacs are 0.75 × 12 = 9 mm; the inscribed diameter of the voxelized
  // lumen is at most one voxel smaller (0.8 mm) and the minimum of noisy samples another 0.4 mm.
  EXPECT_NEAR(m.Value("rightAccessMinDiameter"), 9.0, 1.2);
  EXPECT_NEAR(m.Value("leftAccessMinDiameter"), 9.0, 1.2);
  // The only warnings: this lumen-only phantom (lumen in 40 HU tissue, no fat) shows no outer
  // wall, so the outer-wall values are not measured — and say so.
  for (const std::string& w : m.warnings)
    EXPECT_NE(w.find("outer wall"), std::string::npos) << w;
}

TEST_F(NoisyPhantomMeasurements, EveryValueHasUnitDefinitionAndPlace)
{
  for (const Measurement& m : plan->measurements.values)
  {
    // Every value but the outer wall's, which this lumen-only phantom does not show (no fat).
    EXPECT_EQ(std::isfinite(m.value), m.wall != "outer") << m.name;
    EXPECT_FALSE(m.unit.empty()) << m.name;
    EXPECT_GT(m.definition.size(), 20u) << m.name;
    EXPECT_FALSE(m.vessel.empty()) << m.name;
  }
  // The diameters (a)–(f) also give the ring's min, max and area-equivalent diameter, which on
  // the phantom's circular cross-sections lie within 1 mm of the mean.
  for (const char* name : { "proximalNeckLumenDiameter", "neckLumenDiameter15mm", "maxAneurysmLumenDiameter",
                            "distalNeckMinLumenDiameter", "rightIliacLumenDiameter", "leftIliacLumenDiameter" })
  {
    const Measurement* m = plan->measurements.Find(name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_LE(m->minMm, m->value) << name;
    EXPECT_GE(m->maxMm, m->value) << name;
    EXPECT_NEAR(m->areaMm, m->value, 1.0) << name;
  }
}

TEST_F(NoisyPhantomMeasurements, ProximalSite_AtTheLowestRenalsLowerEdge)
{
  const ProximalSite& site = plan->site;
  EXPECT_EQ(site.source, ProximalSiteSource::Renal);
  EXPECT_EQ(site.renal, "rightRenal"); // the phantom's right renal is the lower one
  // The truth site is the lower edge's level on the aortic axis; within 1.5 mm (the renal's
  // radius is measured on a voxelized 3 mm lumen, and its axis fitted over 15 mm of centerline).
  Point3 truthSite = Point3::Constant(1e9);
  for (const PhantomLandmark& l : phantom->truth.landmarks)
    if (l.name == "proximalImplantationSite")
      truthSite = l.lps;
  EXPECT_LT((site.lps - truthSite).norm(), 1.5);
}

TEST_F(NoisyPhantomMeasurements, UserOstiumPoint_WinsAndMovesTheSite)
{
  // A point on the right aortic wall 10 mm below the detected site: the site moves down 10 mm
  // (within 1 mm: near the renal junction the skeleton's centerline bends up to 1 mm toward the
  // renal branch, which shifts the arc length of the projected point by up to that).
  const Point3 lower = plan->site.lps + Point3(-11.0, 0.0, -10.0);
  const ProximalSite site = FindProximalSite(plan->tree, lower);
  EXPECT_EQ(site.source, ProximalSiteSource::Landmark);
  EXPECT_NEAR(site.abscissaMm - plan->site.abscissaMm, 10.0, 1.0);
  EXPECT_TRUE(site.warning.empty());
}

TEST_F(NoisyPhantomMeasurements, NoRenalsNoPoint_SiteNotKnownAboveTheRenalReach)
{
  // This phantom's aorta reaches 205 mm above its bifurcation, higher than renals are looked for
  // (MaximumRenalHeightMm): without renals its top is not the renal level, and the site is not
  // known; the measure-mode surface starts MaximumRenalHeightMm above the bifurcation instead.
  CenterlineTree tree = plan->tree;
  tree.sideBranches.clear();
  const ProximalSite site = FindProximalSite(tree);
  EXPECT_EQ(site.source, ProximalSiteSource::None);
  EXPECT_FALSE(site.Known());
  const double bifurcationZ = tree.aorta.points(tree.aorta.Size() - 1, 2);
  EXPECT_LE(site.lps.z() - bifurcationZ, MaximumRenalHeightMm);       // the first centerline point at or below it
  EXPECT_GT(site.lps.z() - bifurcationZ, MaximumRenalHeightMm - 2.0); // 1 mm steps, a straight aorta
  EXPECT_NE(site.warning.find("the proximal implantation site is not known"), std::string::npos) << site.warning;
  EXPECT_NE(site.warning.find("Place the lowestRenalOstium point"), std::string::npos) << site.warning;
  // With the scan's extent and where the aorta's top lies in it: inside (this phantom's aorta ends
  // 36 mm below the scan's top), or — a scan that begins at the aorta's top — on its border.
  EXPECT_NE(site.warning.find("The scan spans z " + FormatNumber(tree.scanLowestZMm, 1) + " to " +
                              FormatNumber(tree.scanHighestZMm, 1) + " mm"),
            std::string::npos)
    << site.warning;
  const std::string top = FormatNumber(tree.aorta.points(0, 2), 1);
  EXPECT_NE(site.warning.find("the aorta ends inside it at z " + top + " mm"), std::string::npos) << site.warning;
  tree.scanHighestZMm = tree.aorta.points(0, 2) + 1.0;
  const std::string cut = FindProximalSite(tree).warning;
  EXPECT_NE(cut.find("the aorta runs out of its superior border at z " + top + " mm"), std::string::npos) << cut;
  // Cut or not, an aorta reaching past the renal reach gives no site (CutScanWithoutRenals in
  // LandmarksPlanTest: one that reaches no higher gives the top, and says the renals may lie above).
  EXPECT_EQ(FindProximalSite(tree).source, ProximalSiteSource::None);
}

TEST_F(NoisyPhantomMeasurements, FoldedLandingZoneRings_InscribedDiameterAndWarning)
{
  // Flatten the right leg's distal rings onto a line through their centres (as a fit folded in a
  // tortuous iliac would): their mean is no diameter, so (e) falls back to the centerline.
  Points V = plan->fit.V;
  const StentMesh& mesh = plan->mesh;
  const int last = mesh.RingsIn(RightLegSegment) - 1;
  for (int k = last - 4; k <= last; ++k)
    for (int j = 0; j < mesh.verticesPerRing; ++j)
    {
      const int id = mesh.Id(RightLegSegment, k, j);
      const Eigen::Vector3d offset = V.row(id) - mesh.centre.row(id);
      const Eigen::Vector3d u = (V.row(mesh.Id(RightLegSegment, k, 0)) - mesh.centre.row(id)).normalized();
      V.row(id) = mesh.centre.row(id) + offset.dot(u) * u.transpose(); // onto the line along u
    }
  const Measurements m = MeasureAnatomy(plan->tree, mesh, V, plan->site);
  // The inscribed-sphere diameter of the 12 mm common iliac: within one voxel diagonal (1.4 mm)
  // below it (the sphere is centred on voxel centres of the voxelized lumen).
  EXPECT_NEAR(m.Value("rightIliacLumenDiameter"), 12.0 - 0.7, 0.7);
  ASSERT_NE(m.Find("rightIliacLumenDiameter"), nullptr);
  EXPECT_NE(m.Find("rightIliacLumenDiameter")->definition.find("inscribed-sphere"), std::string::npos);
  const auto warned =
    std::find_if(m.warnings.begin(), m.warnings.end(),
                 [](const std::string& w)
                 { return w.find("right leg's rings in its landing zone are distorted") != std::string::npos; });
  EXPECT_NE(warned, m.warnings.end());
  // The left leg was not touched: still its rings' median.
  EXPECT_DOUBLE_EQ(m.Value("leftIliacLumenDiameter"), plan->measurements.Value("leftIliacLumenDiameter"));
}

TEST_F(NoisyPhantomMeasurements, OstiumPointFarFromTheAorta_InputErrorNamesIt)
{
  try
  {
    FindProximalSite(plan->tree, plan->site.lps + Point3(60.0, 0.0, 0.0));
    FAIL() << "expected InputError";
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("lowestRenalOstium"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("60.0 mm from the aortic centerline"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mm RAS"), std::string::npos) << e.what(); // as the user gave it
  }
}

TEST(MeasureAnatomy, CoarseObliqueFlippedPhantom_WithinOneAndAHalfMillimetres)
{
  PhantomParams p;
  p.spacingMm = { 0.7, 0.7, 2.0 };
  p.directionLps = testing::ObliqueFlippedDirection();
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const MeasuredPlan plan = MeasureFromCt(*phantom.ct, phantom.truth.seedLps);
  ExpectSizing(plan.measurements, phantom, coarseDiameterMm);
}

TEST(MeasureAnatomy, UnequalIliacsOnFlippedAxes_RightAndLeftNeverSwapped)
{
  PhantomParams p;
  p.rightIliacDiameterMm = 10.0;
  p.leftIliacDiameterMm = 14.0;
  p.directionLps = Eigen::Vector3d(-1.0, 1.0, -1.0).asDiagonal(); // i and k stored reversed
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const MeasuredPlan plan = MeasureFromCt(*phantom.ct, phantom.truth.seedLps);
  // 4 mm apart, so a swap would miss by 4 mm; each within the 1 mm bar (and every other value
  // within its bar too).
  EXPECT_NEAR(plan.measurements.Value("rightIliacLumenDiameter"), 10.0, fineDiameterMm);
  EXPECT_NEAR(plan.measurements.Value("leftIliacLumenDiameter"), 14.0, fineDiameterMm);
  ExpectSizing(plan.measurements, phantom, fineDiameterMm);
}

class NeckAngleMeasurement : public ::testing::TestWithParam<double>
{
};

TEST_P(NeckAngleMeasurement, BetaAndLengthsAgainstTruth)
{
  PhantomParams p; // neck 25 mm: (b)'s ring lies 10 mm above the bend at the sac's top
  p.neckAngleDeg = GetParam();
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const MeasuredPlan plan = MeasureFromCt(*phantom.ct, phantom.truth.seedLps);
  ASSERT_DOUBLE_EQ(phantom.truth.sizing.neckAngleBetaDeg, GetParam());
  ExpectSizing(plan.measurements, phantom, fineDiameterMm);
}

INSTANTIATE_TEST_SUITE_P(MeasureAnatomy, NeckAngleMeasurement, ::testing::Values(25.0, 50.0));

TEST(MeasureDiameters, CircularRings_ExactDiametersAndInscribedPolygonArea)
{
  // The initial surface of a Y of straight tubes: every ring a regular 16-gon of radius
  // startRadiusMm around its centerline point, in the plane ⊥ the tangent.
  const testing::YPhantom y = testing::MakeYPhantom(1.0);
  StentMeshParams params;
  params.startRadiusMm = 4.0;
  const StentMesh mesh = BuildStentMesh(y.tree, params);
  const auto profiles = MeasureRingDiameters(mesh, mesh.V);
  const double n = mesh.verticesPerRing;
  const double polygonFactor = std::sqrt(n / (2 * M_PI) * std::sin(2 * M_PI / n));
  for (int seg = 0; seg < 3; ++seg)
  {
    ASSERT_EQ(profiles[seg].rings.size(), static_cast<std::size_t>(mesh.RingsIn(seg)));
    for (const RingDiameters& r : profiles[seg].rings)
    {
      EXPECT_NEAR(r.meanMm, 8.0, 1e-9); // round-off only
      EXPECT_NEAR(r.minMm, 8.0, 1e-9);
      EXPECT_NEAR(r.maxMm, 8.0, 1e-9);
      EXPECT_NEAR(r.areaMm, 8.0 * polygonFactor, 1e-9);
    }
  }
  // Ring abscissae increase along each segment (the start and the interpolation: the next test).
  for (int seg = 0; seg < 3; ++seg)
    for (std::size_t k = 1; k < profiles[seg].rings.size(); ++k)
      EXPECT_GT(profiles[seg].rings[k].abscissaMm, profiles[seg].rings[k - 1].abscissaMm);
}

TEST(MeasureDiameters, BranchMouthVertices_LeftOutOfTheRingsDiameters)
{
  // The circular rings of radius 4 mm; on trunk ring 2 one vertex pushed 5 mm further out (into a
  // branch's mouth, as the balloon does at an ostium) and on trunk ring 4 two neighbours 3 mm out;
  // ring 3 squeezed into an ellipse of aspect 1.5 (radii 4.8 and 3.2 mm), the vessel's own shape.
  const testing::YPhantom y = testing::MakeYPhantom(1.0);
  StentMeshParams params;
  params.startRadiusMm = 4.0;
  const StentMesh mesh = BuildStentMesh(y.tree, params);
  ASSERT_GE(mesh.RingsIn(TrunkSegment), 5);
  const int n = mesh.verticesPerRing;
  Points V = mesh.V;
  const auto push = [&](int ring, int column, double mm)
  {
    const int i = mesh.Id(TrunkSegment, ring, column);
    const Eigen::Vector3d c = mesh.centre.row(i).transpose(), d = V.row(i).transpose() - c;
    V.row(i) = (c + d * ((d.norm() + mm) / d.norm())).transpose();
  };
  push(2, 3, 5.0);
  push(4, 5, 3.0);
  push(4, 6, 3.0);
  Eigen::Vector3d u = Eigen::Vector3d::Zero(); // ring 3's frame: its vertex 0 direction
  {
    const int i0 = mesh.Id(TrunkSegment, 3, 0);
    u = (V.row(i0).transpose() - mesh.centre.row(i0).transpose()).normalized();
  }
  for (int j = 0; j < n; ++j)
  {
    const int i = mesh.Id(TrunkSegment, 3, j);
    const Eigen::Vector3d c = mesh.centre.row(i).transpose(), d = V.row(i).transpose() - c;
    const Eigen::Vector3d along = d.dot(u) * u, across = d - along;
    V.row(i) = (c + 1.2 * along + 0.8 * across).transpose();
  }
  const DiameterProfile trunk = MeasureRingDiameters(mesh, V)[TrunkSegment];
  const double polygonFactor = std::sqrt(n / (2 * M_PI) * std::sin(2 * M_PI / n));
  // Ring 2: the diameter through the pushed vertex left out, the rest exactly 8 mm (round-off
  // only); for the area the vertex counts at the median radius, so the polygon is the regular one.
  EXPECT_EQ(trunk.rings[2].mouthVertices, 1);
  EXPECT_NEAR(trunk.rings[2].meanMm, 8.0, 1e-9);
  EXPECT_NEAR(trunk.rings[2].maxMm, 8.0, 1e-9);
  EXPECT_NEAR(trunk.rings[2].areaMm, 8.0 * polygonFactor, 1e-9);
  EXPECT_EQ(trunk.rings[4].mouthVertices, 2);
  EXPECT_NEAR(trunk.rings[4].meanMm, 8.0, 1e-9);
  // Ring 3: an ellipse is the vessel, not a mouth: every diameter kept, from 6.4 to 9.6 mm.
  EXPECT_EQ(trunk.rings[3].mouthVertices, 0);
  EXPECT_NEAR(trunk.rings[3].minMm, 6.4, 1e-9);
  EXPECT_NEAR(trunk.rings[3].maxMm, 9.6, 1e-9);
  // The untouched rings: none.
  EXPECT_EQ(trunk.rings[1].mouthVertices, 0);
  EXPECT_NEAR(trunk.rings[1].meanMm, 8.0, 1e-9);
}

TEST(MeasureDiameters, RequestedStart_FirstRingThereAndInterpolationLinearBetweenRings)
{
  const testing::YPhantom y = testing::MakeYPhantom(1.0);
  StentMeshParams params;
  params.startRadiusMm = 4.0;
  params.proximalAbscissaMm = 17.3; // off every 1 mm centerline point and every ring spacing
  const StentMesh mesh = BuildStentMesh(y.tree, params);
  // Each ring k of the trunk scaled about its centre to radius 4 + k mm: diameters 8, 10, 12, …
  Points V = mesh.V;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (mesh.segment[i] == TrunkSegment)
    {
      const Eigen::Vector3d c = mesh.centre.row(i).transpose();
      V.row(i) = (c + (4.0 + mesh.ring[i]) / 4.0 * (V.row(i).transpose() - c)).transpose();
    }
  const DiameterProfile trunk = MeasureRingDiameters(mesh, V)[TrunkSegment];
  ASSERT_GE(trunk.rings.size(), 3u);
  EXPECT_NEAR(trunk.rings.front().abscissaMm, 17.3, 1e-9); // the first ring at the requested start
  for (std::size_t k = 0; k + 1 < trunk.rings.size(); ++k)
  {
    const RingDiameters &p = trunk.rings[k], &q = trunk.rings[k + 1];
    EXPECT_NEAR(p.meanMm, 8.0 + 2.0 * k, 1e-9);
    // A quarter of the way from ring k to k + 1: a quarter of the way from its diameter to the
    // next (a nearest-ring lookup would give either end, 0.5 mm off).
    const double s = p.abscissaMm + 0.25 * (q.abscissaMm - p.abscissaMm);
    EXPECT_NEAR(trunk.At(s).meanMm, 8.0 + 2.0 * k + 0.5, 1e-9);
    EXPECT_NEAR(trunk.At(s).minMm, 8.0 + 2.0 * k + 0.5, 1e-9);
  }
  // Clamped beyond the ends.
  EXPECT_NEAR(trunk.At(0.0).meanMm, 8.0, 1e-9);
  EXPECT_NEAR(trunk.At(1e4).meanMm, trunk.rings.back().meanMm, 1e-9);
}

TEST(MeasureDiameters, WrongVertexCount_InputError)
{
  const testing::YPhantom y = testing::MakeYPhantom(1.0);
  const StentMesh mesh = BuildStentMesh(y.tree);
  EXPECT_THROW(MeasureRingDiameters(mesh, Points(mesh.V.topRows(3))), InputError);
}

} // namespace
} // namespace sgp
