#include "Pipeline/PlanValues.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "Centerlines/VesselOrigins.h"
#include "Common/Format.h"

namespace sgp
{
namespace
{

PlanValue Number(const std::string& name, double value)
{
  if (!std::isfinite(value))
    return { name, "-1", false };
  return { name, FormatReturnValue(value), true };
}

PlanValue Text(const std::string& name, const std::string& value, bool had)
{
  return { name, had ? value : "none", had };
}

PlanValue Boolean(const std::string& name, bool value, bool had)
{
  return { name, had && value ? "true" : "false", had };
}

} // namespace

const std::vector<std::string>& ReturnValueNames()
{
  static const std::vector<std::string> names = {
    "seedUsed",
    "seedSource",
    "lumenVolumeMl",
    "lowerHuUsed",
    "upperHuUsed",
    "acmIterations",
    "acmConverged",
    "edgeHuUsed",
    "proximalNeckDiameter",
    "neckDiameter15mm",
    "maxAneurysmDiameter",
    "distalNeckMinDiameter",
    "rightIliacDiameter",
    "leftIliacDiameter",
    "proximalNeckLumenDiameter",
    "neckLumenDiameter15mm",
    "maxAneurysmLumenDiameter",
    "distalNeckMinLumenDiameter",
    "rightIliacLumenDiameter",
    "leftIliacLumenDiameter",
    "proximalNeckLength",
    "proximalSiteToBifurcationLength",
    "rightIliacLength",
    "leftIliacLength",
    "proximalSiteToFlowDividerLength",
    "rightIliacLengthFromFlowDivider",
    "leftIliacLengthFromFlowDivider",
    "neckAngleBeta",
    "neckAngleAlpha",
    "neckConicity",
    "rightIliacTortuosity",
    "leftIliacTortuosity",
    "rightAccessMinDiameter",
    "leftAccessMinDiameter",
    "thrombusVolume",
    "sacVolume",
    "maxThrombusThickness",
    "neckThrombusArc",
    "neckCalcificationArc",
    "hostileNeck",
    "proximalSiteSource",
    "lumenSource",
    "aorticBifurcationSource",
    "rightInternalIliacOriginSource",
    "leftInternalIliacOriginSource",
    "recommendedDevice",
    "mainBodyDiameter",
    "rightLimbDiameter",
    "leftLimbDiameter",
    "mainBodyLength",
    "rightLimbLength",
    "leftLimbLength",
    "ipsilateralSideUsed",
    "orderList",
    "withinIfu",
    "ifuStatus",
    "proximalSealLength",
    "rightIliacSealLength",
    "leftIliacSealLength",
    "proximalOversizing",
    "rightLimbOversizing",
    "leftLimbOversizing",
    "coveredOstia",
    "migrationRisk",
    "fitCheckPassed",
    "deploymentToleranceHeld",
    "estimatedValues",
    "notMeasured",
  };
  return names;
}

std::vector<PlanValue> PlanReturnValues(const RepairPlan& plan)
{
  std::map<std::string, PlanValue> byName;
  const auto put = [&](PlanValue v) { byName[v.name] = std::move(v); };
  const LumenSegmentation& lumen = plan.lumen;
  // The seed in RAS, as the CLI's --seed takes it (x and y negated from LPS).
  const bool seeded = plan.seedAutomatic || plan.seedGiven; // not with a given lumen alone
  put({ "seedUsed",
        seeded ? FormatReturnValue(-plan.seedLps.x()) + "," + FormatReturnValue(-plan.seedLps.y()) + "," +
                   FormatReturnValue(plan.seedLps.z())
               : "-1,-1,-1",
        seeded });
  put({ "seedSource", plan.seedAutomatic ? "automatic" : plan.seedGiven ? "user" : "none" });
  // A given lumen has no edge level, and no window without a CT (LumenFromSegmentation.h): -1.
  put(Number("lumenVolumeMl", lumen.volumeMl));
  put(Number("lowerHuUsed", lumen.lowerHu));
  put(Number("upperHuUsed", lumen.upperHu));
  put(Number("edgeHuUsed", lumen.edgeHu));
  const bool fitted = plan.Reached(PlanStage::StentSurface);
  put({ "acmIterations", std::to_string(fitted ? plan.fit.iterations : 0), fitted });
  put(Boolean("acmConverged", plan.fit.converged, fitted));
  // The table rows: the measurements, then the simulated device's sizes and fit check.
  for (const Measurement& m : plan.rows)
  {
    PlanValue v = Number(m.name, m.value);
    v.estimated = v.measured && m.estimated;
    put(v);
  }
  const bool measured = plan.Reached(PlanStage::Measurements);
  put(Text("proximalSiteSource", ToString(plan.measurements.site.source), measured));
  put(Text("lumenSource", plan.lumenGiven ? "given" : "grown", true));
  const bool labelled = plan.Reached(PlanStage::Centerlines);
  put(Text("aorticBifurcationSource", plan.centerlines.givenBifurcationLps ? "given" : "found", labelled));
  for (int side = 0; side < 2; ++side)
    put(Text(side == 0 ? "rightInternalIliacOriginSource" : "leftInternalIliacOriginSource",
             std::isfinite(plan.centerlines.givenInternalIliacAbscissaMm[std::size_t(side)]) ? "given"
             : std::isfinite(InternalIliacOriginAbscissa(plan.centerlines, side))            ? "found"
                                                                                             : "notFound",
             labelled));
  // Decided: a rule fails, or every rule was decided; an undecided neck is not measured.
  put(Boolean("hostileNeck", plan.neck.hostile,
              measured && !plan.neck.checks.empty() && (plan.neck.hostile || plan.neck.determinate)));
  const bool selected = plan.Reached(PlanStage::Device);
  const DeviceSelection& selection = plan.selection;
  put(Text("recommendedDevice", selection.recommended >= 0 ? selection.families[selection.recommended].family : "none",
           selected));
  // Every criterion passed, none left indeterminate (a partial plan's limbs, a wall not seen).
  put(Boolean("withinIfu", selection.recommended >= 0 && selection.recommendedFullyChecked, selected));
  put(Text("ifuStatus", ToString(selection.ifuStatus), selected));
  const DeviceConfiguration* configuration = plan.Configuration();
  put(Text("ipsilateralSideUsed", configuration && configuration->ipsilateralSide == 1 ? "left" : "right",
           selected && configuration));
  put(Text("orderList", configuration ? configuration->OrderList() : "", selected && configuration));
  const bool simulated = plan.HasGraft();
  put(Text("coveredOstia", plan.fitCheck.CoveredOstia(), simulated));
  put(Boolean("migrationRisk", plan.fitCheck.migrationRisk, simulated));
  put(Boolean("fitCheckPassed", plan.fitCheck.Passed(), simulated));
  put(Boolean("deploymentToleranceHeld", plan.deploymentTolerance.findings.empty(),
              simulated && plan.deploymentTolerance.assessed));

  // estimatedValues lists the values before it that are estimates; notMeasured, the last name,
  // those the plan does not have.
  std::vector<PlanValue> values;
  std::string notMeasured, estimated;
  for (const std::string& name : ReturnValueNames())
  {
    if (name == "notMeasured" || name == "estimatedValues")
    {
      const std::string& list = name == "notMeasured" ? notMeasured : estimated;
      values.push_back({ name, list.empty() ? "none" : list, true });
      continue;
    }
    const auto found = byName.find(name);
    values.push_back(found != byName.end() ? found->second : PlanValue{ name, "-1", false });
    if (!values.back().measured)
      notMeasured += (notMeasured.empty() ? "" : ",") + name;
    if (values.back().estimated)
      estimated += (estimated.empty() ? "" : ",") + name;
    if (found != byName.end())
      byName.erase(found);
  }
  if (!byName.empty()) // a table row or value that the XML does not declare: a programming error
    throw std::logic_error("PlanReturnValues: " + byName.begin()->first + " is not in ReturnValueNames()");
  return values;
}

} // namespace sgp
