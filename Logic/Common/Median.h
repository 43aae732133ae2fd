/// \file Median.h
/// The median of a list of values (the upper middle one for an even count; 0 for none).
#pragma once

#include <algorithm>
#include <vector>

namespace sgp
{

inline double Median(std::vector<double> values)
{
  if (values.empty())
    return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

} // namespace sgp
