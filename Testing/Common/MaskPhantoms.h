/// \file MaskPhantoms.h
/// Binary masks of simple shapes with known axes, painted in physical space on any grid, and
/// counts of a skeleton's end points and junctions.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

#include <itkImageRegionIteratorWithIndex.h>

#include "Centerlines/ThinLabelMap.h"
#include "Common/ImageGeometry.h"

namespace sgp::testing
{

/// A capsule: the segment a–b swept by a ball of radius r (LPS mm).
struct Capsule
{
  Point3 a, b;
  double radiusMm;
  double Distance(const Point3& p) const
  {
    const Point3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm();
  }
};

/// A label image of the union of capsules, on a grid with the given spacing and direction whose
/// extent covers them with a margin of 3 mm.
/// A copy of `image` (its own buffer): for the stages that take a mask over (LumenFromSegmentation).
inline LabelImage::Pointer CopyMask(const LabelImage& image)
{
  auto copy = LabelImage::New();
  copy->CopyInformation(&image);
  copy->SetRegions(image.GetLargestPossibleRegion());
  copy->Allocate();
  std::copy_n(image.GetBufferPointer(), image.GetLargestPossibleRegion().GetNumberOfPixels(), copy->GetBufferPointer());
  return copy;
}

inline LabelImage::Pointer PaintCapsules(const std::vector<Capsule>& capsules,
                                         const std::array<double, 3>& spacing,
                                         const Eigen::Matrix3d& direction = Eigen::Matrix3d::Identity())
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const Capsule& c : capsules)
    for (const Point3& p : { c.a, c.b })
      for (int corner = 0; corner < 8; ++corner)
      {
        const Point3 q = p + (c.radiusMm + 3.0) * Point3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
        const Eigen::Vector3d u = direction.transpose() * q;
        lo = lo.cwiseMin(u);
        hi = hi.cwiseMax(u);
      }
  auto image = LabelImage::New();
  LabelImage::RegionType region;
  itk::Size<3> size;
  for (int a = 0; a < 3; ++a)
    size[a] = static_cast<itk::SizeValueType>(std::ceil((hi[a] - lo[a]) / spacing[a])) + 1;
  region.SetSize(size);
  image->SetRegions(region);
  image->SetSpacing(spacing.data());
  const Eigen::Vector3d origin = direction * lo;
  image->SetOrigin(origin.data());
  LabelImage::DirectionType d;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      d(r, c) = direction(r, c);
  image->SetDirection(d);
  image->Allocate(true);
  itk::ImageRegionIteratorWithIndex<LabelImage> it(image, region);
  for (; !it.IsAtEnd(); ++it)
  {
    const Point3 p = IndexToLps(*image, it.GetIndex());
    for (const Capsule& c : capsules)
      if (c.Distance(p) < c.radiusMm)
      {
        it.Set(1);
        break;
      }
  }
  return image;
}

/// End points (one 26-neighbour) and junction clusters (26-connected voxels with ≥ 3).
struct SkeletonCounts
{
  int ends = 0;
  int junctions = 0;
  bool has2x2x2Block = false;
};

inline SkeletonCounts CountSkeleton(const Skeleton& skeleton)
{
  std::map<std::array<long, 3>, int> id;
  for (int v = 0; v < int(skeleton.voxels.size()); ++v)
    id[{ skeleton.voxels[v][0], skeleton.voxels[v][1], skeleton.voxels[v][2] }] = v;
  const auto has = [&](long i, long j, long k) { return id.count({ i, j, k }) > 0; };
  SkeletonCounts counts;
  std::vector<int> junction;
  for (const auto& [key, v] : id)
  {
    int n = 0;
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          n += (di || dj || dk) && has(key[0] + di, key[1] + dj, key[2] + dk);
    counts.ends += n == 1;
    if (n >= 3)
      junction.push_back(v);
    bool block = true;
    for (int c = 0; c < 8; ++c)
      block = block && has(key[0] + (c & 1), key[1] + ((c >> 1) & 1), key[2] + ((c >> 2) & 1));
    counts.has2x2x2Block = counts.has2x2x2Block || block;
  }
  // Junction clusters by 26-adjacency.
  std::vector<bool> seen(skeleton.voxels.size(), false);
  std::unordered_map<int, bool> isJunction;
  for (int v : junction)
    isJunction[v] = true;
  for (int v : junction)
  {
    if (seen[v])
      continue;
    ++counts.junctions;
    std::vector<int> stack{ v };
    seen[v] = true;
    while (!stack.empty())
    {
      const int u = stack.back();
      stack.pop_back();
      const auto& p = skeleton.voxels[u];
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
          {
            const auto found = id.find({ p[0] + di, p[1] + dj, p[2] + dk });
            if (found != id.end() && isJunction.count(found->second) && !seen[found->second])
            {
              seen[found->second] = true;
              stack.push_back(found->second);
            }
          }
    }
  }
  return counts;
}

} // namespace sgp::testing
