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
#include "IO/ReadTextFile.h"

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
  /// Later messages name this component ("mainBodies.items[3] ETBF2313C124E") before the field.
  void SetComponent(const std::string& label) { m_Component = label; }

  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    std::string where = DescribeCatalogField(m_Origin, m_Index, m_Name, field);
    if (!m_Component.empty())
      where.insert(where.rfind(", field '"), ", component " + m_Component);
    throw InputError(where + ": " + seen + "; expected " + expected + "; correct the entry.");
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
  std::string m_Component;
};

/// A required field that is a number or null (not found in any public source): NaN for null.
double NumberOrNull(const EntryReader& r, const Json& object, const std::string& path, const std::string& key)
{
  if (object.contains(key) && object.at(key).is_null())
    return std::numeric_limits<double>::quiet_NaN();
  const std::string mismatch = JsonMemberMismatch(object, key, Json::value_t::number_float);
  if (!mismatch.empty())
    r.Fail(EntryReader::Join(path, key), mismatch, "a number, or null when no public source gives it");
  return object.at(key).get<double>();
}

std::vector<FigureConflict> ReadConflicts(const EntryReader& r, const Json& item, const std::string& path)
{
  std::vector<FigureConflict> conflicts;
  if (!item.contains("conflicts"))
    return conflicts;
  const Json& array = r.Array(item, path, "conflicts");
  for (size_t i = 0; i < array.size(); ++i)
  {
    const std::string at = EntryReader::Join(path, "conflicts[" + std::to_string(i) + "]");
    const Json& json = r.ObjectAt(array, EntryReader::Join(path, "conflicts"), i);
    r.OnlyKeys(json, at, { "field", "values", "note" });
    FigureConflict conflict;
    conflict.field = r.Text(json, at, "field", true);
    conflict.note = r.Text(json, at, "note");
    const Json& values = r.Array(json, at, "values");
    for (size_t k = 0; k < values.size(); ++k)
    {
      if (!values[k].is_number())
        r.Fail(at + ".values[" + std::to_string(k) + "]", "is " + DescribeJsonValue(values[k]), "a number");
      conflict.values.push_back(values[k].get<double>());
    }
    conflicts.push_back(conflict);
  }
  return conflicts;
}

/// One component of a group (`key`: mainBodies, limbs, iliacExtensions, aorticCuffs); messages
/// name it as "component <key>.items[i] <code>" and the field by its own name.
CatalogueComponent ReadItem(const EntryReader& group,
                            const Json& items,
                            const std::string& key,
                            size_t i,
                            ComponentRole role,
                            const std::string& groupName,
                            const std::string& groupEvidence)
{
  const Json& json = group.ObjectAt(items, key + ".items", i);
  CatalogueComponent c;
  c.role = role;
  c.index = int(i);
  EntryReader r = group;
  r.SetComponent(c.Label());
  if (!json.contains("code"))
    r.Fail("code", "is missing", "the catalogue code, or null when it is not public");
  if (!json.at("code").is_null())
  {
    c.code = r.Text(json, "", "code", true);
    if (TrimBlanks(c.code).empty())
      r.Fail("code", "is empty", "the catalogue code, or null when it is not public");
    r.SetComponent(c.Label());
  }
  const bool body = role == ComponentRole::MainBody;
  std::vector<std::string> allowed = { "name",      "code",     "diameterMm", "distalDiameterMm", "lengthMm",
                                       "profileFr", "evidence", "note",       "conflicts" };
  if (body)
    allowed.insert(allowed.end(), { "flowDividerMm", "gateEndMm", "gateDiameterMm", "crotchWidthMm" });
  r.OnlyKeys(json, "", allowed);
  c.name = json.contains("name") ? r.Text(json, "", "name") : groupName;
  c.diameterMm = NumberOrNull(r, json, "", "diameterMm");
  c.distalDiameterMm = NumberOrNull(r, json, "", "distalDiameterMm");
  c.lengthMm = NumberOrNull(r, json, "", "lengthMm");
  c.profileFr = NumberOrNull(r, json, "", "profileFr");
  if (body)
  {
    c.flowDividerMm = NumberOrNull(r, json, "", "flowDividerMm");
    c.gateEndMm = NumberOrNull(r, json, "", "gateEndMm");
    c.gateDiameterMm = NumberOrNull(r, json, "", "gateDiameterMm");
    c.crotchWidthMm = NumberOrNull(r, json, "", "crotchWidthMm");
  }
  c.evidence = json.contains("evidence") ? r.Text(json, "", "evidence") : groupEvidence;
  c.note = r.Text(json, "", "note");
  c.conflicts = ReadConflicts(r, json, "");
  return c;
}

