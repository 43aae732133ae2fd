/// \file Format.h
/// Number and point formatting for error messages and warnings (STYLE.md B5: messages name the
/// value seen, with units and frame).
#pragma once

#include <cstdio>
#include <string>

#include "Types.h"

namespace sgp
{

/// `value` with `decimals` digits after the point, e.g. FormatNumber(2.345, 1) == "2.3".
inline std::string FormatNumber(double value, int decimals = 1)
{
  char buffer[64];
  // + 0.0 turns a negative zero (a negated coordinate of 0) into "0.0" rather than "-0.0".
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value + 0.0);
  return buffer;
}

/// "(x, y, z)" with one decimal, e.g. for a point in mm.
inline std::string FormatPoint(const Point3& p, int decimals = 1)
{
  return "(" + FormatNumber(p.x(), decimals) + ", " + FormatNumber(p.y(), decimals) + ", " +
         FormatNumber(p.z(), decimals) + ")";
}

} // namespace sgp
