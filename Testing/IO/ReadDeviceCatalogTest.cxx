// Reading the device catalogue: the shipped file, and one clear error per kind of defect.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "DeviceCatalogSupport.h"
#include "IO/DeviceSelectionToJson.h"
#include "IO/ReadDeviceCatalog.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

using testing::ExpectInputError;

using ReadDeviceCatalogTest = testing::TemporaryFolderTest;

nlohmann::json ShippedJson()
{
  std::ifstream in(SGP_DEVICES_JSON);
  return nlohmann::json::parse(in);
}

/// Writes `text` to `name` in `folder`; returns the path.
std::string WriteFile(const std::filesystem::path& folder, const std::string& name, const std::string& text)
{
  const std::string path = (folder / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(ReadDeviceCatalog, ShippedCatalogue_LoadsValidatesAndCarriesEvidence)
{
  const DeviceCatalog catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  EXPECT_EQ(catalog.origin, SGP_DEVICES_JSON);
  ASSERT_EQ(catalog.families.size(), 4u);
  EXPECT_EQ(catalog.families[0].name, "Endurant II");
  EXPECT_EQ(catalog.families[1].name, "Excluder (C3)");
  EXPECT_EQ(catalog.families[2].name, "Excluder Conformable");
  EXPECT_EQ(catalog.families[3].name, "Zenith Flex");
  for (const DeviceFamily& f : catalog.families)
  {
    SCOPED_TRACE(f.name);
    EXPECT_EQ(f.note, "verify against the current IFU");
    EXPECT_FALSE(f.source.empty());
    for (const std::string* evidence :
         { &f.mainBodies.evidence, &f.limbs.evidence, &f.ifu.neckLengthEvidence, &f.ifu.neckDiameterMm.evidence,
           &f.ifu.iliacSealLengthMm.evidence, &f.ifu.iliacDiameterMm.evidence })
      EXPECT_NE(evidence->find('['), std::string::npos) << *evidence; // an evidence mark: [S], [S2] or [K]
  }
  // Figures from evar-sizing.md §2.1–2.2 (copied, so compared exactly).
  const DeviceFamily& endurant = catalog.families[0];
  ASSERT_EQ(endurant.mainBodies.sizes.size(), 5u);
  EXPECT_EQ(endurant.mainBodies.sizes.front().diameterMm, 23.0);
  EXPECT_EQ(endurant.mainBodies.sizes.back().diameterMm, 36.0);
  EXPECT_EQ(endurant.mainBodies.sizes.back().profileFr, 20.0);
  ASSERT_EQ(endurant.ifu.neckLengthTiers.size(), 2u);
  EXPECT_EQ(endurant.ifu.neckLengthTiers[0].minLengthMm, 10.0);
  EXPECT_EQ(endurant.ifu.neckLengthTiers[1].maxBetaDeg, 75.0);
  const DeviceFamily& zenith = catalog.families[3];
  EXPECT_EQ(zenith.ifu.neckAngleAlphaDeg.max, 45.0);
  EXPECT_EQ(zenith.ifu.iliacDiameterMm.min, 7.5);
  EXPECT_EQ(zenith.limbs.sizes.size(), 9u); // 8–24 mm in 2 mm steps
  EXPECT_TRUE(std::isnan(catalog.families[0].ifu.neckAngleAlphaDeg.max));
}

TEST_F(ReadDeviceCatalogTest, MissingField_NamesFileEntryAndField)
{
  nlohmann::json json = ShippedJson();
  json["families"][1]["ifu"]["neckDiameterMm"].erase("max");
  const std::string path = WriteFile(folder, "missing.json", json.dump(2));
  ExpectInputError([&] { ReadDeviceCatalog(path); }, { "'" + path + "'", "families[1] \"Excluder (C3)\"",
                                                       "'ifu.neckDiameterMm.max'", "is missing", "expected a number" });
}

TEST_F(ReadDeviceCatalogTest, WrongType_NamesFileEntryFieldAndValueSeen)
{
  nlohmann::json json = ShippedJson();
  json["families"][0]["mainBodies"]["sizes"][0]["diameterMm"] = "23";
  const std::string path = WriteFile(folder, "type.json", json.dump(2));
  ExpectInputError([&] { ReadDeviceCatalog(path); },
                   { "'" + path + "'", "families[0] \"Endurant II\"", "'mainBodies.sizes[0].diameterMm'",
                     "is the string \"23\"", "expected a number" });
}

TEST_F(ReadDeviceCatalogTest, UnknownForcedDevice_NamesFileAndListsFamilies)
{
  const std::string path = WriteFile(folder, "devices.json", ShippedJson().dump(2));
  DeviceSelectionParams p;
  p.forcedDevice = "Nellix:28";
  ExpectInputError([&] { SelectDevice(testing::MakeGoodAnatomy(), ReadDeviceCatalog(path), p); },
                   { "Forced device 'Nellix:28'", "no family 'Nellix'", "'" + path + "'",
                     "Endurant II, Excluder (C3), Excluder Conformable, Zenith Flex" });
}

TEST(ReadDeviceCatalog, UnknownField_NamesItAndTheAllowedOnes)
{
  nlohmann::json json = ShippedJson();
  json["families"][3]["ifu"]["neckDiamterMm"] = json["families"][3]["ifu"]["neckDiameterMm"];
  ExpectInputError(
    [&] { ParseDeviceCatalog(json.dump(), "edited.json"); },
    { "'edited.json'", "families[3] \"Zenith Flex\"", "'ifu.neckDiamterMm'", "unknown field", "neckDiameterMm" });
}

TEST(ReadDeviceCatalog, MalformedJson_NamesFileLineAndColumn)
{
  const std::string text = "{\n  \"formatVersion\": 1\n  \"families\": []\n}\n"; // comma missing on line 2
  ExpectInputError([&] { ParseDeviceCatalog(text, "broken.json"); },
                   { "'broken.json' is not valid JSON", "line 3, column", "fix the syntax" });
}

TEST(ReadDeviceCatalog, StructuralDefects_EachNamed)
{
  nlohmann::json json = ShippedJson();
  json["formatVersion"] = 2;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "v2.json"); }, { "'v2.json'", "'formatVersion'", "is 2" });
  json = ShippedJson();
  json["families"][2].erase("name");
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "noname.json"); },
                   { "'noname.json', families[2], field 'name'", "is missing", "a string" });
  json = ShippedJson();
  json["families"][1] = 7;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "seven.json"); },
                   { "field 'families[1]'", "the number 7", "an object" });
  json = ShippedJson();
  json["families"][0]["ifu"]["neckLength"]["tiers"][0] = "10 mm";
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "tier.json"); },
                   { "families[0] \"Endurant II\"", "'ifu.neckLength.tiers[0]'", "the string \"10 mm\"" });
  json = ShippedJson();
  json["families"][2]["mainBodies"]["lengthToFlowDividerMm"][1] = true;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "bool.json"); },
                   { "'mainBodies.lengthToFlowDividerMm[1]'", "the boolean true" });
  ExpectInputError([&] { ParseDeviceCatalog("[1, 2]", "array.json"); }, { "'array.json'", "an array" });
  ExpectInputError([&] { ParseDeviceCatalog("{\"formatVersion\": 1.5, \"families\": []}", "float.json"); },
                   { "'formatVersion'", "the number 1.5", "the integer 1" });
}

