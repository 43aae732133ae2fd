// Step 1 of GrowLumenRegion: the HU window from the seed's neighbourhood (GrowLumenRegion.h).
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

namespace
{

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

/// Fraction of `stats.voxels` outside [low, high] HU.
double FractionOutside(const CtImage& ct, const SeedStatistics& stats, double low, double high)
{
  long outside = 0;
  for (const auto& index : stats.voxels)
  {
    const double v = ct.GetPixel(index);
    outside += v < low || v > high;
  }
  return stats.voxels.empty() ? 0.0 : double(outside) / double(stats.voxels.size());
}

/// True when the straight line from `seed` to `centre` stays in voxels of at least `minimumHu`
/// beyond its first `skipMm` (a seed placed on a flap or on the wall's edge lies in dark voxels
/// itself): the two lie in one lumen, not across a wall or flap.
bool JoinedThroughLumen(const CtImage& ct,
                        const CtImage::IndexType& seed,
                        const CtImage::IndexType& centre,
                        double distanceMm,
                        double minimumHu,
                        double skipMm)
{
  const int steps = std::max(1, static_cast<int>(std::ceil(distanceMm / 0.5)));
  for (int s = 1; s <= steps; ++s)
  {
    const double t = double(s) / steps;
    if (t * distanceMm < skipMm)
      continue;
    CtImage::IndexType index;
    for (unsigned a = 0; a < 3; ++a)
      index[a] = seed[a] + std::lround(t * double(centre[a] - seed[a]));
    if (ct.GetPixel(index) < minimumHu)
      return false;
  }
  return true;
}

/// Step 1a (Auto): the neighbourhood the window is taken from. The seed's own ball, unless more
/// than 2 % of its voxels lie outside ±4 σ (at least ± minimumHalfWindowHu) of the lumen's own
/// spread near it — a wall, plaque or dissection flap inside the ball. The lumen's spread is the
/// median and σ of the most homogeneous fifth of the candidate balls: centred on a ~1 mm lattice
/// within `seedSearchRadiusMm` of the seed, each with a median of at least `seedMinimumHu` and
/// joined to the seed by a straight line through lumen (JoinedThroughLumen, the seed's own ball
/// radius skipped). Then the nearest candidate that is clean by the same test is used. Sets the
/// window's source in `result` and, when it moved, a warning.
SeedStatistics ChooseWindowNeighbourhood(const CtImage& ct,
                                         const CtImage::IndexType& seed,
                                         const Point3& seedLps,
                                         const RegionGrowingParams& params,
                                         LumenSegmentation& result)
{
  const double ball = params.seedNeighbourhoodRadiusMm;
  SeedStatistics own = MeasureSeedNeighbourhood(ct, seed, seedLps, ball);
  result.windowCentreLps = seedLps;
  result.windowSource = "the seed's neighbourhood";
  if (params.thresholdMode != ThresholdMode::Auto)
    result.windowSource = "the seed's neighbourhood; the window as given (thresholdMode manual)";
  if (params.thresholdMode != ThresholdMode::Auto || params.seedSearchRadiusMm <= 0.0)
    return own;
  const auto spacing = ct.GetSpacing();
  const auto region = ct.GetLargestPossibleRegion();
  struct Candidate
  {
    double distanceMm;
    Point3 lps;
    SeedStatistics stats;
  };
  std::vector<Candidate> candidates;
  std::array<long, 3> stride{}, reach{};
  for (unsigned a = 0; a < 3; ++a)
  {
    stride[a] = std::max(1L, std::lround(1.0 / spacing[a]));
    reach[a] = static_cast<long>(std::floor(params.seedSearchRadiusMm / spacing[a]));
  }
  for (long dk = -(reach[2] / stride[2]) * stride[2]; dk <= reach[2]; dk += stride[2])
    for (long dj = -(reach[1] / stride[1]) * stride[1]; dj <= reach[1]; dj += stride[1])
      for (long di = -(reach[0] / stride[0]) * stride[0]; di <= reach[0]; di += stride[0])
      {
        CtImage::IndexType index = seed;
        index[0] += di;
        index[1] += dj;
        index[2] += dk;
        if (!region.IsInside(index))
          continue;
        const Point3 lps = IndexToLps(ct, index);
        const double distance = (lps - seedLps).norm();
        if (distance > params.seedSearchRadiusMm ||
            !JoinedThroughLumen(ct, seed, index, distance, params.seedMinimumHu, ball))
          continue;
        SeedStatistics s = MeasureSeedNeighbourhood(ct, index, lps, ball);
        if (s.medianHu >= params.seedMinimumHu)
          candidates.push_back({ distance, lps, std::move(s) });
      }
  if (candidates.empty())
    return own; // the seed checks that follow report it
  // The lumen's own spread: the lowest σ of many 65-voxel balls is biased low (the minimum of
  // noisy estimates), so the reference is the cleanest fifth of the candidates: its σ and median.
  std::vector<double> sigmas;
  for (const Candidate& c : candidates)
    sigmas.push_back(c.stats.sigmaHu);
  std::sort(sigmas.begin(), sigmas.end());
  const double sigma = sigmas[sigmas.size() / 5];
  std::vector<double> medians;
  for (const Candidate& c : candidates)
    if (c.stats.sigmaHu <= sigma)
      medians.push_back(c.stats.medianHu);
  const double half = std::max(4.0 * sigma, params.minimumHalfWindowHu);
  const double low = Median(medians) - half, high = Median(medians) + half;
  constexpr double cleanFraction = 0.02; // Gaussian noise leaves 0.006 % beyond 4 σ
  const double ownOutside = FractionOutside(ct, own, low, high);
  if (own.medianHu >= params.seedMinimumHu && ownOutside <= cleanFraction)
    return own;
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.distanceMm < b.distanceMm; });
  for (Candidate& c : candidates)
  {
    if (FractionOutside(ct, c.stats, low, high) <= cleanFraction)
    {
      const Point3 lps = c.lps;
      result.windowCentreLps = lps;
      result.windowSource = "a neighbourhood " + FormatNumber(c.distanceMm, 1) + " mm from the seed, at " +
                            FormatPoint(lps) + " mm LPS (" + FormatNumber(100.0 * ownOutside, 0) +
                            " % of the voxels around the seed itself lie outside " + FormatNumber(low, 0) + " to " +
                            FormatNumber(high, 0) +
                            " HU, the range of the most homogeneous fifth of the lumen within " +
                            FormatNumber(params.seedSearchRadiusMm, 0) + " mm: wall, plaque or a flap beside the seed)";
      result.warnings.push_back("The seed's neighbourhood is not homogeneous lumen; the HU window was taken from " +
                                result.windowSource + ".");
      return std::move(c.stats);
    }
  }
  return own; // no clean neighbourhood: the seed's own, whose checks follow
}

} // namespace

SeedStatistics EstimateWindow(const CtImage& ct,
                              const CtImage::IndexType& seed,
                              const Point3& seedLps,
                              const RegionGrowingParams& params,
                              LumenSegmentation& result)
{
  SeedStatistics stats = ChooseWindowNeighbourhood(ct, seed, seedLps, params, result);
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
  // Calcium and bone: half the window's width above it (Auto: m + 3.5 h, ~10 σ above the lumen,
  // so noise never reaches it; arterial-phase plaque reads 600–1200 HU, vessel-wall.md §2).
  result.calciumHu = result.upperHu + 0.25 * (result.upperHu - result.lowerHu);
  return stats;
}

} // namespace sgp::lumen_growth
