#include "IO/ReadNeckRules.h"

#include <algorithm>
#include <functional>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "Common/Errors.h"
#include "Common/Text.h"
#include "IO/JsonText.h"
#include "IO/ReadTextFile.h"
#include "IO/ResourcePath.h"

namespace sgp
{

namespace
{

using Json = nlohmann::json;

/// Reads the top level (index −1) or one rule field by field, naming them in errors.
class FieldReader
{
public:
  FieldReader(const std::string& origin, int index)
    : m_Origin(origin)
    , m_Index(index)
  {
  }

  void SetId(const std::string& id) { m_Id = id; }

  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError(DescribeNeckRuleField(m_Origin, m_Index, m_Id, field) + ": " + seen + "; expected " + expected +
                     "; correct the " + (m_Index < 0 ? "file." : "rule."));
  }

  void OnlyKeys(const Json& object, const std::vector<std::string>& allowed) const
  {
    const std::string unknown = UnknownJsonKey(object, allowed);
    if (!unknown.empty())
      Fail(unknown, "is an unknown field", "one of " + JoinWithCommas(allowed) + " (check the spelling)");
  }

  const Json& Member(const Json& object, const std::string& key, Json::value_t type) const
  {
    const std::string mismatch = JsonMemberMismatch(object, key, type);
    if (!mismatch.empty())
      Fail(key, mismatch, JsonTypeWords(type));
    return object.at(key);
  }

  double Number(const Json& object, const std::string& key) const
  {
    return Member(object, key, Json::value_t::number_float).get<double>();
  }

  std::string Text(const Json& object, const std::string& key) const
  {
    return Member(object, key, Json::value_t::string).get<std::string>();
  }

private:
  std::string m_Origin;
  int m_Index;
  std::string m_Id;
};

NeckRule ReadRule(const std::string& origin, const Json& rules, size_t index)
{
  FieldReader r(origin, int(index));
  const Json& json = rules[index];
  if (!json.is_object())
    throw InputError(DescribeNeckRuleField(origin, -1, "", "rules[" + std::to_string(index) + "]") + ": is " +
                     DescribeJsonValue(json) + "; expected an object describing one rule; correct the file.");
  NeckRule rule;
  rule.id = r.Text(json, "id");
  r.SetId(rule.id);
  r.OnlyKeys(json, { "id", "quantity", "hostileWhen", "threshold", "unit", "description", "source" });
  rule.quantity = r.Text(json, "quantity");
  const std::string when = r.Text(json, "hostileWhen");
  const std::optional<HostileWhen> parsed = HostileWhenFromString(when);
  if (!parsed)
    r.Fail("hostileWhen", "is \"" + when + "\"",
           "one of below, atOrBelow, above, atOrAbove (the 'at' forms count the threshold itself as hostile)");
  rule.hostileWhen = *parsed;
  rule.threshold = r.Number(json, "threshold");
  rule.unit = r.Text(json, "unit");
  rule.description = r.Text(json, "description");
  rule.source = r.Text(json, "source");
  return rule;
}

/// Follows the parse (nlohmann's parser callback) so that an error can name where it happened:
/// one frame per open object (its current key, and its "id" once read) or array (the index of
/// its current element). The parser calls back for every key, primitive value and container
/// start/end before it throws, so after an exception the frames hold the path to the failure.
class PathTracker
{
public:
  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed)
  {
    switch (event)
    {
      case Json::parse_event_t::object_start:
        EnterElement();
        m_Frames.push_back({ false, -1, "", "" });
        break;
      case Json::parse_event_t::array_start:
        EnterElement();
        m_Frames.push_back({ true, -1, "", "" });
        break;
      case Json::parse_event_t::key:
        m_Frames.back().key = parsed.get<std::string>();
        break;
      case Json::parse_event_t::value:
        EnterElement();
        if (!m_Frames.empty() && !m_Frames.back().array && m_Frames.back().key == "id" && parsed.is_string())
          m_Frames.back().id = parsed.get<std::string>();
        break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        m_Frames.pop_back();
        break;
    }
    return true;
  }

