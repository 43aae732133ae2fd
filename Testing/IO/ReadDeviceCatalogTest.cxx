// Reading the device catalogue: the shipped file, and one clear error per kind of defect.
#include <algorithm>
#include <cmath>
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
    EXPECT_EQ(f.note.rfind("verify against the current IFU", 0), 0u) << f.note;
    EXPECT_FALSE(f.verified); // nobody has read the manufacturers' current sizing tables yet
    EXPECT_FALSE(f.source.empty());
    for (const std::string* evidence :
         { &f.mainBodies.evidence, &f.limbs.evidence, &f.ifu.neckLengthEvidence, &f.ifu.neckDiameterMm.evidence,
           &f.ifu.iliacSealLengthMm.evidence, &f.ifu.iliacDiameterMm.evidence, &f.junctions.overlapMm.evidence })
      EXPECT_FALSE(evidence->empty());
    for (const std::string* evidence :
         { &f.mainBodies.evidence, &f.limbs.evidence, &f.ifu.neckLengthEvidence, &f.ifu.neckDiameterMm.evidence,
           &f.ifu.iliacSealLengthMm.evidence, &f.ifu.iliacDiameterMm.evidence })
      EXPECT_NE(evidence->find('['), std::string::npos) << *evidence; // an evidence mark: [S], [S2] or [K]
    // Every component carries its source's evidence mark, and every limb a length.
    for (const CatalogueComponent& c : f.components)
    {
      EXPECT_NE(c.evidence.find('['), std::string::npos) << c.Label();
      if (c.role == ComponentRole::Limb)
      {
        EXPECT_TRUE(std::isfinite(c.lengthMm)) << c.Label();
      }
    }
    EXPECT_FALSE(f.ComponentsOf(ComponentRole::MainBody).empty());
    EXPECT_FALSE(f.ComponentsOf(ComponentRole::Limb).empty());
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
  // device-configuration.md §1.1 and the EVP table: Endurant II's geometry, copied, so exact.
  const auto bodies = endurant.ComponentsOf(ComponentRole::MainBody);
  ASSERT_FALSE(bodies.empty());
  EXPECT_EQ(bodies.front()->code, "ETBF2313C124E");
  EXPECT_EQ(bodies.front()->flowDividerMm, 40.0);
  EXPECT_EQ(bodies.front()->gateEndMm, 74.0);
  EXPECT_EQ(bodies.front()->gateDiameterMm, 12.0);
  EXPECT_EQ(bodies.front()->crotchWidthMm, 25.0);
  for (const CatalogueComponent* body : bodies)
    EXPECT_TRUE(body->GeometryKnown()) << body->Label();
  EXPECT_EQ(endurant.junctions.overlapMm.min, 30.0);
  EXPECT_TRUE(std::isnan(endurant.junctions.overlapMm.max)); // not found
  // The 93 mm limb carries the conflicting 95 mm of one source, and the chosen value.
  const auto limbs = endurant.ComponentsOf(ComponentRole::Limb);
  const auto ninetyThree =
    std::find_if(limbs.begin(), limbs.end(), [](const CatalogueComponent* c) { return c->lengthMm == 93.0; });
  ASSERT_NE(ninetyThree, limbs.end());
  ASSERT_EQ((*ninetyThree)->conflicts.size(), 1u);
  EXPECT_EQ((*ninetyThree)->conflicts[0].values, (std::vector<double>{ 93.0, 95.0 }));
  // Zenith Flex's main-body lengths and gate are not in any source read: null, not guessed.
  for (const CatalogueComponent* body : zenith.ComponentsOf(ComponentRole::MainBody))
  {
    EXPECT_TRUE(std::isnan(body->lengthMm));
    EXPECT_TRUE(body->code.empty());
  }
  EXPECT_TRUE(std::isnan(zenith.junctions.overlapMm.min));
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
  json["families"][0]["mainBodies"]["items"][0]["lengthMm"] = "124";
  const std::string path = WriteFile(folder, "type.json", json.dump(2));
  ExpectInputError([&] { ReadDeviceCatalog(path); },
                   { "'" + path + "'", "families[0] \"Endurant II\"", "component mainBodies.items[0] ETBF2313C124E",
                     "field 'lengthMm'", "is the string \"124\"", "expected a number, or null" });
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
  json["formatVersion"] = 1;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "v1.json"); },
                   { "'v1.json'", "'formatVersion'", "is 1; expected 2", "convert the file" });
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
  json["families"][2]["mainBodies"]["items"][1]["flowDividerMm"] = true;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "bool.json"); },
                   { "component mainBodies.items[1] CXT201412", "'flowDividerMm'", "the boolean true" });
  json = ShippedJson();
  json["families"][2]["limbs"]["items"][4].erase("code");
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "code.json"); },
                   { "families[2] \"Excluder Conformable\"", "component limbs.items[4]", "'code'", "is missing",
                     "null when it is not public" });
  json = ShippedJson();
  json["families"][0]["limbs"]["items"][0]["code"] = " ";
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "blank.json"); },
                   { "component limbs.items[0]", "'code'", "is empty" });
  json = ShippedJson();
  json["families"][0]["mainBodies"]["items"][0].erase("crotchWidthMm");
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "crotch.json"); },
                   { "component mainBodies.items[0] ETBF2313C124E", "'crotchWidthMm'", "is missing",
                     "or null when no public source gives it" });
  json = ShippedJson();
  json["families"][0].erase("verified");
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "verified.json"); },
                   { "families[0] \"Endurant II\"", "'verified'", "is missing", "true or false" });
  json = ShippedJson();
  json["families"][1]["limbs"]["items"] = nlohmann::json::array();
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "nolimbs.json"); },
                   { "families[1] \"Excluder (C3)\"", "'limbs.items'", "is empty" });
  ExpectInputError([&] { ParseDeviceCatalog("[1, 2]", "array.json"); }, { "'array.json'", "an array" });
  ExpectInputError([&] { ParseDeviceCatalog("{\"formatVersion\": 1.5, \"families\": []}", "float.json"); },
                   { "'formatVersion'", "the number 1.5", "the integer 2" });
}

TEST(ReadDeviceCatalog, SemanticRule_ReportedWithTheFileName)
{
  // The four defects issue 29 names, each with file, family, component and field.
  nlohmann::json json = ShippedJson();
  json["families"][0]["limbs"]["items"][2]["lengthMm"] = -124;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "negative.json"); },
                   { "Device catalogue 'negative.json', families[0] \"Endurant II\"",
                     "component limbs.items[2] ETLW1610C124E", "field 'lengthMm'", "is -124 mm", "positive" });
  json = ShippedJson();
  json["families"][0]["mainBodies"]["items"][0]["gateEndMm"] = 130;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "gate.json"); },
                   { "'gate.json'", "component mainBodies.items[0] ETBF2313C124E", "field 'gateEndMm'",
                     "130 mm, beyond the body's covered length of 124 mm" });
  json = ShippedJson();
  json["families"][0]["junctions"]["overlapMm"]["min"] = 40;
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "overlap.json"); },
                   { "'overlap.json'", "families[0] \"Endurant II\"", "'junctions.overlapMm.min'",
                     "40 mm, longer than the 34 mm contralateral gate of mainBodies.items[0] ETBF2313C124E" });
  json = ShippedJson();
  json["families"][0]["limbs"]["items"][1]["conflicts"][0]["values"] = { 95, 96 };
  ExpectInputError([&] { ParseDeviceCatalog(json.dump(), "conflict.json"); },
                   { "component limbs.items[1] ETLW1610C093E", "'conflicts'", "lengthMm is 93, not among" });
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
