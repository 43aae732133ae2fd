// The modular configuration (issue 29): component lengths chosen from the shipped catalogue on
// anatomies given as path lengths, checked against brute force over the catalogue and the
// invariants the order list must keep (covered length = lengths − overlaps, overlaps in range,
// distal edges above the internal iliac ostium and as low as the catalogue allows).
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "Device/ConfigureDevice.h"
#include "Common/Errors.h"
#include "Device/CriterionCheck.h"
#include "Device/LimbOptions.h"
#include "IO/ReadDeviceCatalog.h"
#include "ConfigurationFixtures.h"

namespace sgp
{
namespace
{

/// The largest gap between consecutive lengths of the limbs of diameter `distalMm`.
double LengthStep(const DeviceFamily& family, double distalMm)
{
  std::vector<double> lengths;
  for (const CatalogueComponent* limb : family.ComponentsOf(ComponentRole::Limb))
    if (limb->distalDiameterMm == distalMm)
      lengths.push_back(limb->lengthMm);
  std::sort(lengths.begin(), lengths.end());
  double step = 0.0;
  for (std::size_t i = 1; i < lengths.size(); ++i)
    step = std::max(step, lengths[i] - lengths[i - 1]);
  return step;
}

/// Brute force: the highest distal edge ≤ `hi` that one limb of `distalMm` inserted into a stub
/// [stubStart, stubEnd] can reach with an overlap within the family's window (−∞ when none).
double BestSingleLimbEdge(const DeviceFamily& family, double stubStart, double stubEnd, double distalMm, double hi)
{
  const double lo = family.junctions.overlapMm.min;
  const double top = std::isnan(family.junctions.overlapMm.max)
                       ? stubEnd - stubStart
                       : std::min(family.junctions.overlapMm.max, stubEnd - stubStart);
  double best = -1e9;
  for (const CatalogueComponent* limb : family.ComponentsOf(ComponentRole::Limb))
    if (limb->distalDiameterMm == distalMm)
      for (double ov = lo; ov <= top + 1e-9; ov += 0.01) // every 0.01 mm of the window
      {
        const double edge = stubEnd - ov + limb->lengthMm;
        if (edge <= hi + 1e-6)
          best = std::max(best, edge);
      }
  return best;
}

/// The invariants every configured plan keeps, on each side.
void ExpectConsistent(const DeviceFamily& family, const DeviceConfiguration& c, const ConfigurationAnatomy& a)
{
  ASSERT_TRUE(c.configured) << c.unknownReason;
  const ConfiguredComponent* body = c.Find(OrderRole::MainBody);
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(body->proximalMm, 0.0);
  for (const ComponentOverlap& o : c.overlaps)
  {
    SCOPED_TRACE(o.junction);
    EXPECT_GE(o.overlapMm, o.minMm - ExactMm);
    EXPECT_LE(o.overlapMm, o.maxMm + ExactMm);
    // The limb's top lies inside what it is inserted into: the gate or leg below the flow divider.
    const ConfiguredComponent& outer = c.components[std::size_t(o.outer)];
    const ConfiguredComponent& inner = c.components[std::size_t(o.inner)];
    const double outerEnd =
      o.outer == 0 ? (o.side == c.ipsilateralSide ? body->distalMm : c.gateEndMm) : outer.distalMm;
    EXPECT_NEAR(inner.proximalMm, outerEnd - o.overlapMm, ExactMm);
    if (o.outer == 0)
    {
      EXPECT_GE(inner.proximalMm, c.flowDividerMm - ExactMm);
    }
  }
  for (int side = 0; side < 2; ++side)
  {
    SCOPED_TRACE(side == 0 ? "right" : "left");
    // Covered = the components' lengths on this side's path minus their overlaps, exactly.
    double sum = side == c.ipsilateralSide ? body->item.lengthMm : c.gateEndMm;
    double last = sum;
    for (const ConfiguredComponent& part : c.components)
      if (part.role != OrderRole::MainBody && part.side == side)
      {
        sum += part.item.lengthMm;
        last = std::max(last, part.distalMm);
      }
    for (const ComponentOverlap& o : c.overlaps)
      if (o.side == side)
        sum -= o.overlapMm;
    EXPECT_NEAR(c.coveredLengthMm[side], sum, ExactMm);
    EXPECT_NEAR(c.coveredLengthMm[side], last, ExactMm);
    EXPECT_NEAR(c.sealLengthMm[side], c.coveredLengthMm[side] - a.targetToBifurcationMm, ExactMm);
    EXPECT_NEAR(c.marginToInternalIliacMm[side], c.landingHighMm[side] - c.coveredLengthMm[side], ExactMm);
    EXPECT_NEAR(c.landingLowMm[side], a.targetToBifurcationMm + family.ifu.iliacSealLengthMm.min, ExactMm);
  }
}

const ConfigurationFinding* FindFinding(const DeviceConfiguration& c, const std::string& constraint, int side = -2)
{
  for (const ConfigurationFinding& f : c.findings)
    if (f.constraint == constraint && (side == -2 || f.side == side))
      return &f;
  return nullptr;
}

class CommonIliacAndAorta : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

// Common iliacs of 20, 35 and 55 mm, and aortas whose bifurcation lies 90, 120 and 160 mm below
// the proximal edge: each limb's distal edge stays above the internal iliac ostium, lands at
// least the family's minimum seal into the common iliac, is the highest edge any single limb of
// the catalogue reaches there (brute force), and so lies within the family's length step of the
// ostium; overlaps within range; covered lengths exactly the components' lengths minus overlaps.
TEST_P(CommonIliacAndAorta, LimbsLandAboveTheInternalIliacAsLowAsTheCatalogueAllows)
{
  const auto [cia, toBifurcation] = GetParam();
  for (const std::string& name : { std::string("Endurant II"), std::string("Excluder Conformable") })
  {
    SCOPED_TRACE(name);
    const DeviceFamily& family = Family(name);
    const double limb = 16.0; // both families offer 16 mm for a 14 mm iliac (14.3 %)
    const double body = name == "Endurant II" ? 25.0 : 26.0;
    const ConfigurationAnatomy a = Anatomy(toBifurcation, cia, cia);
    // Without a deployment tolerance: the rule this test holds it to (the margin: below).
    const DeviceConfiguration c = ConfigureDevice(family, Chosen(body, limb), a, Right, 0.0);
    ExpectConsistent(family, c, a);
    if (::testing::Test::HasFatalFailure())
      return;
    // Where the catalogue cannot reach (worked out by hand from its lengths): Endurant's shortest
    // reach is 122 mm (74 − 34 + 82) on the contralateral side and 124 mm (the 124 mm body's
    // leg) on the ipsilateral one, so a 90 mm aorta with a 20 or 35 mm common iliac (ostium at
    // 107 or 122 mm) is covered; Conformable's shortest leg reaches 150 mm (85 − 30 + 95) and its
    // gate needs 95 mm of aorta. Everywhere else both sides land without a finding.
    const bool endurant = name == "Endurant II";
    const bool lands =
      endurant ? !(toBifurcation == 90.0 && cia <= 35.0) : toBifurcation >= 120.0 && toBifurcation + cia - 3.0 >= 150.0;
    if (lands)
    {
      EXPECT_TRUE(c.findings.empty()) << c.findings.front().text;
    }
    else
    {
      ASSERT_FALSE(c.findings.empty());
      EXPECT_NE(FindFinding(c, "internalIliacCovered"), nullptr);
    }
    for (const ConfigurationFinding& f : c.findings)
    {
      // Only a finding of the anatomy, never a silent one: a side that cannot land names it.
      EXPECT_TRUE(f.constraint == "internalIliacCovered" || f.constraint == "gateBelowBifurcation") << f.text;
      EXPECT_FALSE(f.option.empty());
    }
    for (int side = 0; side < 2; ++side)
    {
      SCOPED_TRACE(side == 0 ? "right" : "left");
      const double hi = toBifurcation + cia - 3.0; // the ostium's upper edge: origin − r_IIA
      EXPECT_NEAR(c.landingHighMm[side], hi, ExactMm);
      const bool landed = std::none_of(c.findings.begin(), c.findings.end(),
                                       [&](const ConfigurationFinding& f) { return f.side == side; });
      if (!landed)
        continue;
      const double edge = c.coveredLengthMm[side];
      EXPECT_LE(edge, hi + ExactMm) << "covers the internal iliac";
      EXPECT_GE(edge, toBifurcation + family.ifu.iliacSealLengthMm.min - ExactMm) << "seal below the minimum";
      // Within the length step of the ostium — unless the longest limb of this diameter was used
      // and the catalogue has no extension of it: then nothing reaches lower.
      const auto usesLongest = [&]
      {
        double longest = 0.0;
        for (const CatalogueComponent* l : family.ComponentsOf(ComponentRole::Limb))
          if (l->distalDiameterMm == limb)
            longest = std::max(longest, l->lengthMm);
        const auto extensions = family.ComponentsOf(ComponentRole::IliacExtension);
        const ConfiguredComponent* used =
          c.Find(side == c.ipsilateralSide ? OrderRole::IpsilateralLimb : OrderRole::ContralateralLimb, side);
        return used && used->item.lengthMm == longest &&
               std::none_of(extensions.begin(), extensions.end(),
                            [&](const CatalogueComponent* e) { return e->distalDiameterMm == limb; });
      };
      if (edge < hi - LengthStep(family, limb) - ExactMm)
      {
        EXPECT_TRUE(usesLongest()) << "higher than the length step: " << edge << " for an ostium at " << hi;
      }
      const bool limbAlone = std::count_if(c.components.begin(), c.components.end(),
                                           [&](const ConfiguredComponent& p)
                                           { return p.side == side && p.role != OrderRole::MainBody; }) == 1;
      if (side != c.ipsilateralSide && limbAlone)
      {
        EXPECT_NEAR(edge, BestSingleLimbEdge(family, c.flowDividerMm, c.gateEndMm, limb, hi), 0.011)
          << "not the lowest edge the catalogue's limbs reach (brute force every 0.01 mm of overlap)";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Configurations,
                         CommonIliacAndAorta,
                         ::testing::Combine(::testing::Values(20.0, 35.0, 55.0), ::testing::Values(90.0, 120.0, 160.0)),
                         [](const auto& info)
                         {
                           return "Cia" + std::to_string(int(std::get<0>(info.param))) + "_Aorta" +
                                  std::to_string(int(std::get<1>(info.param)));
                         });

TEST(ConfigureDevice, TwelveMillimetreCommonIliac_NamesTheShortSealAndTheExternalIliacOption)
{
  const DeviceFamily& family = Family("Endurant II");
  const ConfigurationAnatomy a = Anatomy(120, 55, 12);
  const DeviceConfiguration c = ConfigureDevice(family, Chosen(25, 16), a, Right);
  ExpectConsistent(family, c, a);
  const ConfigurationFinding* f = FindFinding(c, "commonIliacTooShort", 1);
  ASSERT_NE(f, nullptr);
  // 12 mm to the origin less the 3 mm ostium radius: 9.0 mm of common iliac for a 15 mm seal.
  EXPECT_NE(f->text.find("9.0 mm from the aortic bifurcation"), std::string::npos) << f->text;
  EXPECT_NE(f->text.find("needs ≥ 15 mm"), std::string::npos) << f->text;
  EXPECT_NE(f->option.find("external iliac"), std::string::npos) << f->option;
  EXPECT_NE(f->option.find("covers the internal iliac"), std::string::npos) << f->option;
  // Never silently over the ostium: the limb still ends above it.
  EXPECT_LE(c.coveredLengthMm[1], c.landingHighMm[1] + ExactMm);
  EXPECT_FALSE(c.Feasible());
}

TEST(ConfigureDevice, TwentySixMillimetreCommonIliac_BellBottomLimbAndTheOption)
{
  const DeviceFamily& family = Family("Endurant II");
  ChosenDiameters chosen = Chosen(25, 16);
  chosen.limbMm[0] = std::numeric_limits<double>::quiet_NaN(); // the selection found no limb for 26 mm
  ConfigurationAnatomy a = Anatomy(120, 55, 55);
  a.iliacDiameterMm[0] = 26.0;
  const DeviceConfiguration c = ConfigureDevice(family, chosen, a, Right);
  ExpectConsistent(family, c, a);
  const ConfigurationFinding* f = FindFinding(c, "iliacTooWide", 0);
  ASSERT_NE(f, nullptr);
  // 28 mm, the widest Endurant limb, gives 7.7 % over 26 mm.
  EXPECT_NE(f->text.find("28 mm gives 7.7 %"), std::string::npos) << f->text;
  EXPECT_NE(f->option.find("bell-bottom"), std::string::npos) << f->option;
  EXPECT_NE(f->option.find("covers the internal iliac"), std::string::npos) << f->option;
  const ConfiguredComponent* limb = c.Find(OrderRole::IpsilateralLimb, 0);
  ASSERT_NE(limb, nullptr);
  EXPECT_EQ(limb->item.distalDiameterMm, 28.0);
  EXPECT_FALSE(c.Feasible());
}

TEST(ConfigureDevice, SixteenMillimetreDistalAortaWithTwoFourteenMillimetreLimbs_LimbCompression)
{
  // Excluder Conformable's 14.5 mm legs for 12 mm iliacs (20.8 %), both through a 16 mm aorta.
  const DeviceFamily& family = Family("Excluder Conformable");
  const ConfigurationAnatomy a = Anatomy(120, 40, 40, 12.0, 16.0);
  const DeviceConfiguration c = ConfigureDevice(family, Chosen(26, 14.5), a, Right);
  ExpectConsistent(family, c, a);
  const ConfigurationFinding* f = FindFinding(c, "limbCompression");
  ASSERT_NE(f, nullptr);
  EXPECT_NE(f->text.find("16.0 mm"), std::string::npos) << f->text;
  EXPECT_NE(f->text.find("29.0 mm"), std::string::npos) << f->text; // 14.5 + 14.5
  EXPECT_FALSE(c.Feasible());
  // A 19 mm distal aorta is narrow, not extremely: a note, not a failure.
  const DeviceConfiguration narrow = ConfigureDevice(family, Chosen(26, 14.5), Anatomy(120, 40, 40, 12.0, 19.0), Right);
  EXPECT_EQ(FindFinding(narrow, "limbCompression"), nullptr);
  EXPECT_TRUE(std::any_of(narrow.notes.begin(), narrow.notes.end(),
                          [](const std::string& n) { return n.find("Narrow distal aorta") != std::string::npos; }));
}

TEST(ConfigureDevice, CrotchWiderThanTheAortaAtTheFlowDivider_CrotchFinding)
{
  // Endurant's crotch is 27–30 mm wide: a sac-less aorta of 22 mm throughout is narrower.
  const DeviceFamily& family = Family("Endurant II");
  ConfigurationAnatomy a = Anatomy(120, 55, 55);
  std::fill(a.aortaMinDiameterMm.begin(), a.aortaMinDiameterMm.end(), 22.0);
  const DeviceConfiguration c = ConfigureDevice(family, Chosen(25, 16), a, Right);
  const ConfigurationFinding* f = FindFinding(c, "crotchTooNarrow");
  ASSERT_NE(f, nullptr);
  EXPECT_NE(f->text.find("22.0 mm"), std::string::npos) << f->text;
}

TEST(ConfigureDevice, AortaShorterThanTheShortestGate_GateBelowTheBifurcation)
{
  // Endurant's shortest gate ends 74 mm below the edge; it needs 10 mm above the bifurcation.
  const DeviceFamily& family = Family("Endurant II");
  const DeviceConfiguration c = ConfigureDevice(family, Chosen(25, 16), Anatomy(80, 55, 55), Right);
  const ConfigurationFinding* f = FindFinding(c, "gateBelowBifurcation");
  ASSERT_NE(f, nullptr);
  EXPECT_NE(f->text.find("6.0 mm above the aortic bifurcation"), std::string::npos) << f->text;
  EXPECT_EQ(c.gateEndMm, 74.0); // the shortest gate was kept: the least failing body
}

TEST(ConfigureDevice, LengthsNotInTheCatalogue_NotConfiguredWithTheReason)
{
  const DeviceConfiguration zenith =
    ConfigureDevice(Family("Zenith Flex"), Chosen(26, 14), Anatomy(120, 55, 55), Right);
  EXPECT_FALSE(zenith.configured);
  EXPECT_NE(zenith.unknownReason.find("no length, flow divider and contralateral gate position"), std::string::npos)
    << zenith.unknownReason;
  EXPECT_NE(zenith.OrderList().find("not configured"), std::string::npos);
  ConfigurationAnatomy noOrigin = Anatomy(120, 55, 55);
  noOrigin.targetToInternalIliacMm[1] = std::numeric_limits<double>::quiet_NaN();
  const DeviceConfiguration c = ConfigureDevice(Family("Endurant II"), Chosen(25, 16), noOrigin, Right);
  EXPECT_FALSE(c.configured);
  EXPECT_NE(c.unknownReason.find("left internal iliac origin was not found"), std::string::npos) << c.unknownReason;
}

TEST(ConfigureDevice, AskedSide_MainBodyGoesUpThatSide)
{
  const DeviceFamily& family = Family("Endurant II");
  for (int side : { 0, 1 })
  {
    const ConfigurationAnatomy a = Anatomy(120, 40, 55);
    const DeviceConfiguration c = ConfigureDevice(family, Chosen(25, 16), a, { side, "as asked" });
    ExpectConsistent(family, c, a);
    EXPECT_EQ(c.ipsilateralSide, side);
    EXPECT_EQ(c.Find(OrderRole::MainBody)->side, side);
    EXPECT_NE(c.Find(OrderRole::ContralateralLimb, 1 - side), nullptr);
  }
}

TEST(ChooseIpsilateralSide, WiderAccessThenLessTortuousThenRight)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { 6.0, 8.0 }, { 1.0, 1.5 }).side, 1); // 2 mm wider left
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { 7.5, 8.0 }, { 1.3, 1.1 }).side,
            1); // within 1 mm: tortuosity
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { 8.0, 7.5 }, { 1.1, 1.3 }).side, 0);
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { 7.5, 8.0 }, { 1.10, 1.12 }).side, 1); // alike: wider
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { nan, 8.0 }, { nan, nan }).side, 1);
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Auto, { nan, nan }, { nan, nan }).side, 0);
  EXPECT_EQ(ChooseIpsilateralSide(IpsilateralSide::Left, { 9.0, 6.0 }, { 1.0, 2.0 }).side, 1);
  EXPECT_NE(ChooseIpsilateralSide(IpsilateralSide::Auto, { 7.5, 8.0 }, { 1.3, 1.1 }).reason.find("less tortuous"),
            std::string::npos);
}

