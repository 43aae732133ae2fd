#include "Device/DeviceCatalog.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "Common/Errors.h"
#include "Common/Text.h"
#include "Device/CriterionCheck.h"
#include "Device/ValidateCatalogueComponents.h"

namespace sgp
{

namespace
{

/// Checks one family field by field; `Fail` builds the message with the field's name.
class FamilyValidator
{
public:
  FamilyValidator(const DeviceCatalog& catalog, int index)
    : m_Catalog(catalog)
    , m_Index(index)
    , m_Family(catalog.families[size_t(index)])
  {
  }

  void Run()
  {
    if (TrimBlanks(m_Family.name).empty())
      Fail("name", "is empty", "a family name such as \"Endurant II\"");
    if (m_Family.name.find(':') != std::string::npos)
      Fail("name", "contains ':'", "a name without ':' (--device uses ':' before the diameter)");
    if (TrimBlanks(m_Family.source).empty())
      Fail("source", "is empty", "where the figures come from, with its evidence mark");
    // The components first: the sizes below are derived from them, so a component's defect is
    // reported on the component.
    ValidateCatalogueComponents(m_Catalog, m_Index);
    CheckComponent(m_Family.mainBodies, "mainBodies", "main body");
    CheckComponent(m_Family.limbs, "limbs", "limb");
    if (!m_Family.limbs.lengthToFlowDividerMm.empty())
      Fail("limbs.lengthToFlowDividerMm", "is given", "it only on mainBodies");
    CheckIfu();
  }

private:
  [[noreturn]] void Fail(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError(DescribeCatalogField(m_Catalog.origin, m_Index, m_Family.name, field) + ": " + seen +
                     "; expected " + expected + "; correct the entry.");
  }

  void Positive(const std::string& field, double value, const std::string& unit) const
  {
    if (!(value > 0.0 && std::isfinite(value)))
      Fail(field, "is " + CompactNumber(value) + " " + unit, "a positive number of " + unit);
  }

  void CheckComponent(const DeviceComponent& c, const std::string& field, const std::string& what) const
  {
    if (c.sizes.empty())
      Fail(field + ".sizes", "is empty", "at least one " + what + " size");
    for (size_t i = 0; i < c.sizes.size(); ++i)
    {
      const std::string item = field + ".sizes[" + std::to_string(i) + "]";
      Positive(item + ".diameterMm", c.sizes[i].diameterMm, "mm");
      Positive(item + ".profileFr", c.sizes[i].profileFr, "Fr");
      if (i > 0 && !(c.sizes[i].diameterMm > c.sizes[i - 1].diameterMm))
        Fail(item + ".diameterMm",
             "is " + CompactNumber(c.sizes[i].diameterMm) + " mm after " + CompactNumber(c.sizes[i - 1].diameterMm) +
               " mm",
             "diameters in strictly ascending order");
    }
    if (std::isnan(c.lengthMinMm) != std::isnan(c.lengthMaxMm))
      Fail(field + ".lengthRangeMm", "has only one bound", "both min and max, or neither");
    if (!std::isnan(c.lengthMinMm))
    {
      Positive(field + ".lengthRangeMm.min", c.lengthMinMm, "mm");
      if (!(c.lengthMaxMm >= c.lengthMinMm))
        Fail(field + ".lengthRangeMm",
             "is " + CompactNumber(c.lengthMinMm) + " to " + CompactNumber(c.lengthMaxMm) + " mm", "min <= max");
    }
    for (size_t i = 0; i < c.lengthToFlowDividerMm.size(); ++i)
    {
      const std::string item = field + ".lengthToFlowDividerMm[" + std::to_string(i) + "]";
      Positive(item, c.lengthToFlowDividerMm[i], "mm");
      if (i > 0 && !(c.lengthToFlowDividerMm[i] >= c.lengthToFlowDividerMm[i - 1]))
        Fail(item,
             "is " + CompactNumber(c.lengthToFlowDividerMm[i]) + " mm after " +
               CompactNumber(c.lengthToFlowDividerMm[i - 1]) + " mm",
             "lengths in ascending order");
    }
  }

