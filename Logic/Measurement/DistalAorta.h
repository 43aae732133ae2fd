/// \file DistalAorta.h
/// (d), the distal aorta's smallest diameter, where the aorta narrows right down to its
/// bifurcation (issue 46 item 7: a bifurcation inside the sac).
///
/// The measure-mode stent's trunk ends three stent radii above the skeleton's junction
/// (StentMesh.h), clear of the flow divider; (d) has been read down to that last ring. Where a
/// distal neck runs into the bifurcation that loses nothing: the neck is as narrow at the last
/// ring as at B. Where the sac narrows all the way into the bifurcation, the aorta's narrowest
/// level is B itself, and the last ring lies up the sac's funnel: issue 46's sweep read (d) there
/// 2–16 mm too wide (21.6 for 12.8, 36.0 for 22.6 mm) on every draw without a distal neck. So
/// where the profile is still narrowing at its last reading, (d) is read on down to B — on the
/// lumen's own cross-sections (the stent has no rings there), and on the traced outer wall's
/// planes, which VesselWall.h traces to B (MeasureOuterWall.h; below the last ring only planes
/// whose centre lies above B's level count).
///
/// StillNarrowingAtItsEnd: a profile (abscissa downstream, diameter), mm, still narrows at its end
/// when its last reading is its smallest and the diameter falls by more than NarrowingPerMm per mm
/// over the last NarrowingWindowMm (at least two readings that far apart). A half-sine sac's
/// floor falls by 0.5–2 mm of diameter per mm (the phantom's range: Dmax 40–80 mm over
/// 70–120 mm); a straight distal neck by nothing, its rings' noise by ±0.2 mm: 0.15 mm per mm lies
/// between, and a neck taken for narrowing costs little (its sections read the same diameter).
///
/// NarrowestLumenSectionBelow: the lumen's sections in planes ⊥ `down`, every 1 mm below `from`
/// (the trunk's last ring centre, abscissa `fromMm`) along the straight line `down` — the distal
/// aorta's axis, toward B; the skeleton's last millimetres bend toward one iliac at the junction —
/// and at B's level, `reachMm` below `from` (the last ring may lie less than a step above it); none at or
/// below the flow divider's level (`divider`, when found) or with its centre off the lumen. Each section is read as
/// SectionTilt.h reads a plane: the mask interpolated trilinearly, its edge where it crosses 0.5, `diameterCount`
/// diameters; the narrowest by mean diameter is returned as a RingDiameters (abscissa fromMm + depth, mean, min, max,
/// the area-equivalent diameter of the 2·count edge points' polygon, centre); `found` false when no section was read.
/// B's height decides: the funnel widens by 0.5–2 mm per mm above it, and below it the floor keeps narrowing (a dome
/// over narrower iliacs), so no reading of the profile alone places the level (a knee rule read 25.6 for 27 mm, 3 mm
/// below B); B is where the axes meet (VesselOrigins.h), within 0.5 mm on the flow-divider series
/// (FlowDividerPlanTest).
///
/// Input: the lumen mask (non-zero = lumen), LPS mm. Errors: none.
#pragma once

#include <vector>

#include "Measurement/MeasureDiameters.h"

namespace sgp
{

constexpr double NarrowingPerMm = 0.15;
constexpr double NarrowingWindowMm = 4.0;

struct AbscissaDiameter
{
  double abscissaMm = 0.0, diameterMm = 0.0;
};

bool StillNarrowingAtItsEnd(const std::vector<AbscissaDiameter>& profile);

struct DistalSection
{
  bool found = false;
  RingDiameters section;
};

DistalSection NarrowestLumenSectionBelow(const LabelImage& lumen,
                                         const Point3& from,
                                         double fromMm,
                                         const Eigen::Vector3d& down,
                                         double reachMm,
                                         const Point3* divider,
                                         int diameterCount = 16);

} // namespace sgp