TEST(ConfigureDevice, InternalIliacOriginNearALengthBoundary_ListsTheOtherLength)
{
  // Brute force finds an anatomy whose left limb changes when its origin moves by ±3 mm.
  const DeviceFamily& family = Family("Endurant II");
  bool found = false;
  for (double cia = 20.0; cia <= 60.0 && !found; cia += 0.5)
  {
    const DeviceConfiguration c = ConfigureDevice(family, Chosen(25, 16), Anatomy(120, 55, cia), Right);
    const DeviceConfiguration lower = ConfigureDevice(family, Chosen(25, 16), Anatomy(120, 55, cia + 3.0), Right);
    const ConfiguredComponent *mine = c.Find(OrderRole::ContralateralLimb, 1),
                              *theirs = lower.Find(OrderRole::ContralateralLimb, 1);
    if (!mine || !theirs || mine->item.lengthMm == theirs->item.lengthMm)
      continue;
    found = true;
    const auto listed = std::find_if(c.alternatives.begin(), c.alternatives.end(),
                                     [&](const SizeAlternative& a) { return a.component == "left limb"; });
    ASSERT_NE(listed, c.alternatives.end()) << "cia " << cia;
    EXPECT_EQ(listed->alternative, CompactNumber(theirs->item.lengthMm) + " mm");
    EXPECT_NE(listed->text.find("uncertainty"), std::string::npos);
  }
  EXPECT_TRUE(found);
}

