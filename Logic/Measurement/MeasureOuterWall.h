/// \file MeasureOuterWall.h
/// The sizing diameters (a)–(f) outer wall to outer wall, and the thrombus, sac and calcium values,
/// read off the traced vessel wall (VesselWall.h) in planes perpendicular to the lumen's centerline
/// — the diameters the instructions for use and the guidelines size on (vessel-wall.md §4: SVS
/// 2018, "outer wall to outer wall perpendicular to the path of the aorta").
///
/// Definitions (mm, along each vessel's centerline abscissa; planes every VesselWall::stepMm):
///  - a level's outer diameter: the area-equivalent diameter 2·√(A/π) of the outer contour of the
///    plane nearest the level (within one step), with the contour's smallest and largest width
///    beside it; (c) is the largest maximum caliper (guidelines: Dmax "in any direction");
///  - (a) at the site, (b) 15 mm below, (c) over [site, B], (d) the smallest from (c)'s plane to
///    `trunkEndMm` — to B where the planes still narrow there (DistalAorta.h; below the last ring
///    only planes whose centre lies above B's level), (e)/(f) the median over each iliac's
///    planes in [landing from, landing to];
///  - **support**: a level whose plane is less than `estimatedBelow` (60 %) supported, or whose
///    contour is interpolated between traced planes, is `estimated` with a warning; a plane
///    without a contour (SegmentOuterWall: under 25 % and no traced plane on both sides) or none
///    within a step: NaN with a warning. (c), (d) and the volumes, extremes and sums over a
///    stretch, are NaN with a warning when the stretch has a gap of more than 10 mm without a
///    contour (the extreme may lie in it); (c) is estimated too when an end of its caliper lies on
///    a ray without a boundary (the fitted model's, behind a neighbour);
///  - `thrombusVolume` Σ thrombus area × step over [site, B], mL; `sacVolume` Σ outer area ×
///    step, mL; `maxThrombusThickness` the largest ray thrombus over [site, B]; `neckThrombusArc`
///    the largest share of a plane's rays with thrombus thicker than 2 mm over [site, site + 15];
///    `neckCalcificationArc` likewise for calcified rays, %;
///  - the neck's end on the outer wall: the first plane below the site whose smallest width exceeds
///    (a) by 10 % (linear between planes), as MeasureAnatomy does on the rings;
///  - reverse taper: the outer diameter 10 and 15 mm below the site minus (a), mm.
///
/// Errors: none; values that cannot be measured are NaN, with the reason in `out.warnings`.
#pragma once

#include <array>

#include "Measurement/MeasureAnatomy.h"
#include "Wall/VesselWall.h"

namespace sgp
{

/// Where MeasureAnatomy read the lumen values: the abscissae the outer values use.
struct OuterWallLevels
{
  double siteMm = 0.0;                                                      ///< along the aorta
  double bifurcationMm = 0.0;                                               ///< B along the aorta
  double trunkEndMm = 0.0;                                                  ///< the trunk's last ring
  std::array<double, 2> landingFromMm{ 0.0, 0.0 }, landingToMm{ 0.0, 0.0 }; ///< along each iliac
  /// B and the distal aorta's direction toward it (unit, LPS): below the trunk's last ring a plane
  /// whose centre lies past B's level is not the aorta's (the centerline bends into an iliac).
  Point3 bifurcationLps = Point3::Zero();
  Eigen::Vector3d distalDirection = Eigen::Vector3d::Zero();
};

/// Share of a level's circumference under which its outer diameter is an estimate (issue 12).
constexpr double EstimatedBelowSupport = 0.6;

/// Appends the outer (a)–(f) (names without "Lumen") and the thrombus values to `out.values`,
/// their warnings to `out.warnings`; sets `out.outerNeckEndMm`, `out.reverseTaperMm`.
void MeasureOuterWall(const VesselWall& wall, const OuterWallLevels& levels, Measurements& out);

/// The centroid of the outer contour of the aortic plane within half a step of `s`, or the
/// centerline point there when there is none (or it is flagged).
Point3 OuterAxisPoint(const VesselWall* wall, const Centerline& aorta, double s);

} // namespace sgp
