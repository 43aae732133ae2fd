/// \file CompareConfigurations.h
/// Every way a configuration the surgeon gave differs from the one the plan recommends (issue 47),
/// each with its consequence, from the two configurations' own figures: the family, the side the
/// main body goes up (the limbs then swap roles), the main body (its size; its gate's clearance
/// above the aortic bifurcation), its position, and per side each component (added, removed,
/// another size, another length) and its overlap, with where that side then lands: how far above
/// the internal iliac ostium (or how much of it covered) and the iliac seal, against the
/// recommendation's. Lengths compared to 0.05 mm; the texts at 0.1 mm.
///
/// Input: two configured DeviceConfigurations on the same anatomy, and how far below the
/// recommended proximal edge the given one lies (mm). Output: the differences, empty when they
/// are the same. Pure. Errors: none.
#pragma once

#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"

namespace sgp
{

/// One way the given configuration differs.
struct ConfigurationDifference
{
  std::string what;        ///< "left limb", "main body", "main body side", "family", "right iliac extension"
  std::string change;      ///< "20 mm longer (ETLW1620C124E instead of ETLW1620C104E)"
  std::string consequence; ///< "it covers the left internal iliac ostium by 6.2 mm (recommended: 13.8 mm above it)"
  /// "left limb 20 mm longer (…): it covers …".
  std::string Text() const;
};

std::vector<ConfigurationDifference> CompareConfigurations(const DeviceConfiguration& given,
                                                           const DeviceConfiguration& recommended,
                                                           double givenEdgeBelowRecommendedMm);

} // namespace sgp
