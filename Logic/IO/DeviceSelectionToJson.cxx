#include "IO/DeviceSelectionToJson.h"

#include <cmath>

namespace sgp
{

namespace
{

using Json = nlohmann::json;

/// JSON has no NaN: an unknown number is null.
Json NumberOrNull(double value)
{
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

Json TextOrNull(const std::string& text)
{
  return text.empty() ? Json(nullptr) : Json(text);
}

Json SizeToJson(const SizeChoice& choice)
{
  return { { "diameterMm", NumberOrNull(choice.diameterMm) },
           { "oversizingPercent", NumberOrNull(choice.oversizingPercent) },
           { "profileFr", NumberOrNull(choice.profileFr) },
           { "forced", choice.forced },
           { "reason", TextOrNull(choice.reason) } };
}

Json CheckToJson(const CriterionCheck& c)
{
  return { { "name", c.name },
           { "status", ToString(c.status) },
           { "value", NumberOrNull(c.value) },
           { "unit", c.unit },
           { "min", NumberOrNull(c.min) },
           { "max", NumberOrNull(c.max) },
           { "margin", NumberOrNull(c.margin) },
           { "requirement", c.requirement },
           { "text", c.text },
           { "evidence", c.evidence } };
}

Json FamilyToJson(const FamilyEvaluation& e)
{
  Json checks = Json::array();
  for (const CriterionCheck& c : e.checks)
    checks.push_back(CheckToJson(c));
  Json findings = Json::array();
  for (const ConfigurationFinding& f : e.configuration.findings)
    findings.push_back(f.text);
  const Json configuration = { { "configured", e.configuration.configured },
                               { "unknownReason", TextOrNull(e.configuration.unknownReason) },
                               { "orderList", e.configuration.OrderList() },
                               { "feasible", e.configuration.Feasible() },
                               { "findings", findings } };
  return { { "name", e.family },
           { "withinIfu", e.WithinIfu() },
           { "ifuStatus", ToString(e.IfuStatus()) },
           { "estimated", e.EstimatedOnLumen() ? Json("lumen") : Json(nullptr) },
           { "estimatedLevels", e.estimatedFromLumen },
           { "ipsilateralSide", e.ipsilateral.side == 0 ? "right" : "left" },
           { "ipsilateralReason", e.ipsilateral.reason },
           { "configuration", configuration },
           { "failCount", e.Count(CheckStatus::Fail) },
           { "indeterminateCount", e.Count(CheckStatus::Indeterminate) },
           { "mainBody", SizeToJson(e.mainBody) },
           { "rightLimb", SizeToJson(e.rightLimb) },
           { "leftLimb", SizeToJson(e.leftLimb) },
           { "mainBodyAccessSide", TextOrNull(e.mainBodyAccessSide) },
           { "checks", checks } };
}

} // namespace

nlohmann::json CriterionCheckToJson(const CriterionCheck& check)
{
  return CheckToJson(check);
}

nlohmann::json NeckAssessmentToJson(const NeckAssessment& neck, const std::string& rulesOrigin)
{
  Json checks = Json::array();
  for (const CriterionCheck& c : neck.checks)
    checks.push_back(CheckToJson(c));
  return { { "hostile", neck.hostile },
           { "determinate", neck.determinate },
           { "summary", neck.summary },
           { "rules", rulesOrigin },
           { "checks", checks } };
}

nlohmann::json DeviceSelectionToJson(const DeviceSelection& s)
{
  Json families = Json::array();
  for (const FamilyEvaluation& e : s.families)
    families.push_back(FamilyToJson(e));
  const bool any = s.recommended >= 0 && s.recommended < int(s.families.size());
  Json recommendation = { { "family", any ? Json(s.families[size_t(s.recommended)].family) : Json(nullptr) },
                          { "withinIfu", s.recommendedWithinIfu },
                          { "ifuStatus", ToString(s.ifuStatus) },
                          { "estimated", any && s.families[size_t(s.recommended)].EstimatedOnLumen() ? Json("lumen")
                                                                                                     : Json(nullptr) },
                          { "fullyChecked", s.recommendedFullyChecked },
                          { "summary", s.summary },
                          { "reasons", s.reasons } };
  return { { "proximalOversizingTargetPercent", s.proximalTargetPercent },
           { "limbOversizingTargetPercent", s.limbTargetPercent },
           { "forced", s.forced },
           { "recommendation", recommendation },
           { "families", families } };
}

} // namespace sgp
