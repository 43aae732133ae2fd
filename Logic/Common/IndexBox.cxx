#include "Common/IndexBox.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace sgp
{

IndexBox ForegroundBox(const LabelImage& mask, const std::array<long, 3>& pad)
{
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  const long nx = long(size[0]);
  const unsigned char* data = mask.GetBufferPointer();
  std::array<long, 3> lo{ nx, long(size[1]), long(size[2]) }, hi{ -1, -1, -1 };
  // Row by row: most rows are empty, and an empty row is told by OR-ing it eight bytes at a time
  // (the full-grid mask is 100 MB; a voxel-by-voxel min/max cost 0.1 s per call).
  const long words = nx / 8;
  for (long k = 0; k < long(size[2]); ++k)
    for (long j = 0; j < long(size[1]); ++j)
    {
      const unsigned char* row = data + nx * (j + long(size[1]) * k);
      std::uint64_t any = 0;
      for (long w = 0; w < words; ++w)
      {
        std::uint64_t word;
        std::memcpy(&word, row + 8 * w, 8);
        any |= word;
      }
      for (long i = 8 * words; i < nx; ++i)
        any |= row[i];
      if (!any)
        continue;
      long first = 0, last = nx - 1;
      while (!row[first])
        ++first;
      while (!row[last])
        --last;
      lo = { std::min(lo[0], first), std::min(lo[1], j), std::min(lo[2], k) };
      hi = { std::max(hi[0], last), std::max(hi[1], j), std::max(hi[2], k) };
    }
  return PaddedBox(lo, hi, pad, size);
}

IndexBox PaddedBox(const std::array<long, 3>& lo,
                   const std::array<long, 3>& hi,
                   const std::array<long, 3>& pad,
                   const itk::Size<3>& size)
{
  IndexBox box;
  if (hi[0] < 0)
    return box;
  for (unsigned a = 0; a < 3; ++a)
  {
    box.first[a] = std::max(0L, lo[a] - pad[a]);
    box.size[a] = std::min(long(size[a]) - 1, hi[a] + pad[a]) - box.first[a] + 1;
  }
  return box;
}

} // namespace sgp
