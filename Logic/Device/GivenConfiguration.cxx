#include "Device/GivenConfiguration.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Device/CriterionCheck.h"
#include "Common/Text.h"
#include "Device/ConfigureDevice.h"

namespace sgp
{
namespace
{

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

/// "components[2]" out of "Configuration '…', components[2]".
std::string ItsIndex(const std::string& where)
{
  const std::size_t comma = where.rfind(", ");
  return comma == std::string::npos ? where : where.substr(comma + 2);
}

/// "limb", "iliac extension", "main body", "aortic cuff".
std::string RoleWords(ComponentRole role)
{
  return IdentifierWords(ToString(role));
}

/// "a limb", "an iliac extension", "a main body".
std::string ARole(ComponentRole role)
{
  const std::string words = RoleWords(role);
  return (words.front() == 'i' ? "an " : "a ") + words;
}

std::string Opening(const GivenConfiguration& given, const std::string& where)
{
  return "Configuration '" + given.origin + "'" + (where.empty() ? "" : ", " + where);
}

/// How the component names its size, for messages: "16–10 mm × 124 mm".
std::string SizeText(const GivenComponent& c)
{
  std::string text;
  if (std::isfinite(c.diameterMm))
    text += "proximal " + CompactNumber(c.diameterMm) + " mm";
  if (std::isfinite(c.distalDiameterMm))
    text += std::string(text.empty() ? "" : ", ") + "distal " + CompactNumber(c.distalDiameterMm) + " mm";
  if (std::isfinite(c.lengthMm))
    text += std::string(text.empty() ? "" : ", ") + "length " + CompactNumber(c.lengthMm) + " mm";
  return text;
}

bool Matches(double given, double catalogue)
{
  return std::isnan(given) || (std::isfinite(catalogue) && std::abs(given - catalogue) <= ForcedDiameterToleranceMm);
}

/// What the family makes of `role`, for a message: the sizes as "diameter–distal × length" (and
/// codes where public), at most 12, those matching the given diameters first.
std::string Offer(const DeviceFamily& family, ComponentRole role, const GivenComponent& c)
{
  std::vector<std::string> near, rest;
  // Those whose code begins most like the one given first (a typo in its last digits).
  std::vector<const CatalogueComponent*> items = family.ComponentsOf(role);
  const auto shared = [&](const CatalogueComponent* item)
  {
    std::size_t n = 0;
    while (n < item->code.size() && n < c.code.size() && std::toupper(item->code[n]) == std::toupper(c.code[n]))
      ++n;
    return n;
  };
  std::stable_sort(items.begin(), items.end(),
                   [&](const CatalogueComponent* a, const CatalogueComponent* b) { return shared(a) > shared(b); });
  for (const CatalogueComponent* item : items)
  {
    const std::string text =
      (std::isfinite(item->diameterMm) ? CompactNumber(item->diameterMm) + "–" : std::string()) +
      (std::isfinite(item->distalDiameterMm) ? CompactNumber(item->distalDiameterMm) : std::string("?")) + " × " +
      (std::isfinite(item->lengthMm) ? CompactNumber(item->lengthMm) : std::string("?")) + " mm" +
      (item->code.empty() ? "" : " (" + item->code + ")");
    const bool sameDiameters =
      Matches(c.diameterMm, item->diameterMm) && Matches(c.distalDiameterMm, item->distalDiameterMm);
    (sameDiameters ? near : rest).push_back(text);
  }
  near.insert(near.end(), rest.begin(), rest.end());
  const std::size_t shown = std::min<std::size_t>(near.size(), 12);
  std::vector<std::string> list(near.begin(), near.begin() + std::ptrdiff_t(shown));
  return JoinWithCommas(list) + (near.size() > shown ? " and " + std::to_string(near.size() - shown) + " more" : "");
}

const CatalogueComponent* Resolve(const GivenConfiguration& given, const DeviceFamily& family, const GivenComponent& c)
{
  const std::string opening = Opening(given, c.where);
  if (!c.code.empty())
  {
    const std::string wanted = LowerCase(TrimBlanks(c.code));
    for (const CatalogueComponent& item : family.components)
      if (!item.code.empty() && LowerCase(item.code) == wanted)
      {
        if (item.role != c.role)
          throw InputError(opening + ": code '" + c.code + "' is " + family.name + "'s " + RoleWords(item.role) +
                           ", not " + ARole(c.role) + "; expected " + ARole(c.role) +
                           " code, one of: " + Offer(family, c.role, c) + ".");
        for (const auto& [value, field] :
             { std::pair{ c.diameterMm, item.diameterMm }, std::pair{ c.distalDiameterMm, item.distalDiameterMm },
               std::pair{ c.lengthMm, item.lengthMm } })
          if (!Matches(value, field))
            throw InputError(opening + ": code '" + c.code + "' is " + CompactNumber(item.diameterMm) + "–" +
                             CompactNumber(item.distalDiameterMm) + " × " + CompactNumber(item.lengthMm) +
                             " mm, not the " + SizeText(c) + " also given; expected the code or the sizes alone.");
        return &item;
      }
    throw InputError(opening + ": code '" + c.code + "' is not among " + family.name + "'s " +
                     IdentifierWords(GroupKey(c.role)) +
                     " in the device catalogue; expected one of: " + Offer(family, c.role, c) + ".");
  }
  const bool byDiameter =
    c.role == ComponentRole::MainBody ? std::isfinite(c.diameterMm) : std::isfinite(c.distalDiameterMm);
  if (!byDiameter || !std::isfinite(c.lengthMm))
    throw InputError(opening + ": " + ARole(c.role) + " needs its code, or its " +
                     (c.role == ComponentRole::MainBody ? "diameterMm" : "distalDiameterMm") + " and lengthMm; saw " +
                     (SizeText(c).empty() ? std::string("neither") : SizeText(c)) + ".");
  std::vector<const CatalogueComponent*> found;
  for (const CatalogueComponent* item : family.ComponentsOf(c.role))
    if (Matches(c.diameterMm, item->diameterMm) && Matches(c.distalDiameterMm, item->distalDiameterMm) &&
        Matches(c.lengthMm, item->lengthMm))
      found.push_back(item);
  if (found.empty())
    throw InputError(opening + ": " + family.name + " makes no " + RoleWords(c.role) + " of " + SizeText(c) +
                     "; expected one of: " + Offer(family, c.role, c) + ".");
  if (found.size() > 1)
  {
    std::vector<std::string> names;
    for (const CatalogueComponent* item : found)
      names.push_back(item->Label() + " (" + CompactNumber(item->diameterMm) + "–" +
                      CompactNumber(item->distalDiameterMm) + " mm)");
    throw InputError(opening + ": " + std::to_string(found.size()) + " " + family.name + " " +
                     IdentifierWords(GroupKey(c.role)) + " are " + SizeText(c) + " (" + JoinWithCommas(names) +
                     "); expected a code or the other diameter to tell them apart.");
  }
  return found.front();
}

} // namespace

ComponentRole ParseGivenRole(const std::string& text, const std::string& where)
{
  for (ComponentRole role : { ComponentRole::MainBody, ComponentRole::Limb, ComponentRole::IliacExtension })
    if (text == ToString(role))
      return role;
  if (text == ToString(ComponentRole::AorticCuff))
    throw InputError(where + ": role 'aorticCuff': aortic cuffs are not simulated yet; expected mainBody, limb or "
                             "iliacExtension.");
  throw InputError(where + ": role '" + text + "'; expected mainBody, limb or iliacExtension.");
}

ResolvedConfiguration ResolveGivenConfiguration(const GivenConfiguration& given, const DeviceCatalog& catalog)
{
  ResolvedConfiguration r;
  r.origin = given.origin;
  const DeviceFamily* family = FindDeviceFamily(catalog, given.family);
  if (!family)
  {
    std::vector<std::string> names;
    for (const DeviceFamily& f : catalog.families)
      names.push_back(f.name);
    throw InputError(Opening(given, "family") + ": '" + given.family + "' is not in the device catalogue '" +
                     catalog.origin + "'; expected one of: " + JoinWithCommas(names) + ".");
  }
  r.familyIndex = int(family - catalog.families.data());
  r.mainBodySide = given.mainBodySide;
  r.bodyLegLandsAlone = given.bodyLegLandsAlone;
  const auto fail = [&](const GivenComponent& c, const std::string& text)
  { throw InputError(Opening(given, c.where) + ": " + text); };
  for (const GivenComponent& c : given.components)
  {
    const bool body = c.role == ComponentRole::MainBody;
    if (body != (c.side < 0))
      fail(c, body ? "a main body has no side (it is given by mainBodySide); expected no 'side'."
                   : ARole(c.role) + " needs its side; expected 'side': 'right' or 'left'.");
    if (body && (std::isfinite(c.overlapMm) || std::isfinite(c.distalEdgeAboveInternalIliacMm)))
      fail(c, "a main body's position is proximalEdgeBelowLowestRenalMm; overlapMm and "
              "distalEdgeAboveInternalIliacMm are for limbs and extensions.");
    if (!body && std::isfinite(c.proximalEdgeBelowLowestRenalMm))
      fail(c, "proximalEdgeBelowLowestRenalMm is the main body's position; expected overlapMm or "
              "distalEdgeAboveInternalIliacMm for " +
                ARole(c.role) + ".");
    if (std::isfinite(c.overlapMm) && std::isfinite(c.distalEdgeAboveInternalIliacMm))
      fail(c, "overlapMm " + CompactNumber(c.overlapMm) + " and distalEdgeAboveInternalIliacMm " +
                CompactNumber(c.distalEdgeAboveInternalIliacMm) + " both given; expected one position.");
    if (std::isfinite(c.overlapMm) && c.overlapMm <= 0.0)
      fail(c, "overlapMm is " + CompactNumber(c.overlapMm) + " mm: " + ARole(c.role) +
                " that does not overlap cannot reach what it is inserted into; expected more than 0 mm (the family "
                "needs at least " +
                CompactNumber(family->junctions.overlapMm.min) + " mm).");
    if (std::isfinite(c.proximalEdgeBelowLowestRenalMm) &&
        (c.proximalEdgeBelowLowestRenalMm < -30.0 || c.proximalEdgeBelowLowestRenalMm > 60.0))
      fail(c, "proximalEdgeBelowLowestRenalMm is " + FormatNumber(c.proximalEdgeBelowLowestRenalMm) +
                " mm; expected −30 to 60 mm.");
    const CatalogueComponent* item = Resolve(given, *family, c);
    ResolvedComponent resolved{ item, Opening(given, c.where), c.overlapMm, c.distalEdgeAboveInternalIliacMm };
    ResolvedComponent* slot = body                            ? &r.mainBody
                              : c.role == ComponentRole::Limb ? &r.limb[std::size_t(c.side)]
                                                              : &r.extension[std::size_t(c.side)];
    if (slot->Given())
      fail(c, body ? std::string("a second main body (the first is ") + ItsIndex(slot->where) + "); expected one."
                   : std::string("a second ") + SideName(c.side) + " " + RoleWords(c.role) + " (the first is " +
                       ItsIndex(slot->where) + "); expected at most one per side.");
    *slot = resolved;
    if (body)
      r.proximalEdgeBelowLowestRenalMm = c.proximalEdgeBelowLowestRenalMm;
  }
  if (!r.mainBody.Given())
    throw InputError(Opening(given, "components") + ": no main body; expected one component with role 'mainBody'.");
  if (r.bodyLegLandsAlone && r.mainBodySide < 0)
    throw InputError(Opening(given, "bodyLegLandsAlone") +
                     ": true without mainBodySide; expected the side whose leg lands ('right' or 'left').");
  if (r.bodyLegLandsAlone && r.limb[std::size_t(r.mainBodySide)].Given())
    throw InputError(r.limb[std::size_t(r.mainBodySide)].where + ": a " + SideName(r.mainBodySide) +
                     " limb, but bodyLegLandsAlone says the main body's own leg lands on the " +
                     SideName(r.mainBodySide) + "; expected one or the other.");
  for (int side = 0; side < 2; ++side)
  {
    const ResolvedComponent& limb = r.limb[std::size_t(side)];
    const ResolvedComponent& extension = r.extension[std::size_t(side)];
    if (extension.Given() && !limb.Given())
      throw InputError(extension.where + ": a " + SideName(side) + " iliac extension with no " + SideName(side) +
                       " limb to go into; expected a limb on that side too.");
    if (extension.Given() && std::isfinite(limb.distalEdgeAboveInternalIliacMm))
      throw InputError(limb.where + ": distalEdgeAboveInternalIliacMm on a limb with an iliac "
                                    "extension below it; expected it on the extension (its side's last "
                                    "component), or the limb's overlapMm.");
  }
  return r;
}

GivenConfiguration GivenFromConfiguration(const DeviceConfiguration& configuration,
                                          double proximalEdgeBelowLowestRenalMm)
{
  GivenConfiguration g;
  g.family = configuration.family;
  g.mainBodySide = configuration.ipsilateralSide;
  g.bodyLegLandsAlone = configuration.Find(OrderRole::IpsilateralLimb) == nullptr;
  for (std::size_t k = 0; k < configuration.components.size(); ++k)
  {
    const ConfiguredComponent& part = configuration.components[k];
    GivenComponent c;
    c.where = "components[" + std::to_string(k) + "]";
    c.role = part.item.role;
    c.side = part.role == OrderRole::MainBody ? -1 : part.side;
    c.code = part.item.code;
    if (c.code.empty())
    {
      c.diameterMm = part.item.diameterMm;
      c.distalDiameterMm = part.item.distalDiameterMm;
      c.lengthMm = part.item.lengthMm;
    }
    if (part.role == OrderRole::MainBody)
      c.proximalEdgeBelowLowestRenalMm = proximalEdgeBelowLowestRenalMm;
    for (const ComponentOverlap& o : configuration.overlaps)
      if (o.inner == int(k))
        c.overlapMm = o.overlapMm;
    g.components.push_back(c);
  }
  return g;
}

} // namespace sgp
