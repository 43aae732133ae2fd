#include "Device/HostileNeck.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "Common/Errors.h"
#include "Common/Text.h"

namespace sgp
{

namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool InRange(const NeckQuantity& q, double value)
{
  return std::isfinite(value) && (q.minExclusive ? value > q.min : value >= q.min) && value <= q.max;
}

/// "a number of mm ≥ 0", "a number of deg in 0–180", "a finite number of mm".
std::string RangeText(const NeckQuantity& q)
{
  const std::string unit = q.unit;
  if (std::isinf(q.min) && std::isinf(q.max))
    return "a finite number of " + unit;
  if (std::isinf(q.max))
    return "a number of " + unit + (q.minExclusive ? " > " : " ≥ ") + CompactNumber(q.min);
  return "a number of " + unit + " in " + CompactNumber(q.min) + "–" + CompactNumber(q.max);
}

std::string ValueText(double value, const std::string& unit)
{
  if (std::isnan(value))
    return "NaN";
  if (std::isinf(value))
    return value > 0 ? "infinite" : "−infinite";
  return CompactNumber(value) + " " + unit;
}

/// Checks one rule field by field; `Fail` builds the message with the field's name.
class RuleValidator
{
public:
  RuleValidator(const NeckRuleSet& set, const std::string& file, int index)
    : m_Set(set)
    , m_File(file)
    , m_Index(index)
    , m_Rule(set.rules[size_t(index)])
  {
  }

  void Run() const
  {
    if (TrimBlanks(m_Rule.id).empty())
      Fail("id", "is empty", "a short unique name such as \"short-neck\"");
    for (int j = 0; j < m_Index; ++j)
      if (LowerCase(TrimBlanks(m_Set.rules[size_t(j)].id)) == LowerCase(TrimBlanks(m_Rule.id)))
        Fail("id", "repeats rules[" + std::to_string(j) + "]", "unique ids (case-insensitive)");
    const NeckQuantity* q = FindNeckQuantity(m_Rule.quantity);
    if (!q)
    {
      std::vector<std::string> known;
      for (const NeckQuantity& k : NeckQuantities())
        known.push_back(k.name);
      Fail("quantity", "is \"" + m_Rule.quantity + "\"", "one of " + JoinWithCommas(known) + " (check the spelling)");
    }
    if (m_Rule.unit != q->unit)
      Fail("unit", "is \"" + m_Rule.unit + "\"", "\"" + std::string(q->unit) + "\", the unit of " + q->name);
    if (!InRange(*q, m_Rule.threshold))
      Fail("threshold", "is " + ValueText(m_Rule.threshold, m_Rule.unit), RangeText(*q) + " for " + q->name);
    if (TrimBlanks(m_Rule.source).empty())
      Fail("source", "is empty", "the publication the threshold comes from, with its evidence mark");
  }

private:
  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError(DescribeNeckRuleField(m_File, m_Index, m_Rule.id, field) + ": " + seen + "; expected " + expected +
                     "; correct the rule.");
  }

  const NeckRuleSet& m_Set;
  const std::string& m_File;
  int m_Index;
  const NeckRule& m_Rule;
};

bool HostileAbove(HostileWhen when)
{
  return when == HostileWhen::Above || when == HostileWhen::AtOrAbove;
}

bool ThresholdIsHostile(HostileWhen when)
{
  return when == HostileWhen::AtOrAbove || when == HostileWhen::AtOrBelow;
}

/// The not-hostile side as a requirement: Below → "≥ t", AtOrBelow → "> t", Above → "≤ t",
/// AtOrAbove → "< t".
std::string NotHostileText(const NeckRule& rule)
{
  const char* relation = nullptr;
  switch (rule.hostileWhen)
  {
    case HostileWhen::Below:
      relation = "≥ ";
      break;
    case HostileWhen::AtOrBelow:
      relation = "> ";
      break;
    case HostileWhen::Above:
      relation = "≤ ";
      break;
    case HostileWhen::AtOrAbove:
      relation = "< ";
      break;
  }
  const std::string number = CompactNumber(rule.threshold);
  return relation + (rule.unit == "deg" ? number + "°" : number + " " + rule.unit);
}