/// Brute force over every single limb of `distalMm` and every 0.01 mm of its overlap in a stub
/// [stubStart, stubEnd]: the widest margin (the narrower of its ranges below — to W_hi, to the
/// overlap's minimum — and above — to W_lo, unless the overlap window's top stops it first —
/// capped at `tolerance`) of an edge in [lo, hi], and the lowest edge with it (within 0.05 mm);
/// NaN when none lands.
std::pair<double, double> BestMarginBruteForce(const DeviceFamily& family,
                                               double stubStart,
                                               double stubEnd,
                                               double distalMm,
                                               double lo,
                                               double hi,
                                               double tolerance)
{
  std::vector<std::pair<double, double>> placements; // margin, edge
  for (const CatalogueComponent* limb : family.ComponentsOf(ComponentRole::Limb))
  {
    if (limb->distalDiameterMm != distalMm)
      continue;
    const double ovLo = family.junctions.overlapMm.min;
    double ovHi = std::min(stubEnd - stubStart, limb->lengthMm - 1.0);
    if (!std::isnan(family.junctions.overlapMm.max))
      ovHi = std::min(ovHi, family.junctions.overlapMm.max);
    for (double ov = ovLo; ov <= ovHi + 1e-9; ov += 0.01)
    {
      const double edge = stubEnd - ov + limb->lengthMm;
      // Up, its seal fails unless its overlap reaches the window's top first (a stop: safe).
      const double above = ovHi - ov <= edge - lo ? 1e9 : edge - lo;
      if (edge >= lo && edge <= hi)
        placements.emplace_back(std::min({ tolerance, hi - edge, ov - ovLo, above }), edge);
    }
  }
  double best = -1.0, lowest = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [margin, edge] : placements)
    best = std::max(best, margin);
  for (const auto& [margin, edge] : placements)
    if (margin >= best - 0.05 && !(edge <= lowest))
      lowest = edge;
  return { best < 0.0 ? std::numeric_limits<double>::quiet_NaN() : best, lowest };
}

