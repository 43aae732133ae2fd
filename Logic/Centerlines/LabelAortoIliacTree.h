/// \file LabelAortoIliacTree.h
/// Finds the aortic bifurcation in a skeleton graph and names the vessels around it: the aorta,
/// the right and left iliac arteries, and the side branches (Egger et al. 2007, section 2: "the
/// three vessel centerlines (aorta, right and left iliac)").
///
/// 1. **The bifurcation** is the junction with one branch leaving superiorly (direction's z
///    component > 0.5, LPS z is superior) and two leaving inferiorly (z < −0.2) toward opposite
///    sides of each other (their x components differ by more than 0.3; the one toward −x is the
///    patient's right, whatever the image's axes; compared with each other, not with the x axis,
///    because the aorta may run obliquely),
///    the upper branch leading on to at least `minimumBranchLengthMm` of vessel and each lower one
///    to at least `minimumIliacLengthMm` (common, external and internal iliacs together) and,
///    followed as a vessel (step 2), ending at least `minimumIliacDescentMm` below the junction
///    (which rules out junctions in the chest whose lower limbs are short branches), the two
///    lower ones at
///    least `minimumIliacRadiusRatio` × the upper one's radius (or the aorta's median radius
///    followed up, if narrower: a junction in a sac's floor has the sac's) and the upper one at least 0.8 ×
///    the wider lower one's (which rules out the arch of a chest scan), the aorta followed up
///    (step 2) at least `minimumAortaToIliacRatio` × as wide as each iliac followed down (median
///    radius over the whole vessels), and no lower limb giving off an anterior branch (y < −0.6)
///    at least `visceralRadiusMm` wide and `minimumBranchLengthMm`/2 long that reaches 5 mm past
///    its junction's inscribed sphere, a visceral artery (these two rule out large vessels meeting
///    — the aorta against the heart and the venae cavae when the lumen spreads into them — and
///    each refusal is named in the no-bifurcation error). Branch directions are taken
///    `directionReachMm` along each branch; radii are the median beyond the junction's own
///    radius (an edge that ends inside the junction's sphere is followed on through its widest
///    way: a sac's dome thinning into a blind spur does not carry the sac's radius). Of several
///    such junctions the one with the widest pair of lower branches wins;
///    a runner-up within 10 % of it, elsewhere, makes the answer ambiguous. The two lower limbs
///    must part (LimbDivergence.h): two that run on side by side, a septum apart — the true and
///    false lumens of a dissection — are refused; and two that meet again (followed down, they
///    pass a common node: the skeleton looping round a plaque's blurred end grown into the lumen)
///    are one vessel, not two, and refused too. A Y with another Y below it on a lower limb at
///    least 0.8 × as wide as its upper branch is the aorta running on with a branch leaving it
///    (the superior mesenteric running down in front of the aorta), not the bifurcation.
///    **A partial Y** — only where the scan holds no whole one — is a junction of that shape whose
///    lower limb(s) fall short of `minimumIliacLengthMm` or `minimumIliacDescentMm` because the
///    scan's inferior border cuts them (the vessel followed ends at the border: its inscribed
///    ball reaches it, within its radius + 3 mm of the lowest slice); all the other rules hold.
///    Each such iliac's coverage — mm from B (where the axes meet, VesselOrigins.h) along it to
///    the lowest slice — goes into CenterlineTree::iliacCoverageMm; less than
///    `minimumIliacCoverageMm` on a side is an AlgorithmError naming both coverages and the scan's
///    extent (the scan ends just below the bifurcation).
/// 2. **The aorta** is followed upward from it, at each junction into the widest branch that
///    continues the direction (score: radius × (1 + cos of the turn)/2), among the branches that
///    reach an end not yet passed (a loop in the skeleton, a tunnel through a sac, leads only
///    back into the path and would end the aorta in the sac), to an end; a branch that reaches
///    no end but touches nothing else either (it ends in a loop of its own: a ring at a renal's
///    tip) is a side branch there, never the way on; if the
///    path passes over a top (the arch in a chest scan) and comes down again by more than
///    `minimumBranchLengthMm`, the part after the top is the side branch `ascendingAorta`.
///    The aorta runs from its top down to the bifurcation.
/// 3. **The iliacs** are followed downward the same way; on each, the first side branch at
///    least `minimumBranchLengthMm`/2 long and `internalIliacRadiusRatio` × the common iliac's
///    radius wide is the internal iliac, and its branching point is the iliac bifurcation. A side
///    edge that leads into the other iliac or back into the aorta is a loop of the skeleton (across
///    the crotch, where the two lumens merge), not a branch, and is left out; so is one that runs
///    back into its own iliac (VesselPath::runsBack: the other strand past a hole in the lumen).
/// 4. **Side branches** of the aorta are named by the side they leave from, their calibre, their
///    course and their order (anatomy, not one direction): the *side* is where the branch lies
///    around the aorta 1 mm outside its wall (the radial offset from the aortic axis: anterior
///    within 40° of the front, right or left from 50° in front of lateral to 60° behind it, else
///    unnamed — the
///    skeleton of a branch runs along the axis inside the aorta, and an SMA that turns down at once
///    runs in front of it); the *course* is the chord of the branch from 1 mm outside the wall,
///    `directionReachMm` long. (Two side edges whose paths meet again beyond the aorta are one
///    branch joined twice — a skeleton loop in a long oblique mouth — and the narrower is left
///    out; a side edge whose path ends where every way leads back into the aorta, at no end point
///    of its own, is a strand of a loop in the sac's skeleton, not a branch, and is left out.)
///    Anterior branches 30–250 mm above the bifurcation at least
///    max(`visceralRadiusMm`, 0.7 × the widest anterior one's radius) wide are the visceral trunks:
///    the lowest is the superior mesenteric, the one above it the coeliac trunk. Lateral branches
///    between 20 mm above the bifurcation and 15 mm above the superior mesenteric
///    (MaximumRenalHeightMm without it) whose course runs between 0.6 upward and 65° downward,
///    at least 1 mm in inscribed radius: the widest on each side, if at least 1.5 mm, is the
///    renal artery, the others accessory renals (lumbar arteries are thinner). The widest thinner
///    anterior branch more than 20 mm below the superior mesenteric and the lowest renal (and
///    20 mm above the bifurcation) is the inferior mesenteric (from the sac's front in an AAA).
///    Each named branch's ostium is a landmark (`<name>Ostium`). A branch no rule names is not
///    forced: the others are numbered from the top, aorticBranch1, …; on the iliacs
///    rightIliacBranch1, ….
/// 5. Every vessel is smoothed and resampled (SmoothCenterline).
///
/// Input: a SkeletonGraph (LPS mm). Output: a CenterlineTree with landmarks.
/// Errors (AlgorithmError, never a made-up Y): no junction qualifies as the bifurcation (the
/// message gives the numbers of end points and junctions and the longest path, mm, the scan's
/// extent and the vessels its inferior border cuts); a partial Y with too little iliac; two
/// candidates (the message gives both positions); a skeleton in several pieces; a tangle — more
/// than `maximumJunctionsInTangle` junctions within TangleRadiusMm of one (MeasureTangle), the
/// lumen spread into bowel, marrow or a plexus (checked first, before any Y is looked for).
/// InputError for parameters out of range.
#pragma once

