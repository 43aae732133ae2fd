// The surgeon's own configuration (issue 47 item 1): resolved against the shipped catalogue and
// configured exactly as given on anatomies given as path lengths, so that every expected figure
// is the catalogue's lengths and the anatomy's distances added by hand; and every way a given
// configuration differs from the recommendation, with its consequence.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "ConfigurationFixtures.h"
#include "Device/CompareConfigurations.h"
#include "Device/GivenConfiguration.h"
#include "Device/LimbOptions.h"

namespace sgp
{
namespace
{

/// Endurant II with a 25 mm main body and 16 mm limbs on a 130 mm aorta and 60 mm common iliacs.
struct Case
{
  const DeviceFamily& family = Family("Endurant II");
  ConfigurationAnatomy anatomy = Anatomy(130.0, 60.0, 60.0);
  ChosenDiameters chosen = Chosen(25.0, 16.0);
  DeviceConfiguration recommended = ConfigureDevice(family, chosen, anatomy, Right);

  DeviceConfiguration Configure(const GivenConfiguration& given, const SideChoice& side = Right) const
  {
    return ConfigureGivenDevice(family, ResolveGivenConfiguration(given, Shipped()), chosen, anatomy, side);
  }
};

GivenComponent* Find(GivenConfiguration& g, ComponentRole role, int side)
{
  for (GivenComponent& c : g.components)
    if (c.role == role && c.side == side)
      return &c;
  return nullptr;
}

/// The next longer limb of the same diameters, or nullptr.
const CatalogueComponent* NextLonger(const DeviceFamily& family, const CatalogueComponent& limb)
{
  const CatalogueComponent* next = nullptr;
  for (const CatalogueComponent* c : family.ComponentsOf(limb.role))
    if (c->diameterMm == limb.diameterMm && c->distalDiameterMm == limb.distalDiameterMm &&
        c->lengthMm > limb.lengthMm && (!next || c->lengthMm < next->lengthMm))
      next = c;
  return next;
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST(GivenConfiguration, TheRecommendationGivenBack_IsTheSameConfigurationAndNoDifference)
{
  const Case c;
  ASSERT_TRUE(c.recommended.configured);
  const DeviceConfiguration again = c.Configure(GivenFromConfiguration(c.recommended, 0.0));
  ASSERT_TRUE(again.configured);
  EXPECT_TRUE(again.given);
  ASSERT_EQ(again.components.size(), c.recommended.components.size());
  for (std::size_t k = 0; k < again.components.size(); ++k)
  {
    const ConfiguredComponent &a = again.components[k], &b = c.recommended.components[k];
    EXPECT_EQ(a.item.code, b.item.code);
    EXPECT_EQ(int(a.role), int(b.role));
    // The overlaps are written at full precision: the same sums to rounding.
    EXPECT_NEAR(a.proximalMm, b.proximalMm, ExactMm);
    EXPECT_NEAR(a.distalMm, b.distalMm, ExactMm);
    if (k > 0)
    {
      EXPECT_NEAR(a.holdsAboveMm, b.holdsAboveMm, ExactMm) << a.RoleText();
      EXPECT_NEAR(a.holdsBelowMm, b.holdsBelowMm, ExactMm) << a.RoleText();
    }
  }
  EXPECT_EQ(again.findings.size(), c.recommended.findings.size());
  EXPECT_TRUE(CompareConfigurations(again, c.recommended, 0.0).empty());
}

TEST(GivenConfiguration, LeftLimbOneLengthLonger_CoversTheInternalIliacByWhatTheLengthsAdd)
{
  const Case c;
  GivenConfiguration g = GivenFromConfiguration(c.recommended, 0.0);
  const ConfiguredComponent* limb = c.recommended.Find(OrderRole::ContralateralLimb, 1);
  ASSERT_NE(limb, nullptr);
  ASSERT_EQ(c.recommended.Find(OrderRole::IliacExtension, 1), nullptr) << "the case needs a single left limb";
  const CatalogueComponent* longer = NextLonger(c.family, limb->item);
  ASSERT_NE(longer, nullptr);
  Find(g, ComponentRole::Limb, 1)->code = longer->code;
  const DeviceConfiguration given = c.Configure(g);
  // Same overlap: the distal edge moves down by exactly the length added.
  const double added = longer->lengthMm - limb->item.lengthMm;
  const double margin = c.recommended.marginToInternalIliacMm[1] - added;
  EXPECT_NEAR(given.marginToInternalIliacMm[1], margin, ExactMm);
  ASSERT_LT(margin, 0.0) << "one length longer must reach past the ostium in this case";
  const auto covered =
    std::find_if(given.findings.begin(), given.findings.end(),
                 [](const ConfigurationFinding& f) { return f.constraint == "internalIliacCovered"; });
  ASSERT_NE(covered, given.findings.end());
  EXPECT_EQ(covered->side, 1);
  EXPECT_TRUE(Contains(covered->text, "covers the ostium by " + FormatNumber(-margin) + " mm")) << covered->text;
  // Exactly one difference: that limb, its length, and the consequence in numbers.
  const std::vector<ConfigurationDifference> d = CompareConfigurations(given, c.recommended, 0.0);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].what, "left limb");
  EXPECT_TRUE(Contains(d[0].change, FormatNumber(added, 0) + " mm longer (" + longer->code)) << d[0].change;
  EXPECT_TRUE(Contains(d[0].consequence, "covers the left internal iliac ostium by " + FormatNumber(-margin) + " mm"))
    << d[0].consequence;
  EXPECT_TRUE(Contains(d[0].consequence,
                       "recommended: ends " + FormatNumber(c.recommended.marginToInternalIliacMm[1]) + " mm above"))
    << d[0].consequence;
}

TEST(GivenConfiguration, MainBodyOneLengthShorter_GateClearanceChangesByTheGateEndsAndTheLimbNeededIsNamed)
{
  // An aorta whose recommended main body has a shorter sibling with its gate elsewhere (Endurant
  // II: 124 mm bodies end their gate at 74 mm, the longer ones at 84 mm).
  Case c;
  const CatalogueComponent* shorter = nullptr;
  for (double aorta : { 100.0, 110.0, 120.0, 130.0 })
  {
    c.anatomy = Anatomy(aorta, 60.0, 60.0);
    c.recommended = ConfigureDevice(c.family, c.chosen, c.anatomy, Right);
    const CatalogueComponent& body = c.recommended.components.front().item;
    shorter = nullptr;
    for (const CatalogueComponent* b : c.family.ComponentsOf(ComponentRole::MainBody))
      if (b->diameterMm == body.diameterMm && b->distalDiameterMm == body.distalDiameterMm &&
          b->lengthMm < body.lengthMm && (!shorter || b->lengthMm > shorter->lengthMm))
        shorter = b;
    if (shorter && shorter->gateEndMm != body.gateEndMm)
      break;
    shorter = nullptr;
  }
  ASSERT_NE(shorter, nullptr) << "no aorta of the series recommends a body with a shorter sibling gated elsewhere";
  const CatalogueComponent& body = c.recommended.components.front().item;
  // The main body alone: both sides completed by the plan's rule for this body.
  GivenConfiguration g;
  g.origin = "test";
  g.family = c.family.name;
  g.mainBodySide = 0;
  GivenComponent b;
  b.where = "components[0]";
  b.role = ComponentRole::MainBody;
  b.code = shorter->code;
  g.components = { b };
  const DeviceConfiguration given = c.Configure(g);
  ASSERT_TRUE(given.configured);
  EXPECT_NEAR(given.gateClearanceMm - c.recommended.gateClearanceMm, body.gateEndMm - shorter->gateEndMm, ExactMm);
  const std::vector<ConfigurationDifference> d = CompareConfigurations(given, c.recommended, 0.0);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0].what, "main body");
  EXPECT_TRUE(Contains(d[0].change, FormatNumber(body.lengthMm - shorter->lengthMm, 0) + " mm shorter")) << d[0].change;
  EXPECT_TRUE(Contains(d[0].consequence, "ends " + FormatNumber(given.gateClearanceMm) +
                                           " mm above the aortic bifurcation (recommended: " +
                                           FormatNumber(c.recommended.gateClearanceMm) + " mm)"))
    << d[0].consequence;
  // The contralateral limb the shorter body needs: named where it differs, with where it lands.
  const ConfiguredComponent* needed = given.Find(OrderRole::ContralateralLimb, 1);
  const ConfiguredComponent* before = c.recommended.Find(OrderRole::ContralateralLimb, 1);
  ASSERT_TRUE(needed && before);
  // The gate moved: the left side lands elsewhere, or another limb or overlap keeps it in place;
  // either way a difference on the left names where it lands.
  const auto left =
    std::find_if(d.begin(), d.end(),
                 [](const ConfigurationDifference& x) { return x.what == "left limb" || x.what == "left side"; });
  ASSERT_NE(left, d.end());
  if (needed->item.code != before->item.code)
  {
    EXPECT_TRUE(Contains(left->change, needed->item.code + " instead of " + before->item.code)) << left->change;
  }
  const double margin = given.marginToInternalIliacMm[1];
  EXPECT_TRUE(
    Contains(left->consequence,
             "the left side " + (margin >= 0 ? "ends " + FormatNumber(margin)
                                             : "covers the left internal iliac ostium by " + FormatNumber(-margin))))
    << left->consequence;
}

