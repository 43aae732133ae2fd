/// \file DeviceSelectionToJson.h
/// The device selection as a JSON object, for the planning report (the CLI's JSON output).
///
/// Shape (numbers in mm, %, degrees or Fr as their names say; NaN written as null):
///
///     { "proximalOversizingTargetPercent": 15, "limbOversizingTargetPercent": 17.5,
///       "forced": false,
///       "recommendation": { "family": "Endurant II" | null, "withinIfu": true,
///                           "ifuStatus": "pass" | "fail" | "indeterminate",
///                           "estimated": null | "lumen",
///                           "fullyChecked": true, "summary": "…", "reasons": [ "…" ] },
///       "families": [ { "name": "…", "withinIfu": true, "ifuStatus": "pass",
///                       "estimated": null | "lumen", "estimatedLevels": [ "(a)", … ],
///                       "ipsilateralSide": "right", "ipsilateralReason": "…",
///                       "configuration": { "configured": true, "unknownReason": null | "…",
///                                          "orderList": "…", "feasible": true,
///                                          "findings": [ "…" ] },
///                       "failCount": 0, "indeterminateCount": 0,
///                       "mainBody": SIZE, "rightLimb": SIZE, "leftLimb": SIZE,
///                       "mainBodyAccessSide": "right" | "left" | null,
///                       "checks": [ { "name": "neck length", "status": "pass"|"fail"|"indeterminate",
///                                     "value": 12.0, "unit": "mm", "min": 15, "max": null,
///                                     "margin": -3.0, "requirement": "≥ 15 mm",
///                                     "text": "…", "evidence": "…" } ] } ] }
///
/// where SIZE = { "diameterMm": 25 | null, "oversizingPercent": 13.6 | null,
///                "profileFr": 18 | null, "forced": false, "reason": "…" | null }.
/// `recommendation.family` is null when no device is within IFU. Does not throw.
#pragma once

#include <nlohmann/json.hpp>

#include "Device/HostileNeck.h"
#include "Device/SelectDevice.h"

namespace sgp
{

nlohmann::json DeviceSelectionToJson(const DeviceSelection& selection);

/// One check: {"name", "status" (pass/fail/indeterminate), "value", "unit", "min", "max",
/// "margin", "requirement", "text", "evidence"} (numbers null when NaN).
nlohmann::json CriterionCheckToJson(const CriterionCheck& check);

/// {"hostile", "determinate", "summary", "rules" (the rule set's origin), "checks": [one per rule,
/// pass = not hostile]}.
nlohmann::json NeckAssessmentToJson(const NeckAssessment& neck, const std::string& rulesOrigin);

} // namespace sgp
