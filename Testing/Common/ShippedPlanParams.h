/// \file ShippedPlanParams.h
/// The planning parameters the CLI runs with by default — the XML's defaults, the shipped device
/// catalogue and hostile-neck rules — for the tests that run PlanRepair. The test target defines
/// SGP_DEVICES_JSON and SGP_NECK_RULES_JSON (the files in Resources/) and links sgpIO.
#pragma once

#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "Pipeline/PlanRepair.h"

namespace sgp::testing
{

inline PlanParams ShippedPlanParams()
{
  PlanParams params;
  params.catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  params.neckRules = ReadNeckRules(SGP_NECK_RULES_JSON);
  return params;
}

} // namespace sgp::testing