TEST(GivenConfiguration, MainBodyFromTheOtherSide_TheLimbsSwapRoles)
{
  const Case c;
  GivenConfiguration g = GivenFromConfiguration(c.recommended, 0.0);
  g.origin = "test";
  g.mainBodySide = 1;
  for (GivenComponent& part : g.components)
    part.overlapMm = GivenComponent::NotGiven; // each placed in what it now goes into
  const DeviceConfiguration given = c.Configure(g, SideChoice{ 1, "left, as given" });
  ASSERT_TRUE(given.configured);
  const ConfiguredComponent* right = given.Find(OrderRole::ContralateralLimb, 0);
  const ConfiguredComponent* left = given.Find(OrderRole::IpsilateralLimb, 1);
  ASSERT_TRUE(right && left);
  EXPECT_EQ(right->item.code, c.recommended.Find(OrderRole::IpsilateralLimb, 0)->item.code);
  EXPECT_EQ(left->item.code, c.recommended.Find(OrderRole::ContralateralLimb, 1)->item.code);
  // Each overlaps within its new window: the gate's stub for the right, the leg for the left.
  for (const ComponentOverlap& o : given.overlaps)
  {
    EXPECT_GE(o.overlapMm, o.minMm - ExactMm) << o.junction;
    EXPECT_LE(o.overlapMm, o.maxMm + ExactMm) << o.junction;
  }
  const std::vector<ConfigurationDifference> d = CompareConfigurations(given, c.recommended, 0.0);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0].what, "main body side");
  EXPECT_TRUE(
    Contains(d[0].consequence, "the limbs swap roles: the left limb goes into the main body's ipsilateral leg"))
    << d[0].consequence;
  for (const ConfigurationDifference& x : d)
    EXPECT_TRUE(x.what != "left limb" || !Contains(x.change, "instead of E")) << "no limb was changed: " << x.Text();
}

