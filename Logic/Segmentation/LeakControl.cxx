// Steps 3 and 4 of GrowLumenRegion: cutting leaks and the dark-flood check (GrowLumenRegion.h).
#include "Segmentation/LumenGrowthSteps.h"

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

namespace sgp::lumen_growth
{

double MeasureTissueHu(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth)
{
  std::vector<double> samples;
  ForEachTissueSample(mask, hu, depth, [&](long, short v) { samples.push_back(v); });
  return samples.empty() ? std::numeric_limits<double>::quiet_NaN() : Median(samples);
}

std::array<int, 3> OpeningBallIjk(const CtImage::SpacingType& spacing, double radiusMm)
{
  std::array<int, 3> openIjk{};
  for (unsigned a = 0; a < 3; ++a)
    openIjk[a] = static_cast<int>(std::floor(radiusMm / spacing[a] + 1e-9));
  return openIjk;
}

CutRegion CutLeaks(const CtImage& ct,
                   const CroppedRegion& crop,
                   const SeedStatistics& stats,
                   const std::array<int, 3>& openIjk,
                   const std::string& seedText,
                   const RegionGrowingParams& params,
                   double voxelMl,
                   LumenSegmentation& result)
{
  const MaskGrid& core = crop.region;
  const IndexBox& box = crop.box;
  CutRegion out{ core, core };
  if (openIjk[0] + openIjk[1] + openIjk[2] == 0)
    return out;
  const auto ball = BallOffsets(openIjk);
  const MaskGrid eroded = Erode(core, ball);
  // The component of the eroded voxel nearest the seed: a noise pit next to the seed voxel may
  // erode the seed voxel itself.
  long interiorSeed = -1;
  for (const auto& index : stats.voxels)
  {
    const std::array<long, 3> b{ index[0] - box.first[0], index[1] - box.first[1], index[2] - box.first[2] };
    if (b[0] < 0 || b[1] < 0 || b[2] < 0 || b[0] >= box.size[0] || b[1] >= box.size[1] || b[2] >= box.size[2])
      continue;
    const long flat = core.Flat(b[0], b[1], b[2]);
    if (eroded.voxels[flat])
    {
      interiorSeed = flat;
      break;
    }
  }
  out.interior = ConnectedComponent(eroded, interiorSeed);
  if (out.interior.CountForeground() == 0)
  {
    throw InputError(seedText + " lies in a vessel narrower than the leak-cutting opening (" +
                     FormatNumber(2 * params.leakOpeningRadiusMm, 1) +
                     " mm across); place the seed in the aorta, or lower leakOpeningRadiusMm.");
  }
  out.lumen = Dilate(out.interior, ball);
  MaskGrid cut(core.size);
  for (long flat = 0; flat < core.Count(); ++flat)
  {
    out.lumen.voxels[flat] = out.lumen.voxels[flat] && core.voxels[flat];
    cut.voxels[flat] = core.voxels[flat] && !out.lumen.voxels[flat];
  }
  // Pieces below leakMinimumPieceMl are vessels that narrow below the ball (small branches, a
  // stenosis) and go back; larger ones are what a leak into bone, kidney or bowel looks like.
  std::vector<long> sizes;
  const std::vector<int> pieces = LabelComponents(cut, sizes);
  long largest = 0, largestVoxel = -1;
  for (long flat = 0; flat < cut.Count(); ++flat)
  {
    if (!pieces[flat])
      continue;
    const long size = sizes[pieces[flat] - 1];
    if (size * voxelMl < params.leakMinimumPieceMl)
    {
      out.lumen.voxels[flat] = 1;
      cut.voxels[flat] = 0;
    }
    else if (size > largest)
    {
      largest = size;
      largestVoxel = flat;
    }
  }
  result.cutVolumeMl = cut.CountForeground() * voxelMl;
  if (largestVoxel >= 0)
  {
    const auto ijk = cut.Ijk(largestVoxel);
    CtImage::IndexType where{ { box.first[0] + ijk[0], box.first[1] + ijk[1], box.first[2] + ijk[2] } };
    result.warnings.push_back("Leak cut: " + FormatNumber(result.cutVolumeMl, 1) +
                              " mL joined to the lumen only through bridges thinner than " +
                              FormatNumber(2 * params.leakOpeningRadiusMm, 1) + " mm was removed (the largest piece " +
                              FormatNumber(largest * voxelMl, 1) + " mL, near " + FormatPoint(IndexToLps(ct, where)) +
                              " mm LPS); check for bone or bowel there.");
  }
  return out;
}

void CheckForDarkFlood(const CutRegion& region,
                       const std::vector<short>& hu,
                       const std::array<long, 3>& tissueDepth,
                       const SeedStatistics& stats,
                       const RegionGrowingParams& params,
                       double voxelMl,
                       LumenSegmentation& result)
{
  result.tissueHu = MeasureTissueHu(region.lumen, hu, tissueDepth);
  if (std::isnan(result.tissueHu))
  {
    result.tissueHu = std::min(params.seedMinimumHu, result.lowerHu);
  }
  const double darkHu = result.tissueHu + 0.7 * (stats.medianHu - result.tissueHu);
  long dark = 0;
  for (long flat = 0; flat < region.interior.Count(); ++flat)
  {
    dark += (region.interior.voxels[flat] && hu[flat] < darkHu) ? 1 : 0;
  }
  if (dark * voxelMl > params.darkLeakLimitMl)
  {
    // The advice fits the mode: an automatic window is narrowed through windowSigmas or replaced
    // by a manual one; a manual window's lower end is raised, or the automatic one tried.
    const std::string remedy =
      params.thresholdMode == ThresholdMode::Auto
        ? "the automatic window's lower end is " + FormatNumber(result.lowerHu, 0) + " HU: lower windowSigmas (now " +
            FormatNumber(params.windowSigmas, 1) + "), or use thresholdMode manual with lowerHu above " +
            FormatNumber(darkHu, 0) + " HU."
        : "raise the lower threshold (now " + FormatNumber(result.lowerHu, 0) + " HU) or use thresholdMode auto.";
    throw AlgorithmError("Region growing leaked into darker tissue: " + FormatNumber(dark * voxelMl, 1) +
                         " mL deep inside the region is below " + FormatNumber(darkHu, 0) +
                         " HU, while the lumen at the " + "seed is " + FormatNumber(stats.medianHu, 0) +
                         " HU (likely kidney, bowel or marrow); " + remedy);
  }
}

} // namespace sgp::lumen_growth
