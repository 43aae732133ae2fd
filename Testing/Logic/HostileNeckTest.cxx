// The hostile-neck rule engine: every bundled rule on both sides of its threshold and at it, the
// four comparisons, not-measured and neck-length-uncertainty verdicts, the aggregate, and one
// message per validation error.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "DeviceCatalogSupport.h"
#include "Device/HostileNeck.h"
#include "IO/ReadNeckRules.h"
#include "Measurement/MeasureAnatomy.h"

namespace sgp
{
namespace
{

using testing::ExpectInputError;

/// The bundled rule table as the report documents it (Resources/hostile-neck-rules.json); an edit
/// of the file must be an edit of this table too.
struct ExpectedRule
{
  std::string id;
  std::string quantity;
  HostileWhen hostileWhen;
  double threshold;
  std::string unit;
  std::string requirement; ///< the not-hostile side, as the check writes it
};

const std::vector<ExpectedRule>& BundledTable()
{
  static const std::vector<ExpectedRule> table = {
    { "short-neck", "neckLength", HostileWhen::Below, 15, "mm", "≥ 15 mm" },
    { "wide-neck", "neckDiameter", HostileWhen::Above, 28, "mm", "≤ 28 mm" },
    { "angulated-neck-beta", "neckAngleBeta", HostileWhen::Above, 60, "deg", "≤ 60°" },
    { "angulated-neck-alpha", "neckAngleAlpha", HostileWhen::Above, 60, "deg", "≤ 60°" },
    { "neck-thrombus", "neckThrombusArc", HostileWhen::AtOrAbove, 50, "%", "< 50 %" },
    { "neck-calcification", "neckCalcificationArc", HostileWhen::AtOrAbove, 50, "%", "< 50 %" },
    { "reverse-taper-10mm", "reverseTaper10mm", HostileWhen::Above, 2, "mm", "≤ 2 mm" },
    { "reverse-taper-15mm", "reverseTaper15mm", HostileWhen::AtOrAbove, 2, "mm", "< 2 mm" },
  };
  return table;
}

NeckRuleSet Bundled()
{
  return ReadNeckRules(SGP_NECK_RULES_JSON);
}

/// The field of `a` that holds `quantity`.
double& Field(NeckAnatomy& a, const std::string& quantity)
{
  if (quantity == "neckLength")
    return a.neckLengthMm;
  if (quantity == "neckDiameter")
    return a.neckDiameterMm;
  if (quantity == "neckAngleBeta")
    return a.neckAngleBetaDeg;
  if (quantity == "neckAngleAlpha")
    return a.neckAngleAlphaDeg;
  if (quantity == "neckThrombusArc")
    return a.neckThrombusArcPercent;
  if (quantity == "neckCalcificationArc")
    return a.neckCalcificationArcPercent;
  if (quantity == "reverseTaper10mm")
    return a.reverseTaper10mmMm;
  EXPECT_EQ(quantity, "reverseTaper15mm");
  return a.reverseTaper15mmMm;
}

/// A favourable neck, well inside every bundled rule: 25 mm long, 22 mm wide, β 20°, α 20°,
/// 10 % thrombus and calcium, 0.5 mm widening over 10 and 15 mm.
NeckAnatomy FavourableNeck()
{
  NeckAnatomy a;
  a.neckLengthMm = 25;
  a.neckDiameterMm = 22;
  a.neckAngleBetaDeg = 20;
  a.neckAngleAlphaDeg = 20;
  a.neckThrombusArcPercent = 10;
  a.neckCalcificationArcPercent = 10;
  a.reverseTaper10mmMm = 0.5;
  a.reverseTaper15mmMm = 0.5;
  return a;
}

bool HostileAbove(HostileWhen when)
{
  return when == HostileWhen::Above || when == HostileWhen::AtOrAbove;
}

const std::string BundledName = "StentGraftPlanner default hostile-neck rules";

TEST(HostileNeck, BundledRules_AreTheDocumentedTableWithSources)
{
  const NeckRuleSet set = Bundled();
  EXPECT_EQ(set.name, BundledName);
  const std::vector<ExpectedRule>& table = BundledTable();
  ASSERT_EQ(set.rules.size(), table.size());
  for (size_t i = 0; i < table.size(); ++i)
  {
    SCOPED_TRACE(table[i].id);
    const NeckRule& r = set.rules[i];
    EXPECT_EQ(r.id, table[i].id);
    EXPECT_EQ(r.quantity, table[i].quantity);
    EXPECT_EQ(r.hostileWhen, table[i].hostileWhen);
    EXPECT_EQ(r.threshold, table[i].threshold); // copied from the file, so compared exactly
    EXPECT_EQ(r.unit, table[i].unit);
    EXPECT_FALSE(r.description.empty());
    // Each source opens with its evidence mark; α and calcification are background knowledge.
    const std::string mark = r.source.substr(0, 3);
    EXPECT_TRUE(mark == "[S]" || mark == "[K]") << r.source;
    if (r.id == "angulated-neck-alpha" || r.id == "neck-calcification")
    {
      EXPECT_EQ(mark, "[K]");
    }
  }
  // One rule per quantity the engine knows.
  ASSERT_EQ(NeckQuantities().size(), table.size());
  for (size_t i = 0; i < table.size(); ++i)
    EXPECT_EQ(table[i].quantity, NeckQuantities()[i].name);
}

TEST(HostileNeck, FavourableNeck_PassesEveryBundledRule)
{
  const NeckAssessment a = AssessNeck(FavourableNeck(), Bundled());
  ASSERT_EQ(a.checks.size(), 8u);
  for (const CriterionCheck& c : a.checks)
  {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(c.status, CheckStatus::Pass) << c.text;
    EXPECT_GT(c.margin, 0.0);
  }
  EXPECT_FALSE(a.hostile);
  EXPECT_TRUE(a.determinate);
  EXPECT_EQ(a.summary, "not hostile: passes all 8 rules of '" + BundledName + "'");
}

TEST(HostileNeck, EachBundledRule_BothSidesAndAtItsThreshold)
{
  const NeckRuleSet set = Bundled();
  // 0.1 in the rule's unit: far above rounding, below any decision a clinician would argue about.
  const double step = 0.1;
  // t ± 0.1 is not exact in binary; the margin is then off by a few ulps of t.
  const double marginTolerance = 1e-12;
  for (size_t i = 0; i < set.rules.size(); ++i)
  {
    const ExpectedRule& rule = BundledTable()[i];
    SCOPED_TRACE(rule.id);
    const double towardsSafe = HostileAbove(rule.hostileWhen) ? -step : step;
    const bool thresholdHostile =
      rule.hostileWhen == HostileWhen::AtOrAbove || rule.hostileWhen == HostileWhen::AtOrBelow;
    struct Case
    {
      double value;
      CheckStatus status;
      double margin;
    };
    const Case cases[] = {
      { rule.threshold + towardsSafe, CheckStatus::Pass, step },  // just inside: not hostile
      { rule.threshold - towardsSafe, CheckStatus::Fail, -step }, // just outside: hostile
      { rule.threshold, thresholdHostile ? CheckStatus::Fail : CheckStatus::Pass, 0.0 },
    };
    for (const Case& c : cases)
    {
      SCOPED_TRACE(c.value);
      NeckAnatomy anatomy = FavourableNeck();
      Field(anatomy, rule.quantity) = c.value;
      const NeckAssessment a = AssessNeck(anatomy, set);
      const CriterionCheck& check = a.checks[i];
      EXPECT_EQ(check.name, rule.id);
      EXPECT_EQ(check.status, c.status) << check.text;
      EXPECT_NEAR(check.margin, c.margin, marginTolerance);
      EXPECT_EQ(check.value, c.value);
      EXPECT_EQ(check.requirement, rule.requirement);
      EXPECT_NE(check.text.find("needs " + rule.requirement), std::string::npos) << check.text;
      EXPECT_EQ(check.evidence, set.rules[i].source);
      EXPECT_EQ(a.Count(CheckStatus::Pass), c.status == CheckStatus::Pass ? 8 : 7); // the others stay favourable
      EXPECT_EQ(a.hostile, c.status == CheckStatus::Fail);
      EXPECT_TRUE(a.determinate);
      if (c.status == CheckStatus::Fail)
      {
        EXPECT_EQ(a.summary, "hostile neck: fails " + rule.id + " (1 of 8 rules of '" + BundledName + "')");
        EXPECT_EQ(check.text.find("the threshold itself is hostile") != std::string::npos, c.margin == 0.0)
          << check.text;
      }
    }
  }
}

TEST(HostileNeck, BundledTexts_ReadInWords)
{
  NeckAnatomy anatomy = FavourableNeck();
  anatomy.neckLengthMm = 12;
  anatomy.neckThrombusArcPercent = 50;
  anatomy.neckAngleBetaDeg = 50;
  const NeckAssessment a = AssessNeck(anatomy, Bundled());
  EXPECT_EQ(a.checks[0].text, "neck length 12.0 mm, needs ≥ 15 mm: −3.0 mm");
  EXPECT_EQ(a.checks[2].text, "neck angle β 50.0°, needs ≤ 60°: +10.0°");
  EXPECT_EQ(a.checks[4].text, "neck thrombus arc 50.0 %, needs < 50 %: +0.0 % (the threshold itself is hostile)");
  EXPECT_EQ(a.summary, "hostile neck: fails short-neck, neck-thrombus (2 of 8 rules of '" + BundledName + "')");
}

TEST(HostileNeck, FourComparisons_ThresholdHostileOnlyForTheAtForms)
{
  // The taper admits a negative threshold, so the four forms are tested on −1 mm.
  NeckRuleSet set;
  set.name = "four";
  set.origin = "memory";
  for (HostileWhen when : { HostileWhen::Below, HostileWhen::AtOrBelow, HostileWhen::Above, HostileWhen::AtOrAbove })
    set.rules.push_back({ ToString(when), "reverseTaper10mm", when, -1.0, "mm", "", "test" });
  struct Case
  {
    double value;
    std::vector<CheckStatus> status; ///< below, atOrBelow, above, atOrAbove
    double marginBelowForms;         ///< value − threshold; the above forms have its negative
  };
  const CheckStatus P = CheckStatus::Pass;
  const CheckStatus F = CheckStatus::Fail;
  const Case cases[] = { { -1.5, { F, F, P, P }, -0.5 }, { -1.0, { P, F, P, F }, 0.0 }, { -0.5, { P, P, F, F }, 0.5 } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.value);
    NeckAnatomy anatomy;
    anatomy.reverseTaper10mmMm = c.value;
    const NeckAssessment a = AssessNeck(anatomy, set);
    for (size_t i = 0; i < 4; ++i)
    {
      SCOPED_TRACE(set.rules[i].id);
      EXPECT_EQ(a.checks[i].status, c.status[i]) << a.checks[i].text;
      // Halves and integers are exact in binary: the margin is exact.
      EXPECT_EQ(a.checks[i].margin, i < 2 ? c.marginBelowForms : -c.marginBelowForms);
    }
  }
  EXPECT_EQ(AssessNeck(NeckAnatomy{}, set).checks[1].requirement, "> -1 mm");
  EXPECT_EQ(AssessNeck(NeckAnatomy{}, set).checks[3].requirement, "< -1 mm");
}

TEST(HostileNeck, NotMeasured_IndeterminateWithNaNMargin)
{
  const NeckAssessment a = AssessNeck(NeckAnatomy{}, Bundled());
  ASSERT_EQ(a.checks.size(), 8u);
  for (const CriterionCheck& c : a.checks)
  {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(c.status, CheckStatus::Indeterminate);
    EXPECT_TRUE(std::isnan(c.margin));
    EXPECT_NE(c.text.find("not measured"), std::string::npos) << c.text;
  }
  EXPECT_EQ(a.checks[1].text, "neck diameter (a) not measured, needs ≤ 28 mm: indeterminate");
  EXPECT_FALSE(a.hostile);
  EXPECT_FALSE(a.determinate);
  EXPECT_EQ(a.summary, "undetermined: no rule fails, 0 of 8 rules of '" + BundledName +
                         "' pass; indeterminate: short-neck, wide-neck, angulated-neck-beta, angulated-neck-alpha, "
                         "neck-thrombus, neck-calcification, reverse-taper-10mm, reverse-taper-15mm");
}

TEST(HostileNeck, NeckLengthWithinItsUncertainty_IndeterminateKeepingTheMargin)
{
  const NeckRuleSet set = Bundled(); // short-neck: hostile below 15 mm
  const double u = NeckLengthUncertaintyMm;
  ASSERT_EQ(u, 2.0); // the cases below are placed around ±2 mm
  struct Case
  {
    double lengthMm;
    CheckStatus status;
    double margin;
  };
  // Lengths and margins are exact in binary; a margin of exactly ±u is inside (as SelectDevice).
  const Case cases[] = { { 12.5, CheckStatus::Fail, -2.5 },          { 13.0, CheckStatus::Indeterminate, -2.0 },
                         { 13.5, CheckStatus::Indeterminate, -1.5 }, { 15.0, CheckStatus::Indeterminate, 0.0 },
                         { 17.0, CheckStatus::Indeterminate, 2.0 },  { 17.5, CheckStatus::Pass, 2.5 } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.lengthMm);
    NeckAnatomy anatomy = FavourableNeck();
    anatomy.neckLengthMm = c.lengthMm;
    anatomy.neckLengthUncertaintyMm = u;
    const NeckAssessment a = AssessNeck(anatomy, set);
    EXPECT_EQ(a.checks[0].status, c.status) << a.checks[0].text;
    EXPECT_EQ(a.checks[0].margin, c.margin);
    EXPECT_EQ(a.determinate, c.status != CheckStatus::Indeterminate);
    EXPECT_EQ(a.hostile, c.status == CheckStatus::Fail);
    if (c.status == CheckStatus::Indeterminate)
    {
      EXPECT_NE(a.checks[0].text.find("within the measurement's uncertainty (±2.0 mm): indeterminate"),
                std::string::npos)
        << a.checks[0].text;
      EXPECT_EQ(a.summary,
                "undetermined: no rule fails, 7 of 8 rules of '" + BundledName + "' pass; indeterminate: short-neck");
    }
  }
  // The uncertainty is the neck length's only: β 0.5° over its limit still fails.
  NeckAnatomy anatomy = FavourableNeck();
  anatomy.neckLengthUncertaintyMm = u;
  anatomy.neckAngleBetaDeg = 60.5;
  EXPECT_EQ(AssessNeck(anatomy, set).checks[2].status, CheckStatus::Fail);
}