TEST(GivenConfiguration, Positions_DistalEdgeExactOverlapUnderTheMinimumAFindingImpossibleOnesAnError)
{
  const Case c;
  GivenConfiguration g = GivenFromConfiguration(c.recommended, 0.0);
  g.origin = "test";
  GivenComponent* left = Find(g, ComponentRole::Limb, 1);
  left->overlapMm = GivenComponent::NotGiven;
  left->distalEdgeAboveInternalIliacMm = 7.5;
  const DeviceConfiguration at = c.Configure(g);
  EXPECT_NEAR(at.marginToInternalIliacMm[1], 7.5, ExactMm);
  // An overlap 5 mm under the family's minimum: simulated, and a finding naming it.
  const double minimum = c.family.junctions.overlapMm.min;
  left->distalEdgeAboveInternalIliacMm = GivenComponent::NotGiven;
  left->overlapMm = minimum - 5.0;
  const DeviceConfiguration shallow = c.Configure(g);
  const auto finding = std::find_if(shallow.findings.begin(), shallow.findings.end(),
                                    [](const ConfigurationFinding& f) { return f.constraint == "overlapShort"; });
  ASSERT_NE(finding, shallow.findings.end());
  EXPECT_TRUE(Contains(finding->text, "overlaps " + FormatNumber(minimum - 5.0) + " mm, under")) << finding->text;
  EXPECT_LT(shallow.Find(OrderRole::ContralateralLimb, 1)->holdsBelowMm, 0.0);
  // Deeper than the gate's stub, or so high that it does not reach the gate: errors.
  const double stub = c.recommended.gateEndMm - c.recommended.flowDividerMm;
  left->overlapMm = stub + 1.0;
  try
  {
    c.Configure(g);
    ADD_FAILURE() << "an overlap deeper than the gate was accepted";
  }
  catch (const InputError& e)
  {
    EXPECT_TRUE(Contains(e.what(), "components[")) << e.what();
    EXPECT_TRUE(Contains(e.what(), "deeper than its " + FormatNumber(stub) + " mm")) << e.what();
  }
  left->overlapMm = GivenComponent::NotGiven;
  const ConfiguredComponent* limb = c.recommended.Find(OrderRole::ContralateralLimb, 1);
  // Its distal edge so high that its top lies 1 mm below the gate's end.
  left->distalEdgeAboveInternalIliacMm =
    c.recommended.landingHighMm[1] - (c.recommended.gateEndMm + 1.0 + limb->item.lengthMm);
  EXPECT_THROW(
    {
      try
      {
        c.Configure(g);
      }
      catch (const InputError& e)
      {
        EXPECT_TRUE(Contains(e.what(), "cannot reach it")) << e.what();
        throw;
      }
    },
    InputError);
}

