/// \file SmoothCenterline.h
/// Smooths a centerline that follows voxel staircases and resamples it at a fixed arc-length step.
///
/// The polyline is first resampled finely (a tenth of the step), then every point is replaced by
/// the Gaussian-weighted mean (σ = `smoothingMm`, by arc length) of the points within a window
/// that is symmetric about it — ±3σ in the middle, shrinking to zero at the two ends, which stay
/// where they were — so a straight line stays straight and keeps its length. Radii are smoothed
/// the same way. Finally points are taken every `stepMm` of arc length from the start, plus the
/// end point.
///
/// Input: a Centerline (LPS mm). Output: the same vessel, n ≥ 2 points, abscissa recomputed.
/// Errors: InputError for stepMm outside [0.1, 10] mm or smoothingMm outside [0, 20] mm.
#pragma once

#include "Centerlines/Centerlines.h"

namespace sgp
{

Centerline SmoothCenterline(const Centerline& raw, double stepMm, double smoothingMm);

} // namespace sgp
