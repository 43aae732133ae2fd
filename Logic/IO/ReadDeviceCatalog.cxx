#include "IO/ReadDeviceCatalog.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "Common/Errors.h"
#include "Common/Text.h"
#include "IO/JsonText.h"

namespace sgp
{

namespace
{

using Json = nlohmann::json;

/// Reads one entry (the top level, or one family) field by field, naming them in errors.
class EntryReader
{
public:
  EntryReader(const std::string& origin, int familyIndex)
    : m_Origin(origin)
    , m_Index(familyIndex)
  {
  }

  void SetName(const std::string& name) { m_Name = name; }

  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError(DescribeCatalogField(m_Origin, m_Index, m_Name, field) + ": " + seen + "; expected " + expected +
                     "; correct the entry.");
  }

  /// Rejects fields other than `allowed` in `object` (found at `path`).
  void OnlyKeys(const Json& object, const std::string& path, const std::vector<std::string>& allowed) const
  {
    const std::string unknown = UnknownJsonKey(object, allowed);
    if (!unknown.empty())
      Fail(Join(path, unknown), "is an unknown field", "one of " + JoinWithCommas(allowed) + " (check the spelling)");
  }

  const Json& Member(const Json& object, const std::string& path, const std::string& key, Json::value_t type) const
  {
    const std::string mismatch = JsonMemberMismatch(object, key, type);
    if (!mismatch.empty())
      Fail(Join(path, key), mismatch, JsonTypeWords(type));
    return object.at(key);
  }

  double Number(const Json& object, const std::string& path, const std::string& key) const
  {
    return Member(object, path, key, Json::value_t::number_float).get<double>();
  }

  double OptionalNumber(const Json& object, const std::string& path, const std::string& key) const
  {
    return object.contains(key) ? Number(object, path, key) : std::numeric_limits<double>::quiet_NaN();
  }

  std::string Text(const Json& object, const std::string& path, const std::string& key, bool required = false) const
  {
    if (!required && !object.contains(key))
      return "";
    return Member(object, path, key, Json::value_t::string).get<std::string>();
  }

  const Json& Object(const Json& object, const std::string& path, const std::string& key) const
  {
    return Member(object, path, key, Json::value_t::object);
  }

  const Json& Array(const Json& object, const std::string& path, const std::string& key) const
  {
    return Member(object, path, key, Json::value_t::array);
  }

  /// The element `i` of `array` (at `path`), which must be an object.
  const Json& ObjectAt(const Json& array, const std::string& path, size_t i) const
  {
    const Json& item = array[i];
    if (!item.is_object())
      Fail(path + "[" + std::to_string(i) + "]", "is " + DescribeJsonValue(item), "an object");
    return item;
  }

  static std::string Join(const std::string& path, const std::string& key)
  {
    return path.empty() ? key : path + "." + key;
  }

private:
  std::string m_Origin;
  int m_Index;
  std::string m_Name;
};

std::vector<DeviceSize> ReadSizes(const EntryReader& r, const Json& component, const std::string& path)
{
  const Json& sizes = r.Array(component, path, "sizes");
  std::vector<DeviceSize> result;
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    const std::string item = path + ".sizes[" + std::to_string(i) + "]";
    const Json& size = r.ObjectAt(sizes, path + ".sizes", i);
    r.OnlyKeys(size, item, { "diameterMm", "profileFr" });
    result.push_back({ r.Number(size, item, "diameterMm"), r.Number(size, item, "profileFr") });
  }
  return result;
}

DeviceComponent ReadComponent(const EntryReader& r, const Json& family, const std::string& key, bool mainBody)
{
  const Json& json = r.Object(family, "", key);
  std::vector<std::string> allowed = { "sizes", "lengthRangeMm", "evidence" };
  if (mainBody)
    allowed.push_back("lengthToFlowDividerMm");
  r.OnlyKeys(json, key, allowed);
  DeviceComponent c;
  c.sizes = ReadSizes(r, json, key);
  c.evidence = r.Text(json, key, "evidence");
  if (json.contains("lengthRangeMm"))
  {
    const std::string path = key + ".lengthRangeMm";
    const Json& range = r.Object(json, key, "lengthRangeMm");
    r.OnlyKeys(range, path, { "min", "max" });
    c.lengthMinMm = r.Number(range, path, "min");
    c.lengthMaxMm = r.Number(range, path, "max");
  }
  if (json.contains("lengthToFlowDividerMm"))
  {
    const Json& lengths = r.Array(json, key, "lengthToFlowDividerMm");
    for (size_t i = 0; i < lengths.size(); ++i)
    {
      if (!lengths[i].is_number())
        r.Fail(key + ".lengthToFlowDividerMm[" + std::to_string(i) + "]", "is " + DescribeJsonValue(lengths[i]),
               "a number");
      c.lengthToFlowDividerMm.push_back(lengths[i].get<double>());
    }
  }
  return c;
}

/// One IFU limit object with the given bound keys ("min", "max") and an optional evidence.
IfuLimit ReadLimit(const EntryReader& r, const Json& ifu, const std::string& key, bool min, bool max)
{
  const std::string path = "ifu." + key;
  const Json& json = r.Object(ifu, "ifu", key);
  std::vector<std::string> allowed = { "evidence" };
  if (min)
    allowed.push_back("min");
  if (max)
    allowed.push_back("max");
  r.OnlyKeys(json, path, allowed);
  IfuLimit limit;
  if (min)
    limit.min = r.Number(json, path, "min");
  if (max)
    limit.max = r.Number(json, path, "max");
  limit.evidence = r.Text(json, path, "evidence");
  return limit;
}

