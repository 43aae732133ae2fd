/// \file VesselWall.h
/// The vessel wall of the aorto-iliac segment the graft treats: the outer wall (SegmentOuterWall.h,
/// the radial model of Macía et al. 2009) of the aorta from above the proximal site to the aortic
/// bifurcation and of both common iliacs, the wall's thickness, the thrombus between the lumen and
/// the wall, and the calcium in it — what the measurements read on the outer wall.
///
///  - Two passes per vessel: planes ⊥ the lumen's centerline, then planes ⊥ the vessel's axis
///    through the first pass's contours' area centroids (OuterWallAxis: a smoothing spline over
///    about ±axisHalfWindowMm that runs on straight across the sac's shoulders), so that an
///    eccentric thrombus does not tilt the planes (SegmentOuterWall.h).
///  - Stretches (abscissae, mm): the aorta from `aboveSiteMm` above the proximal site to the
///    bifurcation B (FindAorticBifurcation; where B lies beyond the centerline's end — the
///    skeleton's junction lies above B on thick slices — the centerline carried straight on along
///    its last direction to B, so that (d) can be read down to B: DistalAorta.h); each common iliac from
///    its start to its internal iliac origin (InternalIliacOriginAbscissa), or to its end where no
///    origin was found.
///  - **Wall thickness** w: the aortic wall and the thrombus share the HU band of soft tissue
///    (vessel-wall.md §2), so w is not read ray by ray: with `wallThicknessMm` < 0 it is estimated
///    where the aorta has no thrombus — the median, over the planes from `aboveSiteMm` above the
///    site to 5 mm below it, of each plane's median of (outer − lumen radius) over its supported
///    rays (so the outer and lumen edges' own biases cancel in the thrombus: a lower quantile
///    would leave ~0.2 mm of noise spread as spurious thrombus all round); fewer than three such
///    planes: 1.5 mm (the reference note's typical wall), and `wallThicknessEstimated` false.
///  - **Thrombus** per ray: max(0, outer − lumen radius − w). Per plane the thrombus area is
///    max(0, π(R − w)² − lumen area), R the outer contour's area-equivalent radius.
///  - **Calcium** per ray: a sample at or above `calciumHu` from 1 mm inside the lumen's edge to the
///    outer wall (+0.5 mm); `calciumHu` is the caller's (the pipeline: the lumen segmentation's
///    calciumHu, at most 1000 HU — nothing that bright is blood).
///
/// Input: the CT (HU; the whole grid or a crop of it, CropAroundLumen), the lumen mask on the
/// input grid, the labelled centerlines, the proximal site's abscissa along the aorta (mm). All
/// LPS. Output: VesselWall (vessels in StentSegment order: aorta, right iliac, left iliac).
/// Errors: InputError for parameters out of range (ValidateOuterWallParams, aboveSiteMm ∉ [0, 50],
/// wallThicknessMm > 5).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"
#include "Wall/SegmentOuterWall.h"

namespace sgp
{

struct VesselWallParams
{
  OuterWallParams outer;
  double aboveSiteMm = 10.0;     ///< how far above the proximal site the aortic wall is traced, [0, 50]
  double wallThicknessMm = -1.0; ///< < 0: estimated (see the file comment); else used as given, ≤ 5
  double calciumHu = 1000.0;     ///< see the file comment
  double axisHalfWindowMm = 5.0; ///< the second pass's axis: smoothed over about ±this, (0, 50]
};

struct VesselWall
{
  std::array<OuterWall, 3> vessels; ///< aorta, rightIliac, leftIliac
  std::array<std::string, 3> names{ "aorta", "rightIliac", "leftIliac" };
  double wallThicknessMm = 1.5;        ///< used for the thrombus
  bool wallThicknessEstimated = false; ///< false: the default or the caller's value
  double calciumHu = 1000.0;
  double stepMm = 1.0; ///< plane spacing
  /// No plane of any vessel has a contour (Usable): no outer wall was seen anywhere.
  bool Empty() const
  {
    for (const OuterWall& vessel : vessels)
      for (const OuterWallPlane& plane : vessel.planes)
        if (plane.Usable())
          return false;
    return true;
  }
};

/// See the file comment.
VesselWall TraceVesselWall(const CtImage& ct,
                           const LabelImage& lumen,
                           const CenterlineTree& tree,
                           double siteAbscissaMm,
                           const VesselWallParams& params = {});

/// A copy of the CT over the lumen mask's bounding box grown by `marginMm` (clamped to the grid),
/// buffered from index 0 with its origin moved so that every voxel keeps its LPS position — the
/// part of the CT the wall stage reads once the full volume is released. An empty mask: an empty
/// (0-voxel) image.
CtImage::Pointer CropAroundLumen(const CtImage& ct, const LabelImage& lumen, double marginMm);

/// The vessel on the lumen's grid: 1 lumen (the whole mask), and inside the traced outer walls
/// 2 thrombus and wall, 3 calcification (HU ≥ wall.calciumHu); 0 elsewhere. A voxel belongs to a
/// plane's slab when it lies within half a step of the plane and
/// inside its contour (radius interpolated between rays). `ct` is the input or a crop of it on the
/// same lattice (CropAroundLumen); voxels beyond the crop count as not calcified.
LabelImage::Pointer WallLabelMap(const VesselWall& wall, const LabelImage& lumen, const CtImage& ct);

} // namespace sgp
