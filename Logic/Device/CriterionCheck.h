/// \file CriterionCheck.h
/// One checked criterion of a device's IFU or sizing: pass / fail / indeterminate, the value
/// measured, the requirement, the signed margin and a one-line text.
///
/// The margin is in the criterion's unit and positive inside the requirement: value − min for
/// "≥ min", max − value for "≤ max", and the smaller of the two for a range, so −3 mm means
/// 3 mm short. A criterion whose measurement is NaN (not measured) is indeterminate, with a NaN
/// margin; one whose margin lies within its measurement's uncertainty (SelectDevice: the neck
/// length) is indeterminate too and keeps its margin. Limits are inclusive. The text reads, e.g.:
///   "neck length 12.0 mm, needs ≥ 15 mm: −3.0 mm"
///   "neck angle β 50.0°, needs ≤ 60°: +10.0°"
///   "main body oversizing 13.6 %, needs 10–20 %: +3.6 %"
///   "neck length not measured, needs ≥ 15 mm: indeterminate"
/// (UTF-8: "≥", "≤", "–", "−", "°"). Values are written with one decimal, limits as short as
/// they are exact (15, 28.5).
#pragma once

#include <limits>
#include <string>

namespace sgp
{

enum class CheckStatus
{
  Pass,
  Fail,
  Indeterminate
};

/// "pass", "fail" or "indeterminate".
const char* ToString(CheckStatus status);

struct CriterionCheck
{
  std::string name; ///< short and stable, e.g. "neck length", "right iliac seal length"
  CheckStatus status = CheckStatus::Indeterminate;
  double value = std::numeric_limits<double>::quiet_NaN();  ///< measured value; NaN: not measured
  std::string unit;                                         ///< "mm", "deg" or "%"
  double min = std::numeric_limits<double>::quiet_NaN();    ///< requirement's lower limit; NaN: none
  double max = std::numeric_limits<double>::quiet_NaN();    ///< requirement's upper limit; NaN: none
  double margin = std::numeric_limits<double>::quiet_NaN(); ///< signed, unit; NaN when not decidable
  std::string requirement;                                  ///< e.g. "≥ 15 mm (β ≤ 75°)"
  std::string text;                                         ///< the one-line summary above
  std::string evidence;                                     ///< the catalogue's evidence mark for this criterion
};

/// Checks `value` against [min, max] (either NaN: unbounded on that side; not both).
/// `condition`, when not empty, is appended to the requirement in brackets ("β ≤ 60°").
/// `label` (default: `name`) opens the text. `unit` is "mm", "deg" or "%".
CriterionCheck CheckCriterion(const std::string& name,
                              double value,
                              double min,
                              double max,
                              const std::string& unit,
                              const std::string& condition = "",
                              const std::string& label = "");

/// The requirement text for [min, max]: "≥ 15 mm", "≤ 60°", "10–20 %".
std::string RequirementText(double min, double max, const std::string& unit);

/// A value with one decimal and its unit: "12.0 mm", "50.0°", "13.6 %".
std::string QuantityText(double value, const std::string& unit);

/// A signed margin: "+3.0 mm", "−3.0 mm" (U+2212 minus).
std::string SignedQuantityText(double value, const std::string& unit);

/// The shortest exact decimal form of a catalogue figure: 23 → "23", 28.5 → "28.5".
std::string CompactNumber(double value);

} // namespace sgp
