/// \file LimbDivergence.h
/// Whether the two lower limbs of a Y-shaped junction part like iliac arteries or run on side by
/// side like the true and false lumens of an aortic dissection. The iliacs diverge (each leaves
/// the midline by 15–45°) and are soon apart by more than their walls; a dissection's two channels,
/// split by a thin flap, run along the aorta at a nearly constant distance, their lumens a septum
/// apart. Issue 33: a thoraco-abdominal scan whose dissection ran to the lower border was planned
/// with the two channels taken for the iliac arteries.
///
/// Over the first `reachMm` of both limbs (or as far as the shorter reaches: S), with D(s) the
/// distance between the points at equal arc length s from the junction:
///  - the divergence angle 2·asin((D(S) − D(S/2)) / S), degrees: the full angle between two
///    straight limbs, 0 for parallel ones, negative for converging ones (the first half is left
///    out: there the skeleton of any split moves from the junction to each channel's centre);
///  - the septum at S: D(S) less both limbs' inscribed radii there, mm (the tissue between the two
///    lumens; about a flap's thickness for a dissection).
///
/// Input: the limbs as polylines from the junction with an inscribed radius per point (LPS mm,
/// the junction first). Output: both, NaN when the shorter limb is under 4 mm (too short to tell).
/// Errors: none.
#pragma once

#include <vector>

#include "Common/Types.h"

namespace sgp
{

struct LimbDivergence
{
  double angleDeg = 0.0; ///< divergence over the second half of S, degrees
  double septumMm = 0.0; ///< between the two lumens at S, mm
  double reachMm = 0.0;  ///< S, mm
};

LimbDivergence MeasureLimbDivergence(const std::vector<Point3>& a,
                                     const std::vector<double>& radiiA,
                                     const std::vector<Point3>& b,
                                     const std::vector<double>& radiiB,
                                     double reachMm);

} // namespace sgp