DeviceIfu ReadIfu(const EntryReader& r, const Json& family)
{
  const Json& json = r.Object(family, "", "ifu");
  r.OnlyKeys(json, "ifu",
             { "neckLength", "neckDiameterMm", "neckAngleAlphaDeg", "iliacSealLengthMm", "iliacDiameterMm" });
  DeviceIfu ifu;
  const Json& neck = r.Object(json, "ifu", "neckLength");
  r.OnlyKeys(neck, "ifu.neckLength", { "tiers", "evidence" });
  const Json& tiers = r.Array(neck, "ifu.neckLength", "tiers");
  for (size_t i = 0; i < tiers.size(); ++i)
  {
    const std::string item = "ifu.neckLength.tiers[" + std::to_string(i) + "]";
    const Json& tier = r.ObjectAt(tiers, "ifu.neckLength.tiers", i);
    r.OnlyKeys(tier, item, { "minMm", "maxBetaDeg" });
    ifu.neckLengthTiers.push_back({ r.Number(tier, item, "minMm"), r.Number(tier, item, "maxBetaDeg") });
  }
  ifu.neckLengthEvidence = r.Text(neck, "ifu.neckLength", "evidence");
  ifu.neckDiameterMm = ReadLimit(r, json, "neckDiameterMm", true, true);
  if (json.contains("neckAngleAlphaDeg"))
    ifu.neckAngleAlphaDeg = ReadLimit(r, json, "neckAngleAlphaDeg", false, true);
  ifu.iliacSealLengthMm = ReadLimit(r, json, "iliacSealLengthMm", true, false);
  ifu.iliacDiameterMm = ReadLimit(r, json, "iliacDiameterMm", true, true);
  return ifu;
}

DeviceFamily ReadFamily(const std::string& origin, const Json& families, size_t index)
{
  EntryReader r(origin, int(index));
  const Json& json = families[index];
  if (!json.is_object())
    r.Fail("families[" + std::to_string(index) + "]", "is " + DescribeJsonValue(json),
           "an object describing one device family");
  DeviceFamily family;
  family.name = r.Text(json, "", "name", true);
  r.SetName(family.name);
  r.OnlyKeys(json, "", { "name", "manufacturer", "source", "note", "diameterReference", "mainBodies", "limbs", "ifu" });
  family.manufacturer = r.Text(json, "", "manufacturer");
  family.source = r.Text(json, "", "source", true);
  family.note = r.Text(json, "", "note");
  const std::string reference = r.Text(json, "", "diameterReference", true);
  if (reference != "outerWall" && reference != "lumen")
    r.Fail("diameterReference", "is \"" + reference + "\"",
           "\"outerWall\" or \"lumen\" (the diameter its IFU ranges use)");
  family.diameterReference = reference == "lumen" ? DiameterReference::Lumen : DiameterReference::OuterWall;
  family.mainBodies = ReadComponent(r, json, "mainBodies", true);
  family.limbs = ReadComponent(r, json, "limbs", false);
  family.ifu = ReadIfu(r, json);
  return family;
}

} // namespace

DeviceCatalog ParseDeviceCatalog(const std::string& text, const std::string& origin)
{
  Json json;
  try
  {
    json = Json::parse(text);
  }
  catch (const Json::parse_error& e)
  {
    throw InputError("Device catalogue '" + origin + "' is not valid JSON: " + JsonErrorMessage(e.what()) +
                     "; fix the syntax there (often a missing comma, quote or bracket).");
  }
  catch (const Json::exception& e) // e.g. a number beyond a double (1e309): out_of_range 406
  {
    throw InputError("Device catalogue '" + origin + "' cannot be read: " + JsonErrorMessage(e.what()) +
                     "; write every number as a finite decimal.");
  }
  EntryReader top(origin, -1);
  if (!json.is_object())
    top.Fail("(top level)", "is " + DescribeJsonValue(json), "an object with formatVersion and families");
  top.OnlyKeys(json, "", { "formatVersion", "description", "families" });
  const Json& version = top.Member(json, "", "formatVersion", Json::value_t::number_float);
  if (!version.is_number_integer() && !version.is_number_unsigned())
    top.Fail("formatVersion", "is " + DescribeJsonValue(version),
             "the integer " + std::to_string(DeviceCatalogFormatVersion));
  DeviceCatalog catalog;
  catalog.origin = origin;
  catalog.formatVersion = version.get<int>();
  top.Text(json, "", "description");
  const Json& families = top.Array(json, "", "families");
  for (size_t i = 0; i < families.size(); ++i)
    catalog.families.push_back(ReadFamily(origin, families, i));
  ValidateDeviceCatalog(catalog);
  return catalog;
}

DeviceCatalog ReadDeviceCatalog(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in)
    throw InputError("Cannot read the device catalogue '" + path +
                     "': the file does not exist or is not readable; give the path of a devices.json "
                     "(the shipped one is Resources/devices.json).");
  return ParseDeviceCatalog(text.str(), path);
}

} // namespace sgp
