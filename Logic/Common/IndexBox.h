/// \file IndexBox.h
/// A box of voxels in an image's index space, the bounding box of a mask's foreground, and a loop
/// over a box that gives each voxel's flat index in the box and in the image (i fastest in both).
#pragma once

#include <array>

#include "Common/Types.h"

namespace sgp
{

struct IndexBox
{
  std::array<long, 3> first{ 0, 0, 0 }; ///< index of the box's first voxel in the image
  std::array<long, 3> size{ 0, 0, 0 };  ///< voxels along i, j, k; all 0 for an empty box
  bool Empty() const { return size[0] == 0; }
};

/// Bounding box of the non-zero voxels of `mask`, padded by `pad` voxels per axis and clipped to
/// the image; empty when the mask has no non-zero voxel. One pass over the image.
IndexBox ForegroundBox(const LabelImage& mask, const std::array<long, 3>& pad = { 0, 0, 0 });

/// The box from index `lo` to `hi` (inclusive; hi[0] < 0 for an empty box) grown by `pad` voxels
/// per axis and clipped to an image of `size`.
IndexBox PaddedBox(const std::array<long, 3>& lo,
                   const std::array<long, 3>& hi,
                   const std::array<long, 3>& pad,
                   const itk::Size<3>& size);

/// Calls f(flatInBox, flatInImage) for every voxel of `box` (which lies inside the image) in its
/// slices [firstSlice, endSlice) (k counted from the box's first); flatInBox counts from the box's
/// first voxel, so two calls on disjoint slices (two threads) write disjoint outputs.
template<typename Function>
void ForEachInBoxSlices(const IndexBox& box, const itk::Size<3>& imageSize, long firstSlice, long endSlice, Function f)
{
  long flat = firstSlice * box.size[0] * box.size[1];
  for (long k = firstSlice; k < endSlice; ++k)
  {
    for (long j = 0; j < box.size[1]; ++j)
    {
      long image = box.first[0] + long(imageSize[0]) * ((box.first[1] + j) + long(imageSize[1]) * (box.first[2] + k));
      for (long i = 0; i < box.size[0]; ++i, ++flat, ++image)
      {
        f(flat, image);
      }
    }
  }
}

/// Calls f(flatInBox, flatInImage) for every voxel of `box` (which lies inside the image).
template<typename Function>
void ForEachInBox(const IndexBox& box, const itk::Size<3>& imageSize, Function f)
{
  ForEachInBoxSlices(box, imageSize, 0, box.size[2], f);
}

} // namespace sgp
