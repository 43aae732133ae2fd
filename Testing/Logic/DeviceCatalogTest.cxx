// The device catalogue's semantic rules, and the one-line criterion checks built on them.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "Device/CriterionCheck.h"
#include "Device/DeviceCatalog.h"
#include "DeviceCatalogSupport.h"

namespace sgp
{
namespace
{

using testing::ExpectInputError;
using testing::MakeTestCatalog;

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

TEST(DeviceCatalog, TestCatalogue_Valid)
{
  EXPECT_NO_THROW(ValidateDeviceCatalog(MakeTestCatalog()));
}

TEST(DeviceCatalog, EachBrokenRule_InputErrorNamesOriginEntryFieldAndValue)
{
  struct Case
  {
    std::function<void(DeviceCatalog&)> plant;
    std::vector<std::string> parts; // all must appear in the message
  };
  const std::vector<Case> cases = {
    { [](DeviceCatalog& c) { c.families[1].mainBodies.sizes[2].diameterMm = 25.0; },
      { "families[1] \"FifteenMm\"", "'mainBodies.sizes[2].diameterMm'", "25 mm after 26 mm", "ascending",
        "correct the entry" } },
    { [](DeviceCatalog& c) { c.families[0].limbs.sizes[0].profileFr = 0.0; },
      { "families[0] \"TenMm\"", "'limbs.sizes[0].profileFr'", "is 0 Fr", "positive" } },
    { [](DeviceCatalog& c) { c.families[0].mainBodies.sizes.clear(); },
      { "families[0] \"TenMm\"", "'mainBodies.sizes'", "is empty" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckDiameterMm.max = 19.0; },
      { "'ifu.neckDiameterMm'", "is 19 to 19 mm", "min < max" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.iliacDiameterMm.min = NaN; },
      { "'ifu.iliacDiameterMm.min'", "is nan mm" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckLengthTiers[1].maxBetaDeg = 50.0; },
      { "'ifu.neckLength.tiers[1].maxBetaDeg'", "50 deg after 60 deg", "ascending angle" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckLengthTiers[1].minLengthMm = 5.0; },
      { "'ifu.neckLength.tiers[1].minMm'", "5 mm after 10 mm" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckLengthTiers.clear(); }, { "'ifu.neckLength.tiers'", "is empty" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckLengthTiers[0].maxBetaDeg = 190.0; },
      { "'ifu.neckLength.tiers[0].maxBetaDeg'", "is 190 deg", "(0, 180]" } },
    { [](DeviceCatalog& c) { c.families[1].ifu.neckAngleAlphaDeg.max = -1.0; },
      { "'ifu.neckAngleAlphaDeg.max'", "is -1 deg" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.iliacSealLengthMm.min = -2.0; },
      { "'ifu.iliacSealLengthMm.min'", "is -2 mm" } },
    { [](DeviceCatalog& c) { c.families[0].ifu.neckDiameterMm.max = 36.0; },
      { "'mainBodies.sizes'", "widest main body is 36 mm", "largest IFU neck diameter, 36 mm" } },
    { [](DeviceCatalog& c) { c.families[1].ifu.iliacDiameterMm.max = 27.5; },
      { "'limbs.sizes'", "widest limb is 27 mm", "27.5 mm" } },
    { [](DeviceCatalog& c) { c.families[0].limbs.lengthToFlowDividerMm = { 50.0 }; },
      { "'limbs.lengthToFlowDividerMm'", "only on mainBodies" } },
    { [](DeviceCatalog& c) {
       c.families[1].mainBodies.lengthToFlowDividerMm = { 65.0, 55.0 };
     },
      { "'mainBodies.lengthToFlowDividerMm[1]'", "55 mm after 65 mm" } },
    { [](DeviceCatalog& c) { c.families[0].limbs.lengthMinMm = 100.0; },
      { "'limbs.lengthRangeMm'", "only one bound" } },
    { [](DeviceCatalog& c) { c.families[0].name = "Ten:Mm"; }, { "families[0] \"Ten:Mm\"", "'name'", "':'" } },
    { [](DeviceCatalog& c) { c.families[0].name = " "; }, { "families[0]", "'name'", "is empty" } },
    { [](DeviceCatalog& c) { c.families[1].name = "tenmm"; },
      { "families[1] \"tenmm\"", "repeats families[0]", "rename one" } },
    { [](DeviceCatalog& c) { c.families[1].source.clear(); }, { "families[1] \"FifteenMm\"", "'source'" } },
    { [](DeviceCatalog& c) { c.families.clear(); }, { "'families'", "is empty", "add one" } },
    { [](DeviceCatalog& c) { c.formatVersion = 1; }, { "'formatVersion'", "is 1; expected 2", "convert the file" } },
  };
  for (size_t i = 0; i < cases.size(); ++i)
  {
    SCOPED_TRACE("case " + std::to_string(i));
    DeviceCatalog catalog = MakeTestCatalog();
    cases[i].plant(catalog);
    std::vector<std::string> parts = cases[i].parts;
    parts.push_back("Device catalogue 'test catalogue'");
    parts.push_back("; expected "); // every message says what was expected and what to do
    ExpectInputError([&] { ValidateDeviceCatalog(catalog); }, parts);
  }
}

TEST(DeviceCatalog, FindDeviceFamily_CaseAndSpaceInsensitive)
{
  const DeviceCatalog catalog = MakeTestCatalog();
  ASSERT_NE(FindDeviceFamily(catalog, " fifteenmm "), nullptr);
  EXPECT_EQ(FindDeviceFamily(catalog, " fifteenmm ")->name, "FifteenMm");
  EXPECT_EQ(FindDeviceFamily(catalog, "Fifteen"), nullptr);
}

TEST(CriterionCheck, Margins_SignedPositiveInside)
{
  // All operands are exact in binary; 1e-12 allows only the subtraction's rounding.
  EXPECT_NEAR(CheckCriterion("x", 12.0, 15.0, NaN, "mm").margin, -3.0, 1e-12);
  EXPECT_NEAR(CheckCriterion("x", 50.0, NaN, 60.0, "deg").margin, 10.0, 1e-12);
  EXPECT_NEAR(CheckCriterion("x", 19.5, 19.0, 32.0, "mm").margin, 0.5, 1e-12); // nearer the lower limit
  EXPECT_NEAR(CheckCriterion("x", 33.0, 19.0, 32.0, "mm").margin, -1.0, 1e-12);
  EXPECT_EQ(CheckCriterion("x", 15.0, 15.0, NaN, "mm").status, CheckStatus::Pass); // limits inclusive
  EXPECT_EQ(CheckCriterion("x", 14.9, 15.0, NaN, "mm").status, CheckStatus::Fail);
  const CriterionCheck missing = CheckCriterion("x", NaN, 15.0, NaN, "mm");
  EXPECT_EQ(missing.status, CheckStatus::Indeterminate);
  EXPECT_TRUE(std::isnan(missing.margin));
}

TEST(CriterionCheck, Text_OneReadableLine)
{
  EXPECT_EQ(CheckCriterion("neck length", 12.0, 15.0, NaN, "mm").text, "neck length 12.0 mm, needs ≥ 15 mm: −3.0 mm");
  EXPECT_EQ(CheckCriterion("neck angle β", 50.0, NaN, 60.0, "deg").text, "neck angle β 50.0°, needs ≤ 60°: +10.0°");
  EXPECT_EQ(CheckCriterion("iliac diameter", 14.0, 7.5, 20.0, "mm").text,
            "iliac diameter 14.0 mm, needs 7.5–20 mm: +6.0 mm");
  EXPECT_EQ(CheckCriterion("neck length", NaN, 10.0, NaN, "mm", "β ≤ 60°").text,
            "neck length not measured, needs ≥ 10 mm (β ≤ 60°): indeterminate");
  EXPECT_EQ(SignedQuantityText(-0.04, "mm"), "+0.0 mm"); // no "−0.0"
  EXPECT_EQ(ToString(CheckStatus::Indeterminate), std::string("indeterminate"));
}

} // namespace
} // namespace sgp
