/// \file LumenGrowthSteps.h
/// The steps of GrowLumenRegion (GrowLumenRegion.h, whose file comment describes the method), shared
/// by the files that hold them: LumenWindow.cxx (step 1), LumenWindowFromCore.cxx (1b),
/// RegionGrowth.cxx (2), LeakControl.cxx (3, 4), BoundaryRefinement.cxx (5, 6). Internal to the
/// segmentation: nothing outside Logic/Segmentation includes it. Units HU, mm; indices are the CT's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "Common/HugePages.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"
#include "Common/Types.h"
#include "Segmentation/GrowLumenRegion.h"

namespace sgp::lumen_growth
{

struct SeedStatistics
{
  double medianHu = 0.0;
  double sigmaHu = 0.0;
  std::vector<CtImage::IndexType> voxels; ///< the neighbourhood, nearest to the seed first
};

/// One bit per voxel of the CT's grid (1/16 of the CT's size): the region growing's marks.
class VoxelBits
{
public:
  explicit VoxelBits(long count)
  {
    AssignAdvised(m_Words, static_cast<std::size_t>((count + 63) / 64), std::uint64_t(0));
  }
  bool Test(long flat) const { return (m_Words[flat >> 6] >> (flat & 63)) & 1u; }
  void Set(long flat) { m_Words[flat >> 6] |= std::uint64_t(1) << (flat & 63); }

private:
  std::vector<std::uint64_t> m_Words;
};

/// Per slice k of the CT: the window's lower and upper HU (step 1b); empty: result's one window.
struct SliceWindows
{
  std::vector<short> lower, upper;
};

/// The lumen's core voxels (LumenCore) in slabs `slabMm` thick along k, placed on the k axis's own
/// physical coordinate (so a scan cut shorter keeps the same slabs): each slab's median (NaN: too
/// few core voxels), the overall median, and the noise σ (the median of the slabs' 1.4826 × MAD).
/// Seeds anywhere in one lumen grow nearly the same region, so these are nearly the same for all
/// of them, where the seed ball's 30–100 voxels move the median by a few HU with their noise and
/// place. `core` and `hu` are on `box`.
struct LumenLevels
{
  std::vector<double> sliceMedianHu; ///< per slice k of the CT: its slab's median, NaN where unknown
  double medianHu = 0.0, sigmaHu = 0.0;
  int slabs = 0;
};

/// The grown region's padded bounding box, with the region and the CT's HU copied into it: every
/// later step works on this box only.
struct CroppedRegion
{
  IndexBox box;
  MaskGrid region;
  std::vector<short> hu;
};

/// The region after leak cutting, and its interior (the opening's eroded seed component).
struct CutRegion
{
  MaskGrid lumen;
  MaskGrid interior;
};

/// Step 1b's growths at most: on the automatic-seed tests' 27 phantoms the windows stop changing
/// after one to three (the first moves them from the seed ball's estimate, the rest by an HU or two
/// of rounding as the region settles), or fall into a cycle of two (below).
constexpr int maximumLumenWindowPasses = 6;

/// Core voxels per slab, at least, for the slab's median to count.
constexpr long minimumSlabVoxels = 200;

/// The slabs' thickness along k, mm: a bolus changes the lumen's HU by up to ~10 HU/cm.
constexpr double slabMm = 20.0;

/// The core is found on blocks of about this size (whole voxels per axis, at least one): its depth
/// needs no finer grid, and the distance transform on blocks costs an eighth of one on voxels.
constexpr double lumenCoreBlockMm = 2.0;

/// Step 1b measures the lumen this far inside its edge, mm: beyond the partial-volume rim, and
/// deeper than the radius of a renal artery (5–7 mm across) by more than the blocks the core is
/// found on (lumenCoreBlockMm), so that a kidney the region reached through one (its parenchyma
/// 150–250 HU inside the window of a low-contrast scan) is a core of its own and does not lower
/// the aorta's level. The aorta (at least 16 mm across) keeps a core; the iliacs from 10 mm.
constexpr double lumenCoreDepthMm = 5.0;

/// The darkest level a lumen's edge is taken against, HU. A lumen is bounded by its own wall or by
/// thrombus — soft tissue of 20–80 HU on a CT angiogram (vessel-wall.md §2) — never by the fat
/// beyond the wall. The tissue sampled lumenCoreDepthMm outside the lumen is that fat where the
/// wall is thin (1–2 mm), and a half-maximum taken against it sits outside the lumen's edge: the
/// wall's blurred step from the lumen is what the edge is (issue 32: every lumen diameter 0.55–
/// 1.0 mm large beside a 1.5 mm wall in fat). Darker samples are raised to this level; where the
/// lumen lies in muscle or thrombus (40 HU and above) the samples are used as they are.
constexpr double lumenBorderFloorHu = 40.0;

/// The tissue level a lumen's edge is half-way to: the sampled tissue, raised to lumenBorderFloorHu.
inline double LumenBorderHu(double tissueHu)
{
  return std::isfinite(tissueHu) ? std::max(tissueHu, lumenBorderFloorHu) : tissueHu;
}

/// Clamps to the range of a CT voxel.
inline short ClampToShort(double value)
{
  return static_cast<short>(
    std::clamp(value, double(std::numeric_limits<short>::min()), double(std::numeric_limits<short>::max())));
}

/// Calls `f(k, hu)` for each tissue sample: the voxel `depth[axis]` voxels outside the region
/// along an axis from each boundary face (k: the sample's slice in the crop).
template<class F>
void ForEachTissueSample(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth, F&& f)
{
  for (long flat = 0; flat < mask.Count(); ++flat)
  {
    if (!mask.voxels[flat])
    {
      continue;
    }
    const auto ijk = mask.Ijk(flat);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int sign : { -1, 1 })
      {
        auto n = ijk;
        n[axis] += sign;
        auto far = ijk;
        far[axis] += sign * depth[axis];
        if (far[axis] < 0 || far[axis] >= mask.size[axis] || mask.voxels[mask.Flat(n[0], n[1], n[2])])
        {
          continue;
        }
        const long farFlat = mask.Flat(far[0], far[1], far[2]);
        if (!mask.voxels[farFlat])
        {
          f(far[2], hu[farFlat]);
        }
      }
    }
  }
}