class DeploymentMargin : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

// Issue 47: a limb placed with a margin for the deployment tolerance. On common iliacs of 18–60 mm
// (windows from 0 to 42 mm between the minimum seal and the ostium) and tolerances of 2.5 and
// 5 mm, the contralateral limb's narrowest range is the widest any single limb of the catalogue
// reaches there (brute force every 0.01 mm of overlap), its edge within SameEdgeMm of the lowest
// with that margin; its stated ranges are the path's own differences (to the ostium, to the
// overlap's minimum, to the minimum seal or the window's top). The configuration states them
// and makes no finding of them: the simulated graft's ranges do (DeploymentTolerance.h).
TEST_P(DeploymentMargin, LimbPlacedWhereItsNarrowestRangeIsWidest)
{
  const auto [cia, tolerance] = GetParam();
  for (const std::string& name : { std::string("Endurant II"), std::string("Excluder Conformable") })
  {
    SCOPED_TRACE(name);
    const DeviceFamily& family = Family(name);
    const double body = name == "Endurant II" ? 25.0 : 26.0;
    const ConfigurationAnatomy a = Anatomy(140.0, 55.0, cia);
    const DeviceConfiguration c = ConfigureDevice(family, Chosen(body, 16.0), a, Right, tolerance);
    ExpectConsistent(family, c, a);
    if (::testing::Test::HasFatalFailure())
      return;
    EXPECT_EQ(c.deploymentToleranceMm, tolerance);
    const ConfiguredComponent* limb = c.Find(OrderRole::ContralateralLimb, 1);
    ASSERT_NE(limb, nullptr);
    const double lo = c.landingLowMm[1], hi = c.landingHighMm[1];
    const auto [best, lowest] = BestMarginBruteForce(family, c.flowDividerMm, c.gateEndMm, 16.0, lo, hi, tolerance);
    if (c.Find(OrderRole::IliacExtension, 1) || std::isnan(best))
      continue; // an extension, or no single limb lands: the margin rule is not what decides
    const ComponentOverlap* overlap = nullptr;
    for (const ComponentOverlap& o : c.overlaps)
      if (o.side == 1 && o.inner == int(limb - c.components.data()))
        overlap = &o;
    ASSERT_NE(overlap, nullptr);
    const double edge = limb->distalMm;
    // The ranges are the path's own differences (exact sums of catalogue figures).
    EXPECT_NEAR(limb->holdsBelowMm, std::min(hi - edge, overlap->overlapMm - overlap->minMm), ExactMm);
    const bool stops = overlap->maxMm - overlap->overlapMm <= edge - lo;
    EXPECT_NEAR(limb->holdsAboveMm, stops ? overlap->maxMm - overlap->overlapMm : edge - lo, ExactMm);
    EXPECT_EQ(limb->holdsAboveLimit, stops ? "stop" : "seal");
    EXPECT_EQ(limb->holdsBelowLimit, hi - edge <= overlap->overlapMm - overlap->minMm ? "covers" : "overlap");
    const double margin = std::min({ tolerance, stops ? 1e9 : limb->holdsAboveMm, limb->holdsBelowMm });
    // The brute force's 0.01 mm grid and its 0.05 mm "alike" margins.
    EXPECT_NEAR(margin, best, 0.06) << "not the widest narrowest range a single limb reaches";
    EXPECT_GE(edge, lowest - SameEdgeMm - 0.02) << "a lower edge with the same margin exists";
    for (const ConfigurationFinding& f : c.findings)
      EXPECT_NE(f.constraint, "narrowDeploymentRange") << f.text;
  }
}

