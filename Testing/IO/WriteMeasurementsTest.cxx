// The measurements table, the diameter-profile table and the report's measurement part.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "IO/WriteMeasurements.h"

namespace sgp
{
namespace
{

/// Splits one CSV line with RFC 4180 quoting ("" inside quotes is a quote).
std::vector<std::string> SplitCsv(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
    {
      fields.back() += '"';
      ++i;
    }
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

std::vector<std::vector<std::string>> ParseCsv(const std::string& text)
{
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    rows.push_back(SplitCsv(line));
  return rows;
}

Measurements Sample()
{
  Measurements m;
  m.site.source = ProximalSiteSource::Renal;
  m.site.abscissaMm = 88.5;
  m.site.renal = "rightRenal";
  Measurement a{
    "proximalNeckDiameter", 22.25, "mm", "(a) area-equivalent diameter, outer wall, \"quoted\"", "aorta", 88.5
  };
  a.minMm = 21.5;
  a.maxMm = 23.0;
  a.areaMm = 22.0;
  a.wall = "outer";
  a.estimated = true;
  m.values.push_back(a);
  m.values.push_back({ "neckAngleAlpha", std::nan(""), "deg", "suprarenal, not covered", "aorta", 58.5 });
  DiameterProfile trunk;
  trunk.vessel = "aorta";
  trunk.rings.push_back({ 88.5, 22.25, 21.5, 23.0, 22.0, Point3::Zero() });
  trunk.rings.push_back({ 92.5, 22.5, 22.0, 23.5, 22.3, Point3::Zero() });
  m.profiles[0] = trunk;
  m.profiles[1].vessel = "rightIliac";
  m.profiles[2].vessel = "leftIliac";
  m.warnings.push_back("something was not measured");
  return m;
}

TEST(WriteMeasurements, Table_HeaderQuotedTextEmptyWhenNotMeasured)
{
  const auto rows = ParseCsv(FormatMeasurementsTable(Sample()));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{ "name", "value", "unit", "definition", "vessel", "abscissaMm", "minDiameterMm",
                                       "maxDiameterMm", "areaDiameterMm", "wall", "estimated", "label", "shown" }));
  // The value at full precision for machines; its words and clinical precision for a person.
  EXPECT_EQ(rows[1], (std::vector<std::string>{
                       "proximalNeckDiameter", "22.25", "mm", "(a) area-equivalent diameter, outer wall, \"quoted\"",
                       "aorta", "88.5", "21.5", "23", "22", "outer", "true",
                       "(a) neck diameter at the proximal site, outer wall", "22.2 mm (estimated)" }));
  EXPECT_EQ(rows[2][9], "");       // neither wall applies
  EXPECT_EQ(rows[2][10], "false"); // not estimated
  EXPECT_EQ(rows[2][0], "neckAngleAlpha");
  EXPECT_EQ(rows[2][1], ""); // not measured: empty, never "nan"
  EXPECT_EQ(rows[2][6], "");
  EXPECT_EQ(rows[2][11], "neck angle α (suprarenal aorta to neck)");
  EXPECT_EQ(rows[2][12], "not measured");
}

TEST(WriteMeasurements, Profile_OneRowPerRing)
{
  const auto rows = ParseCsv(FormatDiameterProfiles(Sample()));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{ "vessel", "abscissaMm", "meanDiameterMm", "minDiameterMm",
                                                "maxDiameterMm", "areaDiameterMm" }));
  EXPECT_EQ(rows[2], (std::vector<std::string>{ "aorta", "92.5", "22.5", "22", "23.5", "22.3" }));
}

TEST(WriteMeasurements, Json_NullWhenNotMeasuredSiteAndWarnings)
{
  const nlohmann::json j = MeasurementsToJson(Sample());
  EXPECT_EQ(j["proximalSite"]["source"], "renal");
  EXPECT_EQ(j["proximalSite"]["renal"], "rightRenal");
  ASSERT_EQ(j["measurements"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["measurements"][0]["value"].get<double>(), 22.25);
  EXPECT_DOUBLE_EQ(j["measurements"][0]["minDiameterMm"].get<double>(), 21.5);
  EXPECT_TRUE(j["measurements"][1]["value"].is_null());
  EXPECT_FALSE(j["measurements"][1].contains("minDiameterMm"));
  EXPECT_EQ(j["diameterProfiles"]["aorta"].size(), 2u);
  EXPECT_EQ(j["warnings"][0], "something was not measured");
}

} // namespace
} // namespace sgp