// LumenWindow.cxx
/// Step 1: the window from the seed's neighbourhood, or a cleaner one near it (Auto), or as given
/// (Manual), with the seed checks; sets the window and seed statistics of `result`.
SeedStatistics EstimateWindow(const CtImage& ct,
                              const CtImage::IndexType& seed,
                              const Point3& seedLps,
                              const RegionGrowingParams& params,
                              LumenSegmentation& result);

// LumenWindowFromCore.cxx
/// The sum of a window's widths over its slices (HU): of the windows of a cycle the narrowest wins.
long TotalWidth(const SliceWindows& w);

/// The lumen's core: the voxels of `region` whose block (lumenCoreBlockMm) lies at least
/// lumenCoreDepthMm inside the region, in the 6-connected piece of blocks nearest the seed (the
/// seed ball's first voxel; the aorta and the iliacs for a seed in either). A block belongs to the
/// region when more than three quarters of its voxels do, and the region's cavities are filled
/// first: noise puts voxels outside the window inside the lumen (step 6 fills them later), and as
/// background they would riddle the distance field and break the core into pieces. Empty when no
/// block is that deep (a lumen of small vessels only). `region` is on `box`.
MaskGrid LumenCore(const CtImage& ct, const MaskGrid& region, const IndexBox& box, const CtImage::IndexType& seed);

/// The slab (slabMm thick, at fixed heights along k) that CT slice k lies in: its physical
/// position along its own axis, origin · d_k + k · spacing_k, over slabMm, rounded down.
long SlabOfSlice(const CtImage& ct, long k);

LumenLevels MeasureLumenLevels(const CtImage& ct,
                               const MaskGrid& core,
                               const std::vector<short>& hu,
                               const IndexBox& box);

/// Step 1b's window per CT slice from the lumen's levels, and its overall extent.
SliceWindows WindowsFromLevels(const LumenLevels& lumen,
                               const RegionGrowingParams& params,
                               double& lowest,
                               double& highest);

