/// \file DistanceInsideMask.h
/// Euclidean distance, in mm, from every foreground voxel of a mask box to the nearest background
/// voxel centre, honouring anisotropic spacing.
///
/// Exact: separable passes along i, j and k, each the lower envelope of parabolas on a line
/// (Felzenszwalb & Huttenlocher, Theory of Computing 8, 2012), carrying each voxel's nearest site
/// (the feature transform of Maurer, Qi & Raghavan, IEEE PAMI 25, 2003). Linear in the box's
/// voxels, on two cores (TwoCores.h; the result is the same as one core's); 4 + 12 bytes per voxel
/// plus 16 lines of scratch per core (lines along j and k are transformed in blocks of 16 neighbours
/// along i, for locality on big boxes). When `outsideIsBackground`, the
/// one-voxel shell around the box is background too (its sites may lie just outside the box).
///
/// Input: `mask` (MaskGrid, 0/1), `spacingMm` (the i, j, k spacing). Output, per voxel of the box:
/// the distance (0 for background, at least the smallest spacing for foreground) and the box
/// index (i, j, k) of the nearest background voxel (which may lie just outside the box).
#pragma once

#include <array>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "Common/HugePages.h"
#include "Common/MaskGrid.h"

namespace sgp
{

/// An allocator that leaves new elements default-initialised (for these types: unwritten) instead of
/// zeroing them, so that a field's buffers are first written by the transform's own first loop, on
/// both cores, rather than zero-filled on one beforehand (a sixth of the thinning's time).
template<typename T>
struct DefaultInitAllocator : std::allocator<T>
{
  template<typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template<typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  /// Storage advised for huge pages (HugePages.h) before its first write.
  T* allocate(std::size_t n)
  {
    T* p = std::allocator<T>::allocate(n);
    AdviseHugePages(p, n * sizeof(T));
    return p;
  }
  template<typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template<typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct DistanceField
{
  std::vector<float, DefaultInitAllocator<float>> distanceMm;
  std::vector<std::array<int, 3>, DefaultInitAllocator<std::array<int, 3>>> nearestBackground;
};

/// \param outsideIsBackground  whether voxels outside the box count as background (sites)
/// \param maximumDistanceMm    distances are clipped to it (also a foreground without any site)
DistanceField DistanceInsideMask(const MaskGrid& mask,
                                 const std::array<double, 3>& spacingMm,
                                 bool outsideIsBackground = true,
                                 float maximumDistanceMm = 1e30f);

} // namespace sgp
