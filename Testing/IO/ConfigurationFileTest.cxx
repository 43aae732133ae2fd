// The configuration file (issue 47 item 1): what ConfigurationJson writes ParseConfiguration reads
// back field for field, and each malformed field is one error naming it and what it must be.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "IO/ConfigurationFile.h"

namespace sgp
{
namespace
{

GivenConfiguration Example()
{
  GivenConfiguration g;
  g.family = "Endurant II";
  g.mainBodySide = 1;
  GivenComponent body;
  body.role = ComponentRole::MainBody;
  body.code = "ETBF2516C145E";
  body.proximalEdgeBelowLowestRenalMm = 2.123456789012345;
  GivenComponent limb;
  limb.role = ComponentRole::Limb;
  limb.side = 0;
  limb.distalDiameterMm = 16.0;
  limb.lengthMm = 124.0;
  limb.overlapMm = 33.33333333333333;
  GivenComponent extension;
  extension.role = ComponentRole::IliacExtension;
  extension.side = 0;
  extension.code = "ETEW1313C082E";
  extension.distalEdgeAboveInternalIliacMm = -2.5;
  g.components = { body, limb, extension };
  return g;
}

bool Same(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

TEST(ConfigurationFile, WrittenThenRead_EveryFieldAtFullPrecision)
{
  const GivenConfiguration g = Example();
  const GivenConfiguration back = ParseConfiguration(ConfigurationJson(g, "a test"), "round trip");
  EXPECT_EQ(back.origin, "round trip");
  EXPECT_EQ(back.family, g.family);
  EXPECT_EQ(back.mainBodySide, g.mainBodySide);
  EXPECT_EQ(back.bodyLegLandsAlone, g.bodyLegLandsAlone);
  ASSERT_EQ(back.components.size(), g.components.size());
  for (std::size_t k = 0; k < g.components.size(); ++k)
  {
    const GivenComponent &a = back.components[k], &b = g.components[k];
    EXPECT_EQ(a.where, "components[" + std::to_string(k) + "]");
    EXPECT_EQ(int(a.role), int(b.role));
    EXPECT_EQ(a.side, b.side);
    EXPECT_EQ(a.code, b.code);
    // Exact: the file keeps doubles in their shortest round-trip form.
    for (const auto& [x, y] :
         { std::pair{ a.diameterMm, b.diameterMm }, std::pair{ a.distalDiameterMm, b.distalDiameterMm },
           std::pair{ a.lengthMm, b.lengthMm },
           std::pair{ a.proximalEdgeBelowLowestRenalMm, b.proximalEdgeBelowLowestRenalMm },
           std::pair{ a.overlapMm, b.overlapMm },
           std::pair{ a.distalEdgeAboveInternalIliacMm, b.distalEdgeAboveInternalIliacMm } })
      EXPECT_TRUE(Same(x, y)) << k << ": " << x << " vs " << y;
  }
}

TEST(ConfigurationFile, EachMalformedField_OneErrorNamingIt)
{
  const std::string head = R"({"format":"StentGraftPlanner configuration","formatVersion":1,"family":"Endurant II",)";
  const std::vector<std::pair<std::string, std::string>> cases = {
    { "[1, 2]", "(top level): is an array" },
    { R"({"format":"other","formatVersion":1,"family":"x","components":[]})", "format: is \"other\"" },
    { head + R"("components":[]})", "components: is empty" },
    { head + R"("components":{}})", "components: is an object" },
    { head + R"("mainBodySide":"middle","components":[{"role":"mainBody","code":"A"}]})",
      "mainBodySide: is \"middle\"; expected \"right\" or \"left\"" },
    { head + R"("bodyLegLandsAlone":"yes","components":[{"role":"mainBody","code":"A"}]})",
      "bodyLegLandsAlone: is the string" },
    { head + R"("components":[{"role":"limb","side":"left","distalDiameterMm":16,"lengthMm":-95}]})",
      "components[0].lengthMm: is the number -95; expected a positive number of mm" },
    { head + R"("components":[{"role":"limb","side":"left","code":124}]})", "components[0].code: is the number 124" },
    { head + R"("components":[{"role":"mainBody","code":"A","colour":"red"}]})",
      "components[0].colour: is an unknown field" },
    { head + R"("components":[{"side":"left","code":"A"}]})", "components[0].role: is missing" },
    { head + R"("components":[{"role":"stent","code":"A"}]})",
      "role 'stent'; expected mainBody, limb or iliacExtension" },
  };
  for (const auto& [text, says] : cases)
  {
    try
    {
      ParseConfiguration(text, "c.json");
      ADD_FAILURE() << "accepted: " << text;
    }
    catch (const InputError& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("Configuration 'c.json'"), std::string::npos) << message;
      EXPECT_NE(message.find(says), std::string::npos) << message;
    }
  }
  EXPECT_THROW(ReadConfiguration("/nonexistent/configuration.json"), InputError);
}

} // namespace
} // namespace sgp
