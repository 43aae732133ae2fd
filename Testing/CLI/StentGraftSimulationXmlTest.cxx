// The XML is the single source of truth (STYLE.md B4): the defaults PARSE_ARGS gives from it
// must equal the defaults of the Logic's parameter structs, and the strict point parsing holds.
// The same file compiles and passes against SEM's generated header (Slicer build) and the
// project's (CMake/GenerateCLP.py): it includes what it uses (CLPSupport.h for sgp::clp, which
// SEM's header does not bring in) and reads the defaults after a parse, because SEM declares a
// vector parameter empty and fills it, default included, only when PARSE_ARGS parses.
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "CLPSupport.h"
#include "Pipeline/PlanValues.h"
#include "StentGraftSimulationCLP.h"
#include "StentGraftSimulationParameters.h"

namespace sgp
{
namespace
{

/// PARSE_ARGS on argv, then the parsed values (every one its XML default, since argv gives only the
/// required input volume) against the structs' defaults. A function of its own, not the test body:
/// PARSE_ARGS returns an int on --xml and on a parse error (SEM's TCLAP exits instead).
int ExpectParsedDefaultsEqualStructDefaults(int argc, char* argv[])
{
  PARSE_ARGS;
  EXPECT_EQ(inputVolume, "ct.nrrd");
  const RegionGrowingParams fromXml = MakeRegionGrowingParams(thresholdMode, lowerHu, upperHu, windowSigmas,
                                                              seedMinimumHu, leakOpeningRadiusMm, maximumLumenVolumeMl);
  const RegionGrowingParams defaults;
  EXPECT_EQ(fromXml.thresholdMode, defaults.thresholdMode);
  EXPECT_EQ(fromXml.lowerHu, defaults.lowerHu);
  EXPECT_EQ(fromXml.upperHu, defaults.upperHu);
  EXPECT_EQ(fromXml.windowSigmas, defaults.windowSigmas);
  EXPECT_EQ(fromXml.seedMinimumHu, defaults.seedMinimumHu);
  EXPECT_EQ(fromXml.leakOpeningRadiusMm, defaults.leakOpeningRadiusMm);
  EXPECT_EQ(fromXml.maximumLumenVolumeMl, defaults.maximumLumenVolumeMl);
  EXPECT_EQ(MakeSkeletonGraphParams(spurLengthRatio).spurLengthRatio, SkeletonGraphParams{}.spurLengthRatio);
  const CenterlineParams centerlines = MakeCenterlineParams(centerlineStepMm, centerlineSmoothingMm);
  EXPECT_EQ(centerlines.stepMm, CenterlineParams{}.stepMm);
  EXPECT_EQ(centerlines.smoothingMm, CenterlineParams{}.smoothingMm);
  const StentMeshParams mesh = MakeStentMeshParams(verticesPerRing, ringSpacingMm, startRadiusMm, proximalStartMm);
  EXPECT_EQ(mesh.verticesPerRing, StentMeshParams{}.verticesPerRing);
  EXPECT_EQ(mesh.ringSpacingMm, StentMeshParams{}.ringSpacingMm);
  EXPECT_EQ(mesh.startRadiusMm, StentMeshParams{}.startRadiusMm);
  EXPECT_EQ(mesh.proximalAbscissaMm, StentMeshParams{}.proximalAbscissaMm);
  const auto acm = [&](const char* mode)
  {
    return MakeActiveContourParams(mode, measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
                                   stentDiametersMm, stentStiffnessWeights, stentBalloonPressure, acmTau, wallWeight,
                                   wallSofteningMm, acmMaxIterations, acmToleranceMm);
  };
  const auto same = [](const ActiveContourParams& a, const ActiveContourParams& b)
  {
    EXPECT_EQ(a.weights.w1, b.weights.w1);
    EXPECT_EQ(a.weights.w3, b.weights.w3);
    EXPECT_EQ(a.weights.w5, b.weights.w5);
    EXPECT_EQ(a.balloonPressure, b.balloonPressure);
    EXPECT_EQ(a.balloonRadiusMm, b.balloonRadiusMm);
    EXPECT_EQ(a.tau, b.tau);
    EXPECT_EQ(a.wallWeight, b.wallWeight);
    EXPECT_EQ(a.wallSofteningMm, b.wallSofteningMm);
    EXPECT_EQ(a.maxIterations, b.maxIterations);
    EXPECT_EQ(a.toleranceMm, b.toleranceMm);
  };
  same(acm("measure"), ActiveContourParams::Measure());
  same(acm("simulate"), ActiveContourParams::Simulate({ 24.0, 12.0, 12.0 }));
  const DeviceSelectionParams devices = MakeDeviceSelectionParams(device, proximalOversizingRange, limbOversizingRange);
  const DeviceSelectionParams deviceDefaults;
  EXPECT_EQ(devices.proximalOversizingMinPercent, deviceDefaults.proximalOversizingMinPercent);
  EXPECT_EQ(devices.proximalOversizingMaxPercent, deviceDefaults.proximalOversizingMaxPercent);
  EXPECT_EQ(devices.limbOversizingMinPercent, deviceDefaults.limbOversizingMinPercent);
  EXPECT_EQ(devices.limbOversizingMaxPercent, deviceDefaults.limbOversizingMaxPercent);
  EXPECT_EQ(devices.forcedDevice, deviceDefaults.forcedDevice); // "auto": every family
  EXPECT_TRUE(lowestRenalOstium.empty());                       // optional: no default point
  EXPECT_TRUE(deviceCatalog.empty());                           // the catalogue beside the CLI
  EXPECT_TRUE(seed.empty());                                    // no default point: without one the seed is found
  EXPECT_EQ(std::string(XMLModuleDescription).rfind("<?xml ", 0), 0u);
  return EXIT_SUCCESS;
}

TEST(StentGraftSimulationXml, Defaults_EqualRegionGrowingParams)
{
  std::string program = "StentGraftSimulation";
  std::string volume = "ct.nrrd"; // the one required argument; it is not read
  char* argv[] = { program.data(), volume.data(), nullptr };
  EXPECT_EQ(ExpectParsedDefaultsEqualStructDefaults(2, argv), EXIT_SUCCESS);
}

TEST(StentGraftSimulationXml, ReturnValues_TheDeclaredOutputScalarsInTheirOrder)
{
  // Every scalar parameter of channel output, in the XML's order: what PlanReturnValues writes.
  const std::string xml = XMLModuleDescription;
  const std::regex scalar("<(double|float|integer|boolean|string|string-enumeration|double-vector)>([\\s\\S]*?)</\\1>");
  const std::regex name("<name>\\s*([A-Za-z0-9_]+)\\s*</name>");
  std::vector<std::string> declared;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), scalar); it != std::sregex_iterator(); ++it)
  {
    const std::string body = (*it)[2];
    std::smatch found;
    if (body.find("<channel>output</channel>") != std::string::npos && std::regex_search(body, found, name))
      declared.push_back(found[1]);
  }
  EXPECT_EQ(declared, ReturnValueNames());
}

TEST(StentGraftSimulationXml, SplitNumbers_StrictComponents)
{
  EXPECT_EQ(clp::SplitNumbers<float>("12.5,-3.25,40", "seed", 3), (std::vector<float>{ 12.5f, -3.25f, 40.0f }));
  EXPECT_THROW(clp::SplitNumbers<float>("a,b,c", "seed", 3), clp::ParseError);
  EXPECT_THROW(clp::SplitNumbers<float>("1,2", "seed", 3), clp::ParseError);
  EXPECT_THROW(clp::SplitNumbers<float>("1,,3", "seed", 3), clp::ParseError);
  EXPECT_THROW(clp::SplitNumbers<int>("1,2.5,3", "sizeVoxels", 3), clp::ParseError);
  try
  {
    clp::SplitNumbers<float>("a,b,c", "seed", 3);
  }
  catch (const clp::ParseError& e)
  {
    EXPECT_STREQ(e.what(), "--seed got 'a,b,c': 'a' is not a number; expected comma-separated numbers, for "
                           "example 1.5,-20,33");
  }
}

} // namespace
} // namespace sgp