// RegionGrowth.cxx
/// Step 2: the face-connected (6-neighbour) region of voxels with HU in the window, from the
/// neighbourhood voxel nearest the seed that lies in it (noise may put the seed voxel itself just
/// outside) — the region ITK's ConnectedThresholdImageFilter grows with face connectivity, marked
/// in one bit per voxel instead of its full-size output and scratch images. Returns the marks and
/// sets `box` to the region's bounding box grown by `pad` voxels (clipped to the image).
VoxelBits GrowFromSeed(const CtImage& ct,
                       const SeedStatistics& stats,
                       const LumenSegmentation& result,
                       const std::array<long, 3>& pad,
                       IndexBox& box,
                       const SliceWindows& slices = {});

CroppedRegion CropToRegion(const CtImage& ct, const VoxelBits& inRegion, const IndexBox& box);

// LeakControl.cxx
/// Median HU `depth[axis]` voxels outside the region, sampled along the axes from its boundary.
double MeasureTissueHu(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth);

/// The opening's ball per axis, rounded down so that it never reaches further than
/// leakOpeningRadiusMm: a coarse axis (2–3 mm slices) is not eroded at all rather than by a whole
/// slice too many.
std::array<int, 3> OpeningBallIjk(const CtImage::SpacingType& spacing, double radiusMm);

/// Step 3: opening with the ball, keeping the seed's component; cut-off pieces under
/// leakMinimumPieceMl go back, larger ones stay cut and are reported in `result`.
CutRegion CutLeaks(const CtImage& ct,
                   const CroppedRegion& crop,
                   const SeedStatistics& stats,
                   const std::array<int, 3>& openIjk,
                   const std::string& seedText,
                   const RegionGrowingParams& params,
                   double voxelMl,
                   LumenSegmentation& result);

/// Step 4: the tissue level just outside the region; more than darkLeakLimitMl of the interior
/// darker than tissue + 0.7·(m − tissue) means a flood into another tissue class.
void CheckForDarkFlood(const CutRegion& region,
                       const std::vector<short>& hu,
                       const std::array<long, 3>& tissueDepth,
                       const SeedStatistics& stats,
                       const RegionGrowingParams& params,
                       double voxelMl,
                       LumenSegmentation& result);

// BoundaryRefinement.cxx
/// Step 5's levels on each crop slice, HU: half-way between the slice's lumen level and the tissue
/// around it.
struct EdgeLevels
{
  /// With the tissue raised to lumenBorderFloorHu (LumenBorderHu): the aorta's and the iliacs'
  /// edge, the boundary refinement's.
  std::vector<double> lumenEdge;
  /// With the tissue as sampled: step 7's, for branches so narrow (renal arteries, 5–7 mm, on
  /// 2.5 mm slices) that the blur keeps their own peak well under the lumen's level and a higher
  /// edge breaks them.
  std::vector<double> branchEdge;
};

/// Both levels from one pass over the samples (crop slices; `firstSlice` its first CT slice).
/// Without step 1b's levels (`sliceLevelHu` empty) one level, the seed's median and the tissue
/// median around the whole region. With them each slice's own: its slab's lumen level, and the
/// tissue median of its slab's samples (MeasureTissueHu's samples on that slab's slices, when at
/// least minimumSlabVoxels), else the whole region's; so a bolus fading down the body keeps each
/// level's half-maximum, and what lies around the lumen far from a level — a heart in view 70 mm
/// above the renal arteries, a scan cut lower — does not move its edge.
EdgeLevels MeasureEdgeLevels(const CtImage& ct,
                             const MaskGrid& mask,
                             const std::vector<short>& hu,
                             const std::array<long, 3>& depth,
                             long firstSlice,
                             const std::vector<double>& sliceLevelHu,
                             double medianHu,
                             double tissueHu);

/// Steps 5 and 6: the boundary moved to the half-maximum edge level, `edge[k]` on crop slice k
/// (EdgeLevels::lumenEdge), then pits and holes filled.
void RefineBoundary(MaskGrid& lumen,
                    const std::vector<short>& hu,
                    int refineSteps,
                    const std::vector<std::array<int, 3>>& reachBall,
                    const std::vector<double>& edge,
                    LumenSegmentation& result);

/// The cropped lumen pasted into a mask on the CT's grid.
LabelImage::Pointer PasteOnGrid(const CtImage& ct, const MaskGrid& lumen, const IndexBox& box);

} // namespace sgp::lumen_growth
