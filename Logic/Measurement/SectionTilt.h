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

#include "Common/SmoothMask.h"
#include "Common/Types.h"

namespace sgp
{

/// Distance from `centre` along unit `e` to where `mask` first falls below 0.5: 0.5 mm march, then
/// bisection to 0.01 mm (at most 100 mm out), mm.
double SmoothBoundaryDistance(const SmoothMask& mask, const Point3& centre, const Eigen::Vector3d& e);

double LumenMeanDiameterMm(const LabelImage& lumen,
                           const Point3& centre,
                           const Eigen::Vector3d& normal,
                           int diameterCount = 16);

double TiltSensitivityMm(const LabelImage& lumen, const Point3& centre, const Eigen::Vector3d& normal, double tiltDeg);

/// The lumen's narrowest section through `centre`: of the planes whose normal lies within
/// `maxTiltDeg` of `normal`, the one whose section has the smallest mean diameter — the plane a
/// reader turns a double-oblique reformat to, the vessel's own cross-section (on a tube the plane
/// ⊥ its axis is the narrowest through an axis point; a tilt of θ widens it by about 1/cos θ).
/// Here the mask is interpolated trilinearly and a section's edge is where it crosses 0.5 (so a
/// tilt of the plane changes the mean smoothly, not by whole voxels): `diameterCount` chords,
/// 0.5 mm march then bisection to 0.01 mm. Search: tilts every 3° to `maxTiltDeg` in 20° steps of
/// azimuth, then around the best ±1.5° of tilt in 0.5° steps by ±10° of azimuth in 2.5° steps
/// (about 240 sections: some 5 ms on a 22 mm tube, SectionPlanesTest).
struct NarrowestSection
{
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< unit
  double tiltDeg = 0.0;                                ///< from `normal`
  double meanMm = 0.0;                                 ///< its mean diameter
  double minMm = 0.0, maxMm = 0.0;                     ///< its smallest and largest of the diameters
  double givenPlaneMeanMm = 0.0;                       ///< the mean diameter in the plane ⊥ `normal`
  double givenPlaneMinMm = 0.0, givenPlaneMaxMm = 0.0; ///< that plane's smallest and largest
};
NarrowestSection FindNarrowestSection(const LabelImage& lumen,
                                      const Point3& centre,
                                      const Eigen::Vector3d& normal,
                                      double maxTiltDeg,
                                      int diameterCount = 16);

} // namespace sgp
