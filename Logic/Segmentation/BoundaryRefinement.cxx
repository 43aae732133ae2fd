// Steps 5 and 6 of GrowLumenRegion: the boundary at the half-maximum edge level (GrowLumenRegion.h).
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
#include "Common/TwoCores.h"
#include "Common/Median.h"

namespace sgp::lumen_growth
{

EdgeLevels MeasureEdgeLevels(const CtImage& ct,
                             const MaskGrid& mask,
                             const std::vector<short>& hu,
                             const std::array<long, 3>& depth,
                             long firstSlice,
                             const std::vector<double>& sliceLevelHu,
                             double medianHu,
                             double tissueHu)
{
  const long nz = mask.size[2];
  // Each slice's lumen level and tissue; the levels are half-way between them.
  std::vector<double> lumen(static_cast<std::size_t>(nz), medianHu), tissueOf(static_cast<std::size_t>(nz), tissueHu);
  if (!sliceLevelHu.empty())
  {
    std::vector<long> slabOfK(static_cast<std::size_t>(nz));
    for (long k = 0; k < nz; ++k)
      slabOfK[static_cast<std::size_t>(k)] = SlabOfSlice(ct, firstSlice + k);
    std::map<long, std::vector<double>> samples; // by slab
    ForEachTissueSample(mask, hu, depth,
                        [&](long k, short v) { samples[slabOfK[static_cast<std::size_t>(k)]].push_back(v); });
    std::map<long, double> tissue;
    for (auto& [slab, values] : samples)
      if (static_cast<long>(values.size()) >= minimumSlabVoxels)
        tissue[slab] = Median(values);
    for (long k = 0; k < nz; ++k)
    {
      const long image = firstSlice + k;
      if (image < 0 || image >= static_cast<long>(sliceLevelHu.size()))
        continue;
      const auto t = tissue.find(slabOfK[static_cast<std::size_t>(k)]);
      lumen[static_cast<std::size_t>(k)] = sliceLevelHu[static_cast<std::size_t>(image)];
      if (t != tissue.end())
        tissueOf[static_cast<std::size_t>(k)] = t->second;
    }
  }
  EdgeLevels levels;
  levels.lumenEdge.resize(static_cast<std::size_t>(nz));
  levels.branchEdge.resize(static_cast<std::size_t>(nz));
  for (std::size_t k = 0; k < static_cast<std::size_t>(nz); ++k)
  {
    levels.lumenEdge[k] = 0.5 * (lumen[k] + LumenBorderHu(tissueOf[k]));
    levels.branchEdge[k] = 0.5 * (lumen[k] + tissueOf[k]);
  }
  return levels;
}

void RefineBoundary(MaskGrid& lumen,
                    const std::vector<short>& hu,
                    int refineSteps,
                    const std::vector<std::array<int, 3>>& reachBall,
                    const std::vector<double>& edge,
                    LumenSegmentation& result)
{
  std::vector<std::uint8_t> accept(static_cast<std::size_t>(lumen.Count()));
  const long nx = lumen.size[0], ny = lumen.size[1], nz = lumen.size[2], slice = nx * ny;
  // Within refineDistanceMm of the grown region in millimetres, on every axis: counted in face
  // steps of the finest spacing, the reach along 2.5 mm slices was 3 slices, 7.5 mm — into an
  // enhancing renal vein above or below the lumen (16 % of it on 0.7 × 0.7 × 2.5 mm).
  // Only the few voxels in the window outside the lumen look for a lumen voxel within the ball
  // (no box-sized dilated copy of the lumen, which cost 38 MiB of peak memory on 512 × 512 × 1000).
  const auto withinReach = [&](long flat)
  {
    const long i = flat % nx, j = (flat / nx) % ny, k = flat / slice;
    for (const auto& d : reachBall)
    {
      const long a = i + d[0], b = j + d[1], c = k + d[2];
      if (a >= 0 && b >= 0 && c >= 0 && a < nx && b < ny && c < nz && lumen.voxels[a + nx * (b + ny * c)])
        return true;
    }
    return false;
  };
  OnTwoCores(nz,
             [&](long firstSlice, long endSlice)
             {
               for (long flat = firstSlice * slice; flat < endSlice * slice; ++flat)
                 accept[flat] = !lumen.voxels[flat] && hu[flat] >= edge[static_cast<std::size_t>(flat / slice)] &&
                                hu[flat] <= result.upperHu && withinReach(flat);
             });
  // Not into a calcium's or bone's blurred rim either (as GrowFromSeed).
  for (long flat = 0; flat < lumen.Count(); ++flat)
    if (hu[flat] > result.calciumHu)
    {
      const long i = flat % nx, j = (flat / nx) % ny, k = flat / slice;
      accept[flat] = false;
      if (i > 0)
        accept[flat - 1] = false;
      if (i + 1 < nx)
        accept[flat + 1] = false;
      if (j > 0)
        accept[flat - nx] = false;
      if (j + 1 < ny)
        accept[flat + nx] = false;
      if (k > 0)
        accept[flat - slice] = false;
      if (k + 1 < nz)
        accept[flat + slice] = false;
    }
  GrowConstrained(lumen, accept, refineSteps);
  // Noise leaves single-voxel pits in the boundary (a voxel just inside the wall drawn below the
  // edge level); the inscribed-sphere radius of the centerlines is the distance to the nearest of
  // them, so they are filled: a background voxel with 5 or 6 lumen faces becomes lumen.
  FillSurfacePits(lumen, 5);
  FillHoles(lumen);
}

LabelImage::Pointer PasteOnGrid(const CtImage& ct, const MaskGrid& lumen, const IndexBox& box)
{
  LabelImage::Pointer mask = LabelImage::New();
  mask->CopyInformation(&ct);
  mask->SetRegions(ct.GetLargestPossibleRegion());
  AllocateAdvised(*mask);
  // The grid's pages are first touched here, slice by slice on both cores: zeroed, then the box's
  // voxels pasted.
  const itk::Size<3> size = ct.GetLargestPossibleRegion().GetSize();
  const long slice = long(size[0]) * long(size[1]);
  OnTwoCores(long(size[2]),
             [&](long first, long end)
             {
               LabelImage::PixelType* voxels = mask->GetBufferPointer();
               std::fill(voxels + first * slice, voxels + end * slice, LabelImage::PixelType(0));
               // The box's slices among these (k counted from the box's first).
               const long from = std::max(first - box.first[2], 0L), to = std::min(end - box.first[2], box.size[2]);
               ForEachInBoxSlices(box, size, from, to,
                                  [&](long flat, long image) { voxels[image] = lumen.voxels[flat]; });
             });
  return mask;
}

} // namespace sgp::lumen_growth
