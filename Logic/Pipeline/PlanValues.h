/// \file PlanValues.h
/// The plan's scalar results under the names of StentGraftSimulation's return parameters
/// (DESIGN.md "Contract"), every one of them whatever the plan reached, in the XML's order.
///
/// A value the plan does not have — a stage not run, a measurement that could not be made (NaN),
/// no graft simulated — is written as −1 (numbers), `none` (strings) or `false` (booleans), and
/// flagged `measured = false` so that the front end can say so in a warning: Slicer's generic CLI
/// panel keeps the previous run's value of any return parameter that is missing from the file.
/// The last, `notMeasured`, names every value so flagged (comma-separated, or `none`): a signed
/// value's real −1 (a conicity or an oversizing of −1 %) is told from "not measured" by it.
/// Numbers carry up to 10 significant digits (FormatReturnValue).
#pragma once

#include <string>
#include <vector>

#include "Pipeline/PlanRepair.h"

namespace sgp
{

struct PlanValue
{
  std::string name; ///< the return parameter's <name>
  std::string text; ///< formatted as the return-parameter file carries it
  bool measured = true;
  bool estimated = false; ///< an estimate (Measurement::estimated): listed in estimatedValues
};

/// The names of every return value, in the order of StentGraftSimulation.xml (a test compares).
const std::vector<std::string>& ReturnValueNames();

/// Every return value of `plan`, in ReturnValueNames() order; see the file comment.
std::vector<PlanValue> PlanReturnValues(const RepairPlan& plan);

} // namespace sgp
