/// \file OrderListText.h
/// The order list as a person reads it (summary, visual report, panel): words and clinical
/// precision (0.1 mm), never variable names (STYLE.md B10).
///
///  - AnatomyLengthsText: "lowest renal → aortic bifurcation 125.0 mm → right internal iliac origin
///    55.0 mm (180.0 mm from the lowest renal), left 55.0 mm (180.0 mm)", the lengths the
///    configuration was chosen from, along the centerlines;
///  - OrderLines: a heading ("Endurant II, main body from the right: the wider access vessel
///    (…)"), then one line per component — what it is, its code, where it lies — then the
///    overlaps, the covered lengths, every finding with its option, the notes and the
///    alternatives; "estimated (lumen)" in the heading when the sizes are. One line saying why
///    when the configuration was not made, none without a main body.
/// Input: a plan that reached the device stage. Pure, does not throw.
#pragma once

#include <string>
#include <vector>

#include "Pipeline/PlanRepair.h"

namespace sgp
{

std::string AnatomyLengthsText(const RepairPlan& plan);

std::vector<std::string> OrderLines(const RepairPlan& plan);

/// Where the simulated graft's distal edge on `side` (0 right, 1 left) lies against the covered
/// length read along the centerline (issue 46 item 5): "the fabric ordered, 178.0 mm, over 180.1 mm
/// of centerline: its distal edge 2.1 mm further down than the covered length read along the
/// centerline"; "" when the ordered graft was not simulated.
std::string SimulatedLengthText(const RepairPlan& plan, int side);

/// The window a junction's overlap must lie in: "10.0–20.0 mm", "≥ 10.0 mm" when the catalogue
/// gives no maximum, one value when the gate's stub allows only the minimum.
std::string OverlapNeedsText(const ComponentOverlap& overlap);

} // namespace sgp
