#include "IO/ConfigurationFile.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "Common/Errors.h"
#include "Common/Text.h"
#include "IO/JsonText.h"
#include "IO/ReadTextFile.h"

namespace sgp
{
namespace
{

using Json = nlohmann::ordered_json;
using Type = nlohmann::json::value_t;

class FieldReader
{
public:
  explicit FieldReader(std::string origin)
    : m_Origin(std::move(origin))
  {
  }

  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError("Configuration '" + m_Origin + "', " + field + ": " + seen + "; expected " + expected + ".");
  }

  void OnlyKeys(const nlohmann::json& object, const std::string& where, const std::vector<std::string>& allowed) const
  {
    const std::string unknown = UnknownJsonKey(object, allowed);
    if (!unknown.empty())
      Fail(where + unknown, "is an unknown field", "one of " + JoinWithCommas(allowed) + " (check the spelling)");
  }

  const nlohmann::json& Member(const nlohmann::json& object,
                               const std::string& where,
                               const std::string& key,
                               Type type) const
  {
    const std::string mismatch = JsonMemberMismatch(object, key, type);
    if (!mismatch.empty())
      Fail(where + key, mismatch, JsonTypeWords(type));
    return object.at(key);
  }

  double OptionalNumber(const nlohmann::json& object, const std::string& where, const std::string& key) const
  {
    return object.contains(key) ? Member(object, where, key, Type::number_float).get<double>() : std::nan("");
  }

  std::string OptionalText(const nlohmann::json& object, const std::string& where, const std::string& key) const
  {
    return object.contains(key) ? Member(object, where, key, Type::string).get<std::string>() : std::string();
  }

  int Side(const nlohmann::json& object, const std::string& where, const std::string& key) const
  {
    if (!object.contains(key))
      return -1;
    const std::string side = Member(object, where, key, Type::string).get<std::string>();
    if (side != "right" && side != "left")
      Fail(where + key, "is \"" + side + "\"", "\"right\" or \"left\" (the patient's side)");
    return side == "right" ? 0 : 1;
  }

private:
  std::string m_Origin;
};

} // namespace