/// A group of components of one role: { "name", "evidence", "items": [ … ] }; `required` groups
/// need at least one item.
void ReadGroup(const EntryReader& r, const Json& family, ComponentRole role, bool required, DeviceFamily& out)
{
  const std::string key = GroupKey(role);
  if (!required && !family.contains(key))
    return;
  const Json& json = r.Object(family, "", key);
  r.OnlyKeys(json, key, { "name", "evidence", "items" });
  const std::string name = r.Text(json, key, "name");
  const std::string evidence = r.Text(json, key, "evidence");
  const Json& items = r.Array(json, key, "items");
  if (items.empty())
    r.Fail(key + ".items", "is empty", "at least one component");
  for (size_t i = 0; i < items.size(); ++i)
    out.components.push_back(ReadItem(r, items, key, i, role, name, evidence));
}

/// The junctions: overlapMm {min, max} and gateClearanceMm {min}, each number or null.
ComponentJunctions ReadJunctions(const EntryReader& r, const Json& family)
{
  const Json& json = r.Object(family, "", "junctions");
  r.OnlyKeys(json, "junctions", { "overlapMm", "gateClearanceMm" });
  ComponentJunctions junctions;
  const Json& overlap = r.Object(json, "junctions", "overlapMm");
  r.OnlyKeys(overlap, "junctions.overlapMm", { "min", "max", "evidence" });
  junctions.overlapMm.min = NumberOrNull(r, overlap, "junctions.overlapMm", "min");
  junctions.overlapMm.max = NumberOrNull(r, overlap, "junctions.overlapMm", "max");
  junctions.overlapMm.evidence = r.Text(overlap, "junctions.overlapMm", "evidence");
  const Json& clearance = r.Object(json, "junctions", "gateClearanceMm");
  r.OnlyKeys(clearance, "junctions.gateClearanceMm", { "min", "evidence" });
  junctions.gateClearanceMm.min = NumberOrNull(r, clearance, "junctions.gateClearanceMm", "min");
  junctions.gateClearanceMm.evidence = r.Text(clearance, "junctions.gateClearanceMm", "evidence");
  return junctions;
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
  r.OnlyKeys(json, "",
             { "name", "manufacturer", "source", "note", "verified", "diameterReference", "mainBodies", "limbs",
               "iliacExtensions", "aorticCuffs", "junctions", "ifu" });
  family.manufacturer = r.Text(json, "", "manufacturer");
  family.source = r.Text(json, "", "source", true);
  family.note = r.Text(json, "", "note");
  const std::string reference = r.Text(json, "", "diameterReference", true);
  if (reference != "outerWall" && reference != "lumen")
    r.Fail("diameterReference", "is \"" + reference + "\"",
           "\"outerWall\" or \"lumen\" (the diameter its IFU ranges use)");
  family.diameterReference = reference == "lumen" ? DiameterReference::Lumen : DiameterReference::OuterWall;
  family.verified = r.Member(json, "", "verified", Json::value_t::boolean).get<bool>();
  ReadGroup(r, json, ComponentRole::MainBody, true, family);
  ReadGroup(r, json, ComponentRole::Limb, true, family);
  ReadGroup(r, json, ComponentRole::IliacExtension, false, family);
  ReadGroup(r, json, ComponentRole::AorticCuff, false, family);
  DeriveSizesFromComponents(family);
  family.junctions = ReadJunctions(r, json);
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
  return ParseDeviceCatalog(ReadTextFile(path, "device catalogue",
                                         "a devices.json "
                                         "(the shipped one is Resources/devices.json)"),
                            path);
}

} // namespace sgp