/// The message ResolveGivenConfiguration throws for `g`, "" when it resolves.
std::string ResolveError(const GivenConfiguration& g)
{
  try
  {
    ResolveGivenConfiguration(g, Shipped());
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

TEST(GivenConfiguration, EveryBadEntry_OneErrorNamingItAndWhatTheCatalogueOffers)
{
  const Case c;
  const GivenConfiguration good = [&]
  {
    GivenConfiguration g = GivenFromConfiguration(c.recommended, 0.0);
    g.origin = "plan.json";
    return g;
  }();
  ASSERT_EQ(ResolveError(good), "");
  struct Bad
  {
    const char* what;
    std::function<void(GivenConfiguration&)> edit;
    std::vector<std::string> says;
  };
  const std::vector<Bad> cases = {
    { "unknown family",
      [](GivenConfiguration& g) { g.family = "Endurant III"; },
      { "Configuration 'plan.json', family: 'Endurant III' is not in the device catalogue", "Endurant II" } },
    { "unknown code",
      [](GivenConfiguration& g) { Find(g, ComponentRole::Limb, 1)->code = "ETLW1616C999E"; },
      { "code 'ETLW1616C999E' is not among Endurant II's limbs", "ETLW1616C124E" } },
    { "a cuff's code as a limb",
      [](GivenConfiguration& g) { Find(g, ComponentRole::Limb, 1)->code = "ETTF2828C049E"; },
      { "code 'ETTF2828C049E' is Endurant II's aortic cuff, not a limb" } },
    { "a size the family does not make",
      [](GivenConfiguration& g)
      {
        GivenComponent* l = Find(g, ComponentRole::Limb, 1);
        l->code.clear();
        l->distalDiameterMm = 16.0;
        l->lengthMm = 100.0;
      },
      { "makes no limb of distal 16 mm, length 100 mm", "16–16 × 124 mm (ETLW1616C124E)" } },
    { "a size several share",
      [](GivenConfiguration& g)
      {
        GivenComponent& b = g.components[0];
        b.code.clear();
        b.diameterMm = 25.0;
        b.lengthMm = 124.0;
      },
      { "main bodies are proximal 25 mm, length 124 mm", "expected a code or the other diameter" } },
    { "no main body",
      [](GivenConfiguration& g) { g.components.erase(g.components.begin()); },
      { "no main body; expected one component with role 'mainBody'" } },
    { "two main bodies",
      [](GivenConfiguration& g) { g.components.push_back(g.components[0]); },
      { "a second main body (the first is components[0])" } },
    { "two left limbs",
      [](GivenConfiguration& g) { g.components.push_back(*Find(g, ComponentRole::Limb, 1)); },
      { "a second left limb" } },
    { "an extension with no limb",
      [](GivenConfiguration& g)
      {
        GivenComponent* l = Find(g, ComponentRole::Limb, 1);
        l->role = ComponentRole::IliacExtension;
        l->code = "ETEW1313C082E";
      },
      { "a left iliac extension with no left limb" } },
    { "an overlap of 0",
      [](GivenConfiguration& g) { Find(g, ComponentRole::Limb, 1)->overlapMm = 0.0; },
      { "overlapMm is 0 mm", "cannot reach" } },
    { "two positions",
      [](GivenConfiguration& g) { Find(g, ComponentRole::Limb, 1)->distalEdgeAboveInternalIliacMm = 5; },
      { "both given; expected one position" } },
    { "a side on the main body",
      [](GivenConfiguration& g) { g.components[0].side = 0; },
      { "a main body has no side" } },
    { "a limb without its side",
      [](GivenConfiguration& g) { Find(g, ComponentRole::Limb, 1)->side = -1; },
      { "a limb needs its side" } },
    { "the main body 70 mm down",
      [](GivenConfiguration& g) { g.components[0].proximalEdgeBelowLowestRenalMm = 70; },
      { "proximalEdgeBelowLowestRenalMm is 70.0 mm; expected −30 to 60 mm" } },
    { "the leg alone and a limb on its side",
      [](GivenConfiguration& g) { g.bodyLegLandsAlone = true; },
      { "but bodyLegLandsAlone says the main body's own leg lands" } },
  };
  for (const Bad& bad : cases)
  {
    GivenConfiguration g = good;
    bad.edit(g);
    const std::string message = ResolveError(g);
    EXPECT_NE(message, "") << bad.what;
    EXPECT_EQ(message.find('\n'), std::string::npos) << bad.what << ": one line";
    for (const std::string& part : bad.says)
      EXPECT_TRUE(Contains(message, part)) << bad.what << ": " << message;
  }
  EXPECT_THROW(ParseGivenRole("aorticCuff", "components[1].role"), InputError);
}

} // namespace
} // namespace sgp

