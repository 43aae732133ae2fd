// Tests of the binary-mask operations against masks whose answer is counted by hand.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "Common/MaskGrid.h"

namespace sgp
{
namespace
{

MaskGrid Cube(long boxSize, long first, long last)
{
  MaskGrid grid({ boxSize, boxSize, boxSize });
  for (long k = first; k <= last; ++k)
    for (long j = first; j <= last; ++j)
      for (long i = first; i <= last; ++i)
        grid.voxels[grid.Flat(i, j, k)] = 1;
  return grid;
}

TEST(MaskGrid, BallOffsets_CountsOfDiscreteBalls)
{
  EXPECT_EQ(BallOffsets({ 0, 0, 0 }).size(), 1u);
  EXPECT_EQ(BallOffsets({ 1, 1, 1 }).size(), 7u);  // centre and six faces
  EXPECT_EQ(BallOffsets({ 2, 2, 2 }).size(), 33u); // lattice points with i²+j²+k² ≤ 4
  EXPECT_EQ(BallOffsets({ 1, 1, 0 }).size(), 5u);  // flat along k
}

TEST(MaskGrid, FlatAndIjk_AreInverse)
{
  MaskGrid grid({ 4, 5, 6 });
  EXPECT_EQ(grid.Flat(3, 4, 5), grid.Count() - 1);
  EXPECT_EQ(grid.Ijk(grid.Flat(2, 3, 4)), (std::array<long, 3>{ 2, 3, 4 }));
}

TEST(MaskGrid, ErodeThenDilateCube_ShrinksThenRestoresFaces)
{
  const MaskGrid cube = Cube(12, 2, 8); // 7³
  const auto cross = BallOffsets({ 1, 1, 1 });
  const MaskGrid eroded = Erode(cube, cross);
  EXPECT_EQ(eroded.CountForeground(), 5 * 5 * 5);
  // Dilating the 5³ core by the cross gives the 7³ cube less its 12 edges of 5 voxels and 8 corners.
  EXPECT_EQ(Dilate(eroded, cross).CountForeground(), 7 * 7 * 7 - 12 * 5 - 8);
}

TEST(MaskGrid, ErodeAtBoxBorder_OutsideIsBackground)
{
  const MaskGrid full = Cube(5, 0, 4);
  EXPECT_EQ(Erode(full, BallOffsets({ 1, 1, 1 })).CountForeground(), 3 * 3 * 3);
}

TEST(MaskGrid, ConnectedComponent_FaceConnectivityOnly)
{
  MaskGrid grid({ 5, 5, 5 });
  grid.voxels[grid.Flat(1, 1, 1)] = 1;
  grid.voxels[grid.Flat(2, 1, 1)] = 1; // face neighbour
  grid.voxels[grid.Flat(3, 2, 1)] = 1; // edge neighbour of (2,1,1): another component
  EXPECT_EQ(ConnectedComponent(grid, grid.Flat(1, 1, 1)).CountForeground(), 2);
  EXPECT_EQ(ConnectedComponent(grid, grid.Flat(0, 0, 0)).CountForeground(), 0);
  std::vector<long> sizes;
  const std::vector<int> labels = LabelComponents(grid, sizes);
  EXPECT_EQ(sizes.size(), 2u);
  EXPECT_EQ(*std::max_element(sizes.begin(), sizes.end()), 2);
  EXPECT_EQ(sizes[labels[grid.Flat(1, 1, 1)] - 1], 2); // the largest holds (1, 1, 1)
  EXPECT_EQ(labels[grid.Flat(1, 1, 1)], labels[grid.Flat(2, 1, 1)]);
}

TEST(MaskGrid, FillHoles_FillsCavityNotTunnel)
{
  MaskGrid shell = Cube(9, 1, 7);
  shell.voxels[shell.Flat(4, 4, 4)] = 0; // an enclosed cavity
  for (long i = 0; i <= 8; ++i)
  {
    shell.voxels[shell.Flat(i, 2, 2)] = 0; // a tunnel open to the outside at both ends
  }
  MaskGrid filled = shell;
  FillHoles(filled);
  EXPECT_EQ(filled.voxels[filled.Flat(4, 4, 4)], 1);
  EXPECT_EQ(filled.voxels[filled.Flat(4, 2, 2)], 0);
  EXPECT_EQ(filled.CountForeground(), shell.CountForeground() + 1);
}

// The scanline fill against the definition, voxel by voxel: a background voxel stays background
// exactly when a 6-connected background path joins it to the box's border. Random masks at several
// densities (sparse: one big outside; dense: many cavities, winding tunnels, runs split by walls),
// on boxes that are thin along each axis in turn.
TEST(MaskGrid, FillHoles_EqualsBorderConnectedBackgroundOnRandomMasks)
{
  std::mt19937 random(20261201);
  const std::array<long, 3> boxes[] = { { 13, 11, 9 }, { 1, 12, 10 }, { 12, 1, 10 }, { 12, 10, 1 }, { 2, 2, 30 } };
  long cavities = 0;
  // Each draw also confined to part of a larger box (FillHoles floods only the foreground's box
  // grown by a voxel): background margins of 0–3 voxels on each side, so the foreground touches
  // some faces of the box and not others.
  std::uniform_int_distribution<long> margin(0, 3);
  for (const auto& drawn : boxes)
    for (const bool confined : { false, true })
      for (const double density : { 0.2, 0.5, 0.65, 0.8 })
      {
        std::array<long, 3> low{}, box = drawn;
        if (confined)
          for (unsigned a = 0; a < 3; ++a)
          {
            low[a] = margin(random);
            box[a] = drawn[a] + low[a] + margin(random);
          }
        MaskGrid mask(box);
        std::bernoulli_distribution foreground(density);
        for (long k = 0; k < drawn[2]; ++k)
          for (long j = 0; j < drawn[1]; ++j)
            for (long i = 0; i < drawn[0]; ++i)
              mask.voxels[mask.Flat(low[0] + i, low[1] + j, low[2] + k)] = foreground(random) ? 1 : 0;
        // Reference: breadth-first from every border background voxel.
        std::vector<char> outside(static_cast<std::size_t>(mask.Count()), 0);
        std::vector<long> queue;
        for (long flat = 0; flat < mask.Count(); ++flat)
        {
          const auto ijk = mask.Ijk(flat);
          bool border = false;
          for (unsigned a = 0; a < 3; ++a)
            border = border || ijk[a] == 0 || ijk[a] == box[a] - 1;
          if (border && !mask.voxels[flat])
          {
            outside[flat] = 1;
            queue.push_back(flat);
          }
        }
        for (std::size_t head = 0; head < queue.size(); ++head)
        {
          const auto ijk = mask.Ijk(queue[head]);
          for (unsigned a = 0; a < 3; ++a)
            for (const long d : { -1L, 1L })
            {
              auto n = ijk;
              n[a] += d;
              if (n[a] < 0 || n[a] >= box[a])
                continue;
              const long flat = mask.Flat(n[0], n[1], n[2]);
              if (!mask.voxels[flat] && !outside[flat])
              {
                outside[flat] = 1;
                queue.push_back(flat);
              }
            }
        }
        MaskGrid filled = mask;
        FillHoles(filled);
        for (long flat = 0; flat < mask.Count(); ++flat)
        {
          const int expected = (mask.voxels[flat] || !outside[flat]) ? 1 : 0;
          ASSERT_EQ(filled.voxels[flat], expected) << "voxel " << flat << " of a " << box[0] << "x" << box[1] << "x"
                                                   << box[2] << " box at density " << density;
          cavities += expected && !mask.voxels[flat];
        }
      }
  EXPECT_GT(cavities, 100); // the draws hold enough enclosed background for the comparison to mean something
}

// Pits at the box's faces count only the neighbours inside the box.
TEST(MaskGrid, FillSurfacePits_CountsOnlyNeighboursInsideTheBox)
{
  MaskGrid slab({ 5, 5, 2 });
  for (long j = 0; j < 5; ++j)
    for (long i = 0; i < 5; ++i)
      slab.voxels[slab.Flat(i, j, 0)] = 1;
  slab.voxels[slab.Flat(2, 2, 0)] = 0; // a pit in the layer
  slab.voxels[slab.Flat(0, 0, 0)] = 0; // a pit at the corner
  MaskGrid filled = slab;
  FillSurfacePits(filled, 5);
  EXPECT_EQ(filled.voxels[filled.Flat(2, 2, 0)], 0); // layer k = 1 is background: only 4 of its faces
  for (long j = 0; j < 5; ++j)
    for (long i = 0; i < 5; ++i)
      slab.voxels[slab.Flat(i, j, 1)] = 1;
  slab.voxels[slab.Flat(2, 2, 0)] = 0;
  filled = slab;
  FillSurfacePits(filled, 5);
  EXPECT_EQ(filled.voxels[filled.Flat(2, 2, 0)], 1); // 4 in-plane + 1 above = 5 (below is outside the box)
  EXPECT_EQ(filled.voxels[filled.Flat(0, 0, 0)], 0); // 2 in-plane + 1 above = 3
}

TEST(MaskGrid, GrowConstrained_StopsAfterStepsAndAtRejectedVoxels)
{
  MaskGrid line({ 10, 1, 1 });
  line.voxels[0] = 1;
  std::vector<std::uint8_t> accept(10, 1);
  accept[6] = 0;
  MaskGrid two = line;
  GrowConstrained(two, accept, 2);
  EXPECT_EQ(two.CountForeground(), 3);
  MaskGrid many = line;
  GrowConstrained(many, accept, 50);
  EXPECT_EQ(many.CountForeground(), 6); // voxels 0–5; 6 is rejected and blocks the rest
}

} // namespace
} // namespace sgp
