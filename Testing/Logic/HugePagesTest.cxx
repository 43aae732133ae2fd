// Tests of AdviseHugePages and AssignAdvised (HugePages.h): the contents are what was asked for
// whatever the advice, odd and small ranges are harmless, and — where the kernel gives huge pages
// on request — an advised buffer is backed by them once written while an unadvised one is not.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Common/DistanceInsideMask.h"
#include "Common/HugePages.h"

namespace sgp
{
namespace
{

/// The kernel's transparent huge page mode ("always", "madvise", "never"), "" where not known.
std::string HugePageMode()
{
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  const std::size_t open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

/// This process's anonymous memory backed by huge pages, kB (/proc/self/smaps_rollup); -1 where
/// not known.
long AnonHugePagesKb()
{
  std::ifstream in("/proc/self/smaps_rollup");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("AnonHugePages:", 0) == 0)
    {
      std::istringstream fields(line.substr(14));
      long kb = -1;
      fields >> kb;
      return kb;
    }
  return -1;
}

TEST(HugePages, AssignAdvised_HoldsTheValuesAskedForAndDropsThePreviousOnes)
{
  std::vector<int> v{ 7, 7, 7 };
  AssignAdvised(v, 5u << 20, 3); // 20 MiB: advised
  ASSERT_EQ(v.size(), 5u << 20);
  for (std::size_t i = 0; i < v.size(); i += 4093)
    ASSERT_EQ(v[i], 3) << i;
  EXPECT_EQ(v.back(), 3);
  AssignAdvised(v, 2, -1); // small: not advised, the same contract
  EXPECT_EQ(v, (std::vector<int>{ -1, -1 }));
  AssignAdvised(v, 0, 5);
  EXPECT_TRUE(v.empty());
}

TEST(HugePages, OddRangesNullAndSmallBuffers_AreHarmless)
{
  AdviseHugePages(nullptr, 1u << 30);
  std::vector<std::uint8_t> buffer(9u << 20, 0xAB);
  AdviseHugePages(buffer.data() + 1, buffer.size() - 3); // unaligned both ends: whole pages inside only
  AdviseHugePages(buffer.data(), 100);
  for (std::size_t i = 0; i < buffer.size(); i += 4099)
    ASSERT_EQ(buffer[i], 0xAB) << i;
}

TEST(HugePages, DefaultInitAllocator_AdvisesAndStillLeavesElementsToTheirFirstWrite)
{
  std::vector<float, DefaultInitAllocator<float>> v;
  v.resize(8u << 20);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = float(i % 97);
  for (std::size_t i = 0; i < v.size(); i += 4091)
    ASSERT_EQ(v[i], float(i % 97)) << i;
}

// What the advice is for: with the kernel in "madvise" mode (Debian's default) an advised 64 MiB
// buffer is backed by huge pages once written, an unadvised one of the same size is not. In
// "always" mode both may be (only the advised one is checked); in "never" mode there is nothing to
// check. Bar: half the buffer — the kernel may give small pages at its unaligned ends or where it
// finds no free 2 MiB page, but a buffer taken wholly in 4 KiB pages means the advice did nothing.
TEST(HugePages, AdvisedBufferIsBackedByHugePagesOnceWritten)
{
  const std::string mode = HugePageMode();
  if (mode != "madvise" && mode != "always")
    GTEST_SKIP() << "the kernel gives no huge pages on request here (transparent_hugepage: '" << mode << "')";
  const long before = AnonHugePagesKb();
  ASSERT_GE(before, 0) << "no AnonHugePages in /proc/self/smaps_rollup";
  const std::size_t bytes = std::size_t(64) << 20;
  const char* tunables = std::getenv("GLIBC_TUNABLES"); // glibc.malloc.hugetlb=1 advises every block
  if (mode == "madvise" && !(tunables && std::string(tunables).find("hugetlb") != std::string::npos))
  {
    std::vector<std::uint8_t> plain(bytes, 1);
    EXPECT_LT(AnonHugePagesKb() - before, long(bytes / 1024 / 2)) << "an unadvised buffer in huge pages";
  }
  std::vector<std::uint8_t> advised;
  const long start = AnonHugePagesKb();
  AssignAdvised(advised, bytes, std::uint8_t(1));
  EXPECT_GE(AnonHugePagesKb() - start, long(bytes / 1024 / 2));
}

} // namespace
} // namespace sgp
