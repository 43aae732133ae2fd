// Tests of the foreground bounding box against a voxel-by-voxel scan, on grids whose rows are and
// are not a multiple of the eight-byte words the scan reads.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "Common/IndexBox.h"

namespace sgp
{
namespace
{

LabelImage::Pointer EmptyMask(const std::array<long, 3>& size)
{
  auto mask = LabelImage::New();
  LabelImage::SizeType s{ { itk::SizeValueType(size[0]), itk::SizeValueType(size[1]), itk::SizeValueType(size[2]) } };
  mask->SetRegions(s);
  mask->Allocate(true);
  return mask;
}

TEST(IndexBox, ForegroundBox_EqualsVoxelByVoxelBoxOnRandomMasks)
{
  std::mt19937 random(1201);
  for (const std::array<long, 3> size : { std::array<long, 3>{ 16, 9, 7 }, { 13, 5, 6 }, { 7, 4, 3 }, { 1, 3, 2 } })
    for (int draw = 0; draw < 20; ++draw)
    {
      auto mask = EmptyMask(size);
      unsigned char* data = mask->GetBufferPointer();
      const long count = size[0] * size[1] * size[2];
      std::uniform_int_distribution<long> voxel(0, count - 1);
      const int marks = draw % 4; // 0 (empty) to 3 voxels, any value 1–255
      for (int m = 0; m < marks; ++m)
        data[voxel(random)] = static_cast<unsigned char>(1 + random() % 255);
      std::array<long, 3> lo{ size[0], size[1], size[2] }, hi{ -1, -1, -1 };
      for (long flat = 0; flat < count; ++flat)
        if (data[flat])
        {
          const std::array<long, 3> ijk{ flat % size[0], (flat / size[0]) % size[1], flat / (size[0] * size[1]) };
          for (unsigned a = 0; a < 3; ++a)
            lo[a] = std::min(lo[a], ijk[a]), hi[a] = std::max(hi[a], ijk[a]);
        }
      const std::array<long, 3> pad{ 1, 0, 2 };
      const IndexBox expected = PaddedBox(lo, hi, pad, mask->GetLargestPossibleRegion().GetSize());
      const IndexBox found = ForegroundBox(*mask, pad);
      EXPECT_EQ(found.first, expected.first) << size[0] << "x" << size[1] << "x" << size[2] << " draw " << draw;
      EXPECT_EQ(found.size, expected.size) << size[0] << "x" << size[1] << "x" << size[2] << " draw " << draw;
      EXPECT_EQ(found.Empty(), hi[0] < 0);
    }
}

TEST(IndexBox, ForegroundBox_VoxelsInTheLastBytesOfARow)
{
  auto mask = EmptyMask({ 19, 2, 2 });
  mask->GetBufferPointer()[19 * 3 + 17] = 1; // i = 17 of row (j, k) = (1, 1): beyond the two 8-byte words
  const IndexBox box = ForegroundBox(*mask);
  EXPECT_EQ(box.first, (std::array<long, 3>{ 17, 1, 1 }));
  EXPECT_EQ(box.size, (std::array<long, 3>{ 1, 1, 1 }));
}

} // namespace
} // namespace sgp