CriterionCheck CheckRule(const NeckRule& rule, const NeckQuantity& q, double value, double lengthUncertaintyMm)
{
  CriterionCheck check;
  check.name = rule.id;
  check.value = value;
  check.unit = rule.unit;
  (HostileAbove(rule.hostileWhen) ? check.max : check.min) = rule.threshold;
  check.requirement = NotHostileText(rule);
  check.evidence = rule.source;
  const std::string opening = std::string(q.label) + " ";
  if (std::isnan(value))
  {
    check.text = opening + "not measured, needs " + check.requirement + ": indeterminate";
    return check;
  }
  check.margin = HostileAbove(rule.hostileWhen) ? rule.threshold - value : value - rule.threshold;
  const bool pass = check.margin > 0.0 || (check.margin == 0.0 && !ThresholdIsHostile(rule.hostileWhen));
  check.status = pass ? CheckStatus::Pass : CheckStatus::Fail;
  check.text = opening + QuantityText(value, rule.unit) + ", needs " + check.requirement + ": " +
               SignedQuantityText(check.margin, rule.unit);
  if (check.margin == 0.0 && !pass)
    check.text += " (the threshold itself is hostile)";
  if (rule.quantity == "neckLength" && lengthUncertaintyMm > 0.0 && std::abs(check.margin) <= lengthUncertaintyMm)
  {
    check.status = CheckStatus::Indeterminate;
    check.text +=
      ", within the measurement's uncertainty (±" + QuantityText(lengthUncertaintyMm, "mm") + "): indeterminate";
  }
  return check;
}

/// "a, b, c": the ids of the checks with `status`.
std::string Ids(const std::vector<CriterionCheck>& checks, CheckStatus status)
{
  std::string list;
  for (const CriterionCheck& c : checks)
    if (c.status == status)
      list += (list.empty() ? "" : ", ") + c.name;
  return list;
}

std::string Summary(const NeckAssessment& a, const NeckRuleSet& rules)
{
  const std::string of =
    std::to_string(a.checks.size()) + " rules of '" + (rules.name.empty() ? rules.origin : rules.name) + "'";
  std::string summary;
  if (a.hostile)
    summary = "hostile neck: fails " + Ids(a.checks, CheckStatus::Fail) + " (" +
              std::to_string(a.Count(CheckStatus::Fail)) + " of " + of + ")";
  else if (a.determinate)
    summary = "not hostile: passes all " + of;
  else
    summary = "undetermined: no rule fails, " + std::to_string(a.Count(CheckStatus::Pass)) + " of " + of + " pass";
  if (!a.determinate)
    summary += "; indeterminate: " + Ids(a.checks, CheckStatus::Indeterminate);
  return summary;
}

} // namespace

const char* ToString(HostileWhen when)
{
  switch (when)
  {
    case HostileWhen::Below:
      return "below";
    case HostileWhen::AtOrBelow:
      return "atOrBelow";
    case HostileWhen::Above:
      return "above";
    case HostileWhen::AtOrAbove:
      break;
  }
  return "atOrAbove";
}

std::optional<HostileWhen> HostileWhenFromString(const std::string& text)
{
  for (HostileWhen when : { HostileWhen::Below, HostileWhen::AtOrBelow, HostileWhen::Above, HostileWhen::AtOrAbove })
    if (text == ToString(when))
      return when;
  return std::nullopt;
}

