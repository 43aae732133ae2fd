/// \file PlanTolerance.h
/// The plan's ordered configuration deployed again with each component displaced (issue 47;
/// DeploymentTolerance.h): each displaced configuration laid out along the planned graft's axes
/// (PlacedAlongShiftedGraft: a component moved a few millimetres does not change the graft's
/// course, so one fit serves where the plan's own deployment needed several), fitted with the
/// plan's active-contour parameters in the measure-mode wall field where it covers the graft (else
/// the graft's own), and judged by the fit check on its own findings (the configuration's are the
/// plan's, not the displacement's). The main body's search starts from the planned fit check: down,
/// the proximal seal beyond its minimum and its uncertainty; up, the deployment margin and offset
/// and the ostium tolerance.
///
/// Input: a plan whose ordered configuration was simulated (RepairPlan::graftAxes set), the plan's
/// parameters (PlanParams::selection.deploymentToleranceMm, mesh, graft), the measure-mode wall
/// field, the fit check's context as the plan made it. Output: DeploymentTolerance (mm).
/// Errors: none of its own: a displaced graft that cannot be laid out (a distal edge beyond the
/// iliac in view) fails its check, with the reason.
#pragma once

#include "Device/DeploymentTolerance.h"
#include "Device/FitCheck.h"
#include "Pipeline/PlanRepair.h"
#include "Stent/WallDistanceField.h"

namespace sgp
{

DeploymentTolerance AssessPlanTolerance(const RepairPlan& plan,
                                        const PlanParams& params,
                                        const WallDistanceField& measureWall,
                                        FitCheckContext context);

} // namespace sgp
