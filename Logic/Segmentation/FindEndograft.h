/// \file FindEndograft.h
/// Recognises a scan the plan cannot serve because a stent graft (or another metal device) is
/// already in the aorta: a post-EVAR CT angiogram. Its struts are far brighter than contrast
/// (metal reads 1,500 HU and more, up to the scale's end), so the lumen window leaves them out and
/// the lumen inside the graft breaks into pieces that no longer make an aorto-iliac Y; without this
/// check such a scan ends in "No aortic bifurcation found", which names the wrong cause.
///
/// Method. Voxels at or above `metalHu` within `nearLumenMm` of the lumen (inside the vessel: the
/// struts lie on the graft's fabric, in the lumen or against the wall) are binned by their LPS
/// height, one bin per slice thickness along z. A bin holds a **ring** when its metal voxels,
/// seen from their own centroid in the axial (x, y) plane, fill at least `minimumRingSectors` of
/// 8 sectors of 45° at a mean distance of at least `minimumRingRadiusMm` — the cross-section of a
/// stent ring around an aortic lumen (a Z-stent's zigzag crosses every level of its ring's height
/// all around). An endograft is found when the rings cover at least `minimumRingLengthMm` of
/// height. What it rules out: calcified plaque (arcs, at most about 1,200 HU in the wall: vessel-
/// wall.md), bone (not beside the lumen), a renal stent (runs across the slices), an iliac stent or
/// kissing stents (rings under 7 mm in radius; two side by side fill few sectors from their joint
/// centroid). What it would take for one: a circumferential calcified ring of 1,500 HU and more
/// all around the aorta over a centimetre (not seen on the real scans in ../shared/data).
///
/// **Around the seed** (FindEndograftAroundSeed). A seed in the graft's main body whose lumen the
/// growing cannot follow — struts and their blooming above `calciumHu` stop it, metal streaks
/// break the window: a real post-EVAR scan grew 3 mm of lumen — leaves too little lumen for the
/// check above, and the plan would fail later for a wrong reason. The second check needs only the
/// CT and the seed: metal voxels within `seedSearchRadiusMm` of the seed in (x, y), binned by
/// height as above, are walked from the seed's bin upward and downward; a bin holds a ring when,
/// seen from the walk's current centre (first the seed, which lies inside the graft), metal lies
/// in at least `minimumRingSectors` of the 8 sectors and the nearest metal of each of 32 finer
/// sectors (the ring itself: whatever lies beyond it, a vertebra, is farther) lies at a mean of
/// at least `minimumRingRadiusMm` from its own centroid, which becomes the centre for the next bin
/// (the graft bends with the aorta). A walk ends after `maximumRingGapMm` of bins without a ring
/// (the fabric between two stents). Bone beside the aorta fills two or three sectors seen from a
/// seed inside it; a calcified arc does not reach metalHu.
///
/// Input: the CT (HU), the lumen mask on its grid and a box (image index) holding all of the
/// lumen's voxels. Output: the evidence (rings, their height, where). Units mm, HU; positions LPS.
/// Errors: InputError for parameters out of range. Complexity: one pass over the box's HU, then
/// the metal voxels only (each against a ball of `nearLumenMm` in the mask); around the seed, one
/// pass over a box of 2 seedSearchRadiusMm × 2 seedSearchRadiusMm × 2 seedSearchHeightMm.
#pragma once

#include "Common/IndexBox.h"
#include "Common/Types.h"

namespace sgp
{

struct EndograftParams
{
  double metalHu = 1500.0;           ///< metal (struts) at or above, HU; in [1000, 3071]
  double nearLumenMm = 3.0;          ///< a metal voxel this close to the lumen is inside the vessel, mm; in [1, 10]
  int minimumRingSectors = 7;        ///< of 8 sectors around the bin's metal; in [4, 8]
  double minimumRingRadiusMm = 7.0;  ///< a ring around an aortic lumen (a 14 mm device at least), mm; in [2, 30]
  double minimumRingLengthMm = 10.0; ///< height of rings for an endograft, mm; in [1, 200]
  /// Around the seed: a main body up to 36 mm across, the seed anywhere inside it, mm; in [10, 80].
  double seedSearchRadiusMm = 40.0;
  double seedSearchHeightMm = 200.0; ///< above and below the seed, mm; in [10, 500]
  double maximumRingGapMm = 10.0;    ///< the fabric between two stents of a graft, mm; in [0, 30]
};

struct EndograftEvidence
{
  int metalVoxels = 0;                   ///< at or above metalHu within nearLumenMm of the lumen
  int ringBins = 0;                      ///< height bins that hold a ring
  double ringLengthMm = 0.0;             ///< their height, mm
  double maximumHu = 0.0;                ///< brightest metal voxel beside the lumen, HU
  double ringFromZ = 0.0, ringToZ = 0.0; ///< LPS z of the lowest and highest ring bins, mm
  bool found = false;                    ///< ringLengthMm ≥ minimumRingLengthMm
  bool aroundSeed = false;               ///< from FindEndograftAroundSeed: rings around the seed
};

/// See the file comment. `box` must lie inside the image (LumenSegmentation::box).
EndograftEvidence FindEndograft(const CtImage& ct,
                                const LabelImage& lumen,
                                const IndexBox& box,
                                const EndograftParams& params = {});

/// See the file comment ("Around the seed"). `seedLps` anywhere (outside the image: nothing found).
/// metalVoxels counts the metal within seedSearchRadiusMm of the seed's (x, y), every bin.
EndograftEvidence FindEndograftAroundSeed(const CtImage& ct, const Point3& seedLps, const EndograftParams& params = {});

} // namespace sgp
