#include "Common/IndexBox.h"

#include <algorithm>

namespace sgp
{

IndexBox ForegroundBox(const LabelImage& mask, const std::array<long, 3>& pad)
{
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  const unsigned char* data = mask.GetBufferPointer();
  std::array<long, 3> lo{ long(size[0]), long(size[1]), long(size[2]) }, hi{ -1, -1, -1 };
  long flat = 0;
  for (long k = 0; k < long(size[2]); ++k)
    for (long j = 0; j < long(size[1]); ++j)
      for (long i = 0; i < long(size[0]); ++i, ++flat)
        if (data[flat])
        {
          lo = { std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k) };
          hi = { std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k) };
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