GivenConfiguration ParseConfiguration(const std::string& text, const std::string& origin)
{
  nlohmann::json json;
  try
  {
    json = nlohmann::json::parse(text);
  }
  catch (const nlohmann::json::exception& e)
  {
    throw InputError("Configuration '" + origin + "' is not valid JSON: " + JsonErrorMessage(e.what()) +
                     "; fix the syntax there (often a missing comma, quote or bracket).");
  }
  const FieldReader r(origin);
  if (!json.is_object())
    r.Fail("(top level)", "is " + DescribeJsonValue(json),
           "an object with format, formatVersion, family and components");
  r.OnlyKeys(json, "",
             { "format", "formatVersion", "description", "family", "mainBodySide", "bodyLegLandsAlone", "components" });
  const std::string format = r.Member(json, "", "format", Type::string).get<std::string>();
  if (format != ConfigurationFormat)
    r.Fail("format", "is \"" + format + "\"", "\"" + std::string(ConfigurationFormat) + "\"");
  const nlohmann::json& version = r.Member(json, "", "formatVersion", Type::number_float);
  if ((!version.is_number_integer() && !version.is_number_unsigned()) ||
      version.get<long long>() != ConfigurationFormatVersion)
    r.Fail("formatVersion", "is " + DescribeJsonValue(version),
           std::to_string(ConfigurationFormatVersion) + " (the version this StentGraftPlanner reads)");
  r.OptionalText(json, "", "description");
  GivenConfiguration g;
  g.origin = origin;
  g.family = r.Member(json, "", "family", Type::string).get<std::string>();
  g.mainBodySide = r.Side(json, "", "mainBodySide");
  if (json.contains("bodyLegLandsAlone"))
    g.bodyLegLandsAlone = r.Member(json, "", "bodyLegLandsAlone", Type::boolean).get<bool>();
  const nlohmann::json& components = r.Member(json, "", "components", Type::array);
  if (components.empty())
    r.Fail("components", "is empty", "at least the main body");
  for (std::size_t i = 0; i < components.size(); ++i)
  {
    const std::string where = "components[" + std::to_string(i) + "]";
    const nlohmann::json& c = components[i];
    if (!c.is_object())
      r.Fail(where, "is " + DescribeJsonValue(c), "an object describing one component");
    r.OnlyKeys(c, where + ".",
               { "role", "side", "code", "diameterMm", "distalDiameterMm", "lengthMm", "proximalEdgeBelowLowestRenalMm",
                 "overlapMm", "distalEdgeAboveInternalIliacMm" });
    GivenComponent component;
    component.where = where;
    component.role = ParseGivenRole(r.Member(c, where + ".", "role", Type::string).get<std::string>(),
                                    "Configuration '" + origin + "', " + where + ".role");
    component.side = r.Side(c, where + ".", "side");
    component.code = r.OptionalText(c, where + ".", "code");
    component.diameterMm = r.OptionalNumber(c, where + ".", "diameterMm");
    component.distalDiameterMm = r.OptionalNumber(c, where + ".", "distalDiameterMm");
    component.lengthMm = r.OptionalNumber(c, where + ".", "lengthMm");
    for (const auto& [key, value] :
         { std::pair{ "diameterMm", component.diameterMm }, std::pair{ "distalDiameterMm", component.distalDiameterMm },
           std::pair{ "lengthMm", component.lengthMm } })
      if (!(value > 0.0) && !std::isnan(value))
        r.Fail(where + "." + key, "is " + DescribeJsonValue(c.at(key)), "a positive number of mm");
    component.proximalEdgeBelowLowestRenalMm = r.OptionalNumber(c, where + ".", "proximalEdgeBelowLowestRenalMm");
    component.overlapMm = r.OptionalNumber(c, where + ".", "overlapMm");
    component.distalEdgeAboveInternalIliacMm = r.OptionalNumber(c, where + ".", "distalEdgeAboveInternalIliacMm");
    g.components.push_back(component);
  }
  return g;
}

GivenConfiguration ReadConfiguration(const std::string& path)
{
  return ParseConfiguration(ReadTextFile(path, "configuration",
                                         "a configuration file "
                                         "(one written by --outputConfiguration, edited)"),
                            path);
}

std::string ConfigurationJson(const GivenConfiguration& configuration, const std::string& description)
{
  Json json;
  json["format"] = ConfigurationFormat;
  json["formatVersion"] = ConfigurationFormatVersion;
  if (!description.empty())
    json["description"] = description;
  json["family"] = configuration.family;
  if (configuration.mainBodySide >= 0)
    json["mainBodySide"] = configuration.mainBodySide == 0 ? "right" : "left";
  if (configuration.bodyLegLandsAlone)
    json["bodyLegLandsAlone"] = true;
  Json components = Json::array();
  for (const GivenComponent& c : configuration.components)
  {
    Json entry;
    entry["role"] = ToString(c.role);
    if (c.side >= 0)
      entry["side"] = c.side == 0 ? "right" : "left";
    if (!c.code.empty())
      entry["code"] = c.code;
    for (const auto& [key, value] :
         { std::pair{ "diameterMm", c.diameterMm }, std::pair{ "distalDiameterMm", c.distalDiameterMm },
           std::pair{ "lengthMm", c.lengthMm },
           std::pair{ "proximalEdgeBelowLowestRenalMm", c.proximalEdgeBelowLowestRenalMm },
           std::pair{ "overlapMm", c.overlapMm },
           std::pair{ "distalEdgeAboveInternalIliacMm", c.distalEdgeAboveInternalIliacMm } })
      if (std::isfinite(value))
        entry[key] = value;
    components.push_back(entry);
  }
  json["components"] = components;
  return json.dump(2) + "\n";
}

} // namespace sgp
