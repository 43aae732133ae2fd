#include "IO/DeploymentToJson.h"

#include <cmath>

namespace sgp
{
namespace
{

using Json = nlohmann::json;

Json NumberOrNull(double value)
{
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

/// A component's vessel and its two ends' abscissae along that vessel's centerline.
Json Placement(const RepairPlan& plan, double target, const ConfiguredComponent& c)
{
  const Measurements& m = plan.measurements;
  const double toBifurcation = m.bifurcationAbscissaMm - target;
  const bool inAorta = c.distalMm <= toBifurcation;
  const double shift = inAorta ? target : -(toBifurcation + m.iliacStartBeyondBifurcationMm[std::size_t(c.side)]);
  return { { "vessel", inAorta ? std::string("aorta") : std::string(SideName(c.side)) + "Iliac" },
           { "proximalAbscissaMm", c.proximalMm + shift },
           { "distalAbscissaMm", c.distalMm + shift },
           { "fromTargetMm", { c.proximalMm, c.distalMm } } };
}

/// With a configuration given: the recommendation's order list and every difference from it; null
/// without one.
Json Differences(const RepairPlan& plan)
{
  if (!plan.recommendation)
    return Json(nullptr);
  const int f = FamilyForMainBody(*plan.recommendation);
  Json list = Json::array();
  for (const ConfigurationDifference& d : plan.configurationDifferences)
    list.push_back(
      { { "what", d.what }, { "change", d.change }, { "consequence", d.consequence }, { "text", d.Text() } });
  return { { "recommendedOrderList",
             f >= 0 ? Json(plan.recommendation->families[std::size_t(f)].configuration.OrderList()) : Json(nullptr) },
           { "items", list } };
}

} // namespace

nlohmann::json DeploymentToJson(const RepairPlan& plan)
{
  const DeviceConfiguration* c = plan.Configuration();
  if (!c)
    return nullptr;
  const FamilyEvaluation& family = plan.selection.families[std::size_t(plan.orderedFamily)];
  const double target = plan.deploymentTargetAbscissaMm;
  // The simulated graft is the ordered configuration's when it was laid out from it (same
  // components, in the same order).
  const bool simulated = plan.HasGraft() && plan.simulatedFamily == plan.orderedFamily &&
                         plan.graft.layout.configured && plan.graft.layout.components.size() == c->components.size();
  Json components = Json::array();
  for (std::size_t index = 0; index < c->components.size(); ++index)
  {
    const ConfiguredComponent& part = c->components[index];
    Json json = { { "role", ToString(part.role) },
                  { "side", part.role == OrderRole::MainBody ? Json(nullptr) : Json(SideName(part.side)) },
                  { "name", part.item.name },
                  { "catalogueCode", part.item.code.empty() ? Json(nullptr) : Json(part.item.code) },
                  { "diameterMm", NumberOrNull(part.item.diameterMm) },
                  { "distalDiameterMm", NumberOrNull(part.item.distalDiameterMm) },
                  { "lengthMm", NumberOrNull(part.item.lengthMm) },
                  { "evidence", part.item.evidence } };
    json.update(Placement(plan, target, part));
    // How far it may land from its plan (ConfiguredComponent::holds…; null for the main body).
    json["holdsMm"] = std::isfinite(part.holdsAboveMm + part.holdsBelowMm)
                        ? Json{ { "above", part.holdsAboveMm },
                                { "below", part.holdsBelowMm },
                                { "aboveLimit", part.holdsAboveLimit },
                                { "belowLimit", part.holdsBelowLimit } }
                        : Json(nullptr);
    if (simulated)
    {
      const ConfiguredComponent& placed = plan.graft.layout.components[index];
      json["simulatedFromTargetMm"] = { placed.proximalMm, placed.distalMm };
    }
    else
      json["simulatedFromTargetMm"] = nullptr;
    components.push_back(json);
  }
  Json overlaps = Json::array();
  for (const ComponentOverlap& o : c->overlaps)
    overlaps.push_back({ { "junction", o.junction },
                         { "side", SideName(o.side) },
                         { "overlapMm", o.overlapMm },
                         { "minMm", NumberOrNull(o.minMm) },
                         { "maxMm", NumberOrNull(o.maxMm) } });
  Json findings = Json::array();
  for (const ConfigurationFinding& f : c->findings)
    findings.push_back({ { "constraint", f.constraint },
                         { "side", f.side < 0 ? Json(nullptr) : Json(SideName(f.side)) },
                         { "text", f.text },
                         { "option", f.option } });
  Json alternatives = Json::array();
  for (const SizeAlternative& a : c->alternatives)
    alternatives.push_back(
      { { "component", a.component }, { "chosen", a.chosen }, { "alternative", a.alternative }, { "text", a.text } });
  Json zones = Json::object();
  for (int side = 0; side < 2; ++side)
    zones[SideName(side)] = { { "fromMm", c->configured ? Json(c->landingLowMm[std::size_t(side)]) : Json(nullptr) },
                              { "toMm", c->configured ? Json(c->landingHighMm[std::size_t(side)]) : Json(nullptr) },
                              { "sealMm", c->configured ? Json(c->sealLengthMm[std::size_t(side)]) : Json(nullptr) },
                              { "marginToInternalIliacMm",
                                c->configured ? Json(c->marginToInternalIliacMm[std::size_t(side)]) : Json(nullptr) } };
  Json simulatedLength = nullptr;
  if (simulated)
  {
    simulatedLength = Json::object();
    for (int side = 0; side < 2; ++side)
    {
      const std::size_t s = std::size_t(side);
      simulatedLength[SideName(side)] = { { "fabricMm", NumberOrNull(plan.graftFabricLengthMm[s]) },
                                          { "graftAxisMm", NumberOrNull(plan.graftAxisLengthMm[s]) },
                                          { "centerlineMm", NumberOrNull(plan.graftPathLengthMm[s]) },
                                          { "distalEdgeShiftMm", NumberOrNull(plan.distalEdgeShiftMm[s]) } };
    }
  }
  // How far each component may land from its plan, simulated (issue 47; null when not assessed).
  const DeploymentTolerance& t = plan.deploymentTolerance;
  Json holds = Json::array();
  for (const ComponentHold& h : t.components)
    holds.push_back({ { "component", h.component },
                      { "name", h.name },
                      { "aboveMm", h.aboveMm },
                      { "belowMm", h.belowMm },
                      { "aboveFails", h.aboveFails.empty() ? Json(nullptr) : Json(h.aboveFails) },
                      { "belowFails", h.belowFails.empty() ? Json(nullptr) : Json(h.belowFails) },
                      { "aboveStops", h.aboveStops },
                      { "belowStops", h.belowStops },
                      { "text", h.Text(t.searchMm) },
                      { "finding", h.finding.empty() ? Json(nullptr) : Json(h.finding) } });
  const Json tolerance = { { "assessed", t.assessed },
                           { "notAssessedReason", t.assessed ? Json(nullptr) : Json(t.notAssessedReason) },
                           { "toleranceMm", t.toleranceMm },
                           { "searchMm", t.searchMm },
                           { "resolutionMm", t.resolutionMm },
                           { "simulations", t.simulations },
                           { "components", holds },
                           { "findings", t.findings },
                           { "notes", t.notes } };
  const double toBifurcation = plan.measurements.bifurcationAbscissaMm - target;
  return {
    { "family", c->family },
    { "configured", c->configured },
    { "unknownReason", c->configured ? Json(nullptr) : Json(c->unknownReason) },
    { "estimated", family.EstimatedOnLumen() ? Json("lumen") : Json(nullptr) },
    { "ipsilateralSide", SideName(c->ipsilateralSide) },
    { "ipsilateralReason", c->ipsilateralReason },
    { "orderList", c->OrderList() },
    { "given", c->given },
    { "differences", Differences(plan) },
    { "components", components },
    { "overlaps", overlaps },
    { "rightCoveredLengthMm", c->configured ? Json(c->coveredLengthMm[0]) : Json(nullptr) },
    { "leftCoveredLengthMm", c->configured ? Json(c->coveredLengthMm[1]) : Json(nullptr) },
    { "landingZones", zones },
    { "gateEndMm", c->configured ? Json(c->gateEndMm) : Json(nullptr) },
    { "gateClearanceMm", c->configured ? Json(c->gateClearanceMm) : Json(nullptr) },
    { "flowDividerMm", c->configured ? Json(c->flowDividerMm) : Json(nullptr) },
    { "deploymentToleranceMm", c->configured ? Json(c->deploymentToleranceMm) : Json(nullptr) },
    { "simulatedLength", simulatedLength },
    { "tolerance", simulated && plan.graft.layout.configured ? tolerance : Json(nullptr) },
    { "anatomy",
      { { "deploymentTargetAbscissaMm", target },
        { "deploymentMarginMm", plan.deploymentMarginMm },
        { "siteEdgeUncertaintyMm", plan.measurements.site.edgeUncertaintyMm },
        { "targetToBifurcationMm", NumberOrNull(toBifurcation) },
        { "targetToRightInternalIliacMm", NumberOrNull(toBifurcation + plan.measurements.Value("rightIliacLength")) },
        { "targetToLeftInternalIliacMm", NumberOrNull(toBifurcation + plan.measurements.Value("leftIliacLength")) },
        { "targetToFlowDividerMm",
          NumberOrNull(toBifurcation + plan.measurements.flowDivider.DepthBelowMm(plan.measurements.bifurcationLps)) },
        { "sealFromMm",
          { { "right", c->configured ? Json(c->sealFromMm[0]) : Json(nullptr) },
            { "left", c->configured ? Json(c->sealFromMm[1]) : Json(nullptr) } } } } },
    { "findings", findings },
    { "notes", c->notes },
    { "alternatives", alternatives }
  };
}

} // namespace sgp
