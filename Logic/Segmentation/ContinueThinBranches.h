/// \file ContinueThinBranches.h
/// Step 7 of GrowLumenRegion: a narrow branch the window lost, followed on at the edge level.
///
/// The window's lower end (m − h, GrowLumenRegion.h step 1) sits well above the half-maximum, so
/// that the growth never takes a blurred rim of tissue. On a narrow branch the blur keeps the whole
/// cross-section below it: a lumen of radius r blurred by σ peaks at 1 − exp(−r²/2σ²) of the
/// contrast, 0.76 for r = 1.7 mm and σ = 1 mm, under the window's 0.75–0.8. Where such a branch
/// runs obliquely through thick slices its peak falls further, and the face-connected growth
/// breaks off after a voxel or two. A narrow internal iliac lost that way leaves the common iliac
/// without its division, and the leg's landing zone is then read on the external iliac (issue 32:
/// the narrower of two unequal iliacs read 1.6–2.9 mm small).
///
/// From the finished lumen, every face-connected piece of voxels outside it with HU in
/// [edge level of its slice, upper] is grown — at most `maxPieceMl` (then it is a flood) — and
/// rejected when it meets a voxel at the edge level that is brighter than the window or beside
/// calcium or bone (a face neighbour above calciumHu, as in step 2): the blurred rim of a
/// calcified arc is thin and long, as a branch is. A piece is kept when it is an artery
/// continuing away from the lumen:
///  - **bright**: the 90th percentile of its voxels above half-way between the edge level and the
///    lumen level of their slice — the blurred core of a narrow artery keeps most of the lumen's
///    contrast, an enhancing vein or kidney parenchyma at the edge level does not;
///  - **thin**: no ball of radius `maxRadiusMm` lies inside it but for `ballHoleShare` of its
///    voxels (noise leaves holes in a thick tissue near the edge level) — a kidney, a vertebral
///    body or a vein wider than the branch the window lost is thick; a branch wider than this is
///    grown by the window itself;
///  - **reaching away**: some voxel of it lies at least `minReachMm` from the lumen, along the
///    piece (26-neighbour path lengths in mm from its voxels that touch the lumen): the noise
///    speckle of a wall or the partial-volume rim beyond step 5's reach lies within a millimetre
///    or two of the lumen.
/// The pieces are at the edge level already, so their boundary is the half-maximum of step 5.
///
/// Input: the CT (HU); the lumen mask on its grid (modified in place) and the box that holds
/// all of its foreground; the edge level and the lumen level per image slice k (HU); the window's
/// upper end and the calcium level (HU). Output: the number of pieces added and their volume (mL).
/// Errors: none (an empty mask adds nothing).
#pragma once

#include <functional>

#include "Common/IndexBox.h"
#include "Common/Types.h"

namespace sgp
{

struct ThinBranchParams
{
  double maxRadiusMm = 3.0;    ///< a piece holding a ball this large is not a lost branch, mm
  double minReachMm = 5.0;     ///< a piece must reach this far from the lumen, mm
  double maxPieceMl = 10.0;    ///< larger pieces are floods, mL
  double ballHoleShare = 0.15; ///< share of the ball that may be missing from a thick piece
};

struct ThinBranchResult
{
  int pieces = 0;       ///< pieces added
  double addedMl = 0.0; ///< their volume, mL
};

ThinBranchResult ContinueThinBranches(const CtImage& ct,
                                      LabelImage& lumen,
                                      const IndexBox& lumenBox,
                                      const std::function<double(long k)>& edgeHuOfSlice,
                                      const std::function<double(long k)>& lumenHuOfSlice,
                                      double upperHu,
                                      double calciumHu,
                                      const ThinBranchParams& params);

} // namespace sgp
