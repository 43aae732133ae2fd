#include "Device/CompareConfigurations.h"

#include <cmath>

#include "Common/Format.h"
#include "Device/CriterionCheck.h"

namespace sgp
{
namespace
{

/// Lengths closer than this are the same (catalogue figures and overlaps to 0.1 mm).
constexpr double SameMm = 0.05;

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

std::string Mm(double value)
{
  return FormatNumber(value) + " mm";
}

/// The side's parts below the main body: its limb, then its extension (nullptr: none).
std::pair<const ConfiguredComponent*, const ConfiguredComponent*> Parts(const DeviceConfiguration& c, int side)
{
  std::pair<const ConfiguredComponent*, const ConfiguredComponent*> parts{ nullptr, nullptr };
  for (const ConfiguredComponent& part : c.components)
    if (part.side == side && part.role != OrderRole::MainBody)
      (part.role == OrderRole::IliacExtension ? parts.second : parts.first) = &part;
  return parts;
}

double OverlapOf(const DeviceConfiguration& c, const ConfiguredComponent* part)
{
  for (const ComponentOverlap& o : c.overlaps)
    if (&c.components[std::size_t(o.inner)] == part)
      return o.overlapMm;
  return std::nan("");
}

/// "A instead of B" for two catalogue entries: the code where public, else the sizes.
std::string Names(const CatalogueComponent& a, const CatalogueComponent& b)
{
  const auto name = [](const CatalogueComponent& c)
  {
    return c.code.empty() ? CompactNumber(c.diameterMm) + "–" + CompactNumber(c.distalDiameterMm) + " × " +
                              CompactNumber(c.lengthMm) + " mm"
                          : c.code;
  };
  return name(a) + " instead of " + name(b);
}

/// How two entries of one role differ in size: "20 mm longer, distal 16 instead of 13 mm (…)".
std::string SizeChange(const CatalogueComponent& given, const CatalogueComponent& recommended)
{
  std::string text;
  const auto add = [&](const std::string& piece) { text += (text.empty() ? "" : ", ") + piece; };
  const double dL = given.lengthMm - recommended.lengthMm;
  if (std::abs(dL) > SameMm)
    add(CompactNumber(std::abs(dL)) + " mm " + (dL > 0 ? "longer" : "shorter"));
  if (std::isfinite(given.diameterMm) && std::abs(given.diameterMm - recommended.diameterMm) > SameMm)
    add("proximal " + CompactNumber(given.diameterMm) + " instead of " + CompactNumber(recommended.diameterMm) + " mm");
  if (std::isfinite(given.distalDiameterMm) && std::abs(given.distalDiameterMm - recommended.distalDiameterMm) > SameMm)
    add("distal " + CompactNumber(given.distalDiameterMm) + " instead of " +
        CompactNumber(recommended.distalDiameterMm) + " mm");
  if (text.empty())
    add("another model of the same size");
  return text + " (" + Names(given, recommended) + ")";
}

/// Where a side lands: "ends 9.6 mm above the left internal iliac ostium with a 31.2 mm iliac seal".
std::string Landing(const DeviceConfiguration& c, int side)
{
  const double margin = c.marginToInternalIliacMm[std::size_t(side)];
  const std::string ostium = std::string("the ") + SideName(side) + " internal iliac ostium";
  return (margin >= 0.0 ? "ends " + Mm(margin) + " above " + ostium : "covers " + ostium + " by " + Mm(-margin)) +
         ", with a " + Mm(c.sealLengthMm[std::size_t(side)]) + " iliac seal";
}

} // namespace

std::string ConfigurationDifference::Text() const
{
  return what + " " + change + (consequence.empty() ? "" : ": " + consequence);
}

std::vector<ConfigurationDifference> CompareConfigurations(const DeviceConfiguration& given,
                                                           const DeviceConfiguration& recommended,
                                                           double givenEdgeBelowRecommendedMm)
{
  std::vector<ConfigurationDifference> out;
  if (!given.configured || !recommended.configured)
    return out;
  if (given.family != recommended.family)
    out.push_back(
      { "family", given.family + " instead of " + recommended.family, "every component is " + given.family + "'s" });
  const int ipsi = given.ipsilateralSide;
  if (ipsi != recommended.ipsilateralSide)
    out.push_back(
      { "main body side",
        std::string("up the ") + SideName(ipsi) + " instead of the " + SideName(recommended.ipsilateralSide),
        std::string("the limbs swap roles: the ") + SideName(ipsi) +
          " limb goes into the main body's ipsilateral leg, the " + SideName(1 - ipsi) +
          " limb into the contralateral gate" });
  const CatalogueComponent& body = given.components.front().item;
  const CatalogueComponent& recommendedBody = recommended.components.front().item;
  if (body.code != recommendedBody.code || std::abs(body.lengthMm - recommendedBody.lengthMm) > SameMm ||
      std::abs(body.diameterMm - recommendedBody.diameterMm) > SameMm ||
      std::abs(body.distalDiameterMm - recommendedBody.distalDiameterMm) > SameMm)
    out.push_back({ "main body", SizeChange(body, recommendedBody),
                    "its contralateral gate ends " + Mm(given.gateClearanceMm) +
                      " above the aortic bifurcation (recommended: " + Mm(recommended.gateClearanceMm) + ")" });
  if (std::abs(givenEdgeBelowRecommendedMm) > SameMm)
    out.push_back({ "main body",
                    "placed " + Mm(std::abs(givenEdgeBelowRecommendedMm)) +
                      (givenEdgeBelowRecommendedMm > 0 ? " lower" : " higher") + " (its proximal edge)",
                    "its seal in the neck is the fit check's; everything below it moves with it" });
  for (int side = 0; side < 2; ++side)
  {
    const auto mine = Parts(given, side), theirs = Parts(recommended, side);
    const std::pair<const ConfiguredComponent*, const ConfiguredComponent*> pairs[2] = {
      { mine.first, theirs.first }, { mine.second, theirs.second }
    };
    bool sideChanged = false;
    for (int k = 0; k < 2; ++k)
    {
      const auto [a, b] = pairs[k];
      if (!a && !b)
        continue;
      const std::string what = std::string(SideName(side)) + (k == 0 ? " limb" : " iliac extension");
      std::string change;
      if (a && !b)
        change = "added (" + a->OrderText() + ")";
      else if (!a && b)
        change = "left off (the recommendation's " + b->OrderText() + ")";
      else
      {
        if (a->item.code != b->item.code || std::abs(a->item.lengthMm - b->item.lengthMm) > SameMm ||
            std::abs(a->item.distalDiameterMm - b->item.distalDiameterMm) > SameMm)
          change = SizeChange(a->item, b->item);
        const double ovA = OverlapOf(given, a), ovB = OverlapOf(recommended, b);
        if (std::abs(ovA - ovB) > SameMm)
          change += std::string(change.empty() ? "" : "; ") + "inserted " + Mm(std::abs(ovA - ovB)) +
                    (ovA > ovB ? " deeper" : " less deep") + " (overlap " + Mm(ovA) + " instead of " + Mm(ovB) + ")";
      }
      if (change.empty())
        continue;
      out.push_back({ what, change,
                      sideChanged ? ""
                                  : "the " + std::string(SideName(side)) + " side " + Landing(given, side) +
                                      " (recommended: " + Landing(recommended, side) + ")" });
      sideChanged = true;
    }
    // The same components at the same overlaps, but what they go into moved (another main body,
    // another side): the side lands elsewhere.
    const double moved =
      recommended.marginToInternalIliacMm[std::size_t(side)] - given.marginToInternalIliacMm[std::size_t(side)];
    if (!sideChanged && std::abs(moved) > SameMm)
      out.push_back({ std::string(SideName(side)) + " side",
                      "lands " + Mm(std::abs(moved)) + (moved > 0 ? " lower" : " higher") +
                        " with the same components (what they go into moved)",
                      "the " + std::string(SideName(side)) + " side " + Landing(given, side) +
                        " (recommended: " + Landing(recommended, side) + ")" });
  }
  return out;
}

} // namespace sgp
