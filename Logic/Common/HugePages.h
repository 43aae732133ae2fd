/// \file HugePages.h
/// Asking the kernel to back a large buffer with transparent huge pages (2 MiB on x86-64) before
/// it is first written. A box-sized buffer of 10-200 MB otherwise takes one page fault per 4 KiB
/// page as it is first touched — 20-50 thousand faults per buffer, a few hundred thousand in a
/// plan, on a virtual machine each a trip through the hypervisor — and with huge pages a few
/// hundred. Debian's kernel gives huge pages to memory that asks for them
/// (/sys/kernel/mm/transparent_hugepage/enabled = madvise, its default) or to all (always).
///
/// Advice only: what the buffer holds and every result are the same with or without it; where
/// the kernel refuses (no huge pages configured, "never", not Linux) nothing changes. Buffers
/// under 4 MiB are left alone (their huge pages would mostly lie outside them). Freed memory goes
/// back to the system as before: large blocks are mapped and unmapped by malloc on their own.
#pragma once

#include <cstddef>
#include <vector>

namespace sgp
{

/// Buffers of at least this many bytes are advised (smaller ones: nothing is done).
constexpr std::size_t HugePageAdviceMinimumBytes = std::size_t(4) << 20;

/// Advises [data, data + bytes) — the whole 4 KiB pages inside it — for huge pages. Call it after
/// allocating and before the first write. Never fails: a refusal is ignored.
void AdviseHugePages(const void* data, std::size_t bytes) noexcept;

/// `v` resized to `n` elements of `value` (its previous contents dropped), its storage allocated,
/// advised (AdviseHugePages) and then written, so that the writes fault huge pages.
template<typename T, typename Allocator>
void AssignAdvised(std::vector<T, Allocator>& v, std::size_t n, const T& value)
{
  std::vector<T, Allocator>().swap(v);
  v.reserve(n);
  AdviseHugePages(v.data(), n * sizeof(T));
  v.assign(n, value);
}

/// Allocates an ITK image's buffer (its regions set) and advises it (AdviseHugePages) before
/// anything is written; with `zeroed`, then fills it with 0 (what Allocate(true) gives).
template<typename Image>
void AllocateAdvised(Image& image, bool zeroed = false)
{
  image.Allocate(false);
  AdviseHugePages(image.GetBufferPointer(), image.GetPixelContainer()->Size() * sizeof(typename Image::PixelType));
  if (zeroed)
    image.FillBuffer(typename Image::PixelType{});
}

} // namespace sgp
