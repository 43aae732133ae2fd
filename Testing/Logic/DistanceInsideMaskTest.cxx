// Tests of the exact distance transform against the definition: for every foreground voxel, the
// smallest distance in mm to any background voxel centre (and, when the box's outside is
// background, to any voxel centre of the one-voxel shell around it), found by trying them all.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "Common/DistanceInsideMask.h"

namespace sgp
{
namespace
{

struct BruteForce
{
  std::vector<double> distance;
};

BruteForce Exhaustive(const MaskGrid& mask, const std::array<double, 3>& s, bool outsideIsBackground)
{
  std::vector<std::array<long, 3>> sites;
  for (long k = -1; k <= mask.size[2]; ++k)
    for (long j = -1; j <= mask.size[1]; ++j)
      for (long i = -1; i <= mask.size[0]; ++i)
      {
        const bool outside = i < 0 || j < 0 || k < 0 || i >= mask.size[0] || j >= mask.size[1] || k >= mask.size[2];
        if (outside ? outsideIsBackground : !mask.voxels[mask.Flat(i, j, k)])
          sites.push_back({ i, j, k });
      }
  BruteForce out;
  out.distance.assign(std::size_t(mask.Count()), std::numeric_limits<double>::infinity());
  for (long flat = 0; flat < mask.Count(); ++flat)
  {
    const auto p = mask.Ijk(flat);
    for (const auto& q : sites)
    {
      const double x = (p[0] - q[0]) * s[0], y = (p[1] - q[1]) * s[1], z = (p[2] - q[2]) * s[2];
      out.distance[std::size_t(flat)] = std::min(out.distance[std::size_t(flat)], std::sqrt(x * x + y * y + z * z));
    }
  }
  return out;
}

TEST(DistanceInsideMask, EqualsExhaustiveSearchOnRandomMasks)
{
  std::mt19937 random(4711);
  const std::array<double, 3> spacings[] = { { 1.0, 1.0, 1.0 }, { 0.7, 0.7, 2.5 }, { 0.8, 0.6, 1.25 } };
  long compared = 0;
  for (const auto& spacing : spacings)
    for (const bool outsideIsBackground : { true, false })
      for (const double density : { 0.6, 0.9, 0.98 })
        // 37 along i: the passes along j and k take lines in blocks of 16 neighbours along i (two
        // whole blocks and a part); every fifth i is background throughout, so that blocks mix
        // lines of background only (left as they are) with lines that hold foreground.
        for (const std::array<long, 3> size : { std::array<long, 3>{ 11, 9, 8 }, std::array<long, 3>{ 37, 9, 7 } })
        {
          MaskGrid mask(size);
          std::bernoulli_distribution foreground(density);
          for (auto& v : mask.voxels)
            v = foreground(random) ? 1 : 0;
          if (size[0] > 16)
            for (long flat = 0; flat < mask.Count(); ++flat)
              if (mask.Ijk(flat)[0] % 5 == 3)
                mask.voxels[std::size_t(flat)] = 0;
          const DistanceField field = DistanceInsideMask(mask, spacing, outsideIsBackground, 1e30f);
          const BruteForce truth = Exhaustive(mask, spacing, outsideIsBackground);
          for (long flat = 0; flat < mask.Count(); ++flat)
          {
            const double expected = mask.voxels[flat] ? truth.distance[std::size_t(flat)] : 0.0;
            if (std::isinf(expected))
              continue; // no site at all (a full box with its outside foreground): checked below
            // float storage of the squared distance: 1e-5 mm at these distances.
            ASSERT_NEAR(field.distanceMm[std::size_t(flat)], expected, 1e-4) << "voxel " << flat;
            // The nearest site given is a site at that distance.
            const auto p = mask.Ijk(flat);
            const auto& q = field.nearestBackground[std::size_t(flat)];
            const double x = (p[0] - q[0]) * spacing[0], y = (p[1] - q[1]) * spacing[1], z = (p[2] - q[2]) * spacing[2];
            ASSERT_NEAR(std::sqrt(x * x + y * y + z * z), expected, 1e-4) << "voxel " << flat;
            const bool inBox =
              q[0] >= 0 && q[1] >= 0 && q[2] >= 0 && q[0] < mask.size[0] && q[1] < mask.size[1] && q[2] < mask.size[2];
            if (inBox)
              ASSERT_EQ(mask.voxels[mask.Flat(q[0], q[1], q[2])], 0) << "voxel " << flat;
            else
              ASSERT_TRUE(outsideIsBackground) << "a site outside the box when the outside is not background";
            ++compared;
          }
        }
  EXPECT_GT(compared, 20000);
}

TEST(DistanceInsideMask, ClippedAtTheMaximumAndWithoutSites)
{
  MaskGrid full({ 30, 4, 4 });
  std::fill(full.voxels.begin(), full.voxels.end(), 1);
  full.voxels[full.Flat(0, 0, 0)] = 0; // the only site
  const DistanceField clipped = DistanceInsideMask(full, { 1.0, 1.0, 1.0 }, false, 10.0f);
  EXPECT_FLOAT_EQ(clipped.distanceMm[std::size_t(full.Flat(5, 0, 0))], 5.0f);
  EXPECT_FLOAT_EQ(clipped.distanceMm[std::size_t(full.Flat(29, 3, 3))], 10.0f); // 29.3 mm, clipped
  std::fill(full.voxels.begin(), full.voxels.end(), 1);
  const DistanceField none = DistanceInsideMask(full, { 1.0, 1.0, 1.0 }, false, 7.0f);
  EXPECT_FLOAT_EQ(none.distanceMm[0], 7.0f); // no background anywhere: the maximum
}

} // namespace
} // namespace sgp
