#include "Segmentation/GrowLumenRegion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "Common/CheckRange.h"
#include "Common/DistanceInsideMask.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"
#include "Common/Median.h"
#include "Segmentation/ContinueThinBranches.h"
#include "Segmentation/LumenGrowthSteps.h"

namespace sgp
{

using namespace lumen_growth;

void ValidateRegionGrowingParams(const RegionGrowingParams& params)
{
  const auto check = CheckRange;
  check("lowerHu", params.lowerHu, -1024, 3071, "HU");
  check("upperHu", params.upperHu, -1024, 3071, "HU");
  check("windowSigmas", params.windowSigmas, 1, 10, "standard deviations");
  check("seedMinimumHu", params.seedMinimumHu, -1024, 3071, "HU");
  check("leakOpeningRadiusMm", params.leakOpeningRadiusMm, 0, 5, "mm");
  check("maximumLumenVolumeMl", params.maximumLumenVolumeMl, 1, 20000, "mL");
  check("seedNeighbourhoodRadiusMm", params.seedNeighbourhoodRadiusMm, 0, 20, "mm");
  check("seedSearchRadiusMm", params.seedSearchRadiusMm, 0, 20, "mm");
  check("minimumHalfWindowHu", params.minimumHalfWindowHu, 0, 1000, "HU");
  check("refineDistanceMm", params.refineDistanceMm, 0, 10, "mm");
  check("tissueDepthMm", params.tissueDepthMm, 0, 20, "mm");
  check("thinBranchRadiusMm", params.thinBranchRadiusMm, 0, 20, "mm");
  check("thinBranchReachMm", params.thinBranchReachMm, 0, 50, "mm");
  if (params.thresholdMode == ThresholdMode::Manual && !(params.lowerHu < params.upperHu))
  {
    throw InputError("lowerHu (" + FormatNumber(params.lowerHu, 1) + " HU) must be less than upperHu (" +
                     FormatNumber(params.upperHu, 1) + " HU); swap them or widen the window.");
  }
}

LumenSegmentation GrowLumenRegion(const CtImage& ct,
                                  const Point3& seedLps,
                                  const RegionGrowingParams& params,
                                  const ProgressCallback& progress)
{
  ValidateRegionGrowingParams(params);
  const CtImage::IndexType seed = LpsToIndexInside(ct, seedLps, "Seed");
  const auto spacing = ct.GetSpacing();
  const double voxelMl = spacing[0] * spacing[1] * spacing[2] / 1000.0;
  const std::string seedText = "Seed " + FormatPoint(seedLps) + " mm LPS";
  LumenSegmentation result;

  ReportProgress(progress, 0.0, "Estimating the HU window at the seed");
  SeedStatistics stats = EstimateWindow(ct, seed, seedLps, params, result);

  // The box every later step works in: the grown region padded by the opening, the boundary
  // refinement's reach and the tissue depth.
  const std::array<int, 3> openIjk = OpeningBallIjk(spacing, params.leakOpeningRadiusMm);
  const double minSpacing = std::min({ spacing[0], spacing[1], spacing[2] });
  const int refineSteps = static_cast<int>(std::ceil(params.refineDistanceMm / minSpacing));
  // Tissue is sampled beyond the blur of the edge: tissueDepthMm outside, at least 3 voxels.
  std::array<long, 3> tissueDepth{}, pad{};
  for (unsigned a = 0; a < 3; ++a)
  {
    tissueDepth[a] = std::max(3L, static_cast<long>(std::ceil(params.tissueDepthMm / spacing[a])));
    pad[a] = openIjk[a] + refineSteps + tissueDepth[a] + 2;
  }

  ReportProgress(progress, 0.05, "Region growing");
  CroppedRegion crop;
  std::vector<double> sliceLevelHu; // step 1b's levels slice by slice, when it ran
  {
    IndexBox box;
    const VoxelBits grown = GrowFromSeed(ct, stats, result, pad, box);
    crop = CropToRegion(ct, grown, box);
  } // the marks are freed here: only the CT and box-sized buffers are held until the mask is pasted
  if (params.thresholdMode == ThresholdMode::Auto && params.windowFromLumen)
  {
    // Step 1b: the window again, slab by slab from the lumen's own core, and the region grown again
    // with it until the windows no longer change (file comment): the plan no longer depends on
    // where in the lumen the seed lies, and a bolus that fades down the body keeps each level's
    // own window. The core needs no leak cutting: a leak joins through a bridge thinner than it.
    ReportProgress(progress, 0.2, "Estimating the HU window from the lumen");
    // Each growth's windows and what they came from. Integer HU make the core's σ move in steps
    // of 1.48 HU (its MAD is a whole or half HU), and a window's edge that takes a kidney at 230 HU
    // in or out moves the core's σ by one such step: the windows can alternate between two values,
    // and then which of them the last growth used depended on where the seed started. A window
    // met again ends the loop on the narrowest of the cycle, the same from every start.
    struct Growth
    {
      SliceWindows windows;
      LumenLevels lumen;
      double lowest = 0.0, highest = 0.0;
    };
    std::vector<Growth> growths;
    const CtImage::IndexType& seedVoxel = stats.voxels.front();
    const short seedHu = ct.GetPixel(seedVoxel);
    const size_t seedK = static_cast<size_t>(seedVoxel[2]);
    const auto grow = [&](const Growth& g)
    {
      result.lowerHu = g.lowest; // GrowFromSeed's start voxel and calcium level
      result.upperHu = g.highest;
      result.calciumHu = g.highest + 0.25 * (g.highest - g.lowest);
      IndexBox box;
      const VoxelBits grown = GrowFromSeed(ct, stats, result, pad, box, g.windows);
      crop = CropToRegion(ct, grown, box);
    };
    for (int pass = 0; pass < maximumLumenWindowPasses; ++pass)
    {
      Growth next;
      next.lumen = MeasureLumenLevels(ct, LumenCore(ct, crop.region, crop.box, seedVoxel), crop.hu, crop.box);
      if (next.lumen.slabs == 0)
        break; // no core: a lumen of small vessels only; the seed's window stays
      next.windows = WindowsFromLevels(next.lumen, params, next.lowest, next.highest);
      const auto same = [&](const Growth& g)
      { return g.windows.lower == next.windows.lower && g.windows.upper == next.windows.upper; };
      if (!growths.empty() && same(growths.back()))
        break; // the fixed point: growing again gives the same region
      const auto met = std::find_if(growths.begin(), growths.end(), same);
      if (met != growths.end())
      {
        // Narrowest first, then the higher lower ends: an order of the windows themselves, not of
        // the cycle's phase (two windows of one width, one shifted, would otherwise be told apart
        // by which came first, i.e. by the seed).
        const auto narrowest = std::min_element(met, growths.end(),
                                                [](const Growth& x, const Growth& y)
                                                {
                                                  const long wx = TotalWidth(x.windows), wy = TotalWidth(y.windows);
                                                  return wx != wy ? wx < wy : x.windows.lower > y.windows.lower;
                                                });
        if (narrowest != growths.end() - 1)
        {
          Growth chosen = *narrowest;
          grow(chosen);
          growths.push_back(std::move(chosen));
        }
        break;
      }
      if (seedHu < next.windows.lower[seedK] || seedHu > next.windows.upper[seedK])
        break; // the seed's voxel is not lumen by the lumen's own levels: keep what it grew
      grow(next);
      growths.push_back(std::move(next));
    }
    std::string source;
    if (!growths.empty())
    {
      const Growth& last = growths.back();
      stats.medianHu = last.lumen.medianHu;
      stats.sigmaHu = last.lumen.sigmaHu;
      sliceLevelHu = last.lumen.sliceMedianHu;
      const std::size_t n = growths.size();
      source = ", then slab by slab from the lumen's core (" + std::to_string(last.lumen.slabs) + " slabs of 20 mm, " +
               FormatNumber(lumenCoreDepthMm, 0) + " mm inside its edge, median " +
               FormatNumber(last.lumen.medianHu, 0) + " HU, noise sigma " + FormatNumber(last.lumen.sigmaHu, 0) +
               " HU; " + std::to_string(n) + (n == 1 ? " growth)" : " growths)");
    }
    result.windowSource += source;
  }
  ReportProgress(progress, 0.4, "Cutting leaks");
  CutRegion region = CutLeaks(ct, crop, stats, openIjk, seedText, params, voxelMl, result);

  ReportProgress(progress, 0.6, "Checking for leaks");
  CheckForDarkFlood(region, crop.hu, tissueDepth, stats, params, voxelMl, result);

  ReportProgress(progress, 0.7, "Refining the boundary");
  result.edgeHu = 0.5 * (stats.medianHu + LumenBorderHu(result.tissueHu));
  const EdgeLevels levels = MeasureEdgeLevels(ct, region.lumen, crop.hu, tissueDepth, crop.box.first[2], sliceLevelHu,
                                              stats.medianHu, result.tissueHu);
  const std::vector<double>& edge = levels.lumenEdge;
  const std::vector<double>& branchEdge = levels.branchEdge; // step 7's (EdgeLevels)
  RefineBoundary(region.lumen, crop.hu, refineSteps,
                 PhysicalBallOffsets({ spacing[0], spacing[1], spacing[2] }, params.refineDistanceMm), edge, result);

  result.volumeMl = region.lumen.CountForeground() * voxelMl;
  if (result.volumeMl > params.maximumLumenVolumeMl)
  {
    throw AlgorithmError("Region growing leaked: " + FormatNumber(result.volumeMl, 0) + " mL segmented, limit " +
                         FormatNumber(params.maximumLumenVolumeMl, 0) + " mL (maximumLumenVolumeMl); lower the upper " +
                         "threshold (now " + FormatNumber(result.upperHu, 0) + " HU) or move the seed.");
  }

  ReportProgress(progress, 0.9, "Writing the mask");
  // Free what is no longer needed before the full-grid mask is allocated.
  region.interior = MaskGrid();
  crop.region = MaskGrid();
  std::vector<short>().swap(crop.hu);
  result.mask = PasteOnGrid(ct, region.lumen, crop.box);
  result.box = crop.box; // step 7 adds only inside it

  // Step 7: narrow branches the window lost, followed on at the edge level (ContinueThinBranches.h).
  if (params.thinBranchRadiusMm > 0.0)
  {
    ReportProgress(progress, 0.95, "Following narrow branches");
    ThinBranchParams thin;
    thin.maxRadiusMm = params.thinBranchRadiusMm;
    thin.minReachMm = params.thinBranchReachMm;
    thin.maxPieceMl = params.leakMinimumPieceMl;
    const long firstSlice = crop.box.first[2], slices = static_cast<long>(branchEdge.size());
    const ThinBranchResult added = ContinueThinBranches(
      ct, *result.mask, crop.box,
      [&](long k) { return branchEdge[static_cast<std::size_t>(std::clamp(k - firstSlice, 0L, slices - 1))]; },
      [&](long k)
      {
        return sliceLevelHu.empty()
                 ? stats.medianHu
                 : sliceLevelHu[static_cast<std::size_t>(std::clamp(k, 0L, long(sliceLevelHu.size()) - 1))];
      },
      result.upperHu, result.calciumHu, thin);
    result.thinBranchPieces = added.pieces;
    result.thinBranchMl = added.addedMl;
    result.volumeMl += added.addedMl;
  }
  ReportProgress(progress, 1.0, "Done");
  return result;
}

} // namespace sgp
