/// \file SmoothCenterline.h
/// Smooths a centerline that follows voxel staircases and resamples it at a fixed arc-length step.
///
/// The polyline is first resampled finely (a tenth of the step), then every point is replaced by
/// the Gaussian-weighted mean (by arc length) of the points within a window that is symmetric
/// about it — ±3σ in the middle, shrinking to zero at the two ends, which stay where they were —
/// so a straight line stays straight and keeps its length. Radii are smoothed with σ =
/// `smoothingMm`; points with σ = max(`smoothingMm`, WideVesselSmoothingPerRadius × the smoothed
/// radius there). In a wide sac the distance map has a plateau on which the skeleton wanders: a
/// 66 mm sac on 2.5 mm slices gave a 3 mm jog over 5 mm at its widest level, which tilted the
/// ring planes there by up to 26°, folded the s-chains of the measuring surface and read Dmax
/// 2 mm small. The skeleton's place is known to a fraction of the radius, so it is smoothed on
/// that scale (6.6 mm in that sac; unchanged in necks up to 20 mm and in the iliacs). Finally
/// points are taken every `stepMm` of arc length from the start, plus the end point.
///
/// Input: a Centerline (LPS mm). Output: the same vessel, n ≥ 2 points, abscissa recomputed.
/// Errors: InputError for stepMm outside [0.1, 10] mm or smoothingMm outside [0, 20] mm.
#pragma once

#include "Centerlines/Centerlines.h"

namespace sgp
{

/// σ per mm of the vessel's radius (above), dimensionless.
constexpr double WideVesselSmoothingPerRadius = 0.2;

Centerline SmoothCenterline(const Centerline& raw, double stepMm, double smoothingMm);

} // namespace sgp
