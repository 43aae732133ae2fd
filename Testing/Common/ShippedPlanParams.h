/// \file ShippedPlanParams.h
/// The planning parameters the CLI runs with by default — the XML's defaults, the shipped device
/// catalogue and hostile-neck rules — for the tests that run PlanRepair (under the sanitizers
/// without the deployment tolerance: below). The test target defines
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
#ifdef SGP_TESTS_UNDER_SANITIZERS
  // Under the sanitizers (7-12 times slower) the deployment tolerance — a dozen more deployments
  // per plan along paths the plan itself has just run, and no change to any other value — is left
  // to its own tests, which turn it on (Issue47…; Testing/Sanitizers/release-only.txt). The
  // Release pass runs it as shipped, in every plan.
  params.assessDeploymentTolerance = false;
#endif
  return params;
}

} // namespace sgp::testing
