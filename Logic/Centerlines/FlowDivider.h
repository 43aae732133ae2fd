/// \file FlowDivider.h
/// The flow divider (the carina): where the lumen of the distal aorta divides into the two common
/// iliac lumens — the highest point, along the distal aorta's axis, of the tissue between them.
/// The aortic bifurcation B (VesselOrigins.h) is where the vessel axes meet; the lumens part
/// below it, by about r / sin θ for iliacs of lumen radius r leaving at θ from the midline (14 mm
/// at 6 mm and 25°; 6.6 mm below on issue 46's real aneurysm). Planners and the instructions for
/// use take the lengths that choose a limb from the flow divider (issue 46 item 7): a limb seals
/// in the common iliac below it, not in the shared lumen above it.
///
/// Method: levels are planes ⊥ the distal aorta's axis d (the aortic centerline's chord from 25
/// to 5 mm above its end, pointing down), at depth t below the skeleton's junction (the aorta's
/// last point, where both iliac centerlines begin). At each level each iliac
/// centerline's first crossing gives a point; the segment between the right and the left point
/// is sampled every 0.2 mm on the lumen mask, interpolated trilinearly (the mask's 0.5 level lies
/// halfway between a lumen and a background voxel centre). The lumen has divided at t when a
/// sample reads under 0.5 — and still at t + 1 and t + 2 mm (a single hole in the mask is not
/// the carina). Levels are stepped 0.25 mm down from the highest level both centerlines reach,
/// then the first divided one is bisected to 0.01 mm. The flow divider is the segment's
/// lowest-reading sample there; on each iliac, its projection onto the centerline.
///
/// Uncertainty (`uncertaintyMm`): the mask decides at voxel centres, so the carina's apex is known
/// to about half the mask's coarsest spacing (1.25 mm on 2.5 mm slices); on FlowDividerPlanTest's
/// series it read 1.6 mm low to 1.2 mm high on 2.5 mm slices, 0.9 mm low to 0.1 mm on 1 mm ones.
///
/// Input: the lumen mask (nonzero = lumen; any grid), the labelled CenterlineTree (LPS mm; both
/// iliacs from the skeleton's junction). Output: FlowDivider; `found` false with the
/// reason when the lumens are already apart at the highest level both iliac centerlines reach,
/// no division is seen within 60 mm below it, or the aorta or an iliac has fewer than two points.
/// Errors: none.
#pragma once

#include <array>
#include <limits>
#include <string>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"

namespace sgp
{

struct FlowDivider
{
  bool found = false;
  std::string reason;                                         ///< why not found, one sentence; empty when found
  Point3 lps = Point3::Zero();                                ///< the carina's apex, LPS mm
  Eigen::Vector3d aorticDirection = Eigen::Vector3d::UnitZ(); ///< d, unit, pointing down
  double uncertaintyMm = 0.0;                                 ///< half the mask's coarsest spacing, mm
  /// How far below `bifurcationLps` the divider lies along d, mm (NaN when not found).
  double DepthBelowMm(const Point3& bifurcationLps) const;
  /// Per iliac (0 right, 1 left): the arc length along its centerline of the divider's projection
  /// (the iliac's cross-section through the carina: the first one that is the iliac's alone), mm.
  std::array<double, 2> iliacAbscissaMm{ std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN() };
};

FlowDivider FindFlowDivider(const LabelImage& lumen, const CenterlineTree& tree);

} // namespace sgp
