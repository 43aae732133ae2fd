#include "IO/WriteMeasurements.h"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "IO/WriteReturnParameters.h"
#include "IO/WriteTextFile.h"
#include "Pipeline/ValueText.h"

namespace sgp
{
namespace
{

std::string Number(double value)
{
  return std::isfinite(value) ? FormatReturnValue(value) : std::string();
}

std::string Quoted(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

nlohmann::json JsonNumber(double value)
{
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json JsonPoint(const Point3& p)
{
  return nlohmann::json::array({ p.x(), p.y(), p.z() });
}

} // namespace

std::string FormatMeasurementsTable(const Measurements& measurements)
{
  return FormatMeasurementsTable(measurements.values);
}

std::string FormatMeasurementsTable(const std::vector<Measurement>& rows)
{
  std::ostringstream out;
  out << "name,value,unit,definition,vessel,abscissaMm,minDiameterMm,maxDiameterMm,areaDiameterMm,wall,estimated,label,"
         "shown\n";
  for (const Measurement& m : rows)
  {
    out << m.name << ',' << Number(m.value) << ',' << Quoted(m.unit) << ',' << Quoted(m.definition) << ',' << m.vessel
        << ',' << Number(m.abscissaMm) << ',' << Number(m.minMm) << ',' << Number(m.maxMm) << ',' << Number(m.areaMm)
        << ',' << m.wall << ',' << (m.estimated ? "true" : "false") << ',' << Quoted(ValueLabel(m.name)) << ','
        << Quoted(ClinicalText(m.value, m.unit) + (m.estimated ? " (estimated)" : "")) << '\n';
  }
  return out.str();
}

std::string FormatDiameterProfiles(const Measurements& measurements)
{
  std::ostringstream out;
  out << "vessel,abscissaMm,meanDiameterMm,minDiameterMm,maxDiameterMm,areaDiameterMm\n";
  for (const DiameterProfile& profile : measurements.profiles)
    for (const RingDiameters& r : profile.rings)
      out << profile.vessel << ',' << Number(r.abscissaMm) << ',' << Number(r.meanMm) << ',' << Number(r.minMm) << ','
          << Number(r.maxMm) << ',' << Number(r.areaMm) << '\n';
  return out.str();
}

void WriteMeasurementsTable(const std::vector<Measurement>& rows, const std::string& path)
{
  WriteTextFile(FormatMeasurementsTable(rows), path, "measurements table");
}

void WriteDiameterProfiles(const Measurements& measurements, const std::string& path)
{
  WriteTextFile(FormatDiameterProfiles(measurements), path, "diameter profile table");
}

nlohmann::json MeasurementsToJson(const Measurements& measurements)
{
  nlohmann::json out;
  const ProximalSite& site = measurements.site;
  // Not known (source notFound): no position; where the measure-mode surface started instead.
  out["proximalSite"] = { { "source", ToString(site.source) },
                          { "abscissaMm", site.Known() ? nlohmann::json(site.abscissaMm) : nlohmann::json(nullptr) },
                          { "lps", site.Known() ? JsonPoint(site.lps) : nlohmann::json(nullptr) },
                          { "renal", site.renal } };
  if (!site.Known())
    out["proximalSite"]["surfaceStartAbscissaMm"] = site.abscissaMm;
  out["aorticBifurcation"] = { { "lps", JsonPoint(measurements.bifurcationLps) },
                               { "abscissaMm", measurements.bifurcationAbscissaMm },
                               { "source", measurements.bifurcationGiven ? "given" : "found" } };
  for (int side = 0; side < 2; ++side)
  {
    const Point3& origin = measurements.internalIliacOriginLps[side];
    out[side == 0 ? "rightInternalIliacOrigin" : "leftInternalIliacOrigin"] =
      origin.allFinite()
        ? nlohmann::json{ { "lps", JsonPoint(origin) },
                          { "source", measurements.internalIliacOriginGiven[std::size_t(side)] ? "given" : "found" } }
        : nlohmann::json(nullptr);
  }
  nlohmann::json values = nlohmann::json::array();
  for (const Measurement& m : measurements.values)
  {
    nlohmann::json row = { { "name", m.name },
                           { "value", JsonNumber(m.value) },
                           { "unit", m.unit },
                           { "definition", m.definition },
                           { "vessel", m.vessel },
                           { "abscissaMm", JsonNumber(m.abscissaMm) },
                           { "wall", m.wall.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.wall) },
                           { "estimated", m.estimated } };
    if (std::isfinite(m.minMm))
    {
      row["minDiameterMm"] = m.minMm;
      row["maxDiameterMm"] = m.maxMm;
      row["areaDiameterMm"] = m.areaMm;
    }
    values.push_back(row);
  }
  out["measurements"] = values;
  nlohmann::json profiles = nlohmann::json::object();
  for (const DiameterProfile& profile : measurements.profiles)
  {
    nlohmann::json rows = nlohmann::json::array();
    for (const RingDiameters& r : profile.rings)
      rows.push_back({ r.abscissaMm, r.meanMm, r.minMm, r.maxMm, r.areaMm });
    profiles[profile.vessel] = rows;
  }
  out["diameterProfiles"] = profiles;
  out["warnings"] = measurements.warnings;
  return out;
}

nlohmann::json FitCheckToJson(const FitCheck& check)
{
  nlohmann::json ostia = nlohmann::json::array(), covered = nlohmann::json::array();
  for (const OstiumCoverage& o : check.ostia)
  {
    ostia.push_back({ { "branch", o.branch },
                      { "parent", o.parent },
                      { "upperAbscissaMm", o.upperAbscissaMm },
                      { "lowerAbscissaMm", o.lowerAbscissaMm },
                      { "overlapMm", o.overlapMm },
                      { "covered", o.covered },
                      { "mayBeCovered", o.mayBeCovered },
                      { "edgeUncertaintyMm", o.edgeUncertaintyMm } });
    if (o.covered)
      covered.push_back(o.branch);
  }
  return { { "passed", check.Passed() },
           { "limbsChecked", { { "right", check.limbChecked[0] }, { "left", check.limbChecked[1] } } },
           { "migrationRisk", check.migrationRisk },
           { "proximalSealLengthMm", check.proximalSealLengthMm },
           { "minimumProximalSealMm", check.minimumProximalSealMm },
           { "minimumIliacSealMm", check.minimumIliacSealMm },
           { "proximalSealEnd", check.proximalSealEnd },
           { "proximalSealUncertaintyMm", check.proximalSealUncertaintyMm },
           { "proximalSealUncertainty", check.proximalSealUncertaintyWhy },
           { "shortestAppositionLengthMm", JsonNumber(check.shortestAppositionLengthMm) },
           { "minimumAppositionLengthMm", check.minimumAppositionLengthMm },
           { "shortestAppositionSide", check.shortestAppositionSide },
           { "shortestAppositionEnd", check.shortestAppositionEnd },
           { "proximalCalcifiedPercent", check.proximalCalcifiedPercent },
           { "sealEstimatedOnLumen",
             { { "proximal", check.sealOnLumenOnly[0] },
               { "right", check.sealOnLumenOnly[1] },
               { "left", check.sealOnLumenOnly[2] } } },
           { "sealDefinition", "apposed within 1 mm on healthy wall: thrombus under 2 mm thick and, proximally, the "
                               "outer wall within 10 % of (a); a ring seals when 90 % of it does" },
           { "rightIliacSealLengthMm", JsonNumber(check.rightIliacSealLengthMm) },
           { "leftIliacSealLengthMm", JsonNumber(check.leftIliacSealLengthMm) },
           { "proximalOversizingPercent", JsonNumber(check.proximalOversizingPercent) },
           { "rightLimbOversizingPercent", JsonNumber(check.rightLimbOversizingPercent) },
           { "leftLimbOversizingPercent", JsonNumber(check.leftLimbOversizingPercent) },
           { "coveredOstia", covered },
           { "ostia", ostia },
           { "findings", check.findings } };
}

} // namespace sgp
