// Tests of the Slicer progress protocol and of the CLI edge (RAS → LPS, parameter copies).
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "SlicerProgress.h"
#include "StentGraftSimulationParameters.h"
#include "SyntheticAorticPhantomParameters.h"

namespace sgp
{
namespace
{

std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

TEST(SlicerProgress, ThreeStages_TagsOnePerLineMonotoneEndingAtOne)
{
  std::ostringstream out;
  SlicerProgress progress(out, { { "ReadVolume", 1.0 }, { "SegmentLumen", 3.0 }, { "WriteOutputs", 1.0 } });
  progress.Begin("ReadVolume", "Reading <the> volume");
  progress.Begin("SegmentLumen", "Segmenting");
  auto callback = progress.Callback();
  for (double f : { 0.0, 0.001, 0.5, 0.4, 1.0 })
    callback(f, "step");
  progress.Begin("WriteOutputs", "Writing");
  progress.End();

  const std::regex tag(R"(^(<filter-start>|</filter-start>|<filter-end>|</filter-end>|)"
                       R"(<filter-(name|comment|progress|time)>[^<]*</filter-(name|comment|progress|time)>)$)");
  std::vector<double> values;
  for (const std::string& line : Lines(out.str()))
  {
    EXPECT_TRUE(std::regex_match(line, tag)) << line;
    if (line.rfind("<filter-progress>", 0) == 0)
      values.push_back(std::stod(line.substr(17)));
  }
  ASSERT_GE(values.size(), 4u);
  for (std::size_t i = 1; i < values.size(); ++i)
    EXPECT_GT(values[i], values[i - 1]);
  EXPECT_EQ(values.front(), 0.0);
  EXPECT_EQ(values.back(), 1.0);
  // SegmentLumen half done: (1 + 0.5·3) / 5.
  EXPECT_NE(std::find(values.begin(), values.end(), 0.5), values.end());
  const std::string text = out.str();
  EXPECT_NE(text.find("<filter-comment> \"Reading  the> volume\" </filter-comment>"), std::string::npos);
  // Each stage closes with its name and time; ReadVolume was closed by the next Begin.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), static_cast<long>(Lines(text).size()));
  EXPECT_NE(text.find("<filter-end>\n<filter-name>ReadVolume</filter-name>\n<filter-time>"), std::string::npos);
  EXPECT_NE(text.find("<filter-end>\n<filter-name>WriteOutputs</filter-name>\n<filter-time>"), std::string::npos);
}

// A stage whose work ran on the second core (the wall stage) reports that work's time, not the
// instant its result was taken (issue 34: "SegmentOuterWall 0.00 s"); the next stage its own again.
TEST(SlicerProgress, OwnTime_IsTheStagesTimeUntilTheNextBegin)
{
  std::ostringstream out;
  SlicerProgress progress(out, { { "FitStent", 1.0 }, { "SegmentOuterWall", 1.0 }, { "Measure", 1.0 } });
  progress.Begin("FitStent", "fit");
  progress.Begin("SegmentOuterWall", "wall");
  progress.SetOwnTime(0.437);
  progress.Begin("Measure", "measure");
  progress.End();
  const std::string text = out.str();
  EXPECT_NE(text.find("<filter-name>SegmentOuterWall</filter-name>\n<filter-time>0.437</filter-time>"),
            std::string::npos)
    << text;
  const std::string measureEnd = "<filter-end>\n<filter-name>Measure</filter-name>\n<filter-time>";
  const auto measure = text.find(measureEnd);
  ASSERT_NE(measure, std::string::npos);
  EXPECT_LT(std::stod(text.substr(measure + measureEnd.size())), 0.4); // its own short time, not 0.437 s
}

TEST(SlicerProgress, UndeclaredStage_LogicError)
{
  std::ostringstream out;
  SlicerProgress progress(out, { { "A", 1.0 }, { "B", 1.0 } });
  progress.Begin("B", "b");
  EXPECT_THROW(progress.Begin("A", "a"), std::logic_error); // stages run in declared order
}

TEST(CliEdge, RasToLps_NegatesXAndY)
{
  const Point3 lps = RasToLps({ 12.5f, -3.25f, 40.0f });
  EXPECT_EQ(lps, Point3(-12.5, 3.25, 40.0));
  EXPECT_THROW(RasToLps({ 1.0f, 2.0f }), InputError);
}

TEST(CliEdge, ValidateParameters_NamesWhatIsMissing)
{
  const RegionGrowingParams ok;
  EXPECT_NO_THROW(ValidateParameters("ct.nrrd", { 0, 0, 0 }, ok));
  // No seed is valid (issue 16): the aorta is then found automatically; a seed of two numbers is not.
  EXPECT_NO_THROW(ValidateParameters("ct.nrrd", {}, ok));
  EXPECT_THROW(ValidateParameters("ct.nrrd", { 1, 2 }, ok), InputError);
  EXPECT_THROW(ValidateParameters("", { 0, 0, 0 }, ok), InputError);
  RegionGrowingParams inverted;
  inverted.thresholdMode = ThresholdMode::Manual;
  inverted.lowerHu = 600;
  inverted.upperHu = 200;
  EXPECT_THROW(ValidateParameters("ct.nrrd", { 0, 0, 0 }, inverted), InputError);
  EXPECT_THROW(MakeRegionGrowingParams("fuzzy", 0, 1, 3, 150, 1, 100), InputError);
}

TEST(CliEdge, MakeActiveContourParams_ModeAndCounts)
{
  const std::vector<double> five{ 0.1, 0.2, 0.3, 0.4, 0.5 }, three{ 24, 12, 14 };
  const auto make = [&](const std::string& mode, const std::vector<double>& weights, const std::vector<double>& d)
  { return MakeActiveContourParams(mode, weights, 60, 0.02, d, weights, 5, 0.15, 5, 1, 100, 0.01); };
  const ActiveContourParams simulate = make("simulate", five, three);
  EXPECT_EQ(simulate.balloonRadiusMm, (std::array<double, 3>{ 12, 6, 7 })); // R is half the diameter
  EXPECT_EQ(simulate.weights.w3, 0.3);
  EXPECT_EQ(make("measure", five, three).balloonRadiusMm, (std::array<double, 3>{ 60, 60, 60 }));
  try
  {
    make("measure", { 1, 2 }, three);
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_STREQ(e.what(), "measureStiffnessWeights has 2 values; expected five (w1 to w5).");
  }
  EXPECT_THROW(make("simulate", five, { 24, 12 }), InputError);
  EXPECT_THROW(make("simulate", five, { 24, 12, 1 }), InputError); // a 1 mm leg
  EXPECT_THROW(make("gentle", five, three), InputError);
}

TEST(CliEdge, MakePhantomParams_WrongCounts_InputErrorNamesParameter)
{
  try
  {
    MakePhantomParams({ 1, 1 }, { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, { 0, 0, 0 });
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_STREQ(e.what(), "spacingMm has 2 values; expected 3.");
  }
  EXPECT_THROW(MakePhantomParams({ 1, 1, 1 }, { 1, 0, 0 }, { 0, 0, 0 }), InputError);
  EXPECT_THROW(MakePhantomParams({ 1, 1, 1 }, { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, { 0 }), InputError);
  // Direction values are the i, j, k axes one after another: they become the matrix's columns.
  const PhantomParams p = MakePhantomParams({ 1, 2, 3 }, { 0, 1, 0, -1, 0, 0, 0, 0, 1 }, { 0, 0, 0 });
  EXPECT_EQ(p.directionLps(1, 0), 1.0);
  EXPECT_EQ(p.directionLps(0, 1), -1.0);
}

} // namespace
} // namespace sgp