TEST(ReadDeviceCatalog, SemanticRule_ReportedWithTheFileName)
{
  nlohmann::json json = ShippedJson();
  json["families"][2]["limbs"]["sizes"][3]["diameterMm"] = 15;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "order.json"); },
                   { "Device catalogue 'order.json', families[2] \"Excluder Conformable\"",
                     "'limbs.sizes[3].diameterMm'", "15 mm after 16 mm" });
}

TEST_F(ReadDeviceCatalogTest, UnreadableFile_NamesPath)
{
  const std::string path = (folder / "absent.json").string();
  ExpectInputError([&] { ReadDeviceCatalog(path); }, { "Cannot read the device catalogue '" + path + "'" });
}

TEST(DeviceSelectionToJson, Selection_ReportShapeWithNullForUnknown)
{
  SizingAnatomy a = testing::MakeGoodAnatomy();
  a.proximalNeckLengthMm = 9.0;
  a.leftIliacDiameterMm = std::numeric_limits<double>::quiet_NaN();
  const DeviceSelection s = SelectDevice(a, testing::MakeTestCatalog());
  const nlohmann::json j = nlohmann::json::parse(DeviceSelectionToJson(s).dump()); // survives a round trip
  EXPECT_TRUE(j["recommendation"]["family"].is_null());                            // no device within IFU
  EXPECT_EQ(j["recommendation"]["summary"], "no device within IFU");
  EXPECT_EQ(j["recommendation"]["reasons"].size(), s.reasons.size());
  ASSERT_EQ(j["families"].size(), 2u);
  const nlohmann::json& ten = j["families"][0];
  EXPECT_EQ(ten["name"], "TenMm");
  EXPECT_EQ(ten["mainBody"]["diameterMm"], 25.0);
  EXPECT_TRUE(ten["leftLimb"]["diameterMm"].is_null()); // not measured
  EXPECT_FALSE(ten["leftLimb"]["reason"].is_null());
  EXPECT_EQ(ten["checks"].size(), s.families[0].checks.size());
  bool sawNeckLength = false;
  for (const nlohmann::json& c : ten["checks"])
    if (c["name"] == "neck length")
    {
      sawNeckLength = true;
      EXPECT_EQ(c["status"], "fail");
      EXPECT_NEAR(c["margin"].get<double>(), -1.0, 1e-12); // 9 − 10, exact in binary
      EXPECT_TRUE(c["max"].is_null());
    }
    else if (c["name"] == "left iliac diameter")
    {
      EXPECT_EQ(c["status"], "indeterminate");
      EXPECT_TRUE(c["value"].is_null());
      EXPECT_TRUE(c["margin"].is_null());
    }
  EXPECT_TRUE(sawNeckLength);
  EXPECT_EQ(ten["failCount"], 1);
  EXPECT_EQ(ten["indeterminateCount"], 2); // left iliac diameter and left limb oversizing
}

} // namespace
} // namespace sgp
