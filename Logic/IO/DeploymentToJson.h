/// \file DeploymentToJson.h
/// The ordered configuration (ConfigureDevice.h) as the planning report's `deployment` object.
///
/// Shape (mm; NaN written as null):
///
///     { "family": "Endurant II" | null, "configured": true, "unknownReason": null | "…",
///       "verified": false, "estimated": null | "lumen",
///       "ipsilateralSide": "right" | "left", "ipsilateralReason": "…",
///       "orderList": "…",
///       "components": [ { "role": "mainBody" | "ipsilateralLimb" | "contralateralLimb" |
///                                  "iliacExtension" | "aorticCuff",
///                         "name": "…", "catalogueCode": "ETBF2816C145E" | null,
///                         "diameterMm": 28, "distalDiameterMm": 16, "lengthMm": 145,
///                         "vessel": "aorta" | "rightIliac" | "leftIliac",
///                         "proximalAbscissaMm": …, "distalAbscissaMm": …,
///                         "fromTargetMm": [proximal, distal],
///                         "simulatedFromTargetMm": [proximal, distal] | null, "evidence": "…" } ],
///       "overlaps": [ { "junction": "…", "side": "left", "overlapMm": 31.0, "minMm": 30,
///                       "maxMm": 34 } ],
///       "rightCoveredLengthMm": …, "leftCoveredLengthMm": …,
///       "landingZones": { "right": { "fromMm": …, "toMm": …, "sealMm": …,
///                                    "marginToInternalIliacMm": … }, "left": … },
///       "gateEndMm": 84, "gateClearanceMm": …, "flowDividerMm": 50,
///       "simulatedLength": { "right": { "fabricMm": …, "graftAxisMm": …, "centerlineMm": …,
///                                       "distalEdgeShiftMm": … }, "left": … } | null,
///       "anatomy": { "deploymentTargetAbscissaMm": …, "targetToBifurcationMm": …,
///                    "targetToRightInternalIliacMm": …, "targetToLeftInternalIliacMm": … },
///       "findings": [ { "constraint": "commonIliacTooShort", "side": "right" | "left" | null,
///                       "text": "…", "option": "…" } ],
///       "notes": [ "…" ],
///       "alternatives": [ { "component": "main body", "chosen": "28 mm",
///                           "alternative": "32 mm", "text": "…" } ] }
///
/// `vessel` is where the component's distal edge lies; both abscissae are along that vessel's
/// centerline (the aorta from its top; an iliac from its first point), so a limb's proximal end in
/// the gate, above the iliac's start, is negative: how far up the aorta it reaches. `fromTargetMm`
/// gives both ends along the side's path from the deployment target (ConfigureDevice.h), the
/// fabric's length read along the centerline; `simulatedFromTargetMm` where the simulated graft put
/// them, its fabric measured along its own axis (PlacedAlongTheGraft, issue 46 item 5), and
/// `simulatedLength` per side the fabric ordered, the simulated graft's axis, the centerline it
/// covers and how much further down it its distal edge lies (RepairPlan::distalEdgeShiftMm) — null
/// when the ordered configuration was not simulated. Positions
/// on a path come back to a centerline with the measurements' B and iliac offsets. The whole
/// object is null when no family has a main body. Does not throw.
#pragma once

#include <nlohmann/json.hpp>

#include "Pipeline/PlanRepair.h"

namespace sgp
{

nlohmann::json DeploymentToJson(const RepairPlan& plan);

} // namespace sgp
