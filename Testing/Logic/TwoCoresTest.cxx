// Tests of OnTwoCores (TwoCores.h): every slice is handled exactly once, the two halves run on
// two threads, and an exception from either half comes back to the caller.
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "Common/TwoCores.h"

namespace sgp
{
namespace
{

TEST(TwoCores, EverySliceOnce_ForEveryCountAndSplit)
{
  for (long count = 0; count <= 9; ++count)
    for (long split = -1; split <= count + 1; ++split)
    {
      std::vector<std::atomic<int>> visits(static_cast<std::size_t>(count));
      OnTwoCores(
        count,
        [&](long first, long end)
        {
          for (long k = first; k < end; ++k)
            ++visits[static_cast<std::size_t>(k)];
        },
        split);
      for (long k = 0; k < count; ++k)
        EXPECT_EQ(visits[static_cast<std::size_t>(k)].load(), 1) << "count " << count << " split " << split;
    }
}

TEST(TwoCores, HalvesRunOnTwoThreads)
{
  std::vector<std::thread::id> of(2);
  OnTwoCores(10, [&](long first, long) { of[first == 0 ? 0 : 1] = std::this_thread::get_id(); });
  EXPECT_NE(of[0], of[1]);
  EXPECT_EQ(of[1], std::this_thread::get_id()); // the second half on the caller's
}

TEST(TwoCores, AnExceptionFromEitherHalf_ReachesTheCaller)
{
  for (const long throwingFirst : { 0L, 5L })
    EXPECT_THROW(OnTwoCores(10,
                            [&](long first, long)
                            {
                              if (first == throwingFirst)
                                throw std::runtime_error("half");
                            }),
                 std::runtime_error);
}

} // namespace
} // namespace sgp
