// Step 1b of GrowLumenRegion: the window slab by slab from the lumen's core (GrowLumenRegion.h).
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
#include "Common/TwoCores.h"

namespace sgp::lumen_growth
{

namespace
{

/// Step 1b's window half-width at least this share of the slab's lumen level: 70 HU at 350 HU,
/// what 3.5 σ of a 20 HU noise gives, and what the seed balls gave before step 1b (3 × 23–25 HU).
constexpr double lumenHalfWindowFraction = 0.2;

} // namespace

long TotalWidth(const SliceWindows& w)
{
  long total = 0;
  for (std::size_t k = 0; k < w.lower.size(); ++k)
    total += long(w.upper[k]) - long(w.lower[k]);
  return total;
}

MaskGrid LumenCore(const CtImage& ct, const MaskGrid& region, const IndexBox& box, const CtImage::IndexType& seed)
{
  const auto spacing = ct.GetSpacing();
  // The blocks lie on a grid fixed in space (voxel g along axis a, counted from the physical
  // origin of that axis, is in block floor(g / block)), not on the region's box: a scan cut lower,
  // or a region a little wider, then has the same blocks, so the same core where the lumen is the
  // same.
  const auto floorDiv = [](long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  std::array<long, 3> block{}, coarseSize{}, shift{}, firstBlock{};
  std::array<double, 3> coarseSpacing{};
  for (unsigned a = 0; a < 3; ++a)
  {
    block[a] = std::max(1L, static_cast<long>(std::floor(lumenCoreBlockMm / spacing[a] + 1e-9)));
    double along = 0.0; // the image origin's position along axis a, mm
    for (unsigned b = 0; b < 3; ++b)
      along += ct.GetOrigin()[b] * ct.GetDirection()[b][a];
    shift[a] = static_cast<long>(std::lround(along / spacing[a])) + box.first[a];
    firstBlock[a] = floorDiv(shift[a], block[a]);
    coarseSize[a] = floorDiv(shift[a] + region.size[a] - 1, block[a]) - firstBlock[a] + 1;
    coarseSpacing[a] = double(block[a]) * spacing[a];
  }
  // The block of crop voxel i along axis a, looked up (a division per voxel and axis was most of
  // this step's time).
  std::array<std::vector<long>, 3> blockOf;
  for (unsigned a = 0; a < 3; ++a)
    for (long i = 0; i < region.size[a]; ++i)
      blockOf[a].push_back(floorDiv(shift[a] + i, block[a]) - firstBlock[a]);
  MaskGrid coarse(coarseSize);
  std::vector<int> inside(static_cast<size_t>(coarse.Count()), 0), total(inside.size(), 0);
  // On both cores, split between two layers of blocks (each block's counts are one half's).
  long split = region.size[2] / 2;
  while (split > 0 && blockOf[2][split] == blockOf[2][split - 1])
    --split;
  OnTwoCores(
    region.size[2],
    [&](long first, long end)
    {
      for (long k = first; k < end; ++k)
        for (long j = 0; j < region.size[1]; ++j)
        {
          const long row = coarse.Flat(0, blockOf[1][j], blockOf[2][k]);
          const std::uint8_t* voxel = &region.voxels[region.Flat(0, j, k)];
          for (long i = 0; i < region.size[0]; ++i)
          {
            const size_t c = static_cast<size_t>(row + blockOf[0][i]);
            ++total[c];
            inside[c] += voxel[i];
          }
        }
    },
    split);
  for (size_t c = 0; c < inside.size(); ++c)
    coarse.voxels[c] = 4 * inside[c] > 3 * total[c] ? 1 : 0;
  FillHoles(coarse);
  const DistanceField field = DistanceInsideMask(coarse, coarseSpacing, true, float(lumenCoreDepthMm + 1.0));
  MaskGrid deep(coarseSize);
  long nearest = -1;
  double nearestMm2 = std::numeric_limits<double>::infinity();
  for (long c = 0; c < deep.Count(); ++c)
  {
    if (field.distanceMm[static_cast<size_t>(c)] < lumenCoreDepthMm)
      continue;
    deep.voxels[c] = 1;
    const auto ijk = deep.Ijk(c);
    double d2 = 0.0;
    for (unsigned a = 0; a < 3; ++a)
    {
      const long firstVoxel = (firstBlock[a] + ijk[a]) * block[a] - shift[a] + box.first[a]; // CT index
      const double d = (double(firstVoxel) + 0.5 * double(block[a] - 1) - double(seed[a])) * spacing[a];
      d2 += d * d;
    }
    if (d2 < nearestMm2)
    {
      nearestMm2 = d2;
      nearest = c;
    }
  }
  MaskGrid core(region.size);
  if (nearest < 0)
    return core;
  const MaskGrid piece = ConnectedComponent(deep, nearest);
  OnTwoCores(region.size[2],
             [&](long first, long end)
             {
               for (long k = first; k < end; ++k)
                 for (long j = 0; j < region.size[1]; ++j)
                 {
                   const std::uint8_t* inPiece = &piece.voxels[piece.Flat(0, blockOf[1][j], blockOf[2][k])];
                   const long f = region.Flat(0, j, k);
                   for (long i = 0; i < region.size[0]; ++i)
                     core.voxels[f + i] = region.voxels[f + i] && inPiece[blockOf[0][i]];
                 }
             });
  return core;
}

long SlabOfSlice(const CtImage& ct, long k)
{
  double origin = 0.0;
  for (unsigned a = 0; a < 3; ++a)
    origin += ct.GetOrigin()[a] * ct.GetDirection()[a][2];
  return static_cast<long>(std::floor((origin + double(k) * ct.GetSpacing()[2]) / slabMm));
}

LumenLevels MeasureLumenLevels(const CtImage& ct,
                               const MaskGrid& core,
                               const std::vector<short>& hu,
                               const IndexBox& box)
{
  const long nz = static_cast<long>(ct.GetLargestPossibleRegion().GetSize()[2]);
  const long bx = core.size[0], by = core.size[1], bz = core.size[2];
  const auto slabOf = [&](long k) { return SlabOfSlice(ct, k); };
  LumenLevels levels;
  levels.sliceMedianHu.assign(static_cast<size_t>(nz), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> slab, sigmas, medians;
  const long kFirst = 0, kLast = bz - 1;
  long slabStart = box.first[2] + kFirst;
  const auto closeSlab = [&](long kEnd) // kEnd: the CT slice after the slab
  {
    if (static_cast<long>(slab.size()) >= minimumSlabVoxels)
    {
      const double m = Median(slab);
      for (double& v : slab)
        v = std::abs(v - m);
      sigmas.push_back(1.4826 * Median(slab));
      medians.push_back(m);
      for (long k = slabStart; k < kEnd; ++k)
        levels.sliceMedianHu[static_cast<size_t>(k)] = m;
    }
    slab.clear();
    slabStart = kEnd;
  };
  for (long k = kFirst; k <= kLast; ++k)
  {
    const long kImage = box.first[2] + k;
    if (k > kFirst && slabOf(kImage) != slabOf(kImage - 1))
      closeSlab(kImage);
    for (long f = core.Flat(0, 0, k), end = f + bx * by; f < end; ++f)
      if (core.voxels[f])
        slab.push_back(hu[f]);
  }
  closeSlab(box.first[2] + kLast + 1);
  levels.slabs = static_cast<int>(medians.size());
  if (medians.empty())
    return levels;
  levels.medianHu = Median(medians);
  levels.sigmaHu = Median(sigmas);
  // Slices without a slab level take the nearest slab's (thin vessels only, or beyond the region).
  std::vector<double>& m = levels.sliceMedianHu;
  for (long k = 0, last = -1; k < nz; ++k)
    if (!std::isnan(m[k]))
    {
      for (long q = last + 1; q < k; ++q)
        m[q] = (last < 0 || k - q <= q - last) ? m[k] : m[last];
      last = k;
    }
    else if (k == nz - 1 && last >= 0)
      for (long q = last + 1; q < nz; ++q)
        m[q] = m[last];
  return levels;
}

SliceWindows WindowsFromLevels(const LumenLevels& lumen,
                               const RegionGrowingParams& params,
                               double& lowest,
                               double& highest)
{
  SliceWindows windows;
  lowest = std::numeric_limits<double>::infinity();
  highest = -lowest;
  for (const double m : lumen.sliceMedianHu)
  {
    // The core's σ is the noise alone, where a seed ball's also holds some of the lumen's own
    // variation (measured: 19 against 25 HU in one 20 HU-noise phantom); k σ of the noise alone
    // cuts the partial-volume core of a 5–7 mm branch (an internal iliac) off, so the half-width
    // is at least lumenHalfWindowFraction of the level.
    const double half =
      std::max({ params.windowSigmas * lumen.sigmaHu, params.minimumHalfWindowHu, lumenHalfWindowFraction * m });
    windows.lower.push_back(ClampToShort(std::ceil(m - half)));
    windows.upper.push_back(ClampToShort(std::floor(m + 2.0 * half)));
    lowest = std::min(lowest, m - half);
    highest = std::max(highest, m + 2.0 * half);
  }
  return windows;
}

} // namespace sgp::lumen_growth