  void CheckBounds(const std::string& field, const IfuLimit& limit, const std::string& unit) const
  {
    Positive(field + ".min", limit.min, unit);
    Positive(field + ".max", limit.max, unit);
    if (!(limit.min < limit.max))
      Fail(field, "is " + CompactNumber(limit.min) + " to " + CompactNumber(limit.max) + " " + unit, "min < max");
  }

  void CheckIfu() const
  {
    const DeviceIfu& ifu = m_Family.ifu;
    if (ifu.neckLengthTiers.empty())
      Fail("ifu.neckLength.tiers", "is empty", "at least one tier {minMm, maxBetaDeg}");
    for (size_t i = 0; i < ifu.neckLengthTiers.size(); ++i)
    {
      const std::string item = "ifu.neckLength.tiers[" + std::to_string(i) + "]";
      const NeckLengthTier& t = ifu.neckLengthTiers[i];
      Positive(item + ".minMm", t.minLengthMm, "mm");
      if (!(t.maxBetaDeg > 0.0 && t.maxBetaDeg <= 180.0))
        Fail(item + ".maxBetaDeg", "is " + CompactNumber(t.maxBetaDeg) + " deg", "an angle in (0, 180] deg");
      if (i == 0)
        continue;
      const NeckLengthTier& previous = ifu.neckLengthTiers[i - 1];
      if (!(t.maxBetaDeg > previous.maxBetaDeg))
        Fail(item + ".maxBetaDeg",
             "is " + CompactNumber(t.maxBetaDeg) + " deg after " + CompactNumber(previous.maxBetaDeg) + " deg",
             "tiers in strictly ascending angle");
      if (!(t.minLengthMm >= previous.minLengthMm))
        Fail(item + ".minMm",
             "is " + CompactNumber(t.minLengthMm) + " mm after " + CompactNumber(previous.minLengthMm) + " mm",
             "a steeper tier to need at least the neck length of the tier before it");
    }
    CheckBounds("ifu.neckDiameterMm", ifu.neckDiameterMm, "mm");
    CheckBounds("ifu.iliacDiameterMm", ifu.iliacDiameterMm, "mm");
    Positive("ifu.iliacSealLengthMm.min", ifu.iliacSealLengthMm.min, "mm");
    if (!std::isnan(ifu.neckAngleAlphaDeg.max) &&
        !(ifu.neckAngleAlphaDeg.max > 0.0 && ifu.neckAngleAlphaDeg.max <= 180.0))
      Fail("ifu.neckAngleAlphaDeg.max", "is " + CompactNumber(ifu.neckAngleAlphaDeg.max) + " deg",
           "an angle in (0, 180] deg");
    const double widestBody = m_Family.mainBodies.sizes.back().diameterMm;
    if (!(widestBody > ifu.neckDiameterMm.max))
      Fail("mainBodies.sizes", "the widest main body is " + CompactNumber(widestBody) + " mm",
           "one wider than the largest IFU neck diameter, " + CompactNumber(ifu.neckDiameterMm.max) + " mm");
    const double widestLimb = m_Family.limbs.sizes.back().diameterMm;
    if (!(widestLimb > ifu.iliacDiameterMm.max))
      Fail("limbs.sizes", "the widest limb is " + CompactNumber(widestLimb) + " mm",
           "one wider than the largest IFU iliac diameter, " + CompactNumber(ifu.iliacDiameterMm.max) + " mm");
  }

