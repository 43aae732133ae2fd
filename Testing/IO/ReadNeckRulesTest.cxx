// Reading the hostile-neck rules: the bundled file and its copy beside the CLI, and one clear
// error per kind of planted defect, naming the file, the rule and the field.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "DeviceCatalogSupport.h"
#include "IO/ReadNeckRules.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

using testing::ExpectInputError;

using ReadNeckRulesTest = testing::TemporaryFolderTest;

std::string BundledText()
{
  std::ifstream in(SGP_NECK_RULES_JSON);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json BundledJson()
{
  return nlohmann::json::parse(BundledText());
}

/// Writes `text` to `name` in `folder`; returns the path.
std::string WriteFile(const std::filesystem::path& folder, const std::string& name, const std::string& text)
{
  const std::string path = (folder / name).string();
  std::ofstream(path) << text;
  return path;
}

/// `text` with its first `from` replaced by `to` (which must occur).
std::string Replaced(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(ReadNeckRules, BundledFile_ReadsAndValidates)
{
  const NeckRuleSet set = ReadNeckRules(SGP_NECK_RULES_JSON);
  EXPECT_EQ(set.origin, SGP_NECK_RULES_JSON);
  EXPECT_EQ(set.name, "StentGraftPlanner default hostile-neck rules");
  ASSERT_EQ(set.rules.size(), 8u);
  EXPECT_EQ(set.rules.front().id, "short-neck");
  EXPECT_EQ(set.rules.back().id, "reverse-taper-15mm");
  EXPECT_EQ(BundledJson()["format"], NeckRulesFormat);
  EXPECT_EQ(BundledJson()["version"], NeckRulesFormatVersion);
}

TEST(ReadNeckRules, CopyBesideTheCli_IsTheBundledFile)
{
  // CMake copies Resources/hostile-neck-rules.json beside the CLI (DefaultNeckRulesPath's place).
  const NeckRuleSet copy = ReadNeckRules(SGP_CLI_NECK_RULES_JSON);
  const NeckRuleSet bundled = ReadNeckRules(SGP_NECK_RULES_JSON);
  ASSERT_EQ(copy.rules.size(), bundled.rules.size());
  for (size_t i = 0; i < copy.rules.size(); ++i)
  {
    EXPECT_EQ(copy.rules[i].id, bundled.rules[i].id);
    EXPECT_EQ(copy.rules[i].threshold, bundled.rules[i].threshold); // the same text, so exact
    EXPECT_EQ(copy.rules[i].source, bundled.rules[i].source);
  }
  EXPECT_EQ(std::filesystem::path(SGP_CLI_NECK_RULES_JSON).filename(), NeckRulesFileName);
}

TEST(ReadNeckRules, DefaultPath_IsBesideTheRunningExecutable)
{
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe");
  EXPECT_EQ(DefaultNeckRulesPath("ignored"), (exe.parent_path() / "hostile-neck-rules.json").string());
}

TEST_F(ReadNeckRulesTest, BrokenJson_NamesFileLineAndNearestField)
{
  // The comma after rules[2]'s unit removed (file order: id first, so the rule is named).
  const std::string text = Replaced(BundledText(), "\"unit\": \"deg\",", "\"unit\": \"deg\"");
  const std::string path = WriteFile(folder, "broken.json", text);
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "Hostile-neck rules '" + path + "' is not valid JSON", "line 31, column",
                     "near rules[2] \"angulated-neck-beta\", field 'unit'", "fix the syntax" });
}

TEST_F(ReadNeckRulesTest, MissingField_NamesFileRuleAndField)
{
  nlohmann::json json = BundledJson();
  json["rules"][2].erase("threshold");
  const std::string path = WriteFile(folder, "missing.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "'" + path + "', rules[2] \"angulated-neck-beta\", field 'threshold': is missing",
                     "expected a number", "correct the rule" });
}

TEST_F(ReadNeckRulesTest, WrongType_NamesValueSeen)
{
  nlohmann::json json = BundledJson();
  json["rules"][0]["threshold"] = "15";
  const std::string path = WriteFile(folder, "type.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); }, { "'" + path + "', rules[0] \"short-neck\", field 'threshold'",
                                                   "is the string \"15\"", "expected a number" });
}

TEST_F(ReadNeckRulesTest, UnknownQuantity_ListsTheKnownOnes)
{
  nlohmann::json json = BundledJson();
  json["rules"][1]["quantity"] = "neckDiamter";
  const std::string path = WriteFile(folder, "quantity.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "'" + path + "', rules[1] \"wide-neck\", field 'quantity': is \"neckDiamter\"",
                     "one of neckLength, neckDiameter,", "check the spelling" });
}

TEST_F(ReadNeckRulesTest, UnknownComparison_ListsTheFourForms)
{
  nlohmann::json json = BundledJson();
  json["rules"][4]["hostileWhen"] = ">=";
  const std::string path = WriteFile(folder, "when.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "'" + path + "', rules[4] \"neck-thrombus\", field 'hostileWhen': is \">=\"",
                     "one of below, atOrBelow, above, atOrAbove" });
}