TEST(HostileNeck, HostileAndIndeterminate_BothInTheSummary)
{
  NeckAnatomy anatomy = FavourableNeck();
  anatomy.neckDiameterMm = 30;
  anatomy.reverseTaper15mmMm = 3;
  anatomy.neckCalcificationArcPercent = NeckAnatomy::NotMeasured;
  const NeckAssessment a = AssessNeck(anatomy, Bundled());
  EXPECT_TRUE(a.hostile);
  EXPECT_FALSE(a.determinate);
  EXPECT_EQ(a.Count(CheckStatus::Fail), 2);
  EXPECT_EQ(a.Count(CheckStatus::Indeterminate), 1);
  EXPECT_EQ(a.checks[1].margin, -2.0); // 28 − 30, exact
  EXPECT_EQ(a.checks[7].margin, -1.0); // 2 − 3, exact
  EXPECT_EQ(a.summary, "hostile neck: fails wide-neck, reverse-taper-15mm (2 of 8 rules of '" + BundledName +
                         "'); indeterminate: neck-calcification");
}

TEST(HostileNeck, NamelessSet_SummaryNamesItsOrigin)
{
  NeckRuleSet set = Bundled();
  set.name.clear();
  EXPECT_EQ(AssessNeck(FavourableNeck(), set).summary,
            std::string("not hostile: passes all 8 rules of '") + SGP_NECK_RULES_JSON + "'");
}

