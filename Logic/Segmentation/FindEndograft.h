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
/// Input: the CT (HU), the lumen mask on its grid and a box (image index) holding all of the
/// lumen's voxels. Output: the evidence (rings, their height, where). Units mm, HU; positions LPS.
/// Errors: InputError for parameters out of range. Complexity: one pass over the box's HU, then
/// the metal voxels only (each against a ball of `nearLumenMm` in the mask).
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
};

struct EndograftEvidence
{
  int metalVoxels = 0;                   ///< at or above metalHu within nearLumenMm of the lumen
  int ringBins = 0;                      ///< height bins that hold a ring
  double ringLengthMm = 0.0;             ///< their height, mm
  double maximumHu = 0.0;                ///< brightest metal voxel beside the lumen, HU
  double ringFromZ = 0.0, ringToZ = 0.0; ///< LPS z of the lowest and highest ring bins, mm
  bool found = false;                    ///< ringLengthMm ≥ minimumRingLengthMm
};

/// See the file comment. `box` must lie inside the image (LumenSegmentation::box).
EndograftEvidence FindEndograft(const CtImage& ct,
                                const LabelImage& lumen,
                                const IndexBox& box,
                                const EndograftParams& params = {});

} // namespace sgp
