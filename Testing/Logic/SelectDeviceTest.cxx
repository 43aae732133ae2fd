// Device selection: oversizing choice, IFU checks with margins, indeterminate checks, the
// recommendation and the forced device.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Device/SelectDevice.h"
#include "DeviceCatalogSupport.h"
#include "IO/ReadDeviceCatalog.h"

namespace sgp
{
namespace
{

using testing::ExpectInputError;
using testing::MakeGoodAnatomy;
using testing::MakeTestCatalog;

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
// Margins here are differences of numbers exact in binary (9 − 10, 70 − 75, …): only the
// subtraction's rounding separates them from the hand-computed value.
constexpr double ExactMm = 1e-12;

const FamilyEvaluation& Family(const DeviceSelection& s, const std::string& name)
{
  for (const FamilyEvaluation& e : s.families)
    if (e.family == name)
      return e;
  throw std::runtime_error("no family " + name);
}

const CriterionCheck& Check(const FamilyEvaluation& e, const std::string& name)
{
  for (const CriterionCheck& c : e.checks)
    if (c.name == name)
      return c;
  throw std::runtime_error("no check " + name + " for " + e.family);
}

TEST(SelectDevice, Neck22mm_Endurant25At13Point6Percent)
{
  const DeviceCatalog shipped = ReadDeviceCatalog(SGP_DEVICES_JSON);
  SizingAnatomy a;
  a.proximalNeckDiameterMm = 22.0;
  const DeviceSelection s = SelectDevice(a, shipped);
  const FamilyEvaluation& endurant = Family(s, "Endurant II");
  EXPECT_EQ(endurant.mainBody.diameterMm, 25.0); // a catalogue value, copied, not computed
  // 25 / 22 − 1 = 13.636…%; 1e-9 % is far below any rounding that could matter here.
  EXPECT_NEAR(endurant.mainBody.oversizingPercent, 300.0 / 22.0, 1e-9);
  EXPECT_EQ(Check(endurant, "main body oversizing").status, CheckStatus::Pass);
  EXPECT_EQ(Check(endurant, "main body oversizing").text, "main body oversizing (25 mm) 13.6 %, needs 10–20 %: +3.6 %");

  // Two sizes inside the range: Zenith Flex 30 mm gives 11.1 % (3.9 from 15 %), 32 mm 18.5 % (3.5).
  a.proximalNeckDiameterMm = 27.0;
  EXPECT_EQ(Family(SelectDevice(a, shipped), "Zenith Flex").mainBody.diameterMm, 32.0);
}

TEST(SelectDevice, HandComputedNecks_NearestFifteenPercentWithinRange)
{
  const DeviceCatalog catalog = MakeTestCatalog();
  struct Case
  {
    double neckMm;
    const char* family;
    double expectedMm; // NaN: no size gives 10–20 %
  };
  // TenMm bodies 23, 25, 28, 32, 36; FifteenMm 23, 26, 28.5, 31, 35 (oversizing in brackets).
  const Case cases[] = {
    { 22.0, "TenMm", 25.0 },     // 23 (4.5), 25 (13.6), 28 (27.3)
    { 26.0, "TenMm", NaN },      // 28 (7.7), 32 (23.1): neither inside 10–20
    { 28.0, "TenMm", 32.0 },     // 32 (14.3), 36 (28.6)
    { 28.0, "FifteenMm", 31.0 }, // 31 (10.7), 35 (25.0)
    { 20.0, "FifteenMm", 23.0 }, // 23 (15.0) exactly on target
    { 24.0, "FifteenMm", 28.5 }, // 26 (8.3), 28.5 (18.75)
    { 30.0, "TenMm", 36.0 },     // 32 (6.7), 36 (20.0) on the inclusive upper limit
  };
  for (const Case& c : cases)
  {
    SizingAnatomy a;
    a.proximalNeckDiameterMm = c.neckMm;
    const DeviceSelection s = SelectDevice(a, catalog);
    const FamilyEvaluation& e = Family(s, c.family);
    SCOPED_TRACE(std::string(c.family) + " neck " + std::to_string(c.neckMm));
    if (std::isnan(c.expectedMm))
    {
      EXPECT_FALSE(e.mainBody.Chosen());
      EXPECT_NE(e.mainBody.reason.find("10–20 %"), std::string::npos) << e.mainBody.reason;
      EXPECT_EQ(Check(e, "main body oversizing").status, CheckStatus::Fail);
    }
    else
    {
      EXPECT_EQ(e.mainBody.diameterMm, c.expectedMm);
      EXPECT_EQ(Check(e, "main body oversizing").status, CheckStatus::Pass); // limits inclusive
    }
  }
}

TEST(SelectDevice, NoSizeFits_FailsNamingNearestSizeWithNegativeMargin)
{
  SizingAnatomy a;
  a.proximalNeckDiameterMm = 26.0; // TenMm: 28 mm gives 7.7 %, 32 mm gives 23.1 %
  const CriterionCheck c = Check(Family(SelectDevice(a, MakeTestCatalog()), "TenMm"), "main body oversizing");
  EXPECT_EQ(c.status, CheckStatus::Fail);
  EXPECT_NEAR(c.value, 200.0 / 26.0, 1e-9);         // 28 / 26 − 1, the nearest size; rounding only
  EXPECT_NEAR(c.margin, 200.0 / 26.0 - 10.0, 1e-9); // 2.3 % short of 10 %; rounding only
  EXPECT_NE(c.text.find("nearest 28 mm"), std::string::npos) << c.text;
}

TEST(SelectDevice, SeveralSizesInside_NearestTargetTieToSmaller)
{
  // 22, 23, 24 mm on a 20 mm vessel give 10, 15 and 20 %: the middle one is on target.
  EXPECT_EQ(ChooseDeviceSize({ { 22, 18 }, { 23, 18 }, { 24, 18 } }, 20.0, 10.0, 20.0).diameterMm, 23.0);
  // 22 / 20 and 24 / 20 give 10 % and 20 %, both 5 % from the 15 % target.
  const SizeChoice c = ChooseDeviceSize({ { 22, 18 }, { 24, 18 } }, 20.0, 10.0, 20.0);
  EXPECT_EQ(c.diameterMm, 22.0);
}

TEST(SelectDevice, OversizingOnTheLimitUpToRounding_ChosenAndPasses)
{
  // 10.8 / 9 − 1 is 20 % exactly, but computes as 20.000000000000018 %; a 10–20 % limb window.
  DeviceCatalog catalog = MakeTestCatalog();
  catalog.families[0].limbs.sizes = { { 10.8, 16 }, { 28, 16 } };
  SizingAnatomy a = MakeGoodAnatomy();
  a.rightIliacDiameterMm = 9.0;
  DeviceSelectionParams p;
  p.limbOversizingMaxPercent = 20.0;
  const DeviceSelection s = SelectDevice(a, catalog, p);
  const FamilyEvaluation& e = Family(s, "TenMm");
  EXPECT_EQ(e.rightLimb.diameterMm, 10.8);
  EXPECT_EQ(Check(e, "right limb oversizing").status, CheckStatus::Pass);
  EXPECT_EQ(Check(e, "right limb oversizing").margin, 0.0); // set to the limit, not left at −1.8e-14
}

TEST(SelectDevice, ShippedCatalogue_MatchesBruteForceOverEveryNeck)
{
  const DeviceCatalog shipped = ReadDeviceCatalog(SGP_DEVICES_JSON);
  int chosen = 0;
  for (int tenths = 160; tenths <= 340; ++tenths) // necks 16.0 … 34.0 mm in 0.1 mm steps
  {
    SizingAnatomy a;
    a.proximalNeckDiameterMm = tenths / 10.0;
    const DeviceSelection s = SelectDevice(a, shipped);
    ASSERT_EQ(s.families.size(), shipped.families.size());
    for (size_t f = 0; f < shipped.families.size(); ++f)
    {
      // The oracle: every size inside 10–20 % (1e-9 % for the inclusive limits' rounding),
      // ordered by distance to 15 % and then by diameter; the first one.
      std::vector<std::pair<double, double>> inside; // (distance to 15 %, diameter)
      for (const DeviceSize& size : shipped.families[f].mainBodies.sizes)
      {
        const double o = 100.0 * (size.diameterMm - a.proximalNeckDiameterMm) / a.proximalNeckDiameterMm;
        if (o >= 10.0 - 1e-9 && o <= 20.0 + 1e-9)
          inside.emplace_back(std::round(std::abs(o - 15.0) * 1e6) / 1e6, size.diameterMm); // ties to 1e-6 %
      }
      std::sort(inside.begin(), inside.end());
      const SizeChoice& got = s.families[f].mainBody;
      SCOPED_TRACE(shipped.families[f].name + " neck " + std::to_string(a.proximalNeckDiameterMm));
      if (inside.empty())
        EXPECT_FALSE(got.Chosen());
      else
      {
        EXPECT_EQ(got.diameterMm, inside.front().second);
        ++chosen;
      }
    }
  }
  EXPECT_GT(chosen, 400); // the sweep mostly finds sizes (4 families × 181 necks); it is not vacuous
}

TEST(SelectDevice, NineMmNeck_FailsNeckLengthByOneAndSixMm)
{
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthMm = 9.0;
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
  const CriterionCheck& ten = Check(Family(s, "TenMm"), "neck length");
  const CriterionCheck& fifteen = Check(Family(s, "FifteenMm"), "neck length");
  EXPECT_EQ(ten.status, CheckStatus::Fail);
  EXPECT_NEAR(ten.margin, -1.0, ExactMm);
  EXPECT_EQ(ten.text, "neck length 9.0 mm, needs ≥ 10 mm (β ≤ 60°): −1.0 mm");
  EXPECT_EQ(fifteen.status, CheckStatus::Fail);
  EXPECT_NEAR(fifteen.margin, -6.0, ExactMm);
  EXPECT_EQ(fifteen.text, "neck length 9.0 mm, needs ≥ 15 mm: −6.0 mm");
  EXPECT_EQ(s.recommended, -1);
  EXPECT_EQ(s.summary, "no device within IFU");
  // Every failing check of every family is a reason, and nothing else.
  EXPECT_EQ(s.reasons.size(), 2u);
  EXPECT_NE(std::find(s.reasons.begin(), s.reasons.end(), "FifteenMm: " + fifteen.text), s.reasons.end());
}

TEST(SelectDevice, NeckLengthWithinItsUncertainty_IndeterminateOnBothSidesOfTheLimit)
{
  // TenMm needs ≥ 10 mm (β 30° ≤ 60°); with a ±2 mm measurement the band 8–12 mm cannot be decided.
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthUncertaintyMm = 2.0;
  const std::map<double, CheckStatus> expected = {
    { 7.9, CheckStatus::Fail },           // 2.1 mm short: short whatever the error
    { 8.1, CheckStatus::Indeterminate },  // 1.9 mm short: might be long enough
    { 10.0, CheckStatus::Indeterminate }, // on the limit
    { 11.9, CheckStatus::Indeterminate }, // 1.9 mm over: might be short
    { 12.1, CheckStatus::Pass },          // 2.1 mm over: long enough whatever the error
  };
  for (const auto& [lengthMm, status] : expected)
  {
    a.proximalNeckLengthMm = lengthMm;
    const CriterionCheck c = Check(Family(SelectDevice(a, MakeTestCatalog()), "TenMm"), "neck length");
    EXPECT_EQ(c.status, status) << c.text;
    EXPECT_NEAR(c.margin, lengthMm - 10.0, ExactMm) << c.text; // the margin is kept either way
  }
  a.proximalNeckLengthMm = 11.0;
  EXPECT_EQ(Check(Family(SelectDevice(a, MakeTestCatalog()), "TenMm"), "neck length").text,
            "neck length 11.0 mm, needs ≥ 10 mm (β ≤ 60°): +1.0 mm, within the measurement's uncertainty "
            "(±2.0 mm): indeterminate");
  // An exact input (uncertainty 0, the default) decides at the limit itself.
  a.proximalNeckLengthUncertaintyMm = 0.0;
  EXPECT_EQ(Check(Family(SelectDevice(a, MakeTestCatalog()), "TenMm"), "neck length").status, CheckStatus::Pass);
}

TEST(SelectDevice, ShippedCatalogue_NineMmNeckMarginsPerFamily)
{
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthMm = 9.0;
  const DeviceSelection s = SelectDevice(a, ReadDeviceCatalog(SGP_DEVICES_JSON));
  EXPECT_NEAR(Check(Family(s, "Endurant II"), "neck length").margin, -1.0, ExactMm);   // ≥ 10 mm at β 30°
  EXPECT_NEAR(Check(Family(s, "Excluder (C3)"), "neck length").margin, -6.0, ExactMm); // ≥ 15 mm
  EXPECT_NEAR(Check(Family(s, "Zenith Flex"), "neck length").margin, -6.0, ExactMm);   // ≥ 15 mm
}

TEST(SelectDevice, AngleDependentNeckLength_UsesTheTierAdmittingBeta)
{
  const DeviceCatalog catalog = MakeTestCatalog();
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthMm = 12.0;
  a.neckAngleBetaDeg = 70.0; // beyond 60°: TenMm then needs 15 mm
  const FamilyEvaluation ten = Family(SelectDevice(a, catalog), "TenMm");
  EXPECT_EQ(Check(ten, "neck length").status, CheckStatus::Fail);
  EXPECT_NEAR(Check(ten, "neck length").margin, -3.0, ExactMm);
  EXPECT_EQ(Check(ten, "neck length").text, "neck length 12.0 mm, needs ≥ 15 mm (β ≤ 75°): −3.0 mm");
  EXPECT_EQ(Check(ten, "neck angle β").status, CheckStatus::Pass);
  EXPECT_NEAR(Check(ten, "neck angle β").margin, 5.0, ExactMm);

  a.neckAngleBetaDeg = 80.0; // beyond every tier: the angle fails, the length is held to the last tier
  const FamilyEvaluation steep = Family(SelectDevice(a, catalog), "TenMm");
  EXPECT_EQ(Check(steep, "neck angle β").status, CheckStatus::Fail);
  EXPECT_NEAR(Check(steep, "neck angle β").margin, -5.0, ExactMm);
  EXPECT_EQ(Check(steep, "neck angle β").text, "neck angle β 80.0°, needs ≤ 75°: −5.0°");
}

TEST(SelectDevice, BetaNotMeasured_NeckLengthDecidedOnlyOutsideTheTiers)
{
  const DeviceCatalog catalog = MakeTestCatalog();
  SizingAnatomy a = MakeGoodAnatomy();
  a.neckAngleBetaDeg = NaN;
  const std::map<double, CheckStatus> expected = {
    { 9.0, CheckStatus::Fail },           // below 10 mm: fails whatever β is
    { 12.0, CheckStatus::Indeterminate }, // enough for β ≤ 60°, not for β ≤ 75°
    { 15.0, CheckStatus::Pass },          // enough for every tier
  };
  for (const auto& [lengthMm, status] : expected)
  {
    a.proximalNeckLengthMm = lengthMm;
    const FamilyEvaluation ten = Family(SelectDevice(a, catalog), "TenMm");
    EXPECT_EQ(Check(ten, "neck length").status, status) << Check(ten, "neck length").text;
    EXPECT_EQ(Check(ten, "neck angle β").status, CheckStatus::Indeterminate);
  }
  a.proximalNeckLengthMm = 12.0;
  EXPECT_EQ(Check(Family(SelectDevice(a, catalog), "TenMm"), "neck length").text,
            "neck length 12.0 mm, needs ≥ 10 mm if β ≤ 60°, ≥ 15 mm if β ≤ 75°; β not measured: indeterminate");
}

TEST(SelectDevice, GoodAnatomy_EveryCheckPassesAndNearestTargetRecommended)
{
  const DeviceSelection s = SelectDevice(MakeGoodAnatomy(), MakeTestCatalog());
  for (const FamilyEvaluation& e : s.families)
    for (const CriterionCheck& c : e.checks)
    {
      EXPECT_EQ(c.status, CheckStatus::Pass) << e.family << ": " << c.text;
      EXPECT_GE(c.margin, 0.0) << c.text;
    }
  EXPECT_EQ(Family(s, "FifteenMm").checks.size(), Family(s, "TenMm").checks.size() + 2); // α, flow divider
  // TenMm 25 mm at 13.6 % is nearer 15 % than FifteenMm 26 mm at 18.2 %.
  ASSERT_EQ(s.recommended, 0);
  EXPECT_TRUE(s.recommendedWithinIfu);
  EXPECT_TRUE(s.recommendedFullyChecked);
  EXPECT_TRUE(s.reasons.empty());
  EXPECT_EQ(s.summary, "TenMm: main body 25 mm (13.6 %), right limb 16 mm (14.3 %), left limb 16 mm (14.3 %); "
                       "within IFU");
  EXPECT_EQ(Family(s, "TenMm").mainBodyAccessSide, "right"); // 8 mm right, 7 mm left
  EXPECT_EQ(Check(Family(s, "TenMm"), "main-body access").text,
            "main-body access (right) 8.0 mm, needs ≥ 6 mm (18 Fr): +2.0 mm");
}

TEST(SelectDevice, EachMeasurementNaN_ItsChecksIndeterminateOthersPass)
{
  using Field = double SizingAnatomy::*;
  const std::vector<std::pair<Field, std::vector<std::string>>> cases = {
    { &SizingAnatomy::proximalNeckDiameterMm, { "main body oversizing", "neck diameter" } },
    { &SizingAnatomy::neckDiameter15mmMm, { "neck diameter 15 mm below" } },
    { &SizingAnatomy::proximalNeckLengthMm, { "neck length" } },
    { &SizingAnatomy::neckAngleBetaDeg, { "neck angle β" } }, // the 25 mm neck passes every tier
    { &SizingAnatomy::neckAngleAlphaDeg, { "neck angle α" } },
    { &SizingAnatomy::rightIliacDiameterMm, { "right iliac diameter", "right limb oversizing" } },
    { &SizingAnatomy::leftIliacDiameterMm, { "left iliac diameter", "left limb oversizing" } },
    { &SizingAnatomy::rightIliacSealLengthMm, { "right iliac seal length" } },
    { &SizingAnatomy::leftIliacSealLengthMm, { "left iliac seal length" } },
    { &SizingAnatomy::rightAccessMinDiameterMm, { "contralateral access" } }, // the body then goes left
    { &SizingAnatomy::leftAccessMinDiameterMm, { "contralateral access" } },
    { &SizingAnatomy::proximalSiteToBifurcationLengthMm, { "proximal site to bifurcation" } },
  };
  for (const auto& [field, names] : cases)
  {
    SizingAnatomy a = MakeGoodAnatomy();
    a.*field = NaN;
    const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
    const FamilyEvaluation& e = Family(s, "FifteenMm"); // the family with every optional criterion
    int indeterminate = 0;
    for (const CriterionCheck& c : e.checks)
    {
      const bool expected = std::find(names.begin(), names.end(), c.name) != names.end();
      EXPECT_EQ(c.status, expected ? CheckStatus::Indeterminate : CheckStatus::Pass) << c.text;
      if (c.status == CheckStatus::Indeterminate)
      {
        ++indeterminate;
        EXPECT_TRUE(std::isnan(c.margin)) << c.text;
        EXPECT_NE(c.text.find("indeterminate"), std::string::npos) << c.text;
      }
    }
    EXPECT_EQ(indeterminate, int(names.size())) << names.front();
  }
}

TEST(SelectDevice, IndeterminateFamily_RankedAfterFullyCheckedOne)
{
  // Neck 22.5 mm: TenMm 25 mm gives 11.1 %, FifteenMm 26 mm gives 15.6 %, nearer the target.
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckDiameterMm = 22.5;
  a.neckDiameter15mmMm = 22.5;
  const DeviceSelection measured = SelectDevice(a, MakeTestCatalog());
  EXPECT_EQ(measured.families[size_t(measured.recommended)].family, "FifteenMm");
  a.neckAngleAlphaDeg = NaN; // only FifteenMm limits α, so only it becomes indeterminate
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
  ASSERT_TRUE(Family(s, "FifteenMm").WithinIfu());
  EXPECT_EQ(Family(s, "FifteenMm").Count(CheckStatus::Indeterminate), 1);
  EXPECT_EQ(s.families[size_t(s.recommended)].family, "TenMm"); // fully checked beats nearer target
  EXPECT_TRUE(s.recommendedFullyChecked);
}

TEST(SelectDevice, OnlyIndeterminateFamilies_RecommendedButFlagged)
{
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthMm = NaN;
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
  ASSERT_EQ(s.recommended, 0); // TenMm, nearer 15 %
  EXPECT_TRUE(s.recommendedWithinIfu);
  EXPECT_FALSE(s.recommendedFullyChecked);
  EXPECT_NE(s.summary.find("within IFU except 1 indeterminate check"), std::string::npos) << s.summary;
  ASSERT_EQ(s.reasons.size(), 1u);
  EXPECT_EQ(s.reasons[0], "TenMm: neck length not measured, needs ≥ 10 mm (β ≤ 60°): indeterminate");
}

TEST(SelectDevice, NeckDiameterNotMeasured_NothingToImplantSoNoRecommendation)
{
  // (a) unknown (an outer wall that could not be seen): no family fails, none has a main body.
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckDiameterMm = NaN;
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
  EXPECT_LT(s.recommended, 0) << s.summary;
  EXPECT_EQ(s.summary, "no device sized"); // not "no device within IFU": nothing failed
  EXPECT_EQ(s.ifuStatus, CheckStatus::Indeterminate);
  ASSERT_FALSE(s.reasons.empty());
  EXPECT_NE(s.reasons[0].find("no main body sized"), std::string::npos) << s.reasons[0];
  // Sized on the lumen instead (a catalogue that says so), the same anatomy has its device.
  DeviceCatalog lumen = MakeTestCatalog();
  for (DeviceFamily& f : lumen.families)
    f.diameterReference = DiameterReference::Lumen;
  a.proximalNeckLumenDiameterMm = 22.0;
  a.neckLumenDiameter15mmMm = 22.0;
  a.rightIliacLumenDiameterMm = a.rightIliacDiameterMm;
  a.leftIliacLumenDiameterMm = a.leftIliacDiameterMm;
  EXPECT_GE(SelectDevice(a, lumen).recommended, 0);
}

TEST(SelectDevice, OuterWallNotTracedButLumenMeasured_SizedOnTheLumenAsAnEstimateAndIndeterminate)
{
  // Issue 29 item 4: no fat around the vessel, so no outer wall; the lumen was measured.
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLumenDiameterMm = 20.0;
  a.neckLumenDiameter15mmMm = 20.5;
  a.rightIliacLumenDiameterMm = 11.0;
  a.leftIliacLumenDiameterMm = 11.0;
  a.proximalNeckDiameterMm = a.neckDiameter15mmMm = a.rightIliacDiameterMm = a.leftIliacDiameterMm = NaN;
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog());
  ASSERT_GE(s.recommended, 0) << s.summary; // a recommendation, not "no device within IFU"
  const FamilyEvaluation& e = s.families[std::size_t(s.recommended)];
  EXPECT_EQ(e.estimatedFromLumen, (std::vector<std::string>{ "(a)", "(b)", "(e)", "(f)" }));
  // Sized on the lumen's 20 mm: TenMm's 23 mm body (15.0 %).
  EXPECT_EQ(e.family, "TenMm");
  EXPECT_EQ(e.mainBody.diameterMm, 23.0);
  EXPECT_EQ(s.ifuStatus, CheckStatus::Indeterminate);
  EXPECT_FALSE(s.recommendedFullyChecked);
  EXPECT_NE(s.summary.find("estimated (lumen)"), std::string::npos) << s.summary;
  for (const char* name : { "main body oversizing", "neck diameter", "neck diameter 15 mm below",
                            "right iliac diameter", "left limb oversizing" })
  {
    const CriterionCheck& c = Check(e, name);
    EXPECT_EQ(c.status, CheckStatus::Indeterminate) << name;
    EXPECT_NE(c.text.find("estimated (lumen)"), std::string::npos) << c.text;
  }
  // A failing criterion on a measured value still fails the IFU: a 5 mm neck.
  a.proximalNeckLengthMm = 5.0;
  const DeviceSelection failing = SelectDevice(a, MakeTestCatalog());
  EXPECT_LT(failing.recommended, 0);
  EXPECT_EQ(failing.ifuStatus, CheckStatus::Fail);
  EXPECT_EQ(failing.summary, "no device within IFU");
}

TEST(SelectDevice, ForcedFamilyAndSize_OnlyItEvaluatedAndFlaggedOutsideIfu)
{
  SizingAnatomy a = MakeGoodAnatomy();
  a.proximalNeckLengthMm = 9.0;
  DeviceSelectionParams p;
  p.forcedDevice = "fifteenmm:28.5"; // case-insensitive family; 28.5 / 22 − 1 = 29.5 %
  const DeviceSelection s = SelectDevice(a, MakeTestCatalog(), p);
  ASSERT_EQ(s.families.size(), 1u);
  EXPECT_TRUE(s.forced);
  EXPECT_EQ(s.recommended, 0);
  EXPECT_FALSE(s.recommendedWithinIfu);
  const FamilyEvaluation& e = s.families[0];
  EXPECT_EQ(e.mainBody.diameterMm, 28.5);
  EXPECT_TRUE(e.mainBody.forced);
  EXPECT_EQ(Check(e, "main body oversizing").status, CheckStatus::Fail); // 29.5 % > 20 %
  EXPECT_EQ(Check(e, "neck length").status, CheckStatus::Fail);
  EXPECT_NE(s.summary.find("FifteenMm (forced)"), std::string::npos) << s.summary;
  EXPECT_NE(s.summary.find("OUTSIDE IFU (2 failing checks)"), std::string::npos) << s.summary;
  EXPECT_EQ(s.reasons.size(), 2u);

  p.forcedDevice = "TenMm"; // family only: its size chosen as usual
  const DeviceSelection family = SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p);
  ASSERT_EQ(family.families.size(), 1u);
  EXPECT_EQ(family.families[0].mainBody.diameterMm, 25.0);
  EXPECT_TRUE(family.recommendedFullyChecked);
}

