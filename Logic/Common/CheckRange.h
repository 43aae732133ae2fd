/// \file CheckRange.h
/// The range check every parameter struct's Validate… function uses (STYLE.md B4: numeric XML
/// constraints are a GUI hint only, so C++ checks them, naming the value).
#pragma once

#include <string>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{

/// \throws InputError "<name> is <value> <unit>; expected <lo> to <hi> <unit>." unless
///         lo ≤ value ≤ hi (NaN fails).
inline void CheckRange(const std::string& name, double value, double lo, double hi, const std::string& unit)
{
  if (!(value >= lo && value <= hi))
  {
    const std::string space = unit.empty() ? "" : " ";
    throw InputError(name + " is " + FormatNumber(value, 2) + space + unit + "; expected " + FormatNumber(lo, 1) +
                     " to " + FormatNumber(hi, 1) + space + unit + ".");
  }
}

} // namespace sgp