/// A valid two-rule set named "memory.json", for planting defects.
NeckRuleSet SmallSet()
{
  NeckRuleSet set;
  set.name = "small";
  set.origin = "memory.json";
  set.rules = { { "short-neck", "neckLength", HostileWhen::Below, 15, "mm", "", "[S] test" },
                { "angle", "neckAngleBeta", HostileWhen::Above, 60, "deg", "", "[S] test" } };
  return set;
}

TEST(HostileNeck, RuleSetDefects_EachNamesFileRuleFieldAndValue)
{
  const auto expectError = [](const NeckRuleSet& set, const std::vector<std::string>& parts)
  { ExpectInputError([&] { ValidateNeckRuleSet(set, "rules.json"); }, parts); };
  NeckRuleSet set = SmallSet();
  set.rules.clear();
  expectError(set, { "Hostile-neck rules 'rules.json', field 'rules': is empty", "expected at least one rule" });
  set = SmallSet();
  set.rules[1].id = " ";
  expectError(set, { "'rules.json', rules[1], field 'id': is empty", "a short unique name" });
  set = SmallSet();
  set.rules[1].id = "SHORT-NECK";
  expectError(set, { "'rules.json', rules[1] \"SHORT-NECK\", field 'id': repeats rules[0]", "case-insensitive" });
  set = SmallSet();
  set.rules[1].quantity = "neckWidth";
  expectError(set, { "rules[1] \"angle\", field 'quantity': is \"neckWidth\"",
                     "expected one of neckLength, neckDiameter, neckAngleBeta, neckAngleAlpha, neckThrombusArc, "
                     "neckCalcificationArc, reverseTaper10mm, reverseTaper15mm" });
  set = SmallSet();
  set.rules[1].unit = "mm";
  expectError(set, { "rules[1] \"angle\", field 'unit': is \"mm\"", "expected \"deg\", the unit of neckAngleBeta" });
  set = SmallSet();
  set.rules[0].threshold = std::nan("");
  expectError(set, { "rules[0] \"short-neck\", field 'threshold': is NaN", "a number of mm ≥ 0 for neckLength" });
  set = SmallSet();
  set.rules[0].threshold = -5;
  expectError(set, { "field 'threshold': is -5 mm", "a number of mm ≥ 0 for neckLength" });
  set = SmallSet();
  set.rules[1].threshold = 200;
  expectError(set, { "field 'threshold': is 200 deg", "a number of deg in 0–180 for neckAngleBeta" });
  set = SmallSet();
  set.rules[1] = { "wide", "neckDiameter", HostileWhen::Above, 0, "mm", "", "[S] test" };
  expectError(set, { "rules[1] \"wide\", field 'threshold': is 0 mm", "a number of mm > 0 for neckDiameter" });
  set = SmallSet();
  set.rules[1] = { "taper", "reverseTaper15mm", HostileWhen::AtOrAbove, INFINITY, "mm", "", "[S] test" };
  expectError(set, { "rules[1] \"taper\", field 'threshold': is infinite", "a finite number of mm" });
  set = SmallSet();
  set.rules[0].source = "";
  expectError(set, { "rules[0] \"short-neck\", field 'source': is empty", "the publication" });
  // AssessNeck validates the set under its own origin.
  set = SmallSet();
  set.rules[0].unit = "cm";
  ExpectInputError([&] { AssessNeck(FavourableNeck(), set); }, { "'memory.json', rules[0] \"short-neck\"", "'unit'" });
}