TEST(SelectDevice, ForcedUnknownFamilyOrSize_InputErrorNamesCatalogueAndChoices)
{
  DeviceSelectionParams p;
  p.forcedDevice = "Nellix";
  ExpectInputError([&] { SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p); },
                   { "Forced device 'Nellix'", "'test catalogue'", "expected one of: TenMm, FifteenMm" });
  p.forcedDevice = "TenMm:27";
  ExpectInputError([&] { SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p); },
                   { "'27' is not a main-body diameter of TenMm", "expected one of 23, 25, 28, 32, 36 mm" });
  p.forcedDevice = "TenMm:large";
  ExpectInputError([&] { SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p); }, { "'large'" });
}

TEST(SelectDevice, ParamsOutOfRange_InputErrorNamesParameter)
{
  DeviceSelectionParams p;
  p.proximalOversizingMinPercent = 25.0; // above the 20 % maximum
  ExpectInputError([&] { SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p); },
                   { "proximalOversizingMaxPercent is 20.00 %; expected 25.0 to 100.0 %" });
  p = {};
  p.limbOversizingMinPercent = -5.0;
  ExpectInputError([&] { SelectDevice(MakeGoodAnatomy(), MakeTestCatalog(), p); },
                   { "limbOversizingMinPercent is -5.00 %" });
}

TEST(SelectDevice, ImpossibleMeasurement_InputErrorNamesField)
{
  SizingAnatomy a = MakeGoodAnatomy();
  a.rightIliacDiameterMm = -14.0;
  ExpectInputError([&] { SelectDevice(a, MakeTestCatalog()); },
                   { "rightIliacDiameterMm is -14.00 mm; expected more than 0.0" });
  a = MakeGoodAnatomy();
  a.neckAngleBetaDeg = 200.0; // an angle beyond 180°
  ExpectInputError([&] { SelectDevice(a, MakeTestCatalog()); }, { "neckAngleBetaDeg is 200.00 deg" });
}

} // namespace
} // namespace sgp