  const DeviceCatalog& m_Catalog;
  int m_Index;
  const DeviceFamily& m_Family;
};

} // namespace

std::string DescribeCatalogField(const std::string& origin,
                                 int familyIndex,
                                 const std::string& familyName,
                                 const std::string& field)
{
  std::string text = "Device catalogue '" + origin + "'";
  if (familyIndex >= 0)
  {
    text += ", families[" + std::to_string(familyIndex) + "]";
    if (!familyName.empty())
      text += " \"" + familyName + "\"";
  }
  return text + ", field '" + field + "'";
}

std::string DescribeCatalogComponentField(const std::string& origin,
                                          int familyIndex,
                                          const std::string& familyName,
                                          const CatalogueComponent& component,
                                          const std::string& field)
{
  std::string text = DescribeCatalogField(origin, familyIndex, familyName, field);
  const std::string opening = ", field '";
  return text.insert(text.rfind(opening), ", component " + component.Label());
}

const char* ToString(ComponentRole role)
{
  switch (role)
  {
    case ComponentRole::MainBody:
      return "mainBody";
    case ComponentRole::Limb:
      return "limb";
    case ComponentRole::IliacExtension:
      return "iliacExtension";
    case ComponentRole::AorticCuff:
      return "aorticCuff";
  }
  return "";
}

const char* GroupKey(ComponentRole role)
{
  switch (role)
  {
    case ComponentRole::MainBody:
      return "mainBodies";
    case ComponentRole::Limb:
      return "limbs";
    case ComponentRole::IliacExtension:
      return "iliacExtensions";
    case ComponentRole::AorticCuff:
      return "aorticCuffs";
  }
  return "";
}

bool CatalogueComponent::GeometryKnown() const
{
  return role == ComponentRole::MainBody && std::isfinite(lengthMm) && std::isfinite(flowDividerMm) &&
         std::isfinite(gateEndMm);
}

std::string CatalogueComponent::Label() const
{
  return std::string(GroupKey(role)) + ".items[" + std::to_string(index) + "]" + (code.empty() ? "" : " " + code);
}

std::string CatalogueComponent::CodeText() const
{
  return code.empty() ? "(code not public)" : code;
}

std::vector<const CatalogueComponent*> DeviceFamily::ComponentsOf(ComponentRole role) const
{
  std::vector<const CatalogueComponent*> found;
  for (const CatalogueComponent& c : components)
    if (c.role == role)
      found.push_back(&c);
  return found;
}

void DeriveSizesFromComponents(DeviceFamily& family)
{
  if (family.components.empty())
    return;
  const auto derive = [&](ComponentRole role, DeviceComponent& group, bool proximal)
  {
    std::vector<DeviceSize> sizes;
    group.lengthMinMm = group.lengthMaxMm = std::numeric_limits<double>::quiet_NaN();
    group.lengthToFlowDividerMm.clear();
    for (const CatalogueComponent* c : family.ComponentsOf(role))
    {
      const double d = proximal ? c->diameterMm : c->distalDiameterMm;
      auto same = std::find_if(sizes.begin(), sizes.end(), [&](const DeviceSize& s) { return s.diameterMm == d; });
      if (same == sizes.end())
        sizes.push_back({ d, c->profileFr });
      else
        same->profileFr = std::max(same->profileFr, c->profileFr);
      if (std::isfinite(c->lengthMm))
      {
        group.lengthMinMm = std::isnan(group.lengthMinMm) ? c->lengthMm : std::min(group.lengthMinMm, c->lengthMm);
        group.lengthMaxMm = std::isnan(group.lengthMaxMm) ? c->lengthMm : std::max(group.lengthMaxMm, c->lengthMm);
      }
      if (std::isfinite(c->flowDividerMm) &&
          std::find(group.lengthToFlowDividerMm.begin(), group.lengthToFlowDividerMm.end(), c->flowDividerMm) ==
            group.lengthToFlowDividerMm.end())
        group.lengthToFlowDividerMm.push_back(c->flowDividerMm);
      if (group.evidence.empty())
        group.evidence = c->evidence;
    }
    std::sort(sizes.begin(), sizes.end(),
              [](const DeviceSize& a, const DeviceSize& b) { return a.diameterMm < b.diameterMm; });
    std::sort(group.lengthToFlowDividerMm.begin(), group.lengthToFlowDividerMm.end());
    group.sizes = sizes;
  };
  derive(ComponentRole::MainBody, family.mainBodies, true);
  derive(ComponentRole::Limb, family.limbs, false);
}

const char* ToString(DiameterReference reference)
{
  return reference == DiameterReference::Lumen ? "lumen" : "outerWall";
}

void ValidateDeviceCatalog(const DeviceCatalog& catalog)
{
  if (catalog.formatVersion != DeviceCatalogFormatVersion)
    throw InputError(DescribeCatalogField(catalog.origin, -1, "", "formatVersion") + ": is " +
                     std::to_string(catalog.formatVersion) + "; expected " +
                     std::to_string(DeviceCatalogFormatVersion) +
                     " (the version this StentGraftPlanner reads); convert the file.");
  if (catalog.families.empty())
    throw InputError(DescribeCatalogField(catalog.origin, -1, "", "families") +
                     ": is empty; expected at least one device family; add one.");
  for (size_t i = 0; i < catalog.families.size(); ++i)
  {
    FamilyValidator(catalog, int(i)).Run();
    for (size_t j = 0; j < i; ++j)
      if (LowerCase(TrimBlanks(catalog.families[j].name)) == LowerCase(TrimBlanks(catalog.families[i].name)))
        throw InputError(DescribeCatalogField(catalog.origin, int(i), catalog.families[i].name, "name") +
                         ": repeats families[" + std::to_string(j) +
                         "]; expected unique names (case-insensitive); rename one.");
  }
}

const DeviceFamily* FindDeviceFamily(const DeviceCatalog& catalog, const std::string& name)
{
  const std::string wanted = LowerCase(TrimBlanks(name));
  for (const DeviceFamily& family : catalog.families)
    if (LowerCase(TrimBlanks(family.name)) == wanted)
      return &family;
  return nullptr;
}

std::string DiametersText(const std::vector<DeviceSize>& sizes)
{
  std::string text;
  for (const DeviceSize& s : sizes)
    text += (text.empty() ? "" : ", ") + CompactNumber(s.diameterMm);
  return text + " mm";
}

ForcedDevice ParseForcedDevice(const std::string& text, const DeviceCatalog& catalog)
{
  const auto colon = text.rfind(':');
  const std::string name = text.substr(0, colon);
  const DeviceFamily* family = FindDeviceFamily(catalog, name);
  if (!family)
  {
    std::string known;
    for (const DeviceFamily& f : catalog.families)
      known += (known.empty() ? "" : ", ") + f.name;
    throw InputError("Forced device '" + text + "': no family '" + name + "' in the device catalogue '" +
                     catalog.origin + "'; expected one of: " + known + " (optionally :diameter in mm).");
  }
  ForcedDevice forced;
  forced.familyIndex = int(family - catalog.families.data());
  if (colon == std::string::npos)
    return forced;
  const std::string number = text.substr(colon + 1);
  double diameterMm = std::numeric_limits<double>::quiet_NaN();
  try
  {
    size_t used = 0;
    diameterMm = std::stod(number, &used);
    if (number.find_first_not_of(" \t", used) != std::string::npos)
      diameterMm = std::numeric_limits<double>::quiet_NaN(); // trailing text: "28mm", "28,5"
  }
  catch (const std::logic_error&) // std::stod: not a number at all, or out of range
  {
  }
  for (const DeviceSize& size : family->mainBodies.sizes)
    if (std::abs(size.diameterMm - diameterMm) <= ForcedDiameterToleranceMm)
      forced.mainBodyDiameterMm = size.diameterMm;
  if (std::isnan(forced.mainBodyDiameterMm))
    throw InputError("Forced device '" + text + "': '" + number + "' is not a main-body diameter of " + family->name +
                     " in the device catalogue '" + catalog.origin + "'; expected one of " +
                     DiametersText(family->mainBodies.sizes) + ".");
  return forced;
}

} // namespace sgp
