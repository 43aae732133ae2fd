// The deployment tolerance's displacement and search (issue 47), on configurations of the shipped
// catalogue with a stand-in for the simulation whose limits are known: each component passes
// while its displacement lies in [−above, below]. The search must find each limit to its
// resolution from below (never claim more room than there is), say why it ends, and make a
// finding of a range narrower than the tolerance (the main body's upward range at a renal a note).
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Device/DeploymentTolerance.h"
#include "IO/ReadDeviceCatalog.h"

namespace sgp
{
namespace
{

constexpr double ExactMm = 1e-9;

const DeviceFamily& Endurant()
{
  static const DeviceCatalog catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  return *FindDeviceFamily(catalog, "Endurant II");
}

/// 140 mm to the bifurcation, common iliacs of `rightCia` and `leftCia` mm (internal iliacs of
/// radius 3 mm), 14 mm iliacs, a 50 mm sac.
DeviceConfiguration Configured(double rightCia = 45.0, double leftCia = 45.0)
{
  ConfigurationAnatomy a;
  a.targetToBifurcationMm = 140.0;
  a.targetToInternalIliacMm = { 140.0 + rightCia, 140.0 + leftCia };
  a.internalIliacRadiusMm = { 3.0, 3.0 };
  a.targetToIliacEndMm = { 300.0, 300.0 };
  a.iliacDiameterMm = { 14.0, 14.0 };
  for (double s = 0.0; s <= 140.0; s += 4.0)
  {
    a.aortaProfileMm.push_back(s);
    a.aortaMinDiameterMm.push_back(s < 25.0 ? 22.0 : s > 120.0 ? 22.0 : 50.0);
  }
  a.distalAorticDiameterMm = 22.0;
  ChosenDiameters chosen;
  chosen.mainBodyMm = 25.0;
  chosen.limbMm = { 16.0, 16.0 };
  return ConfigureDevice(Endurant(), chosen, a, { 0, "right, as asked" });
}

/// How far component k was displaced in `moved` against `planned` (down positive).
double DisplacementOf(const DeviceConfiguration& planned,
                      const DeviceConfiguration& moved,
                      std::size_t k,
                      double targetShiftMm)
{
  if (k == 0)
    return targetShiftMm;
  return moved.components[k].distalMm - planned.components[k].distalMm + targetShiftMm;
}

/// A simulation that passes while every component lies within [−above_k, below_k] of its plan.
struct KnownLimits
{
  const DeviceConfiguration* planned = nullptr;
  std::map<std::size_t, std::pair<double, double>> limits; ///< k → (above, below)
  int calls = 0;
  DisplacedCheck operator()(const DeviceConfiguration& moved, double shift)
  {
    ++calls;
    for (const auto& [k, limit] : limits)
    {
      const double d = DisplacementOf(*planned, moved, k, shift);
      if (d < -limit.first - ExactMm)
        return { false, "component " + std::to_string(k) + " too high", k == 0 };
      if (d > limit.second + ExactMm)
        return { false, "component " + std::to_string(k) + " too low", false };
    }
    return { true, "", false };
  }
};

TEST(Displaced, OverlapsFollowAndCoveredLengthsStayTheComponentsLessTheirOverlaps)
{
  const DeviceConfiguration c = Configured();
  ASSERT_TRUE(c.configured) << c.unknownReason;
  ASSERT_GE(c.components.size(), 3u);
  const std::size_t contra = 2; // main body, right (ipsilateral) limb, left contralateral limb
  ASSERT_EQ(c.components[contra].role, OrderRole::ContralateralLimb);
  // A limb 3 mm down: its overlap in the gate 3 mm less, its side 3 mm longer, its seal too.
  const Displacement limb = Displaced(c, contra, 3.0);
  EXPECT_EQ(limb.targetShiftMm, 0.0);
  for (const ComponentOverlap& o : c.overlaps)
    if (std::size_t(o.inner) == contra)
      for (const ComponentOverlap& m : limb.configuration.overlaps)
        if (m.junction == o.junction)
        {
          EXPECT_NEAR(m.overlapMm, o.overlapMm - 3.0, ExactMm);
        }
  EXPECT_NEAR(limb.configuration.coveredLengthMm[1], c.coveredLengthMm[1] + 3.0, ExactMm);
  EXPECT_NEAR(limb.configuration.sealLengthMm[1], c.sealLengthMm[1] + 3.0, ExactMm);
  EXPECT_NEAR(limb.configuration.marginToInternalIliacMm[1], c.marginToInternalIliacMm[1] - 3.0, ExactMm);
  EXPECT_NEAR(limb.configuration.coveredLengthMm[0], c.coveredLengthMm[0], ExactMm);
  // The main body 2 mm up: the target moves −2, the limbs stay in the iliacs (their path
  // positions from the new target +2) as far as their overlaps in the body stay at least the
  // minimum; one that would fall under it is drawn up with the body by the difference.
  const Displacement body = Displaced(c, 0, -2.0);
  EXPECT_EQ(body.targetShiftMm, -2.0);
  for (std::size_t j = 0; j < c.overlaps.size(); ++j)
  {
    const ComponentOverlap& o = c.overlaps[j];
    ASSERT_EQ(o.outer, 0); // both limbs in the main body
    const double expected = std::max(o.minMm, o.overlapMm - 2.0);
    const double drawnUp = expected - (o.overlapMm - 2.0);
    EXPECT_NEAR(body.configuration.overlaps[j].overlapMm, expected, ExactMm);
    const std::size_t k = std::size_t(o.inner);
    EXPECT_NEAR(body.configuration.components[k].distalMm, c.components[k].distalMm + 2.0 - drawnUp, ExactMm);
    const std::size_t side = std::size_t(o.side);
    // Where the iliac seal starts and the ostium lies, from the new target: the seal shorter by
    // as much as the limb was drawn up.
    EXPECT_NEAR(body.configuration.sealLengthMm[side], c.sealLengthMm[side] - drawnUp, ExactMm);
    EXPECT_NEAR(body.configuration.marginToInternalIliacMm[side], c.marginToInternalIliacMm[side] + drawnUp, ExactMm);
  }
  // Placed with a margin, the contralateral limb sits as deep in the gate as it goes (overlap
  // 34 mm of Endurant's 30–34): 2 mm up keeps it in; 6 mm up draws it.
  const Displacement sixUp = Displaced(c, 0, -6.0);
  EXPECT_NEAR(sixUp.configuration.overlaps.back().overlapMm, c.overlaps.back().minMm, ExactMm);
  EXPECT_LT(sixUp.configuration.sealLengthMm[1], c.sealLengthMm[1] - ExactMm);
  EXPECT_THROW(Displaced(c, c.components.size(), 1.0), InputError);
}

TEST(AssessDeploymentTolerance, FindsEachKnownLimitFromBelowToItsResolution)
{
  const DeviceConfiguration c = Configured();
  ASSERT_TRUE(c.configured) << c.unknownReason;
  KnownLimits sim;
  sim.planned = &c;
  // The main body: 1.3 mm up (then a renal), 7.7 mm down; the limbs' own limits as given.
  sim.limits = { { 0, { 1.3, 7.7 } }, { 1, { 6.2, 2.35 } }, { 2, { 9.0, 3.6 } } };
  const DeploymentTolerance t =
    AssessDeploymentTolerance(c, 5.0, [&](const DeviceConfiguration& m, double s) { return sim(m, s); });
  ASSERT_TRUE(t.assessed) << t.notAssessedReason;
  EXPECT_EQ(t.searchMm, 10.0);
  ASSERT_EQ(t.components.size(), c.components.size());
  for (const ComponentHold& h : t.components)
  {
    SCOPED_TRACE(h.name);
    const auto [above, below] = sim.limits.at(h.component);
    // Never more room than there is, and within the resolution of it — unless the overlap
    // window stops the search first (then the window's end, said so).
    // Up, a component stops where its overlap reaches its window's top (then it cannot go
    // further: a stop, not a failure). Down, the main body pushes each limb inserted into it once
    // that limb's overlap reaches its window's top: the limb then fails at its own limit.
    double aboveCap = 1e9, pushedBelow = 1e9;
    for (const ComponentOverlap& o : c.overlaps)
    {
      if (std::size_t(o.inner) == h.component)
        aboveCap = std::min(aboveCap, o.maxMm - o.overlapMm);
      if (std::size_t(o.outer) == h.component && sim.limits.count(std::size_t(o.inner)))
        pushedBelow = std::min(pushedBelow, o.maxMm - o.overlapMm + sim.limits.at(std::size_t(o.inner)).second);
    }
    const double aboveTruth = std::min(above, aboveCap), belowTruth = std::min(below, pushedBelow);
    EXPECT_LE(h.aboveMm, aboveTruth + ExactMm);
    EXPECT_GT(h.aboveMm, aboveTruth - t.resolutionMm - ExactMm);
    EXPECT_LE(h.belowMm, belowTruth + ExactMm);
    EXPECT_GT(h.belowMm, belowTruth - t.resolutionMm - ExactMm);
    EXPECT_EQ(h.aboveStops, aboveCap < above);
    EXPECT_EQ(h.aboveFails.find("too high") != std::string::npos, above <= aboveCap) << h.aboveFails;
    EXPECT_FALSE(h.belowStops);
    EXPECT_NE(h.belowFails.find("too low"), std::string::npos) << h.belowFails;
  }
  // The main body's 1.3 mm upward range ends at a renal: a note; its 7.7 mm below is wide enough.
  EXPECT_TRUE(t.components[0].aboveAtAorticOstium);
  ASSERT_EQ(t.notes.size(), 1u);
  EXPECT_NE(t.notes[0].find("lowest renal ostium on purpose"), std::string::npos) << t.notes[0];
  // The main body pushed down onto the left limb fails at under 5 mm too (the limb at its stop,
  // 3.6 mm from its limit), and the two limbs are narrower than 5 mm below: a finding each,
  // naming it and the tolerance; no finding of an upward range that ends at a stop.
  ASSERT_EQ(t.findings.size(), 3u);
  EXPECT_NE(t.findings[0].find("main body holds only"), std::string::npos) << t.findings[0];
  EXPECT_EQ(t.findings[0].find("above"), std::string::npos) << t.findings[0];
  EXPECT_NE(t.findings[1].find("right ipsilateral limb holds only"), std::string::npos) << t.findings[1];
  EXPECT_NE(t.findings[2].find("left contralateral limb holds only"), std::string::npos) << t.findings[2];
  EXPECT_NE(t.findings[2].find("5.0 mm deployment tolerance"), std::string::npos) << t.findings[2];
  for (const ComponentHold& h : t.components)
    EXPECT_EQ(h.finding.empty(), h.component != 0 && h.belowMm >= 5.0);
  EXPECT_EQ(t.simulations, sim.calls);
  // ≤ 2 + log2(S / resolution) per direction, and the planned one.
  EXPECT_LE(t.simulations, 1 + int(2 * c.components.size()) * (2 + int(std::ceil(std::log2(20.0)))));
}

TEST(AssessDeploymentTolerance, WideEverywhere_AtLeastTheSearchAndNoFinding)
{
  const DeviceConfiguration c = Configured();
  KnownLimits sim;
  sim.planned = &c;
  sim.limits = { { 0, { 50.0, 50.0 } } };
  const DeploymentTolerance t =
    AssessDeploymentTolerance(c, 2.0, [&](const DeviceConfiguration& m, double s) { return sim(m, s); });
  ASSERT_TRUE(t.assessed);
  EXPECT_EQ(t.searchMm, 5.0); // twice the tolerance, at least 5 mm
  EXPECT_TRUE(t.findings.empty()) << t.findings.front();
  EXPECT_NEAR(t.components[0].belowMm, 5.0, ExactMm);
  EXPECT_NE(t.components[0].Text(t.searchMm).find("to at least 5.0 mm below"), std::string::npos)
    << t.components[0].Text(t.searchMm);
}

TEST(AssessDeploymentTolerance, PlannedGraftFails_NotAssessedWithTheReason)
{
  const DeviceConfiguration c = Configured();
  const DeploymentTolerance t =
    AssessDeploymentTolerance(c, 5.0,
                              [](const DeviceConfiguration&, double) {
                                return DisplacedCheck{ false, "proximal seal 6.0 mm", false };
                              });
  EXPECT_FALSE(t.assessed);
  EXPECT_NE(t.notAssessedReason.find("proximal seal 6.0 mm"), std::string::npos) << t.notAssessedReason;
  EXPECT_EQ(t.simulations, 1);
  EXPECT_THROW(AssessDeploymentTolerance(c, -1.0, [](const DeviceConfiguration&, double) { return DisplacedCheck{}; }),
               InputError);
}

} // namespace
} // namespace sgp
