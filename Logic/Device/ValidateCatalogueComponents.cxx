#include "Device/ValidateCatalogueComponents.h"

#include <algorithm>
#include <cmath>

#include "Common/Errors.h"
#include "Common/Text.h"
#include "Device/CriterionCheck.h"

namespace sgp
{
namespace
{

class ComponentValidator
{
public:
  ComponentValidator(const DeviceCatalog& catalog, int index)
    : m_Catalog(catalog)
    , m_Index(index)
    , m_Family(catalog.families[std::size_t(index)])
  {
  }

  void Run() const
  {
    for (const CatalogueComponent& c : m_Family.components)
      Check(c);
    CheckJunctions();
    CheckSizes();
  }

private:
  [[noreturn]] void Fail(const CatalogueComponent& c,
                         const std::string& field,
                         const std::string& seen,
                         const std::string& expected) const
  {
    throw InputError(DescribeCatalogComponentField(m_Catalog.origin, m_Index, m_Family.name, c, field) + ": " + seen +
                     "; expected " + expected + "; correct the entry.");
  }

  [[noreturn]] void FailFamily(const std::string& field, const std::string& seen, const std::string& expected) const
  {
    throw InputError(DescribeCatalogField(m_Catalog.origin, m_Index, m_Family.name, field) + ": " + seen +
                     "; expected " + expected + "; correct the entry.");
  }

  /// Positive where known; with `required`, also known.
  void Positive(const CatalogueComponent& c,
                const std::string& field,
                double value,
                const std::string& unit,
                bool required) const
  {
    if (std::isnan(value))
    {
      if (required)
        Fail(c, field, "is null (not known)", "a positive number of " + unit + " (the selection needs it)");
      return;
    }
    if (!(value > 0.0 && std::isfinite(value)))
      Fail(c, field, "is " + CompactNumber(value) + " " + unit, "a positive number of " + unit + ", or null");
  }

  void Check(const CatalogueComponent& c) const
  {
    const bool body = c.role == ComponentRole::MainBody;
    Positive(c, "diameterMm", c.diameterMm, "mm", body);
    Positive(c, "distalDiameterMm", c.distalDiameterMm, "mm", c.role == ComponentRole::Limb);
    Positive(c, "lengthMm", c.lengthMm, "mm", false);
    Positive(c, "profileFr", c.profileFr, "Fr", true);
    Positive(c, "flowDividerMm", c.flowDividerMm, "mm", false);
    Positive(c, "gateEndMm", c.gateEndMm, "mm", false);
    Positive(c, "gateDiameterMm", c.gateDiameterMm, "mm", false);
    Positive(c, "crotchWidthMm", c.crotchWidthMm, "mm", false);
    if (!body)
    {
      for (const auto& [field, value] : { std::pair<const char*, double>{ "flowDividerMm", c.flowDividerMm },
                                          { "gateEndMm", c.gateEndMm },
                                          { "gateDiameterMm", c.gateDiameterMm },
                                          { "crotchWidthMm", c.crotchWidthMm } })
        if (!std::isnan(value))
          Fail(c, field, "is given", "it only on main bodies");
    }
    else
      CheckMainBodyGeometry(c);
    for (const FigureConflict& conflict : c.conflicts)
      CheckConflict(c, conflict);
  }

  void CheckMainBodyGeometry(const CatalogueComponent& c) const
  {
    const double f = c.flowDividerMm, g = c.gateEndMm, length = c.lengthMm;
    if (!std::isnan(f) && !std::isnan(g) && !(f < g))
      Fail(c, "gateEndMm", "is " + CompactNumber(g) + " mm with the flow divider at " + CompactNumber(f) + " mm",
           "the gate to end below the flow divider");
    if (!std::isnan(g) && !std::isnan(length) && !(g <= length))
      Fail(c, "gateEndMm",
           "is " + CompactNumber(g) + " mm, beyond the body's covered length of " + CompactNumber(length) + " mm",
           "the contralateral gate to end within the body");
    if (!std::isnan(f) && !std::isnan(length) && !(f < length))
      Fail(c, "flowDividerMm", "is " + CompactNumber(f) + " mm, not within the body's " + CompactNumber(length) + " mm",
           "the flow divider within the body");
    if (!std::isnan(c.gateDiameterMm) && !(c.gateDiameterMm < c.diameterMm))
      Fail(c, "gateDiameterMm",
           "is " + CompactNumber(c.gateDiameterMm) + " mm on a " + CompactNumber(c.diameterMm) + " mm body",
           "a gate narrower than the body");
  }

