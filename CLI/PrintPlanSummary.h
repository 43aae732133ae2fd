/// \file PrintPlanSummary.h
/// What StentGraftSimulation prints after a successful run: the lumen and its window, the
/// centerlines, the stent surface, the device and the simulated graft, the measurements in words — each
/// only when the plan reached it; every number at clinical precision (ValueText.h), like every
/// number the user reads. And the warnings of the CLI edge ("WARNING: …", one line each, on stderr).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"

namespace sgp
{

/// One "WARNING: <text>" line each on `err`.
void PrintWarnings(const std::vector<std::string>& warnings, std::ostream& err);

/// One WARNING naming every return value written as −1 / none / false because the plan does not
/// have it (nothing when every value was measured).
void PrintUnmeasuredValues(const std::vector<PlanValue>& values, std::ostream& err);

/// The summary on `out` (see the file comment).
void PrintPlanSummary(const RepairPlan& plan, const std::string& acmMode, std::ostream& out);

} // namespace sgp