TEST_F(ReadNeckRulesTest, DuplicateId_NamesBothRules)
{
  nlohmann::json json = BundledJson();
  json["rules"][5]["id"] = "Neck-Thrombus";
  const std::string path = WriteFile(folder, "duplicate.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "'" + path + "', rules[5] \"Neck-Thrombus\", field 'id': repeats rules[4]", "unique ids" });
}

TEST_F(ReadNeckRulesTest, NonFiniteThreshold_NamesRuleAndField)
{
  // JSON has no NaN or infinity: 1e999 overflows a double, NaN is no JSON at all.
  nlohmann::json json = BundledJson();
  json["rules"][2]["threshold"] = 12345.5;
  const std::string overflow = WriteFile(folder, "overflow.json", Replaced(json.dump(2), "12345.5", "1e999"));
  ExpectInputError([&] { ReadNeckRules(overflow); },
                   { "'" + overflow + "', rules[2] \"angulated-neck-beta\", field 'threshold'",
                     "number overflow parsing '1e999'", "expected a finite number" });
  const std::string nan = WriteFile(folder, "nan.json", Replaced(json.dump(2), "12345.5", "NaN"));
  ExpectInputError([&] { ReadNeckRules(nan); },
                   { "'" + nan + "' is not valid JSON", "near rules[2] \"angulated-neck-beta\", field 'threshold'" });
}

TEST_F(ReadNeckRulesTest, EmptyRules_NamesTheField)
{
  nlohmann::json json = BundledJson();
  json["rules"] = nlohmann::json::array();
  const std::string path = WriteFile(folder, "empty.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "Hostile-neck rules '" + path + "', field 'rules': is empty", "at least one rule" });
}

TEST_F(ReadNeckRulesTest, ExtraUnknownField_NamesItAndTheAllowedOnes)
{
  nlohmann::json json = BundledJson();
  json["rules"][3]["treshold"] = 60;
  const std::string path = WriteFile(folder, "extra.json", json.dump(2));
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "'" + path + "', rules[3] \"angulated-neck-alpha\", field 'treshold': is an unknown field",
                     "one of id, quantity, hostileWhen, threshold, unit, description, source" });
}

TEST(ReadNeckRules, FurtherDefects_EachNamed)
{
  nlohmann::json json = BundledJson();
  json["format"] = "sgp-device-catalogue";
  ExpectInputError([&] { ParseNeckRules(json.dump(), "f.json"); },
                   { "'f.json', field 'format': is \"sgp-device-catalogue\"", "\"sgp-hostile-neck-rules\"" });
  json = BundledJson();
  json["version"] = 2;
  ExpectInputError([&] { ParseNeckRules(json.dump(), "v2.json"); },
                   { "'v2.json', field 'version': is the number 2", "expected 1 (the version" });
  json["version"] = 1.5;
  ExpectInputError([&] { ParseNeckRules(json.dump(), "v.json"); }, { "field 'version'", "the integer 1" });
  json = BundledJson();
  json.erase("name");
  ExpectInputError([&] { ParseNeckRules(json.dump(), "n.json"); }, { "'n.json', field 'name': is missing" });
  json = BundledJson();
  json["rule"] = json["rules"];
  ExpectInputError([&] { ParseNeckRules(json.dump(), "t.json"); },
                   { "'t.json', field 'rule': is an unknown field", "format, version, name, description, rules" });
  json = BundledJson();
  json["rules"][1] = "short";
  ExpectInputError([&] { ParseNeckRules(json.dump(), "o.json"); },
                   { "'o.json', field 'rules[1]': is the string \"short\"", "an object describing one rule" });
  json = BundledJson();
  json["rules"][6].erase("id");
  ExpectInputError([&] { ParseNeckRules(json.dump(), "i.json"); }, { "'i.json', rules[6], field 'id': is missing" });
  json = BundledJson();
  json["rules"][0]["threshold"] = -5;
  ExpectInputError([&] { ParseNeckRules(json.dump(), "neg.json"); },
                   { "rules[0] \"short-neck\", field 'threshold': is -5 mm", "≥ 0 for neckLength" });
  json = BundledJson();
  json["rules"][2]["unit"] = "rad";
  ExpectInputError([&] { ParseNeckRules(json.dump(), "u.json"); },
                   { "rules[2] \"angulated-neck-beta\", field 'unit': is \"rad\"", "\"deg\"" });
  json = BundledJson();
  json["rules"][7]["source"] = nullptr;
  ExpectInputError([&] { ParseNeckRules(json.dump(), "s.json"); },
                   { "rules[7] \"reverse-taper-15mm\", field 'source': is null", "a string" });
  ExpectInputError([&] { ParseNeckRules("[1]", "a.json"); }, { "'a.json', field '(top level)'", "an array" });
}

TEST_F(ReadNeckRulesTest, UnreadableFile_NamesThePath)
{
  const std::string path = (folder / "absent.json").string();
  ExpectInputError([&] { ReadNeckRules(path); },
                   { "Cannot read the hostile-neck rules '" + path + "'", "Resources/hostile-neck-rules.json" });
}

} // namespace
} // namespace sgp
