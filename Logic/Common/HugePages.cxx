#include "Common/HugePages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace sgp
{

void AdviseHugePages(const void* data, std::size_t bytes) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (!data || bytes < HugePageAdviceMinimumBytes)
    return;
  static const std::uintptr_t page = []
  {
    const long size = ::sysconf(_SC_PAGESIZE);
    return size > 0 ? std::uintptr_t(size) : std::uintptr_t(4096);
  }();
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (start + page - 1) / page * page;
  const std::uintptr_t last = (start + bytes) / page * page;
  if (last > first)
    (void)::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE); // advice: a refusal is ignored
#else
  (void)data;
  (void)bytes;
#endif
}

} // namespace sgp
