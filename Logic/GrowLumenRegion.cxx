#include "GrowLumenRegion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <itkConnectedThresholdImageFilter.h>

#include "CheckRange.h"
#include "Errors.h"
#include "Format.h"
#include "Median.h"
#include "ImageGeometry.h"
#include "IndexBox.h"
#include "MaskGrid.h"

namespace sgp
{

namespace
{

struct SeedStatistics
{
  double medianHu = 0.0;
  double sigmaHu = 0.0;
  std::vector<CtImage::IndexType> voxels; ///< the neighbourhood, nearest to the seed first
};

/// Median and 1.4826·MAD of the voxels whose centres lie within `radiusMm` of the seed (at least
/// the seed voxel's 3×3×3 neighbourhood on coarse grids).
SeedStatistics MeasureSeedNeighbourhood(const CtImage& ct,
                                        const CtImage::IndexType& seed,
                                        const Point3& seedLps,
                                        double radiusMm)
{
  const auto spacing = ct.GetSpacing();
  const auto region = ct.GetLargestPossibleRegion();
  std::vector<std::pair<double, CtImage::IndexType>> found;
  std::array<long, 3> reach{};
  for (unsigned a = 0; a < 3; ++a)
  {
    reach[a] = std::max(1L, static_cast<long>(std::ceil(radiusMm / spacing[a])));
  }
  for (long dk = -reach[2]; dk <= reach[2]; ++dk)
  {
    for (long dj = -reach[1]; dj <= reach[1]; ++dj)
    {
      for (long di = -reach[0]; di <= reach[0]; ++di)
      {
        CtImage::IndexType index = seed;
        index[0] += di;
        index[1] += dj;
        index[2] += dk;
        if (!region.IsInside(index))
        {
          continue;
        }
        const double distance = (IndexToLps(ct, index) - seedLps).norm();
        const bool inCube = std::abs(di) <= 1 && std::abs(dj) <= 1 && std::abs(dk) <= 1;
        if (distance <= radiusMm || inCube)
        {
          found.emplace_back(distance, index);
        }
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  SeedStatistics stats;
  std::vector<double> values;
  for (const auto& [distance, index] : found)
  {
    stats.voxels.push_back(index);
    values.push_back(ct.GetPixel(index));
  }
  stats.medianHu = Median(values);
  for (double& v : values)
  {
    v = std::abs(v - stats.medianHu);
  }
  stats.sigmaHu = 1.4826 * Median(values);
  return stats;
}

/// Median HU `depth[axis]` voxels outside the region, sampled along the axes from its boundary.
double MeasureTissueHu(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth)
{
  std::vector<double> samples;
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
          samples.push_back(hu[farFlat]);
        }
      }
    }
  }
  return samples.empty() ? std::numeric_limits<double>::quiet_NaN() : Median(samples);
}

short ClampToShort(double value)
{
  return static_cast<short>(
    std::clamp(value, double(std::numeric_limits<short>::min()), double(std::numeric_limits<short>::max())));
}

} // namespace

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
  check("minimumHalfWindowHu", params.minimumHalfWindowHu, 0, 1000, "HU");
  check("refineDistanceMm", params.refineDistanceMm, 0, 10, "mm");
  check("tissueDepthMm", params.tissueDepthMm, 0, 20, "mm");
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
  LumenSegmentation result;

  ReportProgress(progress, 0.0, "Estimating the HU window at the seed");
  const SeedStatistics stats = MeasureSeedNeighbourhood(ct, seed, seedLps, params.seedNeighbourhoodRadiusMm);
  result.seedMedianHu = stats.medianHu;
  result.seedSigmaHu = stats.sigmaHu;
  const std::string seedText = "Seed " + FormatPoint(seedLps) + " mm LPS";
  if (stats.medianHu < params.seedMinimumHu)
  {
    throw InputError(
      seedText + " lies in tissue of " + FormatNumber(stats.medianHu, 0) + " HU (median of " +
      std::to_string(stats.voxels.size()) + " voxels around it); expected contrast-filled lumen of at least " +
      FormatNumber(params.seedMinimumHu, 0) + " HU (seedMinimumHu); move the seed into the aortic lumen.");
  }
  if (params.thresholdMode == ThresholdMode::Auto)
  {
    const double half = std::max(params.windowSigmas * stats.sigmaHu, params.minimumHalfWindowHu);
    result.lowerHu = stats.medianHu - half;
    result.upperHu = stats.medianHu + 2.0 * half;
  }
  else
  {
    result.lowerHu = params.lowerHu;
    result.upperHu = params.upperHu;
    if (stats.medianHu < params.lowerHu || stats.medianHu > params.upperHu)
    {
      throw InputError(seedText + " has a median of " + FormatNumber(stats.medianHu, 0) +
                       " HU, outside the manual window " + FormatNumber(params.lowerHu, 0) + " to " +
                       FormatNumber(params.upperHu, 0) + " HU; widen the window or use thresholdMode auto.");
    }
  }
  // Start from the neighbourhood voxel nearest the seed that lies in the window (noise may put
  // the seed voxel itself just outside it).
  const auto start = std::find_if(
    stats.voxels.begin(), stats.voxels.end(),
    [&](const auto& index) { return ct.GetPixel(index) >= result.lowerHu && ct.GetPixel(index) <= result.upperHu; });
  if (start == stats.voxels.end())
  {
    // Cannot happen: the median is one of the neighbourhood's values and lies in the window.
    throw std::logic_error("GrowLumenRegion: no seed-neighbourhood voxel in the window");
  }

  ReportProgress(progress, 0.05, "Region growing");
  using GrowFilter = itk::ConnectedThresholdImageFilter<CtImage, LabelImage>;
  auto grow = GrowFilter::New();
  grow->SetInput(&ct);
  grow->SetLower(ClampToShort(std::ceil(result.lowerHu)));
  grow->SetUpper(ClampToShort(std::floor(result.upperHu)));
  grow->SetReplaceValue(1);
  grow->AddSeed(*start);
  grow->Update();
  LabelImage::Pointer grown = grow->GetOutput();
  grown->DisconnectPipeline();

  ReportProgress(progress, 0.4, "Cutting leaks");
  std::array<int, 3> openIjk{};
  for (unsigned a = 0; a < 3; ++a)
  {
    // Rounded down, so that the ball never reaches further than leakOpeningRadiusMm: a coarse
    // axis (2–3 mm slices) is not eroded at all rather than by a whole slice too many.
    openIjk[a] = static_cast<int>(std::floor(params.leakOpeningRadiusMm / spacing[a] + 1e-9));
  }
  const double minSpacing = std::min({ spacing[0], spacing[1], spacing[2] });
  const int refineSteps = static_cast<int>(std::ceil(params.refineDistanceMm / minSpacing));
  // Tissue is sampled beyond the blur of the edge: tissueDepthMm outside, at least 3 voxels.
  std::array<long, 3> tissueDepth{}, pad{};
  for (unsigned a = 0; a < 3; ++a)
  {
    tissueDepth[a] = std::max(3L, static_cast<long>(std::ceil(params.tissueDepthMm / spacing[a])));
    pad[a] = openIjk[a] + refineSteps + tissueDepth[a] + 2;
  }
  const IndexBox box = ForegroundBox(*grown, pad);
  const auto imageSize = ct.GetLargestPossibleRegion().GetSize();
  MaskGrid core(box.size);
  std::vector<short> hu(static_cast<std::size_t>(core.Count()));
  ForEachInBox(box, imageSize,
               [&](long flat, long image)
               {
                 core.voxels[flat] = grown->GetBufferPointer()[image] ? 1 : 0;
                 hu[flat] = ct.GetBufferPointer()[image];
               });

  MaskGrid lumen = core;
  MaskGrid interior = core;
  const bool opening = openIjk[0] + openIjk[1] + openIjk[2] > 0;
  if (opening)
  {
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
    interior = ConnectedComponent(eroded, interiorSeed);
    if (interior.CountForeground() == 0)
    {
      throw InputError(seedText + " lies in a vessel narrower than the leak-cutting opening (" +
                       FormatNumber(2 * params.leakOpeningRadiusMm, 1) +
                       " mm across); place the seed in the aorta, or lower leakOpeningRadiusMm.");
    }
    lumen = Dilate(interior, ball);
    MaskGrid cut(core.size);
    for (long flat = 0; flat < core.Count(); ++flat)
    {
      lumen.voxels[flat] = lumen.voxels[flat] && core.voxels[flat];
      cut.voxels[flat] = core.voxels[flat] && !lumen.voxels[flat];
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
        lumen.voxels[flat] = 1;
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
      result.warnings.push_back(
        "Leak cut: " + FormatNumber(result.cutVolumeMl, 1) +
        " mL joined to the lumen only through bridges thinner than " + FormatNumber(2 * params.leakOpeningRadiusMm, 1) +
        " mm was removed (the largest piece " + FormatNumber(largest * voxelMl, 1) + " mL, near " +
        FormatPoint(IndexToLps(ct, where)) + " mm LPS); check for bone or bowel there.");
    }
  }

  ReportProgress(progress, 0.6, "Checking for leaks");
  result.tissueHu = MeasureTissueHu(lumen, hu, tissueDepth);
  if (std::isnan(result.tissueHu))
  {
    result.tissueHu = std::min(params.seedMinimumHu, result.lowerHu);
  }
  const double darkHu = result.tissueHu + 0.7 * (stats.medianHu - result.tissueHu);
  long dark = 0;
  for (long flat = 0; flat < interior.Count(); ++flat)
  {
    dark += (interior.voxels[flat] && hu[flat] < darkHu) ? 1 : 0;
  }
  if (dark * voxelMl > params.darkLeakLimitMl)
  {
    throw AlgorithmError("Region growing leaked into darker tissue: " + FormatNumber(dark * voxelMl, 1) +
                         " mL deep inside the region is below " + FormatNumber(darkHu, 0) +
                         " HU, while the lumen at the " + "seed is " + FormatNumber(stats.medianHu, 0) +
                         " HU (likely kidney, bowel or marrow); raise the " + "lower threshold (now " +
                         FormatNumber(result.lowerHu, 0) + " HU) or use thresholdMode auto.");
  }

  ReportProgress(progress, 0.7, "Refining the boundary");
  result.edgeHu = 0.5 * (stats.medianHu + result.tissueHu);
  std::vector<bool> accept(static_cast<std::size_t>(lumen.Count()));
  for (long flat = 0; flat < lumen.Count(); ++flat)
  {
    accept[flat] = hu[flat] >= result.edgeHu && hu[flat] <= result.upperHu;
  }
  GrowConstrained(lumen, accept, refineSteps);
  // Noise leaves single-voxel pits in the boundary (a voxel just inside the wall drawn below the
  // edge level); the inscribed-sphere radius of the centerlines is the distance to the nearest of
  // them, so they are filled: a background voxel with 5 or 6 lumen faces becomes lumen.
  FillSurfacePits(lumen, 5);
  FillHoles(lumen);

  result.volumeMl = lumen.CountForeground() * voxelMl;
  if (result.volumeMl > params.maximumLumenVolumeMl)
  {
    throw AlgorithmError("Region growing leaked: " + FormatNumber(result.volumeMl, 0) + " mL segmented, limit " +
                         FormatNumber(params.maximumLumenVolumeMl, 0) + " mL (maximumLumenVolumeMl); lower the upper " +
                         "threshold (now " + FormatNumber(result.upperHu, 0) + " HU) or move the seed.");
  }

  ReportProgress(progress, 0.9, "Writing the mask");
  result.mask = LabelImage::New();
  result.mask->CopyInformation(&ct);
  result.mask->SetRegions(ct.GetLargestPossibleRegion());
  result.mask->Allocate(true);
  ForEachInBox(box, imageSize,
               [&](long flat, long image) { result.mask->GetBufferPointer()[image] = lumen.voxels[flat]; });
  ReportProgress(progress, 1.0, "Done");
  return result;
}

} // namespace sgp
