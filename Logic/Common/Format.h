/// \file Format.h
/// Number and point formatting for error messages and warnings (STYLE.md B5: messages name the
/// value seen, with units and frame).
#pragma once

#include <cstdio>
#include <string>

#include "Common/Types.h"

namespace sgp
{

/// `value` with `decimals` digits after the point, e.g. FormatNumber(2.345, 1) == "2.3".
inline std::string FormatNumber(double value, int decimals = 1)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  // A value that rounds to zero reads "0.0", never "-0.0" (a negated coordinate of 0, a conicity
  // of −0.02 %).
  std::string text = buffer;
  if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos)
    text.erase(0, 1);
  return text;
}

/// "(x, y, z)" with one decimal, e.g. for a point in mm.
inline std::string FormatPoint(const Point3& p, int decimals = 1)
{
  return "(" + FormatNumber(p.x(), decimals) + ", " + FormatNumber(p.y(), decimals) + ", " +
         FormatNumber(p.z(), decimals) + ")";
}

/// A return value or table number with up to 10 significant digits ("34.2", "1e-05"), the
/// precision SEM return parameters and the tables carry.
inline std::string FormatReturnValue(double value)
{
  char buffer[64];
  // + 0.0 turns a negative zero (a negated coordinate of 0) into "0" rather than "-0".
  std::snprintf(buffer, sizeof(buffer), "%.10g", value + 0.0);
  return buffer;
}

} // namespace sgp
