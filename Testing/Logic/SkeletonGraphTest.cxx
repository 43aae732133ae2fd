// Tests of the skeleton graph on skeletons drawn voxel by voxel, whose graph is known.
#include <algorithm>

#include <gtest/gtest.h>

#include "Centerlines/SkeletonGraph.h"
#include "Common/Errors.h"
#include "Common/ImageGeometry.h"

namespace sgp
{
namespace
{

/// A 1 mm grid and a skeleton of the given voxels, every one with radius `radius`.
struct DrawnSkeleton
{
  LabelImage::Pointer grid = LabelImage::New();
  Skeleton skeleton;

  explicit DrawnSkeleton(const std::vector<std::array<long, 3>>& voxels, double radius)
  {
    LabelImage::RegionType region;
    region.SetSize({ { 120, 120, 120 } });
    grid->SetRegions(region);
    for (const auto& v : voxels)
    {
      const itk::Index<3> index{ { v[0], v[1], v[2] } };
      skeleton.voxels.push_back(index);
      skeleton.pointsLps.push_back(IndexToLps(*grid, index));
      skeleton.radiusMm.push_back(radius);
      skeleton.nearestBackgroundLps.push_back(IndexToLps(*grid, index) + Point3(radius, 0, 0));
    }
  }
};

std::vector<std::array<long, 3>> Line(std::array<long, 3> from, std::array<long, 3> step, int count)
{
  std::vector<std::array<long, 3>> voxels;
  for (int i = 0; i < count; ++i)
    voxels.push_back({ from[0] + i * step[0], from[1] + i * step[1], from[2] + i * step[2] });
  return voxels;
}

int CountDegree(const SkeletonGraph& g, int degree)
{
  int n = 0;
  for (int i = 0; i < int(g.nodes.size()); ++i)
    n += g.Degree(i) == degree;
  return n;
}

TEST(SkeletonGraph, ShortSpur_PrunedAndLineJoined)
{
  auto voxels = Line({ 10, 40, 40 }, { 1, 0, 0 }, 41);    // 40 mm along x
  const auto spur = Line({ 30, 41, 40 }, { 0, 1, 0 }, 6); // 6 mm < 2 × radius 5
  voxels.insert(voxels.end(), spur.begin(), spur.end());
  DrawnSkeleton drawn(voxels, 5.0);
  for (int i = 0; i < 6; ++i) // a hair: it narrows from the axis to the wall
    drawn.skeleton.radiusMm[std::size_t(41 + i)] = 4.5 - 0.7 * i;
  const SkeletonGraph g = BuildSkeletonGraph(drawn.skeleton, *drawn.grid);
  ASSERT_EQ(g.nodes.size(), 2u);
  ASSERT_EQ(g.edges.size(), 1u);
  // The four voxels around the T are one junction at their mean, 0.25 mm off the line; once the
  // spur is pruned the path runs through that point: 40 mm within 0.1 mm, one point for three.
  EXPECT_NEAR(g.edges[0].lengthMm, 40.0, 0.1);
  EXPECT_EQ(g.edges[0].points.size(), 39u);
}

TEST(SkeletonGraph, LongBranch_KeptAsThirdEdge)
{
  auto voxels = Line({ 10, 40, 40 }, { 1, 0, 0 }, 41);
  const auto branch = Line({ 30, 41, 40 }, { 0, 1, 0 }, 20); // 20 mm > 2 × radius 5
  voxels.insert(voxels.end(), branch.begin(), branch.end());
  const DrawnSkeleton drawn(voxels, 5.0);
  const SkeletonGraph g = BuildSkeletonGraph(drawn.skeleton, *drawn.grid);
  EXPECT_EQ(CountDegree(g, 1), 3);
  EXPECT_EQ(CountDegree(g, 3), 1);
  EXPECT_EQ(g.edges.size(), 3u);
  double total = 0.0;
  for (const auto& e : g.edges)
    total += e.lengthMm;
  EXPECT_NEAR(total, 40.0 + 20.0, 0.5); // the junction's four voxels are replaced by their mean
  EXPECT_EQ(g.CountComponents(), 1);
}

/// A straight line of radius 5 along x (y = `lineY`) with a branch of `branchLength` voxels along
/// −y from x = 30, whose radii run linearly from `branchFrom` at the junction to `branchTo`.
DrawnSkeleton LineWithBranch(long lineY, int branchLength, double branchFrom, double branchTo)
{
  auto voxels = Line({ 10, lineY, 40 }, { 1, 0, 0 }, 41);
  const auto branch = Line({ 30, lineY - 1, 40 }, { 0, -1, 0 }, branchLength);
  voxels.insert(voxels.end(), branch.begin(), branch.end());
  DrawnSkeleton drawn(voxels, 5.0);
  for (int i = 0; i < branchLength; ++i)
    drawn.skeleton.radiusMm[std::size_t(41 + i)] =
      branchFrom + (branchTo - branchFrom) * double(i) / double(std::max(1, branchLength - 1));
  return drawn;
}

// A hair shorter than the spur length (8 mm < 2 × 5 mm), narrowing from the axis to the wall, is
// pruned; the same hair ending on the image's border (y = 0) is a vessel the scan cuts: kept.
// One voxel short of the border's reach (end radius 0.8 mm, 1 mm spacing: the ball reaches the
// border layer when the end lies within 1.8 mm of it) it is pruned.
TEST(SkeletonGraph, ShortNarrowingBranch_KeptWhenCutByTheImageBorder)
{
  const DrawnSkeleton cut = LineWithBranch(8, 8, 4.5, 0.8); // branch voxels y = 7 … 0
  EXPECT_EQ(CountDegree(BuildSkeletonGraph(cut.skeleton, *cut.grid), 1), 3);
  const DrawnSkeleton inside = LineWithBranch(10, 8, 4.5, 0.8); // ends at y = 2: 2 mm > 1.8 mm
  EXPECT_EQ(CountDegree(BuildSkeletonGraph(inside.skeleton, *inside.grid), 1), 2);
}

TEST(SkeletonGraph, TwoJunctionsFourMillimetresApart_MergedInAWideVessel)
{
  // An H whose bar is 4 mm: in a vessel of radius 20 mm, one branching seen twice by the grid.
  auto voxels = Line({ 0, 40, 40 }, { 1, 0, 0 }, 111);
  for (long x : { 53L, 57L })
  {
    const auto arm = Line({ x, 41, 40 }, { 0, 1, 0 }, 60); // longer than 2 × 20 mm: not spurs
    voxels.insert(voxels.end(), arm.begin(), arm.end());
  }
  const DrawnSkeleton wide(voxels, 20.0);
  const SkeletonGraph merged = BuildSkeletonGraph(wide.skeleton, *wide.grid);
  EXPECT_EQ(CountDegree(merged, 4), 1); // 4 mm < 0.25 × 20 mm
  EXPECT_EQ(CountDegree(merged, 1), 4);
  const DrawnSkeleton narrow(voxels, 10.0);
  const SkeletonGraph kept = BuildSkeletonGraph(narrow.skeleton, *narrow.grid);
  EXPECT_EQ(CountDegree(kept, 3), 2); // 4 mm ≥ 0.25 × 10 mm: two branchings
}

TEST(SkeletonGraph, Loop_KeptAsACycle)
{
  // A loop of diagonal-cornered sides (as thinning leaves them) with a tail: a tunnel in the mask
  // stays a cycle in the graph.
  std::vector<std::array<long, 3>> voxels;
  for (const auto& side : { Line({ 21, 20, 40 }, { 1, 0, 0 }, 19), Line({ 40, 21, 40 }, { 0, 1, 0 }, 19),
                            Line({ 39, 40, 40 }, { -1, 0, 0 }, 19), Line({ 20, 39, 40 }, { 0, -1, 0 }, 19),
                            Line({ 19, 30, 40 }, { -1, 0, 0 }, 15) })
    voxels.insert(voxels.end(), side.begin(), side.end());
  const DrawnSkeleton drawn(voxels, 2.0);
  const SkeletonGraph g = BuildSkeletonGraph(drawn.skeleton, *drawn.grid);
  ASSERT_EQ(g.nodes.size(), 2u); // the tail's end, and the junction on the loop
  ASSERT_EQ(g.edges.size(), 2u); // the tail, and the loop from the junction back to itself
  const int loop = g.edges[0].a == g.edges[0].b ? 0 : 1;
  EXPECT_EQ(g.edges[loop].a, g.edges[loop].b);
  EXPECT_NEAR(g.edges[loop].lengthMm, 4 * 18 + 4 * std::sqrt(2.0), 2.0); // around the loop
}

TEST(SkeletonGraph, EmptySkeleton_InputError)
{
  const DrawnSkeleton drawn({}, 1.0);
  EXPECT_THROW(BuildSkeletonGraph(drawn.skeleton, *drawn.grid), InputError);
}

} // namespace
} // namespace sgp
