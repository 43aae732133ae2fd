/// \file SectionTilt.h
/// Whether a level's plane is the vessel's cross-section: how much the lumen's mean diameter in a
/// plane through a centerline point changes when the plane is tilted.
///
/// On a straight or gently tapering vessel a plane ⊥ the axis and one tilted by a few degrees cut
/// nearly the same section (a 10° tilt widens a round section's mean diameter by under 1 %; on a
/// cone the two sides change in opposite senses). On a bend that is also a shoulder — a short neck
/// angled into the sac — a tilt of the size of the axis' own uncertainty there moves one side of
/// the section along the widening vessel, and the diameter with it: no plane there is *the*
/// cross-section. Issue 32's sweep (seed 32): the (b) levels that read 1.9–3.5 mm beyond the
/// truth's diameter changed by 1.9–5.8 mm per 10° of tilt; the straight necks' by 0.2–0.4 mm.
///
/// The lumen's mean diameter in the plane through `centre` ⊥ `normal`: the mean over
/// `diameterCount` directions of the distance between the first points outside the lumen mask
/// (the voxel holding the point, 0.1 mm steps, at most 100 mm out) on either side.
/// TiltSensitivityMm: the largest change of that mean when `normal` is tilted by `tiltDeg` toward
/// either side along two perpendicular directions (four tilts), mm.
///
/// Input: the lumen mask (non-zero = lumen, any grid), LPS mm; `normal` need not be unit.
/// Errors: none (a ray that never leaves the lumen ends at 100 mm).
#pragma once

#include "Common/Types.h"

namespace sgp
{

double LumenMeanDiameterMm(const LabelImage& lumen,
                           const Point3& centre,
                           const Eigen::Vector3d& normal,
                           int diameterCount = 16);

double TiltSensitivityMm(const LabelImage& lumen, const Point3& centre, const Eigen::Vector3d& normal, double tiltDeg);

} // namespace sgp