  /// Where the failure happened, as the messages name it: "rules[2] \"short-neck\", field
  /// 'threshold'" or "field 'version'"; "" at the top level before any key.
  std::string Location() const
  {
    const bool inRules =
      m_Frames.size() >= 2 && m_Frames[0].key == "rules" && m_Frames[1].array && m_Frames[1].index >= 0;
    std::string field;
    for (size_t i = inRules ? 2 : 0; i < m_Frames.size(); ++i)
    {
      const Frame& f = m_Frames[i];
      if (f.array && f.index >= 0)
        field += "[" + std::to_string(f.index) + "]";
      else if (!f.array && !f.key.empty())
        field += (field.empty() ? "" : ".") + f.key;
    }
    if (!inRules)
      return field.empty() ? "" : "field '" + field + "'";
    const std::string id = m_Frames.size() > 2 ? m_Frames[2].id : "";
    return "rules[" + std::to_string(m_Frames[1].index) + "]" + (id.empty() ? "" : " \"" + id + "\"") +
           (field.empty() ? "" : ", field '" + field + "'");
  }

private:
  struct Frame
  {
    bool array;
    long index;      ///< arrays: the current element
    std::string key; ///< objects: the current key
    std::string id;  ///< objects: the "id" read so far
  };

  void EnterElement()
  {
    if (!m_Frames.empty() && m_Frames.back().array)
      ++m_Frames.back().index;
  }

  std::vector<Frame> m_Frames;
};

/// The parsed text; a syntax error or a number that overflows a double (nlohmann's
/// out_of_range 406, as for 1e999: JSON has no NaN or infinity) becomes an InputError naming
/// the place.
Json ParseJson(const std::string& text, const std::string& origin)
{
  PathTracker tracker;
  try
  {
    return Json::parse(text, std::ref(tracker));
  }
  catch (const Json::parse_error& e)
  {
    const std::string where = tracker.Location();
    throw InputError("Hostile-neck rules '" + origin + "' is not valid JSON: " + JsonErrorMessage(e.what()) +
                     (where.empty() ? "" : " (near " + where + ")") +
                     "; fix the syntax there (often a missing comma, quote or bracket).");
  }
  catch (const Json::exception& e)
  {
    const std::string where = tracker.Location();
    throw InputError("Hostile-neck rules '" + origin + "'" + (where.empty() ? "" : ", " + where) + ": " +
                     JsonErrorMessage(e.what()) +
                     "; expected a finite number (JSON has no NaN or infinity); correct the value.");
  }
}

} // namespace

NeckRuleSet ParseNeckRules(const std::string& text, const std::string& origin)
{
  const Json json = ParseJson(text, origin);
  FieldReader top(origin, -1);
  if (!json.is_object())
    top.Fail("(top level)", "is " + DescribeJsonValue(json), "an object with format, version, name and rules");
  top.OnlyKeys(json, { "format", "version", "name", "description", "rules" });
  const std::string format = top.Text(json, "format");
  if (format != NeckRulesFormat)
    top.Fail("format", "is \"" + format + "\"", "\"" + std::string(NeckRulesFormat) + "\" (a hostile-neck rule file)");
  const Json& version = top.Member(json, "version", Json::value_t::number_float);
  if (!version.is_number_integer() && !version.is_number_unsigned())
    top.Fail("version", "is " + DescribeJsonValue(version), "the integer " + std::to_string(NeckRulesFormatVersion));
  if (version.get<long long>() != NeckRulesFormatVersion)
    top.Fail("version", "is " + DescribeJsonValue(version),
             std::to_string(NeckRulesFormatVersion) + " (the version this StentGraftPlanner reads)");
  NeckRuleSet set;
  set.origin = origin;
  set.name = top.Text(json, "name");
  if (json.contains("description"))
    top.Text(json, "description");
  const Json& rules = top.Member(json, "rules", Json::value_t::array);
  for (size_t i = 0; i < rules.size(); ++i)
    set.rules.push_back(ReadRule(origin, rules, i));
  ValidateNeckRuleSet(set, origin);
  return set;
}

NeckRuleSet ReadNeckRules(const std::string& path)
{
  return ParseNeckRules(ReadTextFile(path, "hostile-neck rules",
                                     "a rule file "
                                     "(the shipped one is Resources/hostile-neck-rules.json)"),
                        path);
}

std::string DefaultNeckRulesPath(const std::string& argv0)
{
  return BesideExecutable(argv0, NeckRulesFileName);
}

} // namespace sgp
