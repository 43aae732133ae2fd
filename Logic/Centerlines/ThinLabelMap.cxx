#include "Centerlines/ThinLabelMap.h"

#include <algorithm>
#include <numeric>

#include "Centerlines/SimplePoint.h"
#include "Common/DistanceInsideMask.h"
#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"

namespace sgp
{

namespace
{

/// The 27-bit neighbourhood of an interior voxel (the box is padded, so every foreground voxel
/// is interior).
std::uint32_t Neighbourhood(const MaskGrid& grid, long flat)
{
  const long sj = grid.size[0], sk = grid.size[0] * grid.size[1];
  std::uint32_t bits = 0;
  int bit = 0;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di, ++bit)
        if (grid.voxels[flat + di + dj * sj + dk * sk])
          bits |= 1u << bit;
  return bits;
}

} // namespace

Skeleton ThinLabelMap(const LabelImage& mask, const ProgressCallback& progress)
{
  const IndexBox found = ForegroundBox(mask);
  if (found.Empty())
  {
    throw InputError("The lumen mask is empty (no non-zero voxel); nothing to thin.");
  }
  // One voxel of background padding on every side (beyond the image's edge too), so that every
  // foreground voxel has a full neighbourhood inside the box.
  const std::array<long, 3> lo = found.first;
  MaskGrid box({ found.size[0] + 2, found.size[1] + 2, found.size[2] + 2 });
  ForEachInBox(found, mask.GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image)
               {
                 const long i = flat % found.size[0], j = (flat / found.size[0]) % found.size[1];
                 const long k = flat / (found.size[0] * found.size[1]);
                 box.voxels[box.Flat(i + 1, j + 1, k + 1)] = mask.GetBufferPointer()[image] ? 1 : 0;
               });
  ReportProgress(progress, 0.05, "Distance map");
  const auto spacing = mask.GetSpacing();
  const std::array<double, 3> spacingMm{ spacing[0], spacing[1], spacing[2] };
  const DistanceField field = DistanceInsideMask(box, spacingMm);

  std::vector<long> order;
  for (long v = 0; v < box.Count(); ++v)
    if (box.voxels[v])
      order.push_back(v);
  std::stable_sort(order.begin(), order.end(),
                   [&](long a, long b) { return field.distanceMm[a] < field.distanceMm[b]; });

  ReportProgress(progress, 0.3, "Thinning");
  for (int sweep = 0;; ++sweep)
  {
    long removed = 0;
    for (const long v : order)
    {
      if (!box.voxels[v])
        continue;
      const std::uint32_t n = Neighbourhood(box, v);
      if (CountNeighbours(n) != 1 && IsSimplePoint(n))
      {
        box.voxels[v] = 0;
        ++removed;
      }
    }
    ReportProgress(progress, std::min(0.9, 0.5 + 0.1 * sweep), "Thinning");
    if (removed == 0)
      break;
    order.erase(std::remove_if(order.begin(), order.end(), [&](long v) { return !box.voxels[v]; }), order.end());
  }

  Skeleton skeleton;
  for (const long v : order)
  {
    if (!box.voxels[v])
      continue;
    const auto b = box.Ijk(v);
    const itk::Index<3> index{ { lo[0] + b[0] - 1, lo[1] + b[1] - 1, lo[2] + b[2] - 1 } };
    const auto& q = field.nearestBackground[v];
    const itk::Index<3> background{ { lo[0] + q[0] - 1, lo[1] + q[1] - 1, lo[2] + q[2] - 1 } };
    skeleton.voxels.push_back(index);
    skeleton.pointsLps.push_back(IndexToLps(mask, index));
    skeleton.radiusMm.push_back(field.distanceMm[v]);
    skeleton.nearestBackgroundLps.push_back(IndexToLps(mask, background));
  }
  ReportProgress(progress, 1.0, "Done");
  return skeleton;
}

LabelImage::Pointer SkeletonToImage(const Skeleton& skeleton, const LabelImage& reference)
{
  auto image = LabelImage::New();
  image->CopyInformation(&reference);
  image->SetRegions(reference.GetLargestPossibleRegion());
  image->Allocate(true);
  for (const auto& index : skeleton.voxels)
    image->SetPixel(index, 1);
  return image;
}

} // namespace sgp
