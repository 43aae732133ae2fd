/// \file LabelAortoIliacTree.h
/// Finds the aortic bifurcation in a skeleton graph and names the vessels around it: the aorta,
/// the right and left iliac arteries, and the side branches (Egger et al. 2007, section 2: "the
/// three vessel centerlines (aorta, right and left iliac)").
///
/// 1. **The bifurcation** is the junction with one branch leaving superiorly (direction's z
///    component > 0.5, LPS z is superior) and two leaving inferiorly (z < −0.2) toward opposite
///    sides (x < −0.15 and x > 0.15; the patient's right is −x in LPS, whatever the image's axes),
///    each branch leading on to at least `minimumBranchLengthMm` of vessel, the two lower ones at
///    least `minimumIliacRadiusRatio` × the upper one's radius. Branch directions are taken
///    `directionReachMm` along each branch; radii are the median beyond the junction's own
///    radius. Of several such junctions the one with the widest pair of lower branches wins;
///    a runner-up within 10 % of it, elsewhere, makes the answer ambiguous.
/// 2. **The aorta** is followed upward from it, at each junction into the widest branch that
///    continues the direction (score: radius × (1 + cos of the turn)/2), to an end; if the
///    path passes over a top (the arch in a chest scan) and comes down again by more than
///    `minimumBranchLengthMm`, the part after the top is the side branch `ascendingAorta`.
///    The aorta runs from its top down to the bifurcation.
/// 3. **The iliacs** are followed downward the same way; on each, the first side branch at
///    least `minimumBranchLengthMm`/2 long and `internalIliacRadiusRatio` × the common iliac's
///    radius wide is the internal iliac, and its branching point is the iliac bifurcation.
/// 4. **Side branches** of the aorta are named by the direction in which they leave: lateral
///    (|x| ≥ 0.6 and |x| > |y|, z < 0.5) → the widest on each side within 250 mm above the
///    bifurcation is the renal artery (others: accessory renal); anterior (y < −0.6) within
///    250 mm above the bifurcation → the lower is the superior mesenteric, a higher one the
///    coeliac trunk. Others are numbered from the top: aorticBranch1, … ; rightIliacBranch1, ….
/// 5. Every vessel is smoothed and resampled (SmoothCenterline).
///
/// Input: a SkeletonGraph (LPS mm). Output: a CenterlineTree with landmarks.
/// Errors (AlgorithmError, never a made-up Y): no junction qualifies as the bifurcation (the
/// message gives the numbers of end points and junctions and the longest path, mm); two
/// candidates (the message gives both positions); a skeleton in several pieces. InputError for
/// parameters out of range.
#pragma once

#include "Centerlines.h"
#include "SkeletonGraph.h"

namespace sgp
{

struct CenterlineParams
{
  double stepMm = 1.0;                    ///< resampling step, mm; in [0.1, 10]
  double smoothingMm = 2.0;               ///< Gaussian σ along the vessel, mm; in [0, 20]
  double directionReachMm = 20.0;         ///< how far along a branch its direction is taken, mm
  double minimumBranchLengthMm = 30.0;    ///< vessel beyond a bifurcation branch, mm
  double minimumIliacRadiusRatio = 0.25;  ///< iliac radius / aortic radius at the bifurcation
  double internalIliacRadiusRatio = 0.35; ///< internal iliac radius / common iliac radius
};

void ValidateCenterlineParams(const CenterlineParams& params);

CenterlineTree LabelAortoIliacTree(const SkeletonGraph& graph, const CenterlineParams& params = {});

} // namespace sgp
