#include "Device/CriterionCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Common/Format.h"

namespace sgp
{

namespace
{

/// Degrees attach to the number ("60°"); mm and % follow a space.
std::string WithUnit(const std::string& number, const std::string& unit)
{
  if (unit == "deg")
    return number + "°";
  return unit.empty() ? number : number + " " + unit;
}

} // namespace

const char* ToString(CheckStatus status)
{
  switch (status)
  {
    case CheckStatus::Pass:
      return "pass";
    case CheckStatus::Fail:
      return "fail";
    case CheckStatus::Indeterminate:
      break;
  }
  return "indeterminate";
}

std::string CompactNumber(double value)
{
  const int decimals = value == std::round(value) ? 0 : (value * 10.0 == std::round(value * 10.0) ? 1 : 2);
  return FormatNumber(value, decimals);
}

std::string RequirementText(double min, double max, const std::string& unit)
{
  if (std::isnan(max))
    return "≥ " + WithUnit(CompactNumber(min), unit);
  if (std::isnan(min))
    return "≤ " + WithUnit(CompactNumber(max), unit);
  return WithUnit(CompactNumber(min) + "–" + CompactNumber(max), unit);
}

std::string QuantityText(double value, const std::string& unit)
{
  return WithUnit(FormatNumber(value, 1), unit);
}

std::string SignedQuantityText(double value, const std::string& unit)
{
  // Rounded first, so that −0.04 reads "+0.0" rather than "−0.0".
  const double rounded = std::round(value * 10.0) / 10.0;
  return WithUnit((rounded < 0.0 ? "−" : "+") + FormatNumber(std::abs(rounded), 1), unit);
}

CriterionCheck CheckCriterion(const std::string& name,
                              double value,
                              double min,
                              double max,
                              const std::string& unit,
                              const std::string& condition,
                              const std::string& label)
{
  CriterionCheck check;
  check.name = name;
  check.value = value;
  check.unit = unit;
  check.min = min;
  check.max = max;
  check.requirement = RequirementText(min, max, unit) + (condition.empty() ? "" : " (" + condition + ")");
  const std::string opening = label.empty() ? name : label;
  if (std::isnan(value))
  {
    check.status = CheckStatus::Indeterminate;
    check.text = opening + " not measured, needs " + check.requirement + ": indeterminate";
    return check;
  }
  const double belowMax = std::isnan(max) ? std::numeric_limits<double>::infinity() : max - value;
  const double aboveMin = std::isnan(min) ? std::numeric_limits<double>::infinity() : value - min;
  check.margin = std::min(belowMax, aboveMin);
  check.status = check.margin >= 0.0 ? CheckStatus::Pass : CheckStatus::Fail;
  check.text = opening + " " + QuantityText(value, unit) + ", needs " + check.requirement + ": " +
               SignedQuantityText(check.margin, unit);
  return check;
}

} // namespace sgp
