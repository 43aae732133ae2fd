/// \file MaskGrid.h
/// Binary-mask operations on a cropped box of voxels, used by the lumen segmentation.
///
/// A MaskGrid is a box of `size[0] × size[1] × size[2]` voxels stored with i fastest (flat index
/// `i + size[0]·(j + size[1]·k)`), holding 0 (background) or 1 (foreground) per voxel. It lives in
/// index space only (the caller keeps the box's place in the image); voxels outside the box count
/// as background. Connectivity is 6 (faces), as in ITK's connected-threshold filter.
///
/// Costs are linear in the number of voxels of the box, times the number of ball offsets for the
/// morphology, which visits foreground (erosion) or boundary (dilation) voxels only.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace sgp
{

struct MaskGrid
{
  std::array<long, 3> size{ 0, 0, 0 };
  std::vector<std::uint8_t> voxels; ///< size[0]·size[1]·size[2] values, 0 or 1

  MaskGrid() = default;
  explicit MaskGrid(const std::array<long, 3>& boxSize);

  long Count() const { return size[0] * size[1] * size[2]; }
  long Flat(long i, long j, long k) const { return i + size[0] * (j + size[1] * k); }
  /// Inverse of Flat.
  std::array<long, 3> Ijk(long flat) const
  {
    const long jk = flat / size[0];
    return { flat % size[0], jk % size[1], jk / size[1] };
  }
  /// Number of foreground voxels.
  long CountForeground() const;
};

/// Offsets (di, dj, dk) of the voxels of an ellipsoidal ball with the given radii in voxels
/// (a radius of 0 along an axis makes the ball flat along it). Includes (0, 0, 0).
std::vector<std::array<int, 3>> BallOffsets(const std::array<int, 3>& radiusIjk);

/// Offsets (di, dj, dk) of the voxels whose centres lie within `radiusMm` of a voxel's centre on a
/// grid of `spacingMm` (mm per axis); includes (0, 0, 0).
std::vector<std::array<int, 3>> PhysicalBallOffsets(const std::array<double, 3>& spacingMm, double radiusMm);

/// Morphological erosion by `ball`: a voxel stays foreground when every ball offset from it is
/// foreground and inside the box.
MaskGrid Erode(const MaskGrid& mask, const std::vector<std::array<int, 3>>& ball);

/// Morphological dilation by `ball`, clipped to the box.
MaskGrid Dilate(const MaskGrid& mask, const std::vector<std::array<int, 3>>& ball);

/// The 6-connected foreground component that contains `seedFlat`; empty (all 0) when the seed
/// voxel is background.
MaskGrid ConnectedComponent(const MaskGrid& mask, long seedFlat);

/// Labels the 6-connected foreground components 1, 2, … (0 = background); `sizes[label − 1]` is
/// each component's voxel count.
std::vector<int> LabelComponents(const MaskGrid& mask, std::vector<long>& sizes);

/// Sets to foreground every background voxel that is not 6-connected to the box's border
/// through background (cavities inside the lumen).
void FillHoles(MaskGrid& mask);

/// Sets to foreground every background voxel with at least `minimumFaceNeighbours` of its six
/// face neighbours in the foreground (one pass): single-voxel pits that noise leaves in a surface.
void FillSurfacePits(MaskGrid& mask, int minimumFaceNeighbours);

/// Grows `mask` by up to `steps` 6-neighbour layers into voxels where `accept[flat]` is non-zero.
void GrowConstrained(MaskGrid& mask, const std::vector<std::uint8_t>& accept, int steps);

} // namespace sgp