#include "Centerlines/Centerlines.h"
#include "Centerlines/SkeletonGraph.h"

namespace sgp
{

struct CenterlineParams
{
  double stepMm = 1.0;                  ///< resampling step, mm; in [0.1, 10]
  double smoothingMm = 2.0;             ///< Gaussian σ along the vessel, mm; in [0, 20]
  double directionReachMm = 20.0;       ///< how far along a branch its direction is taken, mm
  double minimumBranchLengthMm = 30.0;  ///< vessel beyond a bifurcation branch, mm
  double minimumIliacLengthMm = 60.0;   ///< vessel beyond each iliac at the bifurcation, mm
  double minimumIliacDescentMm = 40.0;  ///< how far below the bifurcation each iliac ends, mm
  double minimumIliacCoverageMm = 10.0; ///< of a cut common iliac below B for a partial Y, mm
  /// Iliac radius / aortic radius at the bifurcation (lumen, inscribed). Was 0.25: an 8 mm common
  /// iliac with a 1.6 mm wall (a 4.8 mm lumen) below a 25 mm distal aorta is 0.22 by the truth and
  /// 0.18–0.20 on 2–3 mm slices, and its Y was refused (issue 32's sweep, 4 of 60 draws).
  double minimumIliacRadiusRatio = 0.15;
  double internalIliacRadiusRatio = 0.35; ///< internal iliac radius / common iliac radius
  double minimumAortaToIliacRatio = 1.0;  ///< aorta's median radius / each iliac's, whole vessels
  double visceralRadiusMm = 2.5;          ///< an anterior branch this wide is visceral (below a Y, a trunk), mm
  /// Most junctions within TangleRadiusMm of one junction before the skeleton is a tangle (a
  /// leak): twice the most a real lumen showed (AVT D3's irregular sac: 50 of its 60; D1, D2,
  /// D4: 6–9); in [1, 100000].
  int maximumJunctionsInTangle = 100;
};

/// Two lower limbs that diverge by less than MinimumLimbDivergenceDeg over the second half of
/// their first LimbDivergenceReachMm, with their lumens less than MaximumDissectionSeptumMm apart
/// there, run on side by side: the junction is refused as the bifurcation (step 1), and named in
/// the error. Measured (LimbDivergence.h): a dissection's channels 2.2° with a 1.5 mm flap; the
/// real bifurcations of ../shared/data 15.6–54.7° (AVT D4 the least).
constexpr double MinimumLimbDivergenceDeg = 10.0;
constexpr double MaximumDissectionSeptumMm = 3.0;
constexpr double LimbDivergenceReachMm = 40.0;

/// The radius of the neighbourhood the tangle rule counts junctions in, mm.
constexpr double TangleRadiusMm = 25.0;

/// How tangled a lumen's skeleton is (leak evidence): its independent loops (edges − nodes +
/// components), its total length (mm), and the most junctions (nodes of degree ≥ 3) within
/// `radiusMm` of one junction (itself included) and where that junction lies (LPS mm).
struct TangleMeasure
{
  int loops = 0, densestJunctions = 0;
  double lengthMm = 0.0;
  Point3 densestAt = Point3::Zero();
};

TangleMeasure MeasureTangle(const SkeletonGraph& graph, double radiusMm);

void ValidateCenterlineParams(const CenterlineParams& params);

CenterlineTree LabelAortoIliacTree(const SkeletonGraph& graph, const CenterlineParams& params = {});

} // namespace sgp
