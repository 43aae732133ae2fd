// The phantom's raster helpers (Logic/Phantom/PhantomRaster.h): which voxels a box visits, and
// the edge profile saturated beyond its tails.
#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "Phantom/PhantomRaster.h"

namespace sgp::phantom
{
namespace
{

Grid MakeTestGrid(const Eigen::Matrix3d& direction)
{
  Grid grid;
  grid.direction = direction;
  grid.spacing = Eigen::Vector3d(0.8, 0.7, 1.5);
  grid.size = { 60, 70, 50 };
  // Centred on (0, 30, 0) mm, whatever the direction.
  grid.origin = Point3(0.0, 30.0, 0.0) - grid.IndexToLps() * Eigen::Vector3d(29.5, 34.5, 24.5);
  return grid;
}

/// Every voxel whose centre lies in the box is visited, each at most once, at its own centre; none
/// lies farther outside the box, on any LPS axis, than the voxel's extent along that axis.
void ExpectBoxVisited(const Grid& grid, const Point3& lo, const Point3& hi, long* visitedCount)
{
  std::map<long, int> visits;
  const Eigen::Matrix3d m = grid.IndexToLps();
  const Eigen::Vector3d pad = m.cwiseAbs().rowwise().sum();
  ForEachVoxelNear(grid, lo, hi,
                   [&](long flat, const Point3& x)
                   {
                     ++visits[flat];
                     const long i = flat % grid.size[0], j = (flat / grid.size[0]) % grid.size[1],
                                k = flat / (grid.size[0] * grid.size[1]);
                     const Point3 centre = grid.origin + m * Eigen::Vector3d(double(i), double(j), double(k));
                     EXPECT_LT((x - centre).norm(), 1e-9);
                     for (int c = 0; c < 3; ++c)
                     {
                       EXPECT_GE(x[c], lo[c] - pad[c] - 1e-9) << "axis " << c;
                       EXPECT_LE(x[c], hi[c] + pad[c] + 1e-9) << "axis " << c;
                     }
                   });
  long inside = 0;
  for (long k = 0; k < grid.size[2]; ++k)
    for (long j = 0; j < grid.size[1]; ++j)
      for (long i = 0; i < grid.size[0]; ++i)
      {
        const Point3 x = grid.origin + m * Eigen::Vector3d(double(i), double(j), double(k));
        if ((x.array() >= lo.array()).all() && (x.array() <= hi.array()).all())
        {
          ++inside;
          EXPECT_EQ(visits.count(grid.Flat(i, j, k)), 1u) << "voxel " << i << "," << j << "," << k << " not visited";
        }
      }
  for (const auto& [flat, count] : visits)
    EXPECT_EQ(count, 1) << "voxel " << flat;
  EXPECT_GT(inside, 100); // the box holds voxels: the check above is not empty
  *visitedCount = long(visits.size());
}

TEST(PhantomRaster, ForEachVoxelNear_ATallBoxOnATiltedGridVisitsItsSlabNotTheGrid)
{
  // A column's box (the vertebra's: unbounded along z) on a grid tilted 20° and flipped in i: the
  // index box of its corners is the whole grid; the rows clipped to the box visit a slab.
  const Eigen::Matrix3d tilted =
    Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d(1.0, 0.3, 0.0).normalized()).toRotationMatrix() *
    Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal();
  const Grid grid = MakeTestGrid(tilted);
  long visited = 0;
  ExpectBoxVisited(grid, Point3(-8.0, 30.0, -1e6), Point3(4.0, 42.0, 1e6), &visited);
  const long all = grid.size[0] * grid.size[1] * grid.size[2];
  EXPECT_LT(visited, all / 5) << "visited " << visited << " of " << all;
  // A small box inside the grid, on the same tilted grid.
  ExpectBoxVisited(grid, Point3(-10.0, 20.0, -20.0), Point3(5.0, 35.0, 0.0), &visited);
  EXPECT_LT(visited, all / 5);
}

TEST(PhantomRaster, ForEachVoxelNear_AxisAlignedGridVisitsTheIndexBox)
{
  // On an axis-aligned grid the visit is the index box of the corners, floor to ceiling, as it was
  // before rows were clipped (the phantoms of every test stay the same voxel for voxel).
  const Grid grid = MakeTestGrid(Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal());
  const Point3 lo(-12.3, 20.2, -10.0), hi(3.1, 34.9, 25.2);
  long visited = 0;
  ExpectBoxVisited(grid, lo, hi, &visited);
  const Eigen::Matrix3d toIndex = grid.IndexToLps().inverse();
  const Eigen::Vector3d a = toIndex * (lo - grid.origin), b = toIndex * (hi - grid.origin);
  long expected = 1;
  for (int c = 0; c < 3; ++c)
    expected *= long(std::ceil(std::max(a[c], b[c]))) - long(std::floor(std::min(a[c], b[c]))) + 1;
  EXPECT_EQ(visited, expected);
}

TEST(PhantomRaster, SaturatedEdgeProfile_BeyondEightAndAHalfSigmaIsTheErfcToDoublePrecision)
{
  const double sigma = 0.6;
  for (const double d : { 8.5, 9.0, 12.0, 30.0 })
  {
    // Inside: 0.5·erfc(−x) is 1.0 in double beyond 8.5 σ.
    EXPECT_EQ(SaturatedEdgeProfile(-d * sigma, sigma), 0.5 * std::erfc(-d / std::sqrt(2.0)));
    // Outside: the erfc's value is under 1.2e-17, 0 HU after any scaling the phantom does.
    EXPECT_LT(0.5 * std::erfc(d / std::sqrt(2.0)), 1.2e-17);
    EXPECT_EQ(SaturatedEdgeProfile(d * sigma, sigma), 0.0);
    // The exact profile keeps its tail: DrawAorticWall compares tails.
    EXPECT_GT(EdgeProfile(d * sigma, sigma), 0.0);
  }
  EXPECT_DOUBLE_EQ(SaturatedEdgeProfile(sigma, sigma), 0.5 * std::erfc(1.0 / std::sqrt(2.0)));
  EXPECT_EQ(SaturatedEdgeProfile(0.0, sigma), 0.5);
}

} // namespace
} // namespace sgp::phantom
