/// \file PlanRows.h
/// The plan's device rows (the table and the CLI's return values of the same names) and the scan
/// resolution the fit check needs, from a RepairPlan that reached the device stage (PlanRepair's
/// helpers, kept apart so that the pipeline's file stays one stage per function).
///
/// Input: the plan (LPS mm). Output: rows appended to `plan.rows`; a length in mm. Errors: none.
#pragma once

#include "Device/DeviceCatalog.h"
#include "Pipeline/PlanRepair.h"

namespace sgp
{

/// The simulated device's sizes as table rows, on the wall its IFU names (the graft's diameters:
/// the selection's, or the configuration's where it planned a limb the selection could not size),
/// then the fit check's rows. Needs plan.simulatedFamily ≥ 0.
void AddDeviceRows(const DeviceCatalog& catalog, RepairPlan& plan);

/// The ordered components' lengths as table rows (mainBodyLength, rightLimbLength,
/// leftLimbLength): NaN when the configuration was not made, 0 for a side whose main-body leg
/// lands without a limb.
void AddOrderRows(RepairPlan& plan);

/// The lumen grid's voxel extent along the aorta at the proximal site (FitCheckContext::
/// voxelAlongAortaMm): √Σ_i (axis_i · t spacing_i)², the image's axes in LPS, t the aorta's direction
/// there (its top where the site is not known), mm; NaN without the mask or the aorta.
double VoxelAlongAortaMm(const RepairPlan& plan);

} // namespace sgp