const std::vector<NeckQuantity>& NeckQuantities()
{
  static const std::vector<NeckQuantity> quantities = {
    { "neckLength", "mm", "neck length", 0.0, Infinity, false, &NeckAnatomy::neckLengthMm },
    { "neckDiameter", "mm", "neck diameter (a)", 0.0, Infinity, true, &NeckAnatomy::neckDiameterMm },
    { "neckAngleBeta", "deg", "neck angle β", 0.0, 180.0, false, &NeckAnatomy::neckAngleBetaDeg },
    { "neckAngleAlpha", "deg", "neck angle α", 0.0, 180.0, false, &NeckAnatomy::neckAngleAlphaDeg },
    { "neckThrombusArc", "%", "neck thrombus arc", 0.0, 100.0, false, &NeckAnatomy::neckThrombusArcPercent },
    { "neckCalcificationArc", "%", "neck calcification arc", 0.0, 100.0, false,
      &NeckAnatomy::neckCalcificationArcPercent },
    { "reverseTaper10mm", "mm", "reverse taper over 10 mm", -Infinity, Infinity, false,
      &NeckAnatomy::reverseTaper10mmMm },
    { "reverseTaper15mm", "mm", "reverse taper over 15 mm", -Infinity, Infinity, false,
      &NeckAnatomy::reverseTaper15mmMm },
  };
  return quantities;
}

const NeckQuantity* FindNeckQuantity(const std::string& name)
{
  for (const NeckQuantity& q : NeckQuantities())
    if (name == q.name)
      return &q;
  return nullptr;
}

int NeckAssessment::Count(CheckStatus status) const
{
  return int(
    std::count_if(checks.begin(), checks.end(), [status](const CriterionCheck& c) { return c.status == status; }));
}

std::string DescribeNeckRuleField(const std::string& origin, int index, const std::string& id, const std::string& field)
{
  std::string text = "Hostile-neck rules '" + origin + "'";
  if (index >= 0)
  {
    text += ", rules[" + std::to_string(index) + "]";
    if (!TrimBlanks(id).empty())
      text += " \"" + id + "\"";
  }
  return text + ", field '" + field + "'";
}

void ValidateNeckRuleSet(const NeckRuleSet& rules, const std::string& file)
{
  if (rules.rules.empty())
    throw InputError(DescribeNeckRuleField(file, -1, "", "rules") +
                     ": is empty; expected at least one rule; add one (see Resources/hostile-neck-rules.json).");
  for (size_t i = 0; i < rules.rules.size(); ++i)
    RuleValidator(rules, file, int(i)).Run();
}

void ValidateNeckAnatomy(const NeckAnatomy& anatomy)
{
  for (const NeckQuantity& q : NeckQuantities())
  {
    const double value = anatomy.*q.field;
    if (!std::isnan(value) && !InRange(q, value))
      throw InputError("Neck anatomy: " + std::string(q.name) + " is " + ValueText(value, q.unit) + "; expected " +
                       RangeText(q) + " or NaN (not measured); check the measurement stage's output.");
  }
  if (!(anatomy.neckLengthUncertaintyMm >= 0.0 && std::isfinite(anatomy.neckLengthUncertaintyMm)))
    throw InputError("Neck anatomy: neckLengthUncertaintyMm is " + ValueText(anatomy.neckLengthUncertaintyMm, "mm") +
                     "; expected a number of mm ≥ 0; pass 0 for an exact neck length.");
}

NeckAssessment AssessNeck(const NeckAnatomy& anatomy, const NeckRuleSet& rules)
{
  ValidateNeckRuleSet(rules, rules.origin);
  ValidateNeckAnatomy(anatomy);
  NeckAssessment a;
  for (const NeckRule& rule : rules.rules)
  {
    const NeckQuantity& q = *FindNeckQuantity(rule.quantity);
    a.checks.push_back(CheckRule(rule, q, anatomy.*q.field, anatomy.neckLengthUncertaintyMm));
  }
  a.hostile = a.Count(CheckStatus::Fail) > 0;
  a.determinate = a.Count(CheckStatus::Indeterminate) == 0;
  a.summary = Summary(a, rules);
  return a;
}

} // namespace sgp