namespace sgp
{
namespace
{

/// Endurant II with a 60 mm contralateral gate stub (30 mm of play over the 30 mm minimum overlap)
/// and only the 82 and 199 mm limbs landing at 13 mm: a single limb lands within the length step of
/// the ostium but not always with a margin, where a limb with the 82 mm extension can.
DeviceFamily SparseLimbs()
{
  DeviceFamily f = Family("Endurant II");
  std::vector<CatalogueComponent> kept;
  for (CatalogueComponent c : f.components)
  {
    if (c.role == ComponentRole::MainBody)
    {
      if (c.flowDividerMm + 60.0 >= c.lengthMm)
        continue;
      c.gateEndMm = c.flowDividerMm + 60.0;
    }
    if (c.role == ComponentRole::Limb && c.distalDiameterMm == 13.0 && c.lengthMm != 82.0 && c.lengthMm != 199.0)
      continue;
    kept.push_back(c);
  }
  f.components = kept;
  return f;
}

TEST(ConfigureDevice, NarrowSideWithAWiderWay_TheWayIsNamedWithTheRangeItHolds)
{
  const DeviceFamily family = SparseLimbs();
  int named = 0;
  for (double commonIliac = 20.0; commonIliac <= 110.0; commonIliac += 1.0)
  {
    const DeviceConfiguration c =
      ConfigureDevice(family, Chosen(25.0, 13.0), Anatomy(130.0, commonIliac, commonIliac, 11.0), Right);
    if (!c.configured)
      continue;
    for (int side = 0; side < 2; ++side)
    {
      // The truth by brute force: the side's own narrowest range, and every way of completing it.
      double own = c.deploymentToleranceMm;
      bool hasParts = false;
      for (const ConfiguredComponent& part : c.components)
        if (part.role != OrderRole::MainBody && part.side == side)
        {
          HoldRange h{ part.holdsAboveMm, part.holdsBelowMm, part.holdsAboveLimit, part.holdsBelowLimit };
          own = std::min(own, std::max(0.0, h.Narrowest()));
          hasParts = true;
        }
      const CatalogueComponent& body = c.components.front().item;
      const bool ipsi = side == c.ipsilateralSide;
      double widest = -1.0;
      const SideOption* best = nullptr;
      const std::vector<SideOption> options =
        LimbOptions(family, ipsi ? OrderRole::IpsilateralLimb : OrderRole::ContralateralLimb, side, body.flowDividerMm,
                    ipsi ? body.lengthMm : body.gateEndMm, 13.0, c.landingLowMm[side], c.landingHighMm[side],
                    c.deploymentToleranceMm, true);
      for (const SideOption& o : options)
        if (o.landing == Landing::InWindow && o.margin > widest)
        {
          widest = o.margin;
          best = &o;
        }
      const std::string name = std::string(side == 0 ? "right" : "left") + " side";
      const auto alternative = std::find_if(c.alternatives.begin(), c.alternatives.end(),
                                            [&](const SizeAlternative& a) { return a.component == name; });
      // Named exactly when the side holds under the tolerance and another way holds wider (0.05 mm:
      // the ranges are reported to 0.1 mm).
      const bool wider = hasParts && own < c.deploymentToleranceMm - 0.05 && widest > own + 0.05;
      ASSERT_EQ(alternative != c.alternatives.end(), wider)
        << "common iliac " << commonIliac << ", " << name << ": own " << own << ", widest " << widest;
      if (!wider)
        continue;
      ++named;
      EXPECT_TRUE(Contains(alternative->text, "would hold at least " + FormatNumber(widest) + " mm up and down"))
        << alternative->text;
      for (const ConfiguredComponent& part : best->parts)
        EXPECT_TRUE(Contains(alternative->alternative, part.item.code)) << alternative->alternative;
    }
  }
  EXPECT_GT(named, 0) << "no anatomy of the series has a narrow side a limb with an extension widens";
}

} // namespace
} // namespace sgp