INSTANTIATE_TEST_SUITE_P(CommonIliacs,
                         DeploymentMargin,
                         ::testing::Combine(::testing::Values(18.0, 22.0, 26.0, 30.0, 40.0, 60.0),
                                            ::testing::Values(2.5, 5.0)),
                         [](const auto& info)
                         {
                           return "Cia" + std::to_string(int(std::get<0>(info.param))) + "_Tolerance" +
                                  std::to_string(int(std::get<1>(info.param) * 10)) + "tenths";
                         });

// The failure: with no margin the limb ends at the ostium (0.0 mm below holds). With the
// default tolerance it ends as far above it as the catalogue's lengths and its overlap in the gate
// let it slip (Endurant: a 30–34 mm window, so at most 4 mm), its top at the flow divider (it cannot
// land higher: a stop), and its seal that much shorter.
TEST(ConfigureDevice, DefaultTolerance_LimbNoLongerEndsAtTheOstium)
{
  const DeviceFamily& family = Family("Endurant II");
  // The first left common iliac from 30 mm on (every 0.25 mm) where, without a margin, a limb
  // ends exactly at the ostium (its overlap window holds the ostium's position).
  double cia = 30.0;
  while (cia < 70.0 &&
         ConfigureDevice(family, Chosen(25, 16), Anatomy(140.0, 55.0, cia), Right, 0.0).marginToInternalIliacMm[1] >
           ExactMm)
    cia += 0.25;
  ASSERT_LT(cia, 70.0);
  const ConfigurationAnatomy a = Anatomy(140.0, 55.0, cia);
  const DeviceConfiguration exact = ConfigureDevice(family, Chosen(25, 16), a, Right, 0.0);
  const DeviceConfiguration margin = ConfigureDevice(family, Chosen(25, 16), a, Right);
  ExpectConsistent(family, margin, a);
  EXPECT_NEAR(exact.Find(OrderRole::ContralateralLimb, 1)->holdsBelowMm, 0.0, ExactMm);
  const ConfiguredComponent* limb = margin.Find(OrderRole::ContralateralLimb, 1);
  ASSERT_NE(limb, nullptr);
  const ComponentOverlap& gate = margin.overlaps.back();
  ASSERT_EQ(gate.inner, int(limb - margin.components.data()));
  // The most room any single limb has here (brute force), at most the gate's 4 mm of overlap.
  const double room = BestMarginBruteForce(family, margin.flowDividerMm, margin.gateEndMm, 16.0, margin.landingLowMm[1],
                                           margin.landingHighMm[1], DeploymentToleranceMm)
                        .first;
  EXPECT_GE(room, 1.0);
  EXPECT_LE(room, gate.maxMm - gate.minMm + ExactMm);
  EXPECT_NEAR(limb->holdsBelowMm, room, 0.06) << margin.OrderList(); // the brute force's grid
  EXPECT_GE(margin.marginToInternalIliacMm[1], limb->holdsBelowMm - ExactMm);
  EXPECT_EQ(limb->holdsAboveLimit, "stop");
  EXPECT_TRUE(margin.findings.empty()) << margin.findings.front().text;
  EXPECT_NE(limb->HoldsText().find("it cannot land higher"), std::string::npos) << limb->HoldsText();
  EXPECT_THROW(ConfigureDevice(family, Chosen(25, 16), a, Right, -1.0), InputError);
}

} // namespace
} // namespace sgp
