/// \file LumenFromSegmentation.h
/// The lumen a person gave (a label map made in Segment Editor, by TotalSegmentator, by hand)
/// taken in place of region growing (DESIGN.md, "What the surgeon gives wins"): every later stage
/// runs on it as on a grown lumen.
///
///  1. **Onto the CT's grid.** With a CT, each CT voxel takes the value of the segmentation's voxel
///     nearest to its centre in physical space (LPS mm; the two grids may differ in spacing,
///     origin and direction); CT voxels whose centre lies outside the segmentation are background.
///     Without a CT, the segmentation's own grid is the plan's.
///  2. **One piece.** The 6-connected piece (as the region growing's) that holds the seed, when a
///     seed is given and lies in a piece; else the largest. Every other piece is left out, and a
///     warning names their count and volumes: a vessel painted apart from the aorta, a kidney or
///     vein given the same label, islands of paint.
///  3. **Cavities** not connected to the outside become lumen (as the region growing's step 6).
///  4. **The window**, for the outer wall's calcium threshold and the summary (with a CT only):
///     the region growing's own step 1b on this lumen (GrowLumenRegion.h): the lumen's core
///     (LumenCore: blocks 5 mm inside its edge, in the piece nearest the seed, or nearest the
///     centre of the slice with the most lumen without one), its levels slab by slab, the window
///     from them, and calcium above its top plus a quarter of its width — so the round trip
///     (a plan from its own lumen label map) reads the wall with the threshold it had. A lumen
///     with no core (small vessels only): the median m and robust σ of the lumen's interior
///     (voxels whose six face neighbours are lumen), [m − h, m + 2h], h = max(3σ, 30 HU). The
///     interior's m and σ are reported as the seed statistics; the edge level is NaN.
///
/// Input: `given` on its own grid, non-zero = lumen (LPS geometry from the file); `ct` (HU) or
/// null; `seedLps` (LPS mm) or empty. **`given` is handed over**: where it lies on the CT's grid
/// (or there is no CT) its buffer becomes the lumen's mask and is changed (1 for lumen, the pieces
/// left out and the cavities filled) — the re-plan then holds one full-size mask, not three.
/// Output: LumenSegmentation on the CT's grid (the given grid without a CT); `windowSource` says
/// where the lumen came from.
/// Errors (InputError): the segmentation and the CT do not overlap (both extents named, mm); no
/// voxel of the segmentation falls on the CT's grid; the segmentation is empty.
///
/// Complexity: one pass over the segmentation's foreground box (resampling visits only the CT
/// voxels of that box's physical extent), then linear work in the lumen's bounding box. Memory:
/// no full-size buffer beside `given` on the CT's grid; one (the CT's grid) otherwise.
#pragma once

#include <optional>

#include "Common/Types.h"
#include "Segmentation/GrowLumenRegion.h"

namespace sgp
{

LumenSegmentation LumenFromSegmentation(const LabelImage::Pointer& given,
                                        const CtImage* ct,
                                        const std::optional<Point3>& seedLps,
                                        const std::string& description);

} // namespace sgp
