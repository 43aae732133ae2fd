/// \file ValueText.h
/// A plan's values as a person reads them (STYLE.md B10): each value's name in words, and its
/// number at clinical precision with its unit — 0.1 mm, 0.1°, 1 %, 0.01 for a ratio, 0.1 mL —
/// in the summary, the visual report, the measurement table's `label` and `shown` columns and the
/// Slicer panel. Files for machines (the return file, the JSON report, the table's `value`) keep
/// full precision and the identifiers.
#pragma once

#include <string>

namespace sgp
{

/// The words for a return value or table row, e.g. "proximalNeckDiameter" → "(a) neck diameter at
/// the proximal site, outer wall"; a name without words of its own is split at its capitals.
std::string ValueLabel(const std::string& name);

/// `value` in `unit` ("mm", "deg", "%", "ratio", "mL", or none) at clinical precision with its
/// unit ("22.1 mm", "34.6°", "15 %", "1.01", "135.2 mL"); "not measured" for NaN.
std::string ClinicalText(double value, const std::string& unit);

} // namespace sgp
