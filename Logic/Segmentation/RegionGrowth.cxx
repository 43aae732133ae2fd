// Step 2 of GrowLumenRegion: the face-connected region in the window, and its crop (GrowLumenRegion.h).
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
#include "Common/HugePages.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"
#include "Common/Median.h"
#include "Common/TwoCores.h"

namespace sgp::lumen_growth
{

VoxelBits GrowFromSeed(const CtImage& ct,
                       const SeedStatistics& stats,
                       const LumenSegmentation& result,
                       const std::array<long, 3>& pad,
                       IndexBox& box,
                       const SliceWindows& slices)
{
  const auto start = std::find_if(stats.voxels.begin(), stats.voxels.end(),
                                  [&](const auto& index)
                                  {
                                    const short v = ct.GetPixel(index);
                                    if (!slices.lower.empty())
                                      return v >= slices.lower[static_cast<size_t>(index[2])] &&
                                             v <= slices.upper[static_cast<size_t>(index[2])];
                                    return v >= result.lowerHu && v <= result.upperHu;
                                  });
  if (start == stats.voxels.end())
  {
    // Cannot happen: the median is one of the neighbourhood's values and lies in the window.
    throw std::logic_error("GrowLumenRegion: no seed-neighbourhood voxel in the window");
  }
  const short lower = ClampToShort(std::ceil(result.lowerHu)), upper = ClampToShort(std::floor(result.upperHu));
  const short calcium = ClampToShort(std::floor(result.calciumHu));
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  const long nx = long(size[0]), ny = long(size[1]), nz = long(size[2]), slice = nx * ny;
  const short* hu = ct.GetBufferPointer();
  // Beside calcium or bone (a face neighbour above calciumHu) lies its blurred rim, whose HU
  // passes through the lumen's window: not grown into (file comment, step 2).
  const auto besideCalcium = [&](long flat, long i, long j, long k)
  {
    return (i > 0 && hu[flat - 1] > calcium) || (i + 1 < nx && hu[flat + 1] > calcium) ||
           (j > 0 && hu[flat - nx] > calcium) || (j + 1 < ny && hu[flat + nx] > calcium) ||
           (k > 0 && hu[flat - slice] > calcium) || (k + 1 < nz && hu[flat + slice] > calcium);
  };
  VoxelBits inRegion(slice * nz);
  std::array<long, 3> lo{ nx, ny, nz }, hi{ -1, -1, -1 };
  std::vector<long> stack{ (*start)[0] + nx * ((*start)[1] + ny * (*start)[2]) };
  inRegion.Set(stack.back());
  const auto visit = [&](long flat)
  {
    const long k = flat / slice;
    const short lo = slices.lower.empty() ? lower : slices.lower[k],
                up = slices.upper.empty() ? upper : slices.upper[k];
    if (!inRegion.Test(flat) && hu[flat] >= lo && hu[flat] <= up &&
        !besideCalcium(flat, flat % nx, (flat / nx) % ny, flat / slice))
    {
      inRegion.Set(flat);
      stack.push_back(flat);
    }
  };
  while (!stack.empty())
  {
    const long flat = stack.back();
    stack.pop_back();
    const long k = flat / slice, j = (flat - k * slice) / nx, i = flat - k * slice - j * nx;
    lo = { std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k) };
    hi = { std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k) };
    if (i > 0)
      visit(flat - 1);
    if (i + 1 < nx)
      visit(flat + 1);
    if (j > 0)
      visit(flat - nx);
    if (j + 1 < ny)
      visit(flat + nx);
    if (k > 0)
      visit(flat - slice);
    if (k + 1 < nz)
      visit(flat + slice);
  }
  box = PaddedBox(lo, hi, pad, size);
  return inRegion;
}

CroppedRegion CropToRegion(const CtImage& ct, const VoxelBits& inRegion, const IndexBox& box)
{
  CroppedRegion crop;
  crop.box = box;
  crop.region = MaskGrid(crop.box.size);
  AssignAdvised(crop.hu, static_cast<std::size_t>(crop.region.Count()), short(0));
  OnTwoCores(crop.box.size[2],
             [&](long first, long end)
             {
               ForEachInBoxSlices(crop.box, ct.GetLargestPossibleRegion().GetSize(), first, end,
                                  [&](long flat, long image)
                                  {
                                    crop.region.voxels[flat] = inRegion.Test(image) ? 1 : 0;
                                    crop.hu[flat] = ct.GetBufferPointer()[image];
                                  });
             });
  return crop;
}

} // namespace sgp::lumen_growth