TEST(HostileNeck, AnatomyOutOfRange_NamesQuantityAndValue)
{
  const auto expectError = [](double NeckAnatomy::*field, double value, const std::vector<std::string>& parts)
  {
    NeckAnatomy anatomy = FavourableNeck();
    anatomy.*field = value;
    ExpectInputError([&] { AssessNeck(anatomy, SmallSet()); }, parts);
  };
  expectError(&NeckAnatomy::neckLengthMm, -1, { "Neck anatomy: neckLength is -1 mm", "a number of mm ≥ 0" });
  expectError(&NeckAnatomy::neckDiameterMm, 0, { "neckDiameter is 0 mm", "a number of mm > 0" });
  expectError(&NeckAnatomy::neckAngleAlphaDeg, 181, { "neckAngleAlpha is 181 deg", "in 0–180" });
  expectError(&NeckAnatomy::neckThrombusArcPercent, 150, { "neckThrombusArc is 150 %", "in 0–100" });
  expectError(&NeckAnatomy::reverseTaper15mmMm, INFINITY, { "reverseTaper15mm is infinite", "a finite number of mm" });
  expectError(&NeckAnatomy::neckLengthUncertaintyMm, -1, { "neckLengthUncertaintyMm is -1 mm", "≥ 0" });
}

TEST(HostileNeck, HostileWhenSpelling_RoundTripsAndRejectsOthers)
{
  for (HostileWhen when : { HostileWhen::Below, HostileWhen::AtOrBelow, HostileWhen::Above, HostileWhen::AtOrAbove })
    EXPECT_EQ(HostileWhenFromString(ToString(when)), when);
  EXPECT_FALSE(HostileWhenFromString("Above").has_value()); // case-sensitive, as every field name
  EXPECT_FALSE(HostileWhenFromString(">=").has_value());
}

} // namespace
} // namespace sgp