  void CheckConflict(const CatalogueComponent& c, const FigureConflict& conflict) const
  {
    static const std::vector<std::string> fields = { "diameterMm",     "distalDiameterMm", "lengthMm",
                                                     "profileFr",      "flowDividerMm",    "gateEndMm",
                                                     "gateDiameterMm", "crotchWidthMm" };
    if (std::find(fields.begin(), fields.end(), conflict.field) == fields.end())
      Fail(c, "conflicts", "names the field '" + conflict.field + "'", "one of " + JoinWithCommas(fields));
    if (conflict.values.size() < 2)
      Fail(c, "conflicts", "lists " + std::to_string(conflict.values.size()) + " value(s) for " + conflict.field,
           "every value the sources give, at least two");
    const double chosen = conflict.field == "diameterMm"         ? c.diameterMm
                          : conflict.field == "distalDiameterMm" ? c.distalDiameterMm
                          : conflict.field == "lengthMm"         ? c.lengthMm
                          : conflict.field == "profileFr"        ? c.profileFr
                          : conflict.field == "flowDividerMm"    ? c.flowDividerMm
                          : conflict.field == "gateEndMm"        ? c.gateEndMm
                          : conflict.field == "gateDiameterMm"   ? c.gateDiameterMm
                                                                 : c.crotchWidthMm;
    if (std::none_of(conflict.values.begin(), conflict.values.end(), [&](double v) { return v == chosen; }))
      Fail(c, "conflicts", conflict.field + " is " + CompactNumber(chosen) + ", not among the values listed",
           "the chosen value among the conflicting ones");
  }

  void CheckJunctions() const
  {
    const IfuLimit& overlap = m_Family.junctions.overlapMm;
    if (!std::isnan(overlap.min) && !(overlap.min >= 0.0 && std::isfinite(overlap.min)))
      FailFamily("junctions.overlapMm.min", "is " + CompactNumber(overlap.min) + " mm", "0 mm or more, or null");
    if (!std::isnan(overlap.max) && !(overlap.max > 0.0 && std::isfinite(overlap.max)))
      FailFamily("junctions.overlapMm.max", "is " + CompactNumber(overlap.max) + " mm", "a positive number, or null");
    if (!std::isnan(overlap.min) && !std::isnan(overlap.max) && !(overlap.max >= overlap.min))
      FailFamily("junctions.overlapMm",
                 "is " + CompactNumber(overlap.min) + " to " + CompactNumber(overlap.max) + " mm", "min <= max");
    const double clearance = m_Family.junctions.gateClearanceMm.min;
    if (!std::isnan(clearance) && !(clearance >= 0.0 && std::isfinite(clearance)))
      FailFamily("junctions.gateClearanceMm.min", "is " + CompactNumber(clearance) + " mm", "0 mm or more, or null");
    if (std::isnan(overlap.min))
      return;
    for (const CatalogueComponent* body : m_Family.ComponentsOf(ComponentRole::MainBody))
      if (!std::isnan(body->flowDividerMm) && !std::isnan(body->gateEndMm) &&
          overlap.min > body->gateEndMm - body->flowDividerMm)
        Fail(*body, "junctions.overlapMm.min",
             "is " + CompactNumber(overlap.min) + " mm, longer than the " +
               CompactNumber(body->gateEndMm - body->flowDividerMm) + " mm contralateral gate of " + body->Label(),
             "at most the shortest gate stub (gate end minus flow divider): a limb cannot be inserted deeper");
  }

  /// The selection's sizes must be the ones the components give.
  void CheckSizes() const
  {
    if (m_Family.components.empty())
      return;
    DeviceFamily derived = m_Family;
    DeriveSizesFromComponents(derived);
    const auto same = [](const std::vector<DeviceSize>& a, const std::vector<DeviceSize>& b)
    {
      return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                                [](const DeviceSize& x, const DeviceSize& y)
                                                { return x.diameterMm == y.diameterMm && x.profileFr == y.profileFr; });
    };
    if (!same(derived.mainBodies.sizes, m_Family.mainBodies.sizes))
      FailFamily("mainBodies", "lists sizes " + DiametersText(m_Family.mainBodies.sizes),
                 "the main-body components' diameters and profiles, " + DiametersText(derived.mainBodies.sizes));
    if (!same(derived.limbs.sizes, m_Family.limbs.sizes))
      FailFamily("limbs", "lists sizes " + DiametersText(m_Family.limbs.sizes),
                 "the limb components' distal diameters and profiles, " + DiametersText(derived.limbs.sizes));
  }

  const DeviceCatalog& m_Catalog;
  int m_Index;
  const DeviceFamily& m_Family;
};

} // namespace

void ValidateCatalogueComponents(const DeviceCatalog& catalog, int familyIndex)
{
  ComponentValidator(catalog, familyIndex).Run();
}

} // namespace sgp
